C LISTING VII.10 DNMA5: BELOKONEV 1990, BOOK LINES L5464-5513
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: heading printed VII.9 (DNMA4 is VII.9); Table 33 says VII.10, which the text also gives to a program
      SUBROUTINE DNMA5(ETA3, FIM, AS2, AS3, FIAS2, FIAS3, M2, Q2,
     *G2, M3, Q3, G3, RA, GA, RB, HB, GB, RC, HC, GC)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ПЯТОГО ВИДА.
C ETA2, ETA3 — УГЛОВЫЕ РАЗМЕРЫ ЗВЕНЬЕВ 2 И 3.
C FIM — УГОЛ ОРИЕНТАЦИИ НАПРАВЛЯЮЩЕЙ ДВИЖЕНИЯ ЗВЕНА 3.
C AS2, FIAS2 И AS3, FIAS3 — ДЛИНА И НАПРАВЛЯЮЩИЕ
C УГЛЫ ОТРЕЗКОВ, СОЕДИНЯЮЩИХ ЦЕНТР ПРИСОЕДИНИТЕЛЬНОГО
C ШАРНИРА ЗВЕНА 2 И ЦЕНТРОВ ПРИВЕДЕНИЯ СИЛ ЗВЕНЬЕВ 2 И 3.
C M2, Q2, G2 И M3, Q3, G3 — МОМЕНТЫ И РАВНОДЕЙСТВУЮЩИЕ
C ВНЕШНИХ СИЛ, ДЕЙСТВУЮЩИХ НА ЗВЕНЬЯ 2 И 3.
C РЕЗУЛЬТАТ — RA, GA, RB, HB, GB, RC, HC, GC.
      REAL M2, M3
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2, 2), Y(2)
      X(1, 1) = COS(FIM + PID2)
      X(1, 2) = COS(FIM + ETA3 + PID2)
      X(2, 1) = SIN(FIM + PID2)
      X(2, 2) = SIN(FIM + ETA3 + PID2)
      Y(1) = -Q3 * COS(G3)
      Y(2) = -Q3 * SIN(G3)
C OCR: "8.00001" -> "0.00001"
      CALL GELG(Y, X, 2, 1, 0.00001, IER)
      RC = ABS(Y(1))
      GC = DUGL3(FIM, PID2, Y(1))
      RB = ABS(Y(2))
      GB = DUGL3((FIM + ETA3), PID2, Y(2))
      CALL DSMVKT(RB, (GB + PI), Q2, G2, RA, GA)
      GA = GA + PI
      SM1 = M2 + Q2 * COS(G2) * AS2 * SIN(FIAS2) - Q2 * SIN(G2) *
     *COS(FIAS2) * AS2
      HB = -SM1/RB
      SM = M3 + SM1 + Q3 * COS(G3) * AS3 * SIN(FIAS3) - Q3 * SIN(G3) *
     *AS3 * COS(FIAS3)
      HC = -SM/RC
      RETURN
      END
