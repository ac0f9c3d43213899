C LISTING VII.6 DNMA1: BELOKONEV 1990, BOOK LINES L5272-5318
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DNMA1(L2, FI2, L3, FI3, BS2, BS3, M2, Q2, G2,
     *M3, Q3, G3, RA, GA, RB, GB, RC, GC)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ПЕРВОГО ВИДА.
C OCR: "L2, F12 И L3, F13 —" -> "L2, FI2 И L3, FI3 —"
C L2, FI2 И L3, FI3 — РАЗМЕРЫ ЗВЕНЬЕВ И УГЛЫ, ОПРЕДЕЛЯЮЩИЕ
C ИХ ПОЛОЖЕНИЕ.
C BS2 И BS3 — РАССТОЯНИЯ ОТ ЦЕНТРА ПРОМЕЖУТОЧНОГО ШАРНИРА
C ДО ТОЧЕК ПРИВЕДЕНИЯ НА СООТВЕТСТВУЮЩИХ ЗВЕНЬЯХ.
C M2, M3 И Q2, Q3, G2, G3 — МОМЕНТЫ ВНЕШНИХ СИЛ, РАВНОДЕЙ-
C OCR: "СТВУЮЩИЕ ВНЕШНИХ СИЛ" -> "C СТВУЮЩИЕ ВНЕШНИХ СИЛ" (the comment mark lost)
C СТВУЮЩИЕ ВНЕШНИХ СИЛ И ИХ НАПРАВЛЯЮЩИЕ УГЛЫ.
C РЕЗУЛЬТАТ: RA, GA, RB, GB, RC, GC
      REAL L2, L3, M2, M3, MBQ2, MBQ3
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2,2), Y(2)
C OCR: "F12" -> "FI2"
      MBQ2 = Q2 * COS(G2) * BS2 * SIN(PI + FI2) - Q2 * SIN(G2) * BS2 * COS(PI + FI2)
      SM = M2 + MBQ2
      RAT = SM/L2
C OCR: "DUGL3(RI2," -> "DUGL3(FI2,"
      GAT = DUGL3(FI2, PID2, RAT)
C OCR: "F13" -> "FI3"
      MBQ3 = Q3 * COS(G3) * BS3 * SIN(PI + FI3) - Q3 * SIN(G3) * BS3 * COS(PI + FI3)
      SM = M3 + MBQ3
      RCT = SM/L3
C OCR: "F13" -> "FI3"
      GCT = DUGL3(FI3, PID2, RCT)
      RAT = ABS(RAT)
      RCT = ABS(RCT)
C OCR: "F12" -> "FI2"
      X(1, 1) = COS(FI2)
C OCR: "F13" -> "FI3"
      X(1, 2) = COS(FI3)
C OCR: "F12" -> "FI2"
      X(2, 1) = SIN(FI2)
C OCR: "F13" -> "FI3"
      X(2, 2) = SIN(FI3)
      Y(1) = -(RAT * COS(GAT) + Q2 * COS(G2) + Q3 * COS(G3) + RCT * COS(GCT))
      Y(2) = -(RAT * SIN(GAT) + Q2 * SIN(G2) + Q3 * SIN(G3) + RCT * SIN(GCT))
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
C OCR: "F12" -> "FI2"
      GAN = DUGL4(FI2, PI, Y(1))
      RAN = ABS(Y(1))
C OCR: "F13" -> "FI3"
      GCN = DUGL4(FI3, PI, Y(2))
      RCN = ABS(Y(2))
C OCR: "\sqrt{RAN^2 + RAT^2}" -> "SQRT(RAN ** 2 + RAT ** 2)"
      RA = SQRT(RAN ** 2 + RAT ** 2)
C OCR: "\sqrt{RCN^2 + RCT^2}" -> "SQRT(RCN ** 2 + RCT ** 2)"
      RC = SQRT(RCN ** 2 + RCT ** 2)
C OCR: "F12" -> "FI2"
      GA = DUGL6(RAN, GAN, RAT, GAT, FI2)
C OCR: "F13" -> "FI3"
      GC = DUGL6(RCN, GCN, RCT, GCT, FI3)
      RBX = -(RA * COS(GA) + Q2 * COS(G2))
      RBY = -(RA * SIN(GA) + Q2 * SIN(G2))
C OCR: "\sqrt{RBX^2 + RBY^2}" -> "SQRT(RBX ** 2 + RBY ** 2)"
      RB = SQRT(RBX ** 2 + RBY ** 2)
      GB = DUGL5(RBX, RBY)
      RETURN
      END
