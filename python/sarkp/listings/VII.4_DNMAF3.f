C LISTING VII.4 DNMAF3: BELOKONEV 1990, BOOK LINES L5179-5210
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "F/3" -> "FI3"
      SUBROUTINE DNMAF3(XA, YA, XC, YC, FI3, XS2, YS2, F2, G2, XS3, YS3, F3, G3, T2, T3, AAA, F21, G21, F23, G23, H23, F34, G34)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ТРЕТЬЕГО ВИДА.
C А, С — ЦЕНТРЫ ШАРНИРОВ КИНЕМАТИЧЕСКИХ ПАР.
C S2, S3 — ТОЧКИ ПРИЛОЖЕНИЯ РАВНОДЕЙСТВУЮЩИХ СИСТЕМ
C СИЛ ЗВЕНЬЕВ 2 И 3.
C T2, T3 — ГЛАВНЫЕ МОМЕНТЫ СИСТЕМ СИЛ.
C F21, F23, F34 — РЕАКЦИИ В КИНЕМАТИЧЕСКИХ ПАРАХ,
C G21, G23, G34 — ИХ НАПРАВЛЯЮЩИЕ УГЛЫ,
C H23 — ПЛЕЧО СИЛЫ F23 ОТ С.
      COMMON/PRMTR/PI, PID2
C OCR: "F/3" -> "FI3"
      F12T3 = -F2 * COS(G2 - FI3)
C OCR: "F13" -> "FI3"
      G12T3 = DUGL4(FI3, PI, F12T3)
      CALL DVKT(XC, YC, XA, YA, RCA, FICA)
      CALL DVKT(XC, YC, XS2, YS2, RCS2, FICS2)
      CALL DVKT(XC, YC, XS3, YS3, RCS3, FICS3)
      F12N3 = -(RCA * ABS(F12T3) * SIN(G12T3 - FICA) + RCS2 * F2 *
     *SIN(G2 - FICS2) + RCS3 * F3 * SIN(G3 - FICS3) + T2 + T3)/(RCA *
C OCR: "F13" -> "FI3"
     *SIN(FI3 + PID2 - FICA))
C OCR: "F13" -> "FI3"
      G12N3 = DUGL3(FI3, PID2, F12N3)
      CALL DSMVKT(ABS(F12T3), G12T3, ABS(F12N3), G12N3, F21, G)
      G21 = G - PI
      CALL DSMVKT(F21, G, F2, G2, F23, G23)
      CALL DSMVKT(F23, G23, F3, G3, F34, G34)
      IF(F23.EQ.0.0)GO TO 1
      H23 = -(T3 + RCS3 * F3 * SIN(G3 - FICS3))/F23
      GO TO 2
1     H23 = 0.0
2     RETURN
      END
