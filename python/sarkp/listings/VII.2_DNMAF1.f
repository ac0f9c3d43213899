C LISTING VII.2 DNMAF1: BELOKONEV 1990, BOOK LINES L5055-5087
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DNMAF1(XA, YA, XB, YB, XC, YC, XS2, YS2, F2, G2,
     *XS3, YS3, F3, G3, T2, T3, AAA, F21, G21, F23, G23, F34, G34)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ПЕРВОГО ВИДА.
C А, В, С — ЦЕНТРЫ ШАРНИРОВ КИНЕМАТИЧЕСКИХ ПАР.
C S2, S3 — ТОЧКИ ПРИЛОЖЕНИЯ РАВНОДЕЙСТВУЮЩИХ СИСТЕМ
C СИЛ ЗВЕНЬЕВ 2 И 3.
C T2, T3 — ГЛАВНЫЕ МОМЕНТЫ СИСТЕМ СИЛ.
C F21, F23, F34 — РЕАКЦИИ В КИНЕМАТИЧЕСКИХ ПАРАХ.
C G21, G23, G34 — ИХ НАПРАВЛЯЮЩИЕ УГЛЫ.
      COMMON/PRMTR/PI, PID2
      CALL DVKT(XB, YB, XS2, YS2, RBS2, FIBS2)
      CALL DVKT(XC, YC, XS2, YS2, RCS2, FICS2)
      CALL DVKT(XC, YC, XS3, YS3, RCS3, FICS3)
      CALL DVKT(XC, YC, XA, YA, RCA, FICA)
      CALL DVKT(XA, YA, XB, YB, R, FI)
      F12T = -(RBS2 * F2 * SIN(G2 - FIBS2) + T2)/R
      G12T = DUGL4(FI - PID2, -PI, F12T)
      F12T = ABS(F12T)
      F12N = -(F12T * RCA * SIN(G12T - FICA) + F2 * RCS2 * SIN(G2 -
     *FICS2) + F3 * RCS3 * SIN(G3 - FICS3) + T2 + T3)/(RCA * SIN(FI -
     *FICA))
      G12N = DUGL4(FI, PI, F12N)
      CALL DSMVKT(ABS(F12T), G12T, ABS(F12N), G12N, F21, G)
      G21 = G - PI
      CALL DSMVKT(F21, G, F2, G2, F23, G23)
      CALL DSMVKT(F23, G23, F3, G3, F34, G34)
      RETURN
      END
