C LISTING X PROGRAM: BELOKONEV 1990, BOOK LINES L7254-7647
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: program X of chapter 10
C ПРИМЕР ВЫПОЛНЕНИЯ КУРСОВОГО ПРОЕКТА С ИСПОЛЬЗОВАНИЕМ
C САРКП — ТММ
C КАФЕДРА МАШИНОВЕДЕНИЯ И ДЕТАЛЕЙ МАШИН.
C ГРУППА КП—851. СТУДЕНТ ИВАНОВ И. И., РУКОВОДИТЕЛЬ
C БЕЛОКОНЕВ И. М.
C ТЕМА: ПРОЕКТИРОВАНИЕ И ИССЛЕДОВАНИЕ МЕХАНИЗМА
C ПИТАТЕЛЯ, ВАРИАНТ М
C
      COMMON/PRMTR/PI, PID2
      COMMON/ZUB/ZKRN, ZKRW, DZ, Z1, Z2, Z3, Z4
      REAL M4, M3, M2, IS4, IS3, IS2, ML, M1, IS1, IPR, IMH, M5
      INTEGER ZKRN, ZKRW, DZ, Z1, Z2, Z3, Z4
      DIMENSION FICD(3), FI5(3), X5(3)
      DIMENSION FIK(26), VT(26), AT(26), ST(26), X(26), Y(26), RK(26),
     *DLT(26), ROK(26)
      DIMENSION FI2(37), FICB(37), XE(37), FIDE(37),
     *W2(37), W3(37), VE(37), ALE(37), W4(37), E2(37),
     *AE(37), BE(37), FI1(37), XB(37), YB(37),
     *E3(37), E4(37)
      DIMENSION F43(37), G43(37), F45(37), G45(37), F50(37),
     *G50(37), F21(37), G21(37), F23(37), G23(37), F30(37),
     *G30(37), M1(37)
      DIMENSION AS(37), ASUM(37), EV(37), DEC(37), WPR(37),
     *EPR(37), WPRM(37), EPRM(37), IPR(37)
      PI = 3.14159
      PID2 = PI/2.0
C
C ОПРЕДЕЛЕНИЕ РАЗМЕРОВ ЗВЕНЬЕВ МАНИПУЛЯТОРА.
      DATA FICD/0.0, 0.349, 0.698/, FI5/1.57, 1.57, 1.57/, X5/0.82, 0.62,
C OCR: "*0.42/H5/0.64/," -> "*0.42/, H5/0.64/,"
     *0.42/, H5/0.64/, DELTA/0.698/
      CALL DSNTZR(X5, H5, FICD, FI5, 1.0, RCD, RDE, FICD1)
      WRITE(3, 1) RCD, RDE, FICD1
