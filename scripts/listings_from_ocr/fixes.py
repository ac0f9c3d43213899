import sys, os
from apply import apply
F = {}
F['II.13_program.f'] = [
    ('all', r'\bF11\b', 'FI1'),
    ('sub', 'F1(18)', 'FI(18)'),
    ('sub', 'F1(K)', 'FI(K)'),
    ('sub', 'DOMEQA(L2', 'DOMEGA(L2'),
    ('sub', 'DOMEQA(L3', 'DOMEGA(L3'),
    ('raw', '''      CALL DSMVKT(VBC, ALBC, ABS(W2) * LBD, DUGL3(FI2 + PI -- NU),
      PI/2., W2).
     *VD. ALD)''', '''C OCR: "PI -- NU" -> "PI - NU"; "PI/2., W2)." -> "*PI/2., W2),"; "* VD. ALD)" -> "*VD, ALD)"
      CALL DSMVKT(VBC, ALBC, ABS(W2) * LBD, DUGL3(FI2 + PI - NU,
     *PI/2., W2),
     *VD, ALD)'''),
]
F['II.9_DMOMNT.f'] = []
# Two defects ERRATA calls "OCR/author" are read as OCR here: the book's own printed results
# come from code that called these routines, so the code the author ran had a label 110
# (a label 111 does not exist) and took the step H (its body uses H; every call passes it).
F['II.6_DUGL4.f'] = [
    ('sub', 'IF(VEL)109,110,111', 'IF(VEL)109,110,110', 'no label 111 exists; ERRATA E-DUGL4-1'),
]
F['II.1_DINTGR.f'] = [
    ('sub', 'DINTGR(M, N, NOMER, Y, FINT)', 'DINTGR(M, H, NOMER, Y, FINT)', 'the body and every call use the step H; ERRATA E-DINTGR-1'),
]
F['III.1_DSNTZR.f'] = [
    ('all', r'\bF11\(', 'FI1('), ('all', r'\bF13\(', 'FI3('),
    ('sub', 'DSNTZR(LO, L3, F11, F13,', 'DSNTZR(LO, L3, FI1, FI3,'),
    ('sub', 'F11(3) — УГЛОВЫЕ', 'FI1(3) — УГЛОВЫЕ'), ('sub', 'F13(3) — УГЛОВЫЕ', 'FI3(3) — УГЛОВЫЕ'), ('sub', 'МАССИВА F13(3)', 'МАССИВА FI3(3)'),
    ('sub', '/2,0', '/2.0'),
    ('sub', "FORMAT(1X, СИНТЕЗ МЕХАНИЗМА ШАРНИРНОГО/", "FORMAT(1X, 'СИНТЕЗ МЕХАНИЗМА ШАРНИРНОГО'/", 'quotes lost'),
    ('sub', "'ЗВЕНЬЕВ. '//ИСХОДНЫЕ", "'ЗВЕНЬЕВ. '//'ИСХОДНЫЕ", 'quote lost'),
]
F['III.2_DSNTZ1.f'] = [
    ('all', r'\bKCIE\b', 'KC1E'),
    ('all', r'A\((\d)\.(\d)\)', r'A(\1,\2)'),
    ('sub', "      FORMAT(1X 'СИНТЕЗ", "1     FORMAT(1X, 'СИНТЕЗ", 'label 1 and a comma lost'),
    ('sub', "ПОЛОЖЕНИЯМ и KW3.'", "ПОЛОЖЕНИЯМ И KW3.'"),
    ('sub', "'ВХОДНЫЕ ПАРАМЕТРЫ:.'/", "'ВХОДНЫЕ ПАРАМЕТРЫ:'/"),
    ('sub', "L3 = ',F6.3.", "L3 = ',F6.3,"),
    ('sub', "//1X.' ВЫХОДНЫЕ ПАРАМЕТРЫ:.'/", "//1X,' ВЫХОДНЫЕ ПАРАМЕТРЫ:'/"),
]
F['III.3_DSNTZ2.f'] = [
    ('sub', 'KC1A + TAN', 'KC1A = TAN'),
    ('sub', "*' 1X, 'ВЫХОДНЫЕ", "*1X, 'ВЫХОДНЫЕ"),
    ('raw', """     *' L1 = ',F7.4,' L2 = ',F7.4,' LO = ',F7.4,' XA = ',F7.4,' Y
     *'F7.4//)""", """C OCR: "' Y" -> "' YA = ',"; "*'F7.4//)" -> "*F7.4//)"
     *' L1 = ',F7.4,' L2 = ',F7.4,' LO = ',F7.4,' XA = ',F7.4,' YA = ',
     *F7.4//)"""),
]
F['III.4_DSNTZ3.f'] = [
    ('all', r'\bF11\b(?!\s*=\s*\')', 'FI1'),
    ('sub', "ПО//ДВУМ ПОЛОЖЕНИЯМ ШАТУНА. '//", "ПО ДВУМ ПОЛОЖЕНИЯМ ШАТУНА. '//"),
    ('raw', "      1X, *'ВХОДНЫЕ ПАРАМЕТРЫ: '//", "C OCR: \"1X, *'ВХОДНЫЕ\" -> \"*1X, 'ВХОДНЫЕ\"\n     *1X, 'ВХОДНЫЕ ПАРАМЕТРЫ: '//"),
]
F['III.5_program.f'] = [
    ('all', r'\bF11\b', 'FI1'), ('all', r'\bF13\b', 'FI3'),
    ('raw', 'C ПРИМЕР ГЛАВНОЙ ПРОГРАММЫ, ИСПОЛЬЗУЮЩЕЙ РАЗНЫЕ ПОДСПРОГРАММЫ СИНТЕЗА', 'C OCR: "ПОДСПРОГРАММЫ" -> "ПОДПРОГРАММЫ"\nC ПРИМЕР ГЛАВНОЙ ПРОГРАММЫ, ИСПОЛЬЗУЮЩЕЙ РАЗНЫЕ ПОДПРОГРАММЫ\nC СИНТЕЗА'),
]
F['IV.3_DPRM3.f'] = [
    ('all', r'\bFIZ\b', 'FI3'),
]
F['IV.4_DPRM4.f'] = [
    ('sub', 'X(1, 1) = 1, 0', 'X(1, 1) = 1.0'),
    ('sub', 'X(2, 1) = 1, 0', 'X(2, 1) = 1.0'),
]
F['IV.6_DSKOR2.f'] = [('sub', 'DOMECA', 'DOMEGA')]
F['IV.8_DSKOR4.f'] = [
    ('sub', 'AAA, VBVM, ALBVM, VBBN', 'AAA, VBBM, ALBBM, VBBN', 'ERRATA E-DSKOR4-1'),
    ('sub', 'ALBVM = DUGL3', 'ALBM = DUGL3', 'ERRATA E-DSKOR4-2'),
    ('sub', '2, 1, 8, 0, 0, 1, IER', '2, 1, 0.0001, IER'),
]
F['IV.9_DSKOR5.f'] = [('sub', 'ALC3CM = DUGL4', 'ALC2CM = DUGL4')]
F['IV.10_DUSKR1.f'] = [
    ('sub', '8.0001', '0.0001'),
    ('sub', 'E2 = DOMEQA', 'E2 = DOMEGA'), ('sub', 'E3 = DOMEQA', 'E3 = DOMEGA'),
]
F['IV.11_DUSKR2.f'] = [
    ('all', r'\bF12\b', 'FI2'),
    ('all', r'\bDSMVKI\b', 'DSMVKT'),
]
F['IV.12_DUSKR3.f'] = [
    ('raw', 'BA3CT, E3, AA3, BA3) COMMON/PRMTR/PI, PID2', 'BA3CT, E3, AA3, BA3)\n      COMMON/PRMTR/PI, PID2'),
    ('all', r'\bBAZA([RK])\b', r'BA3A\1'),
    ('sub', 'DSMVWT', 'DSMVKT'),
]
F['IV.13_DUSKR4.f'] = [
    ('sub', 'AAA, ABVMR, BBVMR,', 'AAA, ABBMR, BBBMR,'),
    ('sub', 'ABBMK = ABS(Y(1))', 'ABBMR = ABS(Y(1))', 'ERRATA E-DUSKR4-4'),
    ('sub', 'DSMVKT(ABM, BVM,', 'DSMVKT(ABM, BBM,'),
    ('sub', '8     X(1, 1)', '      X(1, 1)', 'a stray label; ERRATA E-DUSKR4-6'),
]
F['IV.14_DUSKR5.f'] = [
    ('sub', 'SQRT(WM *', 'SQRT(WM **'),
]
F['IV.15_program.f'] = [
    ('sub', 'ROI59, WI', 'RO1S9, W1'),
    ('sub', 'RBF -1.0', 'RBF, -1.0'),
    ('sub', 'FIO1M,\n', 'FIO1M)\n'),
    ('sub', 'W2, W3, AA, ABAT', 'W2, W3, AAA, ABAT'),
    ('sub', '0.0, 0.0, 0.0, 0.0, PID2, RFG * SQRT*', '0.0, 0.0, 0.0, 0.0, 0.0, PID2, RFG * SQRT'),
    ('sub', '*(W3 ** 4 + E3, BC,', '*(W3 ** 4 + E3 ** 2), BC,'),
    ('sub', 'FIO1M,*', 'FIO1M,'),
    ('sub', '*2.0 VNM * A(W9)', '*2.0 * VNM * ABS(W9)'),
    ('sub', '0.0, 0.0,*', '0.0, 0.0,'),
    ('sub', '*2.0 VPM * ABS(W9)', '*2.0 * VPM * ABS(W9)'),
    ('sub', '*BPR, APS, AP, BP)', '*BPR, APS, BPS, AP, BP)'),
    ('sub', '*ALPM, VP, A\n', '*ALPM, VP, ALP\n'),
]
F['IV.16_DKNMA1.f'] = [
    ('sub', 'ABCN, ABAN, AVAT, BVAT, AVCT, BVCT, AB, VB, E2,', 'ABCN, ABAN, ABAT, BBAT, ABCT, BBCT, AB, BB, E2,'),
]
F['IV.17_DKNMA2.f'] = [
    ('sub', '*ABBM, VBBM, AB, VB, E2)', '*ABBM, BBBM, AB, BB, E2)'),
    ('sub', 'AA ** COS(BA)', 'AA * COS(BA)'),
    ('sub', 'AE = SQRT', 'AB = SQRT'),
]
F['IV.18_DKNMA3.f'] = [
    ('sub', '*ALAC, W3, VA3,', '*ALAR, VAC, ALAC, W3, VA3,', 'two names lost; uncertain, ERRATA E-DKNMA3-1'),
    ('all', r'\bOMEGA\(', 'DOMEGA('),
    ('all', r'X\((\d)\.(\d)\)', r'X(\1,\2)'),
]
F['IV.19_DKNMA4.f'] = [
    ('sub', 'RZ2, ETA2, RZ3\n', 'RZ2, ETA2, RZ3,\n'),
    ('sub', 'WM, MN, EM', 'WM, WN, EM'),
    ('sub', 'AB3R, BB3R, AB, BB\n', 'AB3R, BB3R, AB, BB)\n'),
    ('sub', 'ABM = PAB *', 'ABM = RAB *'),
    ('sub', 'COS(BBM) --', 'COS(BBM) -'),
]
F['IV.20_DKNMA5.f'] = [
    ('sub', 'VC2CM, ALC2CM, VC, AC, AC2C3K', 'VC2CM, ALC2CM, VC, ALC, AC2C3K'),
    ('sub', 'ALMC = DUGL3', 'ALCM = DUGL3'),
    ('sub', 'DUGL4(FIM + ETA2), PI', 'DUGL4((FIM + ETA2), PI'),
]

