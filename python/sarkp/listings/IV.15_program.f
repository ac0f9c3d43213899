C LISTING IV.15 PROGRAM: BELOKONEV 1990, BOOK LINES L2476-2545
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      COMMON/PRMTR/PI, PID2
C ОТЛАДКА ПРОГРАММЫ КИНЕМАТИЧЕСКОГО РАСЧЕТА МЕХАНИЗМА
C ГРУППАМИ ВСЕХ ПЯТИ ВИДОВ
      DATA ROA, RAB, RBF, RCF, RFG, RGD, ROM, A, B, C, D, RFS3, RFS4,
C OCR: "ROI59, WI" -> "RO1S9, W1"
     *RO1S9, W1
     */0.22, 0.45, 0.35, 0.5, 0.7, 0.58, 0.3, 0.2, 0.77, 0.62, 0.27, 0.17, 0.2,
     *0.15, 2.0/, AAA/5.0/, ROF/0.42/, Q5/100.0/, Q2/50.0/
      PI = 3.14159
      PID2 = PI/2.0
      DFI = 2.0 * PI/24.0
      FI = DFI
5     FI = FI - DFI
      IF(FI.LT.(-6.3))GO TO 53
6     YA = ROA * SIN(FI)
      XA = ROA * COS(FI)
C OCR: "RBF -1.0" -> "RBF, -1.0"
      CALL DPRM1(XA, YA, ROF, 0.0, RAB, RBF, -1.0, AAA, F12, F13, XB, YB)
      XC = RCF * COS(FI3) + ROF
      YC = RCF * SIN(FI3)
      CALL DPRM2(XC, YC, 0.0, A, 0.0, RCD, 0.0, 0.0, AAA, XD, Y, F14)
      XH = RFG * COS(FI3) + ROF
      YH = RFG * SIN(FI3)
      XM = ROM * COS(FI + PI)
      YM = ROM * SIN(FI + PI)
C OCR: "FIO1M," -> "FIO1M)"
      CALL DPRM3(XM, YM, 0.0, -C, 0.0, 0.0, 1.0, AAA, RO1M, F19, FIO1M)
      CALL DPRM4(0.0, -C, 0.0, -C, F19, 0.0, 0.0, 0.0, -(C + D), 0.0, 0.0,
     *0.0, 0.0, 0.0, AAA, XP, YP, RO1P, FIO1P, RV, FV)
      CALL DSKOR1(RAB, F12, RBF, F13, W1 * ROA, FI - PID2, 0.0, 0.0,
     *AAA, VBA, ALBA, VBF, ALBF, VB, ALB, W2, W3)
      VC = ABS(W3) * RCF
      ALC = DUGL3(FI3, PID2, W3)
      CALL DSKOR2(VC, ALC, 0.0, 0.0, RCD, F14, 0.0, AAA, VDC, ALDC,
     *VDE, ALDE, VD, ALD, W4)
      CALL DSKOR5(XH, YH, 0.0, 0.0, 0.0, PID2, 0.0, ABS(W3) * RFG,
     *DUGL3(FI3, PID2, W3), AAA, VGH, ALGH, VGL, ALGL, VG, ALG)
      CALL DSKOR3(XM, YM, 0.0, -C, W1 * ROM, FI + PID2, 0.0, 0.0,
     *F19, AAA, VNM, ALNM, VNO1, ALNO1, VN, ALN, W9)
      CALL DSKOR4(RO1P, FIO1P, F19, RV, FV, 0.0, W9, 0.0, AAA, VPM,
     *ALPM, VPM, ALPN, VP, ALP)
      CALL DUSKR1(W1 ** 2 * ROA, FI - PI, 0.0, 0.0, RAB, F12, RBF, F13,
C OCR: "W2, W3, AA, ABAT" -> "W2, W3, AAA, ABAT"
     *W2, W3, AAA, ABAT, BBAT, ABFT, BBFT, AB, BB, E2, E3)
      AC = RCF * SQRT(W3 ** 4 + E3 ** 2)
      BC = DUGL3(FI3, PI - ATAN(ABS(E3)/W3 ** 2), E3)
      CALL DUSKR2(AC, BC, 0.0, 0.0, 0.0, 0.0, RCD, F14, W4, 0.0, AAA,
     *ADCT, BDCT, ADE, BDE, E4, AD, BD)
C OCR: "0.0, 0.0, 0.0, 0.0, PID2, RFG * SQRT*" -> "0.0, 0.0, 0.0, 0.0, 0.0, PID2, RFG * SQRT"
      CALL DUSKR5(XH, YH, 0.0, 0.0, 0.0, 0.0, 0.0, PID2, RFG * SQRT
C OCR: "*(W3 ** 4 + E3, BC," -> "*(W3 ** 4 + E3 ** 2), BC,"
     *(W3 ** 4 + E3 ** 2), BC, 0.0, 0.0, 0.0, 0.0, AAA, AGH, BGH, AGL, BGL, AG, BG)
C OCR: "FIO1M,*" -> "FIO1M,"
      CALL DUSKR3(W1 ** 2 * ROM, FI, 0.0, 0.0, F19, W9, RO1M, FIO1M,
C OCR: "*2.0 VNM * A(W9)" -> "*2.0 * VNM * ABS(W9)"
     *2.0 * VNM * ABS(W9), DUGL3(ALNM, PID2, W9), AAA, ANM, BNM, ANOIT,
     *BNOIT, E9, AN, BN)
C OCR: "0.0, 0.0,*" -> "0.0, 0.0,"
      CALL DUSKR4(RO1P, FIO1P, FIO1P, 0.0, 0.0, 0.0, W9, E9, 0.0, 0.0,
C OCR: "*2.0 VPM * ABS(W9)" -> "*2.0 * VPM * ABS(W9)"
     *2.0 * VPM * ABS(W9), DUGL3(ALPM, PID2, W9), 0.0, 0.0, AAA, APR,
C OCR: "*BPR, APS, AP, BP)" -> "*BPR, APS, BPS, AP, BP)"
     *BPR, APS, BPS, AP, BP)
      PRINT 10, FI, F12, F13, XB, YB, XD, F14, RO1M, F19, XP, RO1P, FIO1P
10    FORMAT(1X, 12F9.4)
      PRINT 11, FI, VBA, ALBA, VB, ALB, W2, W3, VDC, ALDC, VD, ALD, W4
      PRINT 11, FI, ANM, BNM, E9, AN, BN, APR, BPR, AP, BP, ANOIT, BNOIT
      PRINT 11, FI, AB, BB, E2, E3, E4, AD, BD, AGH, BGH, AG, BG
11    FORMAT(1X, 12F10.3)
      PRINT 12, FI, VGH, ALGH, VG, ALG, VNM, ALNM, VN, ALN, W9, VPM,
C OCR: "*ALPM, VP, A" -> "*ALPM, VP, ALP"
     *ALPM, VP, ALP
12    FORMAT(1X, 14F8.3)
      GO TO 5
53    STOP
      END
