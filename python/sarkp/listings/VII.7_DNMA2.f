C LISTING VII.7 DNMA2: BELOKONEV 1990, BOOK LINES L5320-5368
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "DNMA2(L2, F12, L3, ETA, F10," -> "DNMA2(L2, FI2, L3, ETA, FIO,"
      SUBROUTINE DNMA2(L2, FI2, L3, ETA, FIO, BS2, BS3, M2,
C OCR: "RA, CA, RB," -> "RA, GA, RB,"
     *Q2, G2, M3, Q3, G3, RA, GA, RB, GB, RC, HC, GC)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ВТОРОГО ВИДА.
C OCR: "L2, F12 И L3, ETA, F10 —" -> "L2, FI2 И L3, ETA, FIO —"
C L2, FI2 И L3, ETA, FIO — ЛИНЕЙНЫЕ И УГЛОВЫЕ РАЗМЕРЫ
C ЗВЕНЬЕВ И УГЛЫ, ОПРЕДЕЛЯЮЩИЕ ИХ ПОЛОЖЕНИЯ.
C BS2 И BS3 — РАССТОЯНИЯ ОТ ЦЕНТРА ПРОМЕЖУТОЧНОГО
C ШАРНИРА ДО ТОЧЕК ПРИВЕДЕНИЯ НА СООТВЕТСТВУЮЩИХ
C ЗВЕНЬЯХ.
C M2, M3 И Q2, Q3, G2, G3 — МОМЕНТЫ ВНЕШНИХ СИЛ,
C РАВНОДЕЙСТВУЮЩИЕ ВНЕШНИХ СИЛ И ИХ НАПРАВЛЯЮЩИЕ
C УГЛЫ.
C РЕЗУЛЬТАТ: RA, GA, RB, GB, RC, GC, HC.
      COMMON/PRMTR/PI, PID2
      REAL L2, L3, M2, M3, MBQ2, MBQ3
      DIMENSION X(2, 2), Y(2)
      MBQ2 = Q2 * COS(G2) * BS2 * SIN(PI + FI2) - Q2 * SIN(G2) * BS2 *
     *COS(PI + FI2)
      SM = M2 + MBQ2
      RAT = SM/L2
      GAT = DUGL3(FI2, PID2, RAT)
      RAT = ABS(RAT)
      X(1, 1) = COS(FI2)
      X(1, 2) = COS(FIO + PID2)
      X(2, 1) = SIN(FI2)
      X(2, 2) = SIN(FIO + PID2)
      Y(1) = -(RAT * COS(GAT) + Q2 * COS(G2) + Q3 * COS(G3))
      Y(2) = -(RAT * SIN(GAT) + Q2 * SIN(G2) + Q3 * SIN(G3))
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      GAN = DUGL4(FI2, PI, Y(1))
      RAN = ABS(Y(1))
      GC = DUGL3(FIO, PID2, Y(2))
      RC = ABS(Y(2))
      RA = SQRT(RAN ** 2 + RAT ** 2)
C OCR: "DUGL6(RAN, CAN," -> "DUGL6(RAN, GAN,"
      GA = DUGL6(RAN, GAN, RAT, GAT, FI2)
      MBQ3 = Q3 * COS(G3) * BS3 * SIN(PI + FIO + ETA) - Q3 * SIN(G3) *
     *BS3 * COS(PI + FIO + ETA)
      HC = -(M3 + MBQ3)/RC
      RX = -(RA * COS(GA) + Q2 * COS(G2))
      RY = -(RA * SIN(GA) + Q2 * SIN(G2))
      RB = SQRT(RX ** 2 + RY ** 2)
      GB = DUGL5(RX, RY)
      RETURN
      END
