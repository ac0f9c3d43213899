C LISTING III.3 DSNTZ2: BELOKONEV 1990, BOOK LINES L1134-1181
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSNTZ2(KW3, FI3, L3, XD, GMIN, GMAX, AAA, L1, L2, LO)
      REAL KW3, L3, L1, L2, LO, KC1A, KC2A
      DIMENSION A(2,2), C(2)
      PI = 3.14159
      BETA = PI * (KW3 - 1)/(KW3 + 1.)
      PSI = BETA + GMAX - GMIN
      XC1 = XD + L3 * COS(FI3)
      YC1 = L3 * SIN(FI3)
      XC2 = XD + L3 * COS(FI3 + PSI)
      YC2 = L3 * SIN(FI3 + PSI)
C OCR: "KC1A + TAN" -> "KC1A = TAN"
      KC1A = TAN(FI3 - GMIN)
      KC2A = TAN(FI3 + PSI - GMAX)
      A(1,1) = -KC1A
      A(1,2) = 1.
      A(2,1) = -KC2A
      A(2,2) = 1.
      C(1) = YC1 - KC1A * XC1
      C(2) = YC2 - KC2A * XC2
      CALL GELG(C, A, 2, 1, 0.0001, IER)
      XA = C(1)
      YA = C(2)
      L1 = 0.5 * (SQRT((XC1 - XA) ** 2 + (YC1 - YA) ** 2) - SQRT((XC2 -
     *XA) ** 2 + (YC2 - YA) ** 2))
      L2 = SQRT((XC1 - XA) ** 2 + (YC1 - YA) ** 2) - L1
      LO = SQRT((XD - XA) ** 2 + YA ** 2)
C OCR: ", NE," -> ".NE."
      IF(AAA.NE.0.0)RETURN
      WRITE(3,1)
1     FORMAT(1X,'СИНТЕЗ ШАРНИРНОГО ЧЕТЫРЕХЗВЕННИКА ПО'/
     *'УГЛУ ПЕРЕДАЧИ ДВИЖЕНИЯ И КОЭФФИЦИЕНТУ ИЗМЕНЕНИЯ'/
     *'СКОРОСТИ ВЫХОДНОГО ЗВЕНА'//)
      WRITE(3,2)KW3, FI3, L3, XD, GMIN, GMAX, L1, L2, LO, XA, YA
2     FORMAT(1X,'ВХОДНЫЕ ПАРАМЕТРЫ СИНТЕЗА:'/
     *' KW3 = ',F6.4,' FI3 = ',F6.4,' L3 = ',F7.4,' XD = ',F7.4,
     *' GMIN = ',F6.4,' GMAX = ',F6.4/
C OCR: "*' 1X, 'ВЫХОДНЫЕ" -> "*1X, 'ВЫХОДНЫЕ"
     *1X, 'ВЫХОДНЫЕ ПАРАМЕТРЫ СИНТЕЗА:'/
C OCR: "' Y" -> "' YA = ',"; "*'F7.4//)" -> "*F7.4//)"
     *' L1 = ',F7.4,' L2 = ',F7.4,' LO = ',F7.4,' XA = ',F7.4,' YA = ',
     *F7.4//)
      RETURN
      END
