C LISTING III.2 DSNTZ1: BELOKONEV 1990, BOOK LINES L1061-1105
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSNTZ1 (KW3, FI31, FI32, L3, XD, Q, AAA, L1, L2, LO)
      REAL KW3, L1, L2, L3, LO, KSD, KC1E
      DIMENSION A(2, 2), C(2)
      PI = 3.14159
      BETA = PI * (KW3 - 1.)/(KW3 + 1.)
      XC1 = XD + L3 * COS(FI31)
      YC1 = L3 * SIN(FI31)
      XC2 = XD + L3 * COS(FI32)
      YC2 = L3 * SIN(FI32)
      KSD = -(XC2 - XC1)/(YC2 - YC1)
C OCR: "KCIE" -> "KC1E"
      KC1E = TAN(FI31 + BETA)
C OCR: "A(1.1)" -> "A(1,1)"
      A(1,1) = 1.
C OCR: "A(1.2)" -> "A(1,2)"
      A(1,2) = -KSD
C OCR: "A(2.1)" -> "A(2,1)"
      A(2,1) = 1.
C OCR: "KCIE" -> "KC1E"; "A(2.2)" -> "A(2,2)"
      A(2,2) = -KC1E
      C(1) = -KSD * XD
C OCR: "KCIE" -> "KC1E"
      C(2) = -KC1E * XC1 + YC1
      CALL GELG(C, A, 2, 1, 0.0001, IER)
      YE = C(1)
      XE = C(2)
      R = SQRT((XE - XC1) ** 2 + (YE - YC1) ** 2)
      XA = XE + SIGN(SQRT(R ** 2 - YE ** 2), Q)
      L1 = 0.5 * (SQRT((XA - XC1) ** 2 + YC1 ** 2) - SQRT((XA - XC2) **
     *2 + YC2 ** 2))
      L2 = SQRT((XA - XC1) ** 2 + YC1 ** 2) - L1
      LO = ABS(XD - XA)
C OCR: "KCIE" -> "KC1E"
      PRINT 5, XC1, YC1, XC2, YC2, KSD, KC1E, XE, YE, R, XA
5     FORMAT(1X, 10F11.4)
C OCR: ", NE," -> ".NE."
      IF(AAA.NE.0.0)RETURN
C OCR: "WRITE(3.1)" -> "WRITE(3,1)"
      WRITE(3,1)KW3, FI31, FI32, L3, XD, Q, L1, L2, LO
C OCR: "      FORMAT(1X 'СИНТЕЗ" -> "1     FORMAT(1X, 'СИНТЕЗ" (label 1 and a comma lost)
1     FORMAT(1X, 'СИНТЕЗ МЕХАНИЗМА ШАРНИРНОГО'/
C OCR: "ПОЛОЖЕНИЯМ и KW3.'" -> "ПОЛОЖЕНИЯМ И KW3.'"
     *'ЧЕТЫРЕХЗВЕННИКА ПО ДВУМ ПОЛОЖЕНИЯМ И KW3.'/
C OCR: "'ВХОДНЫЕ ПАРАМЕТРЫ:.'/" -> "'ВХОДНЫЕ ПАРАМЕТРЫ:'/"
     *'ВХОДНЫЕ ПАРАМЕТРЫ:'/
C OCR: "L3 = ',F6.3." -> "L3 = ',F6.3,"
     *'KW3 = ',F5.3,' FI31 = ',F7.4,' FI32 = ',F7.4,' L3 = ',F6.3,
C OCR: "//1X.' ВЫХОДНЫЕ ПАРАМЕТРЫ:.'/" -> "//1X,' ВЫХОДНЫЕ ПАРАМЕТРЫ:'/"
     *'XD = ',F7.3,' Q = ',F3.0//1X,' ВЫХОДНЫЕ ПАРАМЕТРЫ:'/
     *'L1 = ',F7.3,' L2 = ',F7.3,' LO = ',F7.3)
      RETURN
      END