F['V.2_DPRFLP.f'] = [
    ('sub', 'R1(N), *DELTA(N),', 'R1(N), DELTA(N),', 'a stray continuation mark'),
    ('raw', """     *(K))) ** - D 2 SDFI * (COS(ALFA(K)))/C ** 2""", """C OCR: "** - D 2 SDFI * (COS(ALFA(K)))/C ** 2" -> "** 2 - D2SDFI * (COS(ALFA(K))) ** 3)/C ** 2" (exponents and a parenthesis lost)
     *(K))) ** 2 - D2SDFI * (COS(ALFA(K))) ** 3)/C ** 2"""),
]
F['V.4_DPRFLK.f'] = [
    ('sub', 'DPRFLK(N, W1, ETAO, F1, RO,', 'DPRFLK(N, W1, ETAO, FI, RO,'),
    ('sub', 'RSI(N) —', 'PSI(N) —'),
    ('sub', '*DPSIFI) * COS(PSI(K) + COS(PSI(K) + ETAO)) ** (3.0/2.0))', '*DPSIFI) * COS(PSI(K) + ETAO)) ** (3.0/2.0)', 'ERRATA E-DPRFLK-2'),
]
F['V.5_program.f'] = [
    ('raw', '      EXCTST, ETAO', 'C OCR: "      EXCTST, ETAO" -> "     *EXCTST, ETAO" (continuation mark lost)\n     *EXCTST, ETAO'),
    ('sub', 'RKRVZN(51)', 'RKRZVN(51)', 'ERRATA E-V5-3'),
    ('sub', 'DATA PI, N/31.4159,51/', 'DATA PI, N/3.14159,51/', 'ERRATA E-V5-1'),
    ('sub', '*ТОЛКАТЕЛЯ).', '*ТОЛКАТЕЛЯ)'),
    ('sub', 'FORMAT(1H, 4F12.5)', 'FORMAT(1H , 4F12.5)', 'the blank of 1H lost'),
    ('raw', """11    FORMAT(1X, 'ОСНОВНЫЕ РАЗМЕРЫ КУЛАЧКА: РАДИУС
     *КУЛАЧКОВОЙ ШАЙБЫ F9.5, 'ЭКСЦЕНТРИСИТЕТ —', F9.5//""", """C OCR: "ШАЙБЫ F9.5," -> "ШАЙБЫ —', F9.5," (an apostrophe and a dash lost; uncertain)
11    FORMAT(1X, 'ОСНОВНЫЕ РАЗМЕРЫ КУЛАЧКА: РАДИУС
     *КУЛАЧКОВОЙ ШАЙБЫ —', F9.5, 'ЭКСЦЕНТРИСИТЕТ —', F9.5//"""),
    ('sub', "*'DELTA 6X,", "*'DELTA', 6X,"),
    ('sub', 'ALFA(K), ZN(K), K', 'ALFA(K), RKRZVN(K), K', 'the name cut'),
]
F['VI.1_DZBPL.f'] = [
    ('sub', 'ОПРЕДЕЛЕНИЕМ ЧИСЕЛ', 'ОПРЕДЕЛЕНИЕ ЧИСЕЛ'),
    ('sub', 'ЗАЩЕПЛЕНИЯ ПО', 'ЗАЦЕПЛЕНИЯ ПО'),
    ('all', r'\bZKRH\b', 'ZKRN'),
    ('sub', 'Z2, Z3, Z3, KS', 'Z2, Z3, Z4, KS'),
    ('raw', """11    FORMAT(1X, 'ЧИСЛА ЗУБЬЕВ ПЛАНЕТАРНОГО РЕДУКТОРА/'
     *1X, 'SHEMA =', 11/' Z1 = I, 13.' Z3 = ', 13.
     *' Z4 = ', 13/
     *'КОЛИЧЕСТВО БЛОКОВ САТЕЛЛИТОВ KS = ', 12)""", """C OCR: "РЕДУКТОРА/'" -> "РЕДУКТОРА'/"; "11/" -> "I1/"; "' Z1 = I, 13.' Z3 = ', 13." -> "' Z1 = ', I3, ' Z2 = ', I3, ' Z3 = ', I3," (the Z2 item lost; uncertain); "13/" -> "I3/"; "12)" -> "I2)"
11    FORMAT(1X, 'ЧИСЛА ЗУБЬЕВ ПЛАНЕТАРНОГО РЕДУКТОРА'/
     *1X, 'SHEMA =', I1/' Z1 = ', I3, ' Z2 = ', I3, ' Z3 = ', I3,
     *' Z4 = ', I3/
     *'КОЛИЧЕСТВО БЛОКОВ САТЕЛЛИТОВ KS = ', I2)"""),
]
F['VI.3_DKRKT.f'] = [
    ('sub', "*КОЭФФИЦИЕНТ СМЕЩЕНИЯ X2 = '", "*' КОЭФФИЦИЕНТ СМЕЩЕНИЯ X2 = '"),
    ('raw', "54    FORMAT(1X, 'ЗАДАВАЕМЫЕ ПАРАМЕТРЫ ТРЕБУЮТ\n      'КОРРЕКТИРОВКИ')", "C OCR: \"ТРЕБУЮТ\" -> \"ТРЕБУЮТ '\"; \"'КОРРЕКТИРОВКИ')\" -> \"*'КОРРЕКТИРОВКИ')\" (an apostrophe and the continuation mark lost)\n54    FORMAT(1X, 'ЗАДАВАЕМЫЕ ПАРАМЕТРЫ ТРЕБУЮТ '\n     *'КОРРЕКТИРОВКИ')"),
    ('sub', "*X1P = ', F6.3,", "*' X1P = ', F6.3,"),
    ('sub', "*XS = ', F6.3)/ X1 = ', F6.3, ' X2 = 1, F6.3, ' SDVIG = ', 12,", "*' XS = ', F6.3/' X1 = ', F6.3, ' X2 = ', F6.3, ' SDVIG = ', I2,"),
]
F['VI.5_DGMTZK.f'] = [
    ('sub', 'WRITE(2,5)', 'WRITE(3,5)'),
    ('raw', '      КОЛЕСА)', 'C OCR: "      КОЛЕСА)" -> "     *КОЛЕСА)" (continuation mark lost)\n     *КОЛЕСА)'),
]
F['VI.6_DGMZPC.f'] = [
    ('sub', 'DUGINY(INVALW, PI/18.0, 0.0, 0.0, 0.0)', 'DUGINV(INVALW, PI/18.0, 0.00001)'),
    ('sub', "' — AW', F10.4", "' — AW = ', F10.4"),
    ('sub', "— XY', F7.4", "— XY = ', F7.4"),
    ('sub', "— XUR', F7.4", "— XUR = ', F7.4"),
    ('sub', '      I FORMAT(', '1     FORMAT('),
]
F['VI.7_DGMZVN.f'] = [
    ('sub', 'DUGINV(INVALW, PI/18, 0, 0.00001)', 'DUGINV(INVALW, PI/18.0, 0.00001)'),
    ('sub', 'DUGINV(INVO2, PI/18, 0, 0.00001)', 'DUGINV(INVO2, PI/18.0, 0.00001)'),
    ('raw', """     *(ALFAW))/(2.0 * PISA1 = DA1 * ((0.5 * PI + 2.0 * X1 * TAN(ALFA)))/
     *Z1 + (TAN(ALFA) - ALFA) - (TAN(ALA1) - ALA1))""", """C OCR: "(2.0 * PISA1 = DA1 * ((0.5 * PI + 2.0 * X1 * TAN(ALFA)))/" -> "(2.0 * PI)" and "SA1 = DA1 * ((0.5 * PI + 2.0 * X1 * TAN(ALFA))/" (two statements run together)
     *(ALFAW))/(2.0 * PI)
      SA1 = DA1 * ((0.5 * PI + 2.0 * X1 * TAN(ALFA))/
     *Z1 + (TAN(ALFA) - ALFA) - (TAN(ALA1) - ALA1))"""),
    ('raw', "      ALFA) * (TAN(ALA2) - ALA2))", "C OCR: \"      ALFA) *\" -> \"     *ALFA) *\" (continuation mark lost)\n     *ALFA) * (TAN(ALA2) - ALA2))"),
]
F['VI.8_DCHRVC.f'] = [
    ('raw', "     *'ДЕЛИТЕЛЬНЫЙ ДИАМЕТР:/'", "C OCR: \"ДИАМЕТР:/'\" -> \"ДИАМЕТР:'/\"\n     *'ДЕЛИТЕЛЬНЫЙ ДИАМЕТР:'/"),
] + [('sub', '     *' + w, "     *'" + w, 'apostrophe lost') for w in (
    'ДЕЛИТЕЛЬНЫЙ УГОЛ', 'НАЧАЛЬНЫЙ УГОЛ', 'ВЫСОТА ВИТКА', 'ВЫСОТА ГОЛОВКИ', 'ЧЕРВЯКА — DA1',
    'ЧЕРВЯЧНОГО КОЛЕСА — DA2', 'НАИБОЛЬШИЙ', 'ДЛИНА', 'ШИРИНА', 'РАДИУС', 'ЗУБЬЕВ ЧЕРВЯЧНОГО')] + [
    ('sub', '     *ДИАМЕТР ВЕРШИН:', "     *'ДИАМЕТР ВЕРШИН:'/", 'apostrophes and a slash lost'),
    ('sub', "R = ', F7.3//", "R = ', F7.3//)", 'the closing parenthesis lost'),
]

