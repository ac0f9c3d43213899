C LISTING VII.5 DNMAF5: BELOKONEV 1990, BOOK LINES L5233-5268
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DNMAF5(XA, YA, FIM, TT3, XS2, YS2, F2, G2, XS3, YS3,
     *F3, G3, T2, T3, AAA, F21, G21, F32, G32, H32, F34, G34, H34)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ПЯТОГО ВИДА.
C А — ЦЕНТР ШАРНИРА КИНЕМАТИЧЕСКОЙ ПАРЫ.
C FIM — УГОЛ НАПРАВЛЯЮЩЕЙ ДВИЖЕНИЯ ЗВЕНА 3
C КИНЕМАТИЧЕСКОЙ ПАРЫ С.
C TT3 — УГОЛ НАПРАВЛЯЮЩЕЙ ДВИЖЕНИЯ ЗВЕНА 2
C ОТНОСИТЕЛЬНО ЗВЕНА 3 КИНЕМАТИЧЕСКОЙ ПАРЫ В.
C S2, S3 — ТОЧКИ ПРИЛОЖЕНИЯ РАВНОДЕЙСТВУЮЩИХ СИСТЕМ
C СИЛ ЗВЕНЬЕВ 2 И 3.
C T2, T3 — ГЛАВНЫЕ МОМЕНТЫ СИСТЕМ СИЛ.
C F21, F23, F34 — РЕАКЦИИ В КИНЕМАТИЧЕСКИХ ПАРАХ.
C G21, G23, G34 — ИХ НАПРАВЛЯЮЩИЕ УГЛЫ.
C H23, H34 — ПЛЕЧИ СИЛ F23, F34 ОТНОСИТЕЛЬНО ТОЧКИ А.
      COMMON/PRMTR/PI, PID2
      CALL DVKT(XA, YA, XS2, YS2, RAS2, FIAS2)
      CALL DVKT(XA, YA, XS3, YS3, RAS3, FIAS3)
      F43 = -F3 * COS(G3 - FIM - TT3)/COS(PID2 - TT3)
      G43 = DUGL3(FIM, PID2, F43)
      G34 = G43 - PI
      F34 = ABS(F43)
      CALL DSMVKT(F34, G34 - PI, F3, G3, F32, G32)
      CALL DSMVKT(F32, G32, F2, G2, F21, G21)
      IF(F34.EQ.0.0)GO TO 1
C OCR: "RAS2 * F2 * *" -> "RAS2 * F2 *" (the continuation mark printed twice)
      H34 = -(T2 + T3 + RAS3 * F3 * SIN(G3 - FIAS3) + RAS2 * F2 *
     *SIN(G2 - FIAS2))/F34
      GO TO 2
1     H34 = 0.0
2     IF(F32.EQ.0.0)GO TO 3
      H32 = -(T2 + RAS2 * F2 * SIN(G2 - FIAS2))/F32
      GO TO 4
3     H32 = 0.0
4     RETURN
      END