C OCR: "(IX," -> "(1X,"
1     FORMAT(1X, 'РАЗМЕРЫ ЗВЕНЬЕВ МАНИПУЛЯТОРА'//
     *'RCD = ', F7.3,' RDE = ', F7.3,' FICD = ', F7.3//)
      SKW = 1.1
      RCB = RCD
      FICB1 = FICD1 + PI - (PID2 + DELTA)
      CALL DSNTZ1(SKW, FICB1, FICB1 + DELTA, RCB, 0.7, -1.0, 1.0, ROA,
C OCR: "*RAB, R)" -> "*RAB, ROC)"
     *RAB, ROC)
      R2 = RAB
      WRITE(3, 2) ROA, RAB, ROC
2     FORMAT('ROA = ', F7.3,' RAB = ', F7.3,' ROC = ', F7.3//)
C
C ПОДБОР ЧИСЕЛ ЗУБЬЕВ ПЛАНЕТАРНОГО РЕДУКТОРА.
      ZKRN = 20
      ZKRW = 85
      DZ = 8
      CALL DZBPL(1, 1, 25, 2, 3, 30, 200, 3)
      CALL DZBPL(1, 1, 25, 3, 4, 30, 200, 3)
      CALL DZBPL(1, 1, 25, 4, 5, 30, 200, 3)
C OCR: "6, 7, 3, 0, 200, 3)" -> "6, 7, 30, 200, 3)"
      CALL DZBPL(1, 1, 25, 6, 7, 30, 200, 3)
      CALL DZBPL(2, 5, 1, 1, 1, 13, 35, 1)
      CALL DZBPL(3, 5, 1, 1, 1, 13, 35, 1)
      CALL DZBPL(2, 71, 10, 1, 1, 13, 35, 1)
      CALL DZBPL(3, 71, 10, 1, 1, 13, 35, 1)
C
C ГЕОМЕТРИЧЕСКИЙ РАСЧЕТ ЗУБЧАТЫХ КОЛЕС РЕДУКТОРА.
C ОПРЕДЕЛЕНИЕ КОЭФФИЦИЕНТОВ СМЕЩЕНИЯ КОЛЕС 1, 2 ИЗ
C УСЛОВИЯ ПОВЫШЕНИЯ ИЗНОСОСТОЙКОСТИ ПОВЕРХНОСТЕЙ
C ЗУБЬЕВ.
      CALL DKRKT(3.0, 20.0, 51.0, 0.0, 3, 1.0, X1, X2, AL12)
      WRITE(3, 3)X1, X2, AL12
C OCR: "КОЛЕС:')" -> "КОЛЕС:'/" (uncertain: the quotes and slashes of FORMAT 3)
3     FORMAT(1X, 'КОЭФФИЦИЕНТЫ СМЕЩЕНИЯ КОЛЕС:'/
C OCR: "*X1 = ', F7.3," -> "*' X1 = ', F7.3,"
     *' X1 = ', F7.3,' X2 = ', F7.3/
C OCR: "*УГОЛ ЗАЦЕПЛЕНИЯ AL12" -> "*' УГОЛ ЗАЦЕПЛЕНИЯ AL12"
     *' УГОЛ ЗАЦЕПЛЕНИЯ AL12 = ', F8.4)
C
C ОПРЕДЕЛЕНИЕ РАЗМЕРОВ КОЛЕС И ХАРАКТЕРИСТИКА
C ЗАЦЕПЛЕНИЙ.
      CALL DGMTZK(3.0, 20.0, 0.0, X1, 0.0, D1, S1, DB1, SB1, DA1, SA1, DF1)
      CALL DGMTZK(3.0, 51.0, 0.0, X2, 0.0, D2, S2, DB2, SB2, DA2, SA2, DF2)
      CALL DGMZPC(3.0, 20.0, 51.0, 0.0, X1, X2, 20.0, 0.0)
      CALL DGMZVN(3.0, 51.0, 122.0, X2, 0.0, 25.0, 75.0, 0.17, 83.8, 0.0)
C
C РАСЧЕТ КУЛАЧКОВОГО МЕХАНИЗМА
      BETA = PI * (SKW - 1.) / (SKW + 1.)
      FIU = (PI - BETA) * 0.4
      FIV = FIU
      FID = (PI - BETA) * 0.2
      SK = FIU / PI
C OCR: "DATA W1/3.0, DSMAX/0.06/" -> "DATA W1/3.0/, DSMAX/0.06/"
      DATA W1/3.0/, DSMAX/0.06/
      WO = DSMAX * W1 ** 2 / (2.0 * SK ** 2)
      DFI = FIU / 10.0
      FI = -DFI
      DO 5 K = 1, 26
      FI = FI + DFI
      FIK(K) = FI
C OCR: ", LE," -> ".LE."
      IF(FI.LE.FIU) AO = WO
C OCR: ", GT," -> ".GT."
C OCR: ", AND," -> ".AND."
C OCR: ", LT," -> ".LT."
      IF(FI.GT.FIU.AND.FI.LT.(FIU + FID)) AO = 0.0
C OCR: ", GT," -> ".GT."
      IF(FI.GT.(FIU + FID)) AO = -WO
      IF(FI - FIU) 25, 26, 26
25    PSI = FI
      SMAX = 0.0
      GO TO 27
26    PSI = FI - (FIU + FID)
      SMAX = 2.0 * WO * (SK / W1) ** 2
C OCR: "PHI" -> "PSI"
27    AT(K) = AO * COS(PSI / SK)
C OCR: "PHI" -> "PSI"
      VT(K) = AO * SK / W1 * SIN(PSI / SK)
C OCR: "PHI" -> "PSI"
      ST(K) = AO * (SK / W1) ** 2 * (1.0 - COS(PSI / SK)) + SMAX
5     CONTINUE
      CALL DPRFPL(26, PI/3.0, W1, FIK, AT, VT, X, Y, RK, DLT, ROK, RKSH)
      WRITE(3, 6)
6     FORMAT(1X, 'КИНЕМАТИЧЕСКИЕ ХАРАКТЕРИСТИКИ ДВИЖЕНИЯ
C OCR: "*ГОЛКАТЕЛЯ' 5X," -> "*ТОЛКАТЕЛЯ'/5X,"
     *ТОЛКАТЕЛЯ'/5X, 'FIK', 8X, 'AT', 8X, 'VT', 8X, 'ST')
      WRITE(3, 7)(FIK(K), AT(K), VT(K), ST(K), K = 1, 26)
7     FORMAT(1X, 4F10.4)
      WRITE(3, 8)RKSH
8     FORMAT(1X// 'РАДИУС КУЛАЧКОВОЙ ШАЙБЫ - RKSH = ', F7.4//)
      WRITE(3, 9)
C OCR: "ПРОФИЛЯ КУЛАЧКА//" -> "ПРОФИЛЯ КУЛАЧКА'//"
9     FORMAT(1X, 'ХАРАКТЕРИСТИКИ ПРОФИЛЯ КУЛАЧКА'//
     *5X, 'FIK', 7X, 'X', 9X, 'Y', 9X, 'RK', 7X, 'DLT', 7X, 'ROK')
      WRITE(3, 4)(FIK(K), X(K), Y(K), RK(K), DLT(K), ROK(K), K = 1, 26)
4     FORMAT(1X, 6F10.4)
C
C КИНЕМАТИЧЕСКИЙ РАСЧЕТ МЕХАНИЗМА МАНИПУЛЯТОРА.
      DF = 2.0 * PI/36.0
      F = -DF
      XC = -ROC * SIN(DELTA)
      YC = ROC * COS(DELTA)
      DO 30 K = 1, 37
      F = F + DF
      FI1(K) = F
      XA = ROA * COS(F)
      YA = ROA * SIN(F)
      CALL DPRM1(XA, YA, XC, YC, R2, RCB, -1.0, 2.0, FI2(K),
     *FICB(K), XB(K), YB(K))
      XD = XC + RCD * COS(FICB(K) + PI)
      YD = YC + RCD * SIN(FICB(K) + PI)
      CALL DPRM2(XD, YD, 0.0, 0.0, H5 + YC, 0.0, RDE, 0.0, PID2, 2.0,
     *XE(K), YE, FIDE(K))
      VA = W1 * ROA
      ALA = F + PID2
      CALL DSKOR1(R2, FI2(K), RCB, FICB(K), VA, ALA, 0.0,
C OCR: "0.0, 2.0, VBA, ALBA, VEC, ALBC," -> "0.0, 2.0, VBA, ALBA, VBC, ALBC,"
     *0.0, 2.0, VBA, ALBA, VBC, ALBC, VB, ALB, W2(K), W3(K))
      VD = RCD * ABS(W3(K))
      ALD = DUGL3(FICB(K) + PI, PID2, W3(K))
      CALL DSKOR2(VD, ALD, 0.0, 0.0, RDE, FIDE(K), 0.0, 2.0,
     *VED, ALED, VEG, ALEG, VE(K), ALE(K), W4(K))
      AA = W1 ** 2 * ROA
      BA = F + PI
      CALL DUSKR1(AA, BA, 0.0, 0.0, R2, FI2(K), RCB, FICB(K),
     *W2(K), W3(K), 2.0, ABAT, BBAT, ABCT, BBCT, AB, BB,
     *E2(K), E3(K))
      AD = RCD * SQRT(W3(K) ** 4 + E3(K) ** 2)
C OCR: "ATAN(ABS(K))/W3(K) ** 2)" -> "ATAN(ABS(E3(K))/W3(K) ** 2),"
      BD = DUGL3(FICB(K) + PI, PI - ATAN(ABS(E3(K))/W3(K) ** 2),
     *E3(K))
C OCR: "DUSKR2(AD, BD, 0., 0., 0., RDE," -> "DUSKR2(AD, BD, 0., 0., 0., 0., RDE," (a zero lost)
      CALL DUSKR2(AD, BD, 0., 0., 0., 0., RDE, FIDE(K), W2(K),
     *0.0, 2.0, AEDT, BEDT, AEG, BEG, E4(K), AE(K), BE(K))
C
C ОПРЕДЕЛЕНИЕ УСИЛИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C МАНИПУЛЯТОРА
      DATA G/9.81/, ML/50.0/, AAA/2.0/
      M4 = ML * RDE
      M5 = 2.0 * M4
      M3 = 2.0 * RCD * ML
      M2 = ML * R2
      IS4 = M4 * RDE ** 2
      IS3 = M3 * (2.0 * RCD) ** 2
      IS2 = M2 * R2 ** 2
      IS1 = (ML * ROA) * ROA ** 2
      IF (W3(K))15, 16, 16
15    FS = 2000.0
      GO TO 17
16    FS = 400.0
17    CALL DSMVKT(FS, PI, 2. * G * M4, -PID2, F5, G5)
      XS4 = XD + 0.3 * RDE * COS(FIDE(K))
      YS4 = YD + 0.3 * RDE * SIN(FIDE(K))
      CALL DNMAF2(XD, YD, XE(K), YE, 0., XS4, YS4, G * M4, -PID2,
     *XE(K), YE, F5, G5, 0.0, 0.0, 2.0, F43(K), G43(K), F45(K),
     *G45(K), F50(K), G50(K), H50)
      CALL DSMVKT(F43(K), G43(K), G * M3, -PID2, F3, G3)
C OCR: "DMOONT" -> "DMOMNT"
      T3 = DMOMNT(0.85 * RCD, FICB(K) + PI, F43(K), G43(K))
      CALL DNMAF1(XA, YA, XB(K), YB(K), XC, YC, XA + 0.5 * R2 *
     *COS(FI2(K)), YA + 0.5 * R2 * SIN(FI2(K)), G * M2, -PID2,
     *XC + 0.15 * RCD * COS(FICB(K) + PI), YC + 0.15 * RCD * SIN(FICB
     *(K) + PI), F3, G3, 0.0, T3, 2.0, F21(K), G21(K), F23(K),
C OCR: "*G23(K), F30(K), G30(K)" -> "*G23(K), F30(K), G30(K))" (the closing parenthesis lost)
     *G23(K), F30(K), G30(K))
C OCR: "F11(K)" -> "FI1(K)"
      M1(K) = DMOMNT(ROA, FI1(K), F21(K), G21(K))
C
C ОПРЕДЕЛЕНИЕ ПРИВЕДЕННОГО МОМЕНТА ИНЕРЦИИ
      CALL DSMVKT(VD, ALD, ABS(W4(K)) * 0.3 * RDE, ALED, VS4, ALS4)
      CALL DSMVKT(VA, ALA, ABS(W2(K)) * R2/2.0, ALBA, VS2, ALS2)
      IPR(K) = (M5 * VE(K) ** 2 + M4 * VS4 ** 2 + IS4 * W4(K) ** 2 + M3 *
     *(W3(K) * 0.15 * RCD) ** 2 + (IS3 + M3 * (0.15 * RCD) ** 2) *
     *W3(K) ** 2 + M2 * VS2 ** 2 + IS2 * W2(K) ** 2)/W1 ** 2
C OCR: "30    C CONTINUE" -> "30    CONTINUE"
30    CONTINUE
C
C ОПЕРАТОРЫ ВЫВОДА ИНФОРМАЦИИ НА ПЕЧАТАЮЩЕЕ
C УСТРОЙСТВО
      WRITE(3, 10)
10    FORMAT(1X, 'КИНЕМАТИЧЕСКИЙ РАСЧЕТ МЕХАНИЗМА',
     *'МАНИПУЛЯТОРА'//5X,
     *'ЛИНЕЙНЫЕ И УГЛОВЫЕ ПЕРЕМЕЩЕНИЯ ЗВЕНЬЕВ'/
     *3X, 'F11', 5X, 'F12', 6X, 'FICB', 6X, 'XE', 6X, 'FIDE',
     *6X, 'XB', 7X, 'YB'/)
C OCR: "F11(K)" -> "FI1(K)", "F12(K)" -> "FI2(K)"
      WRITE(3, 11)(FI1(K), FI2(K), FICB(K), XE(K),
     *FIDE(K), XB(K), YB(K), K = 1, 37)
      WRITE(3, 12)
11    FORMAT(7F9.4)
12    FORMAT(5X//'ЛИНЕЙНЫЕ И УГЛОВЫЕ СКОРОСТИ ЗВЕНЬЕВ'/
     *3X, 'F11', 6X, 'W2', 7X, 'W3', 7X, 'VE', 7X, 'ALE', 6X,
     *'W4'/)
C OCR: "F11(K)" -> "FI1(K)"
      WRITE(3, 13)(FI1(K), W2(K), W3(K), VE(K), ALE(K),
     *W4(K), K = 1, 37)
13    FORMAT(6F9.4)
      WRITE(3, 14)
14    FORMAT(5X//'ЛИНЕЙНЫЕ И УГЛОВЫЕ УСКОРЕНИЯ ЗВЕНЬЕВ'/
     *3X, 'F11', 6X, 'E2', 7X, 'E3', 7X, 'E4', 7X, 'AE', 7X, 'BE'/)
C OCR: "F11(K)" -> "FI1(K)"
      WRITE(3, 15)(FI1(K), E2(K), E3(K), E4(K), AE(K),
     *BE(K), K = 1, 37)
      WRITE(3, 18)
C OCR: "FORMAT('//ОПРЕДЕЛЕНИЕ" -> "FORMAT(//'ОПРЕДЕЛЕНИЕ"
18    FORMAT(//'ОПРЕДЕЛЕНИЕ УСИЛИЙ В КИНЕМАТИЧЕСКИХ'/
     *'ПАРАХ МЕХАНИЗМА МАНИПУЛЯТОРА'//10X,
     *'ВЕЛИЧИНЫ УСИЛИЙ И МОМЕНТ СОПРОТИВЛЕНИЯ'/
     *4X, 'F11', 5X, 'F43', 6X, 'F45', 6X, 'F50', 6X, 'F30', 6X,
     *'F23', 6X, 'F21', 6X, 'M1')
C OCR: "F11(K)" -> "FI1(K)"
      WRITE(3, 19)(FI1(K), F43(K), F45(K), F50(K), F30(K),
     *F23(K), F21(K), M1(K), K = 1, 37)
19    FORMAT(F8.3, 6F9.1, F8.1)
      WRITE(3, 20)
20    FORMAT(/10X, 'НАПРАВЛЯЮЩИЕ УГЛЫ ВЕКТОРОВ СИЛ'/
     *4X, 'F11', 5X, 'G43', 6X, 'G45', 6X, 'G50', 6X, 'G30',
     *6X, 'G23', 6X, 'G21')
C OCR: "F11(K)" -> "FI1(K)"
      WRITE(3, 21)(FI1(K), G43(K), G45(K), G50(K), G30(K),
     *G23(K), G21(K), K = 1, 37)
21    FORMAT(F8.3, 6F9.3)
C
C РЕШЕНИЕ УРАВНЕНИЯ ДВИЖЕНИЯ МЕХАНИЗМА МАНИПУЛЯТОРА
      CALL DZKNDV(37, 37.0, W1, IS1, M1, IPR, AAA, AS, ASUM, EV,
     *DEC, WPR, EPR)
C
C ОПРЕДЕЛЕНИЕ МОМЕНТА ИНЕРЦИИ МАХОВИКА
      CALL DMHVK(37, 0.01, IS1, W1, DEC, AAA, IMH)
      CALL DZKNDV(37, 37.0, W1, IS1 + IMH, M1, IPR, AAA, AS, ASUM,
     *EV, DEC, WPRM, EPRM)
      WRITE(3, 22)
C OCR: "//IX," -> "//1X,"; "УРАВНЕНИЯ ДВИЖЕНИЯ /" -> "УРАВНЕНИЯ ДВИЖЕНИЯ'/"
22    FORMAT(//1X, 'РЕЗУЛЬТАТЫ РЕШЕНИЯ УРАВНЕНИЯ ДВИЖЕНИЯ'/
     *8X, 'МЕХАНИЗМА МАНИПУЛЯТОРА'/
     *2X, 'F11', 4X, 'IPR', 5X, 'AS', 4X, 'ASUM', 4X, 'EV', 5X,
     *'DEC', 3X, 'WPR', 5X, 'EPR', 2X, 'WPRM', 4X, 'EPRM'/)
C OCR: "F11(K)" -> "FI1(K)"
      WRITE(3, 23)(FI1(K), IPR(K), AS(K), ASUM(K), EV(K),
C OCR: "DE3(K)" -> "DEC(K)"
     *DEC(K), WPR(K), EPR(K), WPRM(K), EPRM(K), K = 1, 37)
      WRITE(3, 24)IMH
C OCR: "//IX," -> "//1X,"
24    FORMAT(//1X, 'МОМЕНТ ИНЕРЦИИ МАХОВИКА — IMH = ', F7.2)
23    FORMAT(F6.3, 5F7.1, F7.2, F8.2, F6.2, F8.2)
      STOP
      END
