C LISTING V.5 PROGRAM: BELOKONEV 1990, BOOK LINES L3358-3433
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C ПРИМЕР ПРОЕКТИРОВАНИЯ КУЛАЧКОВОГО МЕХАНИЗМА С
C ПОСТУПАТЕЛЬНО ДВИЖУЩИМСЯ ЗАОСТРЕННЫМ ТОЛКАТЕЛЕМ.
      COMMON/KLCHK/ALFAD, BETA, W, RSCNTR, RZMR, INDEX, RKSH,
C OCR: "      EXCTST, ETAO" -> "     *EXCTST, ETAO" (continuation mark lost)
     *EXCTST, ETAO
      DIMENSION FI(51), D2SDT(51), DSDT(51), S(51), XPRFL(51),
C OCR: "RKRVZN(51)" -> "RKRZVN(51)" (ERRATA E-V5-3)
     *YPRFL(51), RPRFL(51), DELTA(51), ALFA(51), RKRZVN(51)
C OCR: "DATA PI, N/31.4159,51/" -> "DATA PI, N/3.14159,51/" (ERRATA E-V5-1)
      DATA PI, N/3.14159,51/
      W = 5.0
      A1 = 15.0
      ALFAD = 0.523
      BETA = 0.35
      RSCNTR = 0.0
      RZMR = 0.0
      INDEX = 1
      ETAO = 0.0
      FIU = 5.0 * PI/9.0
      FID = PI/18.0 * 5.0
      FIV = 5.0 * PI/9.0
      FIB = 2.0 * PI - FIU - FID - FIV
      DFI = PI/36.0
      C = -DFI
      TK1 = FIU/2.0/PI
      TK2 = FIV/2.0/PI
      A2 = A1 * FIU/FIV
      DO 2 K = 1, N
      C = C + DFI
      FI(K) = C
      IF(FI(K).LE.FIU)GO TO 3
      IF(FI(K).LE.(FIU + FID))GO TO 4
      D2SDT(K) = -A2 * SIN((FI(K) - (FIU + FID))/TK2)
      GO TO 2
4     D2SDT(K) = 0.0
      GO TO 2
3     D2SDT(K) = A1 * SIN(FI(K)/TK1)
2     CONTINUE
      NOMER = 2
      CALL DINTGR(N, DFI, NOMER, D2SDT, DSDT)
      DO 6 K = 1, N
      DSDT(K) = DSDT(K)/W
6     CONTINUE
      CALL DINTGR(N, DFI, NOMER, DSDT, S)
      DO 7 K = 1, N
      S(K) = S(K)/W
7     CONTINUE
      CALL DKLCHK(N, S, DSDT, D2SDT)
      CALL DPRFLP(N, RKSH, EXCTST, W, FI, D2SDT, DSDT, S, XPRFL,
     *YPRFL, RPRFL, A, ALFA, RKRZVN)
      WRITE(3, 8)
8     FORMAT(50H КИНЕМАТИЧЕСКИЕ ХАРАКТЕРИСТИКИ ДВИЖЕНИЯ
C OCR: "*ТОЛКАТЕЛЯ)." -> "*ТОЛКАТЕЛЯ)"
     *ТОЛКАТЕЛЯ)
      WRITE(3, 9)
9     FORMAT(1X, 5X, 'FI', 10X, 'D2SDT', 7X, 'DSDT', 10X, 'S')
      WRITE(3, 10)(FI(K), D2SDT(K), DSDT(K), S(K), K = 1, N)
C OCR: "FORMAT(1H, 4F12.5)" -> "FORMAT(1H , 4F12.5)" (the blank of 1H lost)
10    FORMAT(1H , 4F12.5)
      WRITE(3, 11)RKSH, EXCTST
C OCR: "ШАЙБЫ F9.5," -> "ШАЙБЫ —', F9.5," (an apostrophe and a dash lost; uncertain)
11    FORMAT(1X, 'ОСНОВНЫЕ РАЗМЕРЫ КУЛАЧКА: РАДИУС
     *КУЛАЧКОВОЙ ШАЙБЫ —', F9.5, 'ЭКСЦЕНТРИСИТЕТ —', F9.5//
     *10X, 'ХАРАКТЕРИСТИКИ ПРОФИЛЯ КУЛАЧКА')
      WRITE(3, 15)
15    FORMAT(1X, 5X, 'FI', 8X, 'XPRFL', 6X, 'YPRFL', 6X, 'RPRFL', 6X,
C OCR: "*'DELTA 6X," -> "*'DELTA', 6X,"
     *'DELTA', 6X, 'ALFA', 6X, 'RKRZVN')
      WRITE(3,16)(FI(K), XPRFL(K), YPRFL(K), RPRFL(K), DELTA(K),
C OCR: "ALFA(K), ZN(K), K" -> "ALFA(K), RKRZVN(K), K" (the name cut)
     *ALFA(K), RKRZVN(K), K = 1, N)
16    FORMAT(1X, 7F11.5)
      STOP
      END