F['VII.3_DNMAF4.f'] = [
    ('sub', '+ F3 * COS(G3 - FIN))\n', '+ F3 * COS(G3 - FIN))/\n', 'the division sign lost'),
]
F['VII.4_DNMAF3.f'] = [
    ('all', r'\bF/3\b|\bF13\b', 'FI3'),
]
F['VII.5_DNMAF5.f'] = [
    ('sub', 'RAS2 * F2 * *', 'RAS2 * F2 *', 'the continuation mark printed twice'),
]
F['VII.6_DNMA1.f'] = [
    ('all', r'\bF1([23])\b', r'FI\1'),
    ('sub', 'DUGL3(RI2,', 'DUGL3(FI2,'),
    ('sub', 'L2, F12 И L3, F13 —', 'L2, FI2 И L3, FI3 —'),
    ('raw', '      СТВУЮЩИЕ ВНЕШНИХ СИЛ', 'C OCR: "СТВУЮЩИЕ ВНЕШНИХ СИЛ" -> "C СТВУЮЩИЕ ВНЕШНИХ СИЛ" (the comment mark lost)\nC СТВУЮЩИЕ ВНЕШНИХ СИЛ'),
    ('raw', '      RA = SQRT{RAN^2 + RAT^2}', 'C OCR: "\\sqrt{RAN^2 + RAT^2}" -> "SQRT(RAN ** 2 + RAT ** 2)"\n      RA = SQRT(RAN ** 2 + RAT ** 2)'),
    ('raw', '      RC = SQRT{RCN^2 + RCT^2}', 'C OCR: "\\sqrt{RCN^2 + RCT^2}" -> "SQRT(RCN ** 2 + RCT ** 2)"\n      RC = SQRT(RCN ** 2 + RCT ** 2)'),
    ('raw', '      RB = SQRT{RBX^2 + RBY^2}', 'C OCR: "\\sqrt{RBX^2 + RBY^2}" -> "SQRT(RBX ** 2 + RBY ** 2)"\n      RB = SQRT(RBX ** 2 + RBY ** 2)'),
]
F['VII.7_DNMA2.f'] = [
    ('sub', 'DNMA2(L2, F12, L3, ETA, F10,', 'DNMA2(L2, FI2, L3, ETA, FIO,'),
    ('sub', 'RA, CA, RB,', 'RA, GA, RB,'),
    ('sub', 'L2, F12 И L3, ETA, F10 —', 'L2, FI2 И L3, ETA, FIO —'),
    ('sub', 'DUGL6(RAN, CAN,', 'DUGL6(RAN, GAN,'),
]
F['VII.8_DNMA3.f'] = [
    ('sub', 'COS(GR + PI)', 'COS(GB + PI)'),
]
F['VII.10_DNMA5.f'] = [
    ('sub', '8.00001', '0.00001'),
]

