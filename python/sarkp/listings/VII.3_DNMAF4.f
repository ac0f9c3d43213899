C LISTING VII.3 DNMAF4: BELOKONEV 1990, BOOK LINES L5116-5149
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DNMAF4(FIM, FIN, XB, YB, XS2, YS2, F2, G2, XS3, YS3,
     *F3, G3, T2, T3, AAA, F21, G21, H21, F23, G23, F34, G34, H34)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ЧЕТВЕРТОГО ВИДА, FIM, FIN — УГЛЫ
C ОБРАЗУЕМЫЕ FIM, FIN — УГЛЫ ОБРАЗУЕМЫЕ НАПРАВЛЯЮЩИМИ
C ДВИЖЕНИЯ ЗВЕНЬЕВ 2 И 3 КИНЕМАТИЧЕСКИХ ПАР А И С.
C В — ЦЕНТР ШАРНИРА КИНЕМАТИЧЕСКОЙ ПАРЫ ЗВЕНЬЕВ 2 И 3.
C S2, S3 — ТОЧКИ ПРИЛОЖЕНИЯ РАВНОДЕЙСТВУЮЩИХ СИСТЕМ СИЛ
C ЗВЕНЬЕВ 2 И 3.
C T2, T3 — ГЛАВНЫЕ МОМЕНТЫ СИСТЕМ СИЛ.
C F21, F23, F34 — РЕАКЦИИ В КИНЕМАТИЧЕСКИХ ПАРАХ.
C G21, G23, G34 — ИХ НАПРАВЛЯЮЩИЕ УГЛЫ.
C H21, H34 — ПЛЕЧИ СИЛ F21, F34 ОТНОСИТЕЛЬНО С.
      COMMON/PRMTR/PI, PID2
      CALL DVKT(XB, YB, XS2, YS2, RBS2, FIBS2)
      CALL DVKT(XB, YB, XS3, YS3, RBS3, FIBS3)
C OCR: "+ F3 * COS(G3 - FIN))" -> "+ F3 * COS(G3 - FIN))/" (the division sign lost)
      F12 = -(F2 * COS(G2 - FIN) + F3 * COS(G3 - FIN))/
     *COS(FIM + PID2 - FIN)
      G12 = DUGL3(FIM, PID2, F12)
      G21 = G12 - PI
      F21 = ABS(F12)
      CALL DSMVKT(ABS(F12), G21, F2, G2, F23, G23)
      CALL DSMVKT(F23, G23, F3, G3, F34, G34)
      IF(F21.EQ.0.0)GO TO 1
      H21 = -(T2 + F2 * RBS2 * SIN(G2 - FIBS2))/F21
      GO TO 2
1     H21 = 0.0
2     IF(F34.EQ.0.0)GO TO 3
      H34 = -(T3 + F3 * RBS3 * SIN(G3 - FIBS3))/F34
      GO TO 4
3     H34 = 0.0
4     RETURN
      END
