C LISTING VII.1 DNMAF2: BELOKONEV 1990, BOOK LINES L4988-5020
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DNMAF2(XA, YA, XB, YB, FIM, XS2, YS2, F2, G2, XS3,
     *YS3, F3, G3, T2, T3, AAA, F21, G21, F23, G23, F34, G34, H34)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ВТОРОГО ВИДА. А, В — ЦЕНТРЫ
C ШАРНИРОВ КИНЕМАТИЧЕСКИХ ПАР. FIM — УГОЛ НАПРАВЛЯЮЩЕЙ
C ПАРЫ С. S2, S3 — ТОЧКИ ПРИЛОЖЕНИЯ РАВНОДЕЙСТВУЮЩИХ
C СИСТЕМ СИЛ ЗВЕНЬЕВ 2 И 3, T2 И T3 — ГЛАВНЫЕ МОМЕНТЫ
C СИСТЕМ СИЛ. F21, F23, F34 — РЕАКЦИИ В КИНЕМАТИЧЕСКИХ
C ПАРАХ. G21, G23, G34 — ИХ НАПРАВЛЯЮЩИЕ УГЛЫ.
      COMMON/PRMTR/PI,PID2
      F12M = -(F2 * COS(G2 - FIM) + F3 * COS(G3 - FIM))
      G12M = DUGL4(FIM, PI, F12M)
      CALL DVKT(XB, YB, XA, YA, R, FI)
      CALL DVKT(XB, YB, XS2, YS2, RBS2, FIBS2)
      F12NM = -(T2 + RBS2 * F2 * SIN(G2 - FIBS2) + R * ABS(F12M) *
     *SIN(G12M - FI)) / (R * SIN(FIM + PID2 - FI))
      G12NM = DUGL3(FIM, PID2, F12NM)
      CALL DSMVKT(ABS(F12M), G12M, ABS(F12NM), G12NM, F12, G)
      G21 = G - PI
      F21 = F12
      CALL DSMVKT(F12, G, F2, G2, F23, G23)
      CALL DSMVKT(F23, G23, F3, G3, F34, G34)
      CALL DVKT(XB, YB, XS3, YS3, RBS3, FIBS3)
      IF(F34.EQ.0.0) GO TO 1
      H34 = -(RBS3 * F3 * SIN(G3 - FIBS3) + T3) / F34
      GO TO 2
1     H34 = 0.0
2     RETURN
      END
