C LISTING III.4 DSNTZ3: BELOKONEV 1990, BOOK LINES L1214-1264
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "F11" -> "FI1"
      SUBROUTINE DSNTZ3(XB1, YB1, XB2, YB2, XC1, YC1, XC2, YC2, FI1,
     *ALC1, AAA, L1, L2, LO)
      REAL L1, L2, LO, KS1A, KS2E, KC1D
      PI = 3.14159
      DIMENSION A1(2, 2), C1(2), A2(2, 2), C2(2)
      FIB1B2 = DUGL2(XB1, YB1, XB2, YB2)
      FIC1C2 = DUGL2(XC1, YC1, XC2, YC2)
      KS1A = -1./TAN(FIB1B2)
      KS2D = -1./TAN(FIC1C2)
C OCR: "F11" -> "FI1"
      KB1A = TAN(FIB1B2 - PI/2. + FI1/2.)
      KC1D = -1./TAN(ALC1)
      XS1 = 0.5 * (XB1 + XB2)
      YS1 = 0.5 * (YB1 + YB2)
      XS2 = 0.5 * (XC1 + XC2)
      YS2 = 0.5 * (YC1 + YC2)
      A1(1, 1) = -KB1A
      A1(1, 2) = 1.
      A1(2, 1) = -KS1A
      A1(2, 2) = 1.
      C1(1) = YB1 - KB1A * XB1
      C1(2) = YS1 - KS1A * XS1
      CALL GELG(C1, A1, 2, 1, 0.0001, IER)
      A2(1, 1) = -KC1D
      A2(1, 2) = 1.
      A2(2, 1) = -KS2D
      A2(2, 2) = 1.
      C2(1) = YC1 - KC1D * XC1
      C2(2) = YS2 - KS2D * XS2
      CALL GELG(C2, A2, 1, 0.0001, IER)
      L1 = SQRT((C1(1) - XB1) ** 2 + (C1(2) - YB1) ** 2)
      L3 = SQRT((XC1 - C2(1)) ** 2 + (YC1 - C2(2)) ** 2)
      LO = SQRT((C2(1) - C1(1)) ** 2 + (C2(2) - C1(2)) ** 2)
C OCR: ", NE," -> ".NE."
      IF(AAA.NE.0)RETURN
C OCR: "F11" -> "FI1"
      WRITE(3, 1)XB1, YB1, XB2, YB2, FI1, ALC1, L1, L3, LO
1     FORMAT(1X, 'СИНТЕЗ МЕХАНИЗМА ШАРНИРНОГО'/
C OCR: "ПО//ДВУМ ПОЛОЖЕНИЯМ ШАТУНА. '//" -> "ПО ДВУМ ПОЛОЖЕНИЯМ ШАТУНА. '//"
     *'ЧЕТЫРЕХЗВЕННИКА ПО ДВУМ ПОЛОЖЕНИЯМ ШАТУНА. '//
C OCR: "1X, *'ВХОДНЫЕ" -> "*1X, 'ВХОДНЫЕ"
     *1X, 'ВХОДНЫЕ ПАРАМЕТРЫ: '//
     *'XB1 = ',F7.3,' YB1 = ',F7.3,' XB2 = ',F7.3,' YB2 = ',F7.3,
     *' F11 = ',F7.3,' ALC1 = ',F7.3//1X, 'ВЫХОДНЫЕ ПАРАМЕТРЫ: '//
     *'L1 = ',F7.3,' L3 = ',F7.3,' LO = ',F7.3//)
      RETURN
      END
