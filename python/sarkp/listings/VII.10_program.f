C LISTING VII.10 PROGRAM: BELOKONEV 1990, BOOK LINES L5596-5650
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      COMMON/PRMTR/PI, PID2
C ОТЛАДКА ПРОГРАММЫ СИЛОВОГО РАСЧЕТА МЕХАНИЗМА
C ГРУППАМИ ВСЕХ ПЯТИ ВИДОВ
      DATA FS1, FS2, FS3, Q4, Q3, Q9/500.0, 1000.0, 750.0, 200.0, 300.0,
C OCR: "      200.0/" -> "     *200.0/" (continuation mark lost)
     *200.0/
      IF(W3)20, 20, 21
20    FC1 = FS1
      FC2 = FS2
      GO TO 22
21    FC1 = 0.0
      FC2 = 0.0
22    IF(W9)23, 23, 24
23    FC3 = 0.0
      GO TO 25
24    FC3 = FS3
25    CALL DSMVKT(FC1, PI, Q5, -PID2, R, G)
      CALL DNMAF5(XH, YH, 0.0, PID2, XH, YH, 0.0, 0.0, XH, B, R, G, 0.0,
     *0.0, AA, F63, G63, F76, G76, H76, F70, G70, H70)
      CALL DNMAF2(XC, YC, XD, Y, 0.0, 0.5 * (XC + XD), 0.5 * (YC + Y),
C OCR: "Q4, -PID2, X, FC2," -> "Q4, -PID2, XD, Y, FC2," (two names lost)
     *Q4, -PID2, XD, Y, FC2, PI, 0.0, 0.0, AAA, F43, G43, F54, G54, F50, G50, H50)
      CALL DSMVKT(F63, G63, F43, G43, F, G)
      CALL DSMVKT(F, G, Q3, -PID2, F3, G3)
      TM1 = DMOMNT(RFG - RFS3, FI3, F63, G63)
      TM2 = DMOMNT(RCF - RFS3, FI3, F43, G43)
      TM3 = TM1 + TM2
C OCR: "θ.θ" -> "0.0"
C OCR: "θ.5" -> "0.5"
C OCR: "θ.5" -> "0.5"
      CALL DNMAF1(XA, YA, XB, YB, ROF,0.0,0.5 * (XA + XB),0.5 * (YA +
C OCR: "θ.θ" -> "0.0"; "Q2, -RFS3 * COS(FI3) + ROF," -> "Q2, -PID2, RFS3 * COS(FI3) + ROF," (PID2 and a comma lost)
     *YB), Q2, -PID2, RFS3 * COS(FI3) + ROF, RFS3 * SIN(FI3), F3, G3,0.0, TM3,
C OCR: "F3θ" -> "F30"
C OCR: "G3θ" -> "G30"
     *AAA, F21, G21, F23, G23, F30, G30)
C OCR: "θ.θ" -> "0.0"
C OCR: "θ.θ" -> "0.0"
C OCR: "θ.θ" -> "0.0"
C OCR: "θ.θ" -> "0.0"
      CALL DNMAF4(FI9,0.0, XP, YP, XP, YP,0.0,0.0, XP, YP, FC3, PI,0.0,
C OCR: "θ.θ" -> "0.0"
C OCR: "F1θ9" -> "F109"
C OCR: "G1θ9" -> "G109"
C OCR: "H1θ9" -> "H109"
C OCR: "F1θ11" -> "F1011"
C OCR: "D1θ11" -> "G1011"
C OCR: "F11θ" -> "F110"
C OCR: "G11θ" -> "G110"
C OCR: "H11θ" -> "H110"
     *0.0, AAA, F109, G109, H109, F1011, G1011, F110, G110, H110)
C OCR: "F1θ9" -> "F109"
C OCR: "G1θ9" -> "G109"
      CALL DSMVKT(F109, G109, Q9, -PID2, F, G)
C OCR: "F1θ9" -> "F109"
C OCR: "G1θ9" -> "G109"
      TM9 = DMOMNT(RO1P + RO1S9, FIO1P, F109, G109)
C OCR: "θ.θ" -> "0.0"
C OCR: "θ.θ" -> "0.0"
C OCR: "θ.θ" -> "0.0"
      CALL DNMAF3(XM, YM,0.0, -C, F19, XM, YM,0.0,0.0, RO1S9 * COS
C OCR: "θ.θ" -> "0.0"
     *(F19), RO1S9 * SIN(F19) - C, F, G,0.0, TM9, AAA, F81, G81, F89, G89,
C OCR: "F9θ" -> "F90"
C OCR: "G9θ" -> "G90"
     *H89, F90, G90)
      TMR = DMOMNT(ROA, FI, F21, G21) + DMOMNT(ROM, FI - PI, F81,
     *G81)
C OCR: "F7θ" -> "F70"
C OCR: "F5θ" -> "F50"
C OCR: "F3θ" -> "F30"
C OCR: "F1θ9" -> "F109"
C OCR: "F1θ11" -> "F1011"
C OCR: "F11θ" -> "F110"
      PRINT 40, F63, F76, F70, F43, F54, F50, F21, F23, F30, F109, F1011, F110
C OCR: "4θFORMAT" -> "40FORMAT"
C OCR: "12F1θ.1" -> "12F10.1"
40    FORMAT(1X, 12F10.1)
C OCR: "G7θ" -> "G70"
C OCR: "G5θ" -> "G50"
C OCR: "G3θ" -> "G30"
C OCR: "G1θ9" -> "G109"
C OCR: "G1θ11" -> "G1011"
      PRINT 41, G63, G76, G70, G43, G54, G50, G21, G23, G30, G109, G1011,
C OCR: "G11θ" -> "*G110" (the continuation mark lost)
     *G110
C OCR: "12F1θ.3" -> "12F10.3"
41    FORMAT(1X, 12F10.3)
C OCR: "H7θ" -> "H70"
C OCR: "H5θ" -> "H50"
C OCR: "H1θ9" -> "H109"
C OCR: "H11θ" -> "H110"
      PRINT 42, H76, H70, H50, H109, H110
C OCR: "F2.θ3" -> "F20.3"
C OCR: "F1θ.3" -> "F10.3"
C OCR: "F3θ.3" -> "F30.3"
C OCR: "F4θ.3" -> "F40.3"
C OCR: "F2θ.3" -> "F20.3"
42    FORMAT(1X, F20.3, F10.3, F30.3, F40.3, F20.3)
C OCR: "F9θ" -> "F90"
C OCR: "G9θ" -> "G90"
      PRINT 43, F81, G81, F89, G89, H89, F90, G90, TMR, FI
43    FORMAT(1X, 9F12.3//)
53    STOP
      END
