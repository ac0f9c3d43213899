C LISTING VII.8 DNMA3: BELOKONEV 1990, BOOK LINES L5372-5413
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DNMA3(L2, ETA2, FI3, CS2, FICS2, CS3, FICS3, AC, FIAC,
     *M2, M3, Q3, G3, RA, GA, RB, HB, GB, RC, GC)
      COMMON/PRMTR/PI, PID2
      REAL L2, M2, M3, MCQ2, MCQ3, MAQ2
      DIMENSION X(2, 2), Y(2)
      MCQ2 = Q2 * SIN(G2) * CS2 * COS(FICS2) - Q2 * COS(G2) * CS2 * SIN
     *(FICS2)
      MCQ3 = Q3 * SIN(G3) * CS3 * COS(FICS3) - Q3 * COS(G3) * CS3 * SIN
     *(FICS3)
      SM = M2 + M3 + MCQ2 + MCQ3
      RAT = SM/AC
      GAT = DUGL3(FIAC, -PID2, RAT)
      RAT = ABS(RAT)
      X(1, 2) = COS(FIAC)
      X(1, 2) = COS(FI3 + PID2)
      X(2, 1) = SIN(FIAC)
      X(2, 2) = SIN(FI3 + PID2)
      Y(1) = -(RAT * COS(GAT) + Q2 * COS(G2))
      Y(2) = -(RAT * SIN(GAT) + Q2 * SIN(G2))
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      GAN = DUGL4(FIAC, PI, Y(1))
      RAN = ABS(Y(1))
      GB = DUGL3(FI3, PID2, Y(2))
      RB = ABS(Y(2))
      RA = SQRT(RAN ** 2 + RAT ** 2)
      GA = DUGL6(RAN, GAN, RAT, GAT, FIAC)
C OCR: "COS(GR + PI)" -> "COS(GB + PI)"
      RX = -(RB * COS(GB + PI) + Q3 * COS(G3))
      RY = -(RB * SIN(GB + PI) + Q3 * SIN(G3))
      RC = SQRT(RX ** 2 + RY ** 2)
      GC = DUGL5(RX, RY)
      HB = -(M3 + MCQ3)/RB
      RETURN
      END
