C LISTING II.13 PROGRAM: BELOKONEV 1990, BOOK LINES L831-884
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: heading printed П.13.
C ПРИМЕР СОСТАВЛЕНИЯ ПРОГРАММЫ ГЕОМЕТРИЧЕСКОГО И КИНЕМАТИЧЕСКОГО РАСЧЕТОВ МЕХАНИЗМА, ПРИВЕДЕННОГО НА РИС. 3
      REAL L1, LO, LAC, L3, L2, LBD, NU
C OCR: "F1(18)" -> "FI(18)"
      DIMENSION A(2,2), C(2), FI(18)
      READ(1, 1)L1, L2, L3, LO, NU, LBD
1     FORMAT(6F8.4)
      W1 = 2.0
      PI = 3.14159
      DFI = PI/18.0
C OCR: "F11" -> "FI1"
      FI1 = -DFI
      DO 5 K = 1, 18
C OCR: "F11" -> "FI1"
      FI1 = FI1 + DFI
C OCR: "F11" -> "FI1"; "F1(K)" -> "FI(K)"
      FI(K) = FI1
C OCR: "F11" -> "FI1"
      XA = L1 * COS(FI1)
C OCR: "F11" -> "FI1"
      YA = L1 * SIN(FI1)
      CALL DVKT(XA, YA, LO, 0.0, LAC, FIAC)
      DELTA = ARCOS((L2**2 + LAC**2 - L3**2)/(2.0 * L2 * LAC))
      FI2 = FIAC + DELTA
      XB = XA + L2 * COS(FI2)
      YB = YA + L2 * SIN(FI2)
      FI3 = DUGL1(LO, 0.0, XB, YB)
      XD = XB + LBD * COS(FI2 + (PI - NU))
      YD = YB + LBD * SIN(FI2 + (PI - NU))
      VA = ABS(W1 * L1)
C OCR: "F11" -> "FI1"
      ALA = DUGL1(FI1, PI/2., W1)
      A(1, 1) = COS(FI3 + PI/2.)
      A(1, 2) = -COS(FI2 + PI/2.)
      A(2, 1) = SIN(FI3 + PI/2.)
      A(2, 2) = -SIN(FI2 + PI/2.)
      C(1) = VA * COS(ALA)
      C(2) = VA * SIN(ALA)
      CALL GELG(C, A, 2, 1, 0.0001, IER)
      VBC = C(1)
      VBA = C(2)
      ALBA = DUGL3(FI2, PI/2., VBA)
      ALBC = DUGL3(FI3, PI/2., VBC)
C OCR: "DOMEQA(L2" -> "DOMEGA(L2"
      W2 = DOMEGA(L2, FI2, VBA, ALBA)
C OCR: "DOMEQA(L3" -> "DOMEGA(L3"
      W3 = DOMEGA(L3, FI3, VBC, ALBC)
C OCR: "PI -- NU" -> "PI - NU"; "PI/2., W2)." -> "*PI/2., W2),"; "* VD. ALD)" -> "*VD, ALD)"
      CALL DSMVKT(VBC, ALBC, ABS(W2) * LBD, DUGL3(FI2 + PI - NU,
     *PI/2., W2),
     *VD, ALD)
      PRINT 2, FI(K), FI2, FI3, XB, YB, XD, YD, VD, ALD, W2, W3
2     FORMAT(1X, 11F10.4)
5     CONTINUE
      STOP
      END
