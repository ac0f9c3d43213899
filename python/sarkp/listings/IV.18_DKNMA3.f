C LISTING IV.18 DKNMA3: BELOKONEV 1990, BOOK LINES L2749-2827
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DKNMA3(XA, YA, XC, YC, RZ2, ETA, VA, ALA, VC, ALC,
     *AA, BA, AC, BC, P, ANALOG, XB, YB, RZBC, FI3, VAR,
C OCR: "*ALAC, W3, VA3," -> "*ALAR, VAC, ALAC, W3, VA3," (two names lost; uncertain, ERRATA E-DKNMA3-1)
     *ALAR, VAC, ALAC, W3, VA3, ALA3, AAK, BAK, AAR, BAR, AACT, BACT,
     *AA3, BA3, E3, AACN)
      COMMON/PRMTR/PI, PID2
C ПАРАМЕТРЫ В ОПЕРАТОРЕ ДО ПЕРЕМЕННОЙ ANALOG ДОЛЖНЫ
C БЫТЬ ОПРЕДЕЛЕНЫ ДО ОБРАЩЕНИЯ К ПОДПРОГРАММЕ.
C ПОСЛЕ НЕЕ — РЕЗУЛЬТАТЫ РАБОТЫ ПОДПРОГРАММЫ.
C XA, YA, VA, ALA, AA, BA — КООРДИНАТЫ ЦЕНТРА ШАРНИРА
C КИНЕМАТИЧЕСКОЙ ПАРЫ А, МОДУЛИ И НАПРАВЛЯЮЩИЕ УГЛЫ
C ВЕКТОРОВ СКОРОСТИ И УСКОРЕНИЯ ЭТОЙ ТОЧКИ.
C ДЛЯ ДРУГИХ ТОЧЕК ОБОЗНАЧЕНИЯ АНАЛОГИЧНЫ.
C RZ — ИНДЕКС ЛИНЕЙНОГО РАЗМЕРА, ETA — ИНДЕКС УГЛОВОГО
C РАЗМЕРА.
C FI — УГОЛ, ОПРЕДЕЛЯЮЩИЙ ПОЛОЖЕНИЕ ЗВЕНА.
C N, T, K — ИНДЕКСЫ НОРМАЛЬНОЙ, ТАНГЕНЦИАЛЬНОЙ И
C КОРИОЛИСОВОЙ СОСТАВЛЯЮЩИХ ВЕКТОРА УСКОРЕНИЯ.
C W, E — ИНДЕКСЫ УГЛОВОЙ СКОРОСТИ И УГЛОВОГО УСКОРЕНИЯ.
      DIMENSION X(2,2), Y(2)
      RAC = SQRT((XA - XC) ** 2 + (YA - YC) ** 2)
      FI = ATAN((YC - YA)/(XC - XA))
      DX = XA - XC
      FIK = DUGL1(YA, YC, DX, FI)
      UGBAC = PI - ETA - ARSIN(RZ2/RAC * SIN(ETA))
      XB1 = RZ2 * COS(UGBAC)
      YB1 = P * RZ2 * SIN(UGBAC)
      XB = XB1 * COS(FIK) - YB1 * SIN(FIK) + XA
      YB = XB1 * SIN(FIK) + YB1 * COS(FIK) + YA
      RZBC = SQRT((YB - YC) ** 2 + (XB - XC) ** 2)
      FI3 = DUGL2(XC, YC, XB, YB)
      X(1,1) = COS(FI3)
      X(1,2) = -COS((FIK + PI) + PID2)
      X(2,1) = SIN(FI3)
      X(2,2) = -SIN((FIK + PI) + PID2)
      Y(1) = VC * COS(ALC) - VA * COS(ALA)
      Y(2) = VC * SIN(ALC) - VA * SIN(ALA)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      VAR = ABS(Y(1))
      ALAR = DUGL4(FI3, PI, Y(1))
      VAC = ABS(Y(2))
      ALAC = DUGL3((FIK + PI), PID2, Y(2))
C OCR: "OMEGA(" -> "DOMEGA("
      W3 = DOMEGA(RAC, VAC, (ALAC - (FIK + PI)))
      PRX = VC * COS(ALC) + VAC * COS(ALAC)
      PRY = VC * SIN(ALC) + VAC * SIN(ALAC)
      VA3 = SQRT(PRX ** 2 + PRY ** 2)
      ALA3 = DUGL5(PRX, PRY)
      IF(ANALOG.EQ.1.0) RETURN
      AAK = 2.0 * VAR * ABS(W3)
      BAK = DUGL3(ALAR, PID2, W3)
      AACN = W3 ** 2 * RAC
C OCR: "X(1.1)" -> "X(1,1)"
      X(1,1) = COS(ALAR)
C OCR: "X(1.2)" -> "X(1,2)"
      X(1,2) = -COS((FIK + PI) + PID2)
C OCR: "X(2.1)" -> "X(2,1)"
      X(2,1) = SIN(ALAR)
C OCR: "X(2.2)" -> "X(2,2)"
      X(2,2) = -SIN((FIK + PI) + PID2)
      Y(1) = AC * COS(BC) + AACN * COS(FIK) - AA * COS(BA) - AAK *
     *COS(BAK)
      Y(2) = AC * SIN(BC) + AACN * SIN(FIK) - AA * SIN(BA) - AAK *
     *SIN(BAK)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      AAR = ABS(Y(1))
      BAR = DUGL4(ALAR, PID2, Y(1))
      AACT = ABS(Y(2))
      BACT = DUGL3((FIK + PI), PID2, Y(2))
      AA3X = AA * COS(BA) + AAK * COS(BAK) + AAR * COS(BAR)
      AA3Y = AA * SIN(BA) + AAK * SIN(BAK) + AAR * SIN(BAR)
      AA3 = SQRT(AA3X ** 2 + AA3Y ** 2)
      BA3 = DUGL5(AA3X, AA3Y)
C OCR: "OMEGA(" -> "DOMEGA("
      E3 = DOMEGA(RAC, AACT, (BACT - (FIK + PI)))
      RETURN
      END