F['VII.10_program.f'] = [
    ('raw', '      200.0/', 'C OCR: "      200.0/" -> "     *200.0/" (continuation mark lost)\n     *200.0/'),
    ('sub', 'Q4, -PID2, X, FC2,', 'Q4, -PID2, XD, Y, FC2,', 'two names lost'),
    ('sub', 'Q2, -RFS3 * COS(FI3) + ROF,', 'Q2, -PID2, RFS3 * COS(FI3) + ROF,', 'PID2 and a comma lost'),
    ('sub', 'D1011', 'G1011'),
    ('raw', '      40FORMAT(1X, 12F10.1)', '40    FORMAT(1X, 12F10.1)'),
    ('raw', 'C OCR: "F2.θ3" -> "F2.03"', 'C OCR: "F2.θ3" -> "F20.3"'),
    ('raw', '42    FORMAT(1X, F2.03,', '42    FORMAT(1X, F20.3,'),
    ('raw', 'C OCR: "G11θ" -> "G110"\n      G110\n', 'C OCR: "G11θ" -> "*G110" (the continuation mark lost)\n     *G110\n'),
]
F['X_program.f'] = [
    ('sub', '*0.42/H5/0.64/,', '*0.42/, H5/0.64/,'),
    ('all', r'\(IX,', '(1X,'),
    ('all', r'//IX,', '//1X,'),
    ('sub', '6, 7, 3, 0, 200, 3)', '6, 7, 30, 200, 3)'),
    ('sub', "КОЛЕС:')", "КОЛЕС:'/", 'uncertain: the quotes and slashes of FORMAT 3'),
    ('sub', "*X1 = ', F7.3,", "*' X1 = ', F7.3,"),
    ('sub', "*УГОЛ ЗАЦЕПЛЕНИЯ AL12", "*' УГОЛ ЗАЦЕПЛЕНИЯ AL12"),
    ('sub', 'DATA W1/3.0, DSMAX/0.06/', 'DATA W1/3.0/, DSMAX/0.06/'),
    ('all', r'\bPHI\b', 'PSI'),
    ('sub', "*ГОЛКАТЕЛЯ' 5X,", "*ТОЛКАТЕЛЯ'/5X,"),
    ('sub', "ПРОФИЛЯ КУЛАЧКА//", "ПРОФИЛЯ КУЛАЧКА'//"),
    ('sub', '0.0, 2.0, VBA, ALBA, VEC, ALBC,', '0.0, 2.0, VBA, ALBA, VBC, ALBC,'),
    ('raw', """      BD = DUGL3(FICB(K) + PI, PI - ATAN(ABS(K))/W3(K) ** 2)
     *E3(K))""", """C OCR: "ATAN(ABS(K))/W3(K) ** 2)" -> "ATAN(ABS(E3(K))/W3(K) ** 2),"
      BD = DUGL3(FICB(K) + PI, PI - ATAN(ABS(E3(K))/W3(K) ** 2),
     *E3(K))"""),
    ('sub', 'DUSKR2(AD, BD, 0., 0., 0., RDE,', 'DUSKR2(AD, BD, 0., 0., 0., 0., RDE,', 'a zero lost'),
    ('sub', 'DMOONT', 'DMOMNT'),
    ('sub', '*G23(K), F30(K), G30(K)\n', '*G23(K), F30(K), G30(K))\n', 'the closing parenthesis lost'),
    ('all', r'\bF1([12])\(K\)', r'FI\1(K)'),
    ('sub', '30    C CONTINUE', '30    CONTINUE'),
    ('sub', "FORMAT('//ОПРЕДЕЛЕНИЕ", "FORMAT(//'ОПРЕДЕЛЕНИЕ"),
    ('sub', "УРАВНЕНИЯ ДВИЖЕНИЯ /", "УРАВНЕНИЯ ДВИЖЕНИЯ'/"),
    ('sub', 'DE3(K)', 'DEC(K)'),
]

if __name__ == '__main__':
    d = sys.argv[1]
    for f, fx in F.items():
        apply(os.path.join(d, f), fx)
