C LISTING IV.17 DKNMA2: BELOKONEV 1990, BOOK LINES L2660-2745
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DKNMA2(XA, YA, XK, YK, FIM, RZ2, RZ3, ETA, VA, ALA,
     *WM, VBM, ALBM, AA, BA, ABM, BBM, P, ANALOG, XB, YB, FI2, VBA,
     *ALBA, VBBM, ALBBM, VB, ALB, W2, ABAN, ABK, BBK, ABAT, BBAT,
C OCR: "*ABBM, VBBM, AB, VB, E2)" -> "*ABBM, BBBM, AB, BB, E2)"
     *ABBM, BBBM, AB, BB, E2)
      COMMON/PRMTR/PI, PID2
C ПАРАМЕТРЫ В ОПЕРАТОРЕ ДО ПЕРЕМЕННОЙ ANALOG ДОЛЖНЫ
C БЫТЬ ОПИСАНЫ ДО ОБРАЩЕНИЯ К ПОДПРОГРАММЕ.
C ПОСЛЕ ПЕРЕМЕННОЙ — РЕЗУЛЬТАТ РАБОТЫ ПОДПРОГРАММЫ.
C XA, YA — КООРДИНАТЫ ЦЕНТРОВ ШАРНИРОВ КИНЕМАТИЧЕСКИХ
C ПАР XK, YK — КООРДИНАТЫ ТОЧКИ ПЕРЕСЕЧЕНИЯ ОСЕЙ
C НАПРАВЛЯЮЩЕЙ И ДВИЖУЩЕГОСЯ ОТНОСИТЕЛЬНО НЕЕ ЗВЕНА.
C FIM — УГОЛ, ОБРАЗОВАННЫЙ ОСЬЮ НАПРАВЛЯЮЩЕЙ.
C VA, ALA, AA, BA — МОДУЛИ И НАПРАВЛЯЮЩИЕ УГЛЫ ВЕКТОРОВ
C СКОРОСТИ И УСКОРЕНИЯ ТОЧКИ А. ДЛЯ ДРУГИХ ТОЧЕК —
C АНАЛОГИЧНО.
C M — ИНДЕКС ЗВЕНА, НА КОТОРОМ ЗАКРЕПЛЕНА НАПРАВЛЯЮЩАЯ
C N, T, K — ИНДЕКСЫ НОРМАЛЬНОЙ, ТАНГЕНЦИАЛЬНОЙ И
C КОРИОЛИСОВОЙ СОСТАВЛЯЮЩИХ ВЕКТОРА УСКОРЕНИЯ.
C W И E — УГЛОВАЯ СКОРОСТЬ И УГЛОВОЕ УСКОРЕНИЕ.
C RZ, ETA — ЛИНЕЙНЫЕ И УГЛОВЫЕ РАЗМЕРЫ ЗВЕНА.
      DIMENSION X(2,2), Y(2)
      UK1 = TAN(FIM)
      XO1 = ((XA + UK1 ** 2 * XK) - UK1 * (YK - YA))/(UK1 ** 2 + 1.0)
      YO1 = ((YK + UK1 ** 2 * YA) - UK1 * (XK - XA))/(UK1 ** 2 + 1.0)
      DX = XO1 - XA
      FIK = DUGL1(YO1, YA, DX, (FIM - PI/2.0))
      AO1 = SQRT((YA - YO1) ** 2 + (XA - XO1) ** 2)
      YB1 = RZ3 * SIN(ETA)
      XB1 = P * RZ2 * SIN((ARCOS((SIGN(AO1, (FIK - FIM)) - YB1)/RZ2)))
      FIK = FIM
      XB = XB1 * COS(FIK) - YB1 * SIN(FIK) + XO1
      YB = XB1 * SIN(FIK) + YB1 * COS(FIK) + YO1
      FI2 = DUGL2(XA, YA, XB, YB)
      X(1,1) = COS(FI2 + PI/2.0)
      X(1,2) = -COS(FIM)
      X(2,1) = SIN(FI2 + PI/2.0)
      X(2,2) = -SIN(FIM)
      Y(1) = VBM * COS(ALBM) - VA * COS(ALA)
      Y(2) = VBM * SIN(ALBM) - VA * SIN(ALA)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      VBA = ABS(Y(1))
      ALBA = DUGL3(FI2, (PI/2.0), Y(1))
      VBBM = ABS(Y(2))
      ALBBM = DUGL4(FIM, PI, Y(2))
      VBX = VA * COS(ALA) + VBA * COS(ALBA)
      VBY = VA * SIN(ALA) + VBA * SIN(ALBA)
      VB = SQRT(VBX ** 2 + VBY ** 2)
      ALB = DUGL5(VBX, VBY)
      W2 = DOMEGA(RZ2, VBA, (ALBA - FI2))
C OCR: ", EQ," -> ".EQ."
      IF(ANALOG.EQ.1.0) RETURN
      ABAN = W2 ** 2 * RZ2
      ABK = 2.0 * VBBM * ABS(WM)
      BBK = DUGL3(ALBBM, (PI/2.0), WM)
      X(1,1) = COS(ALBA)
      X(1,2) = -COS(ALBBM)
      X(2,1) = SIN(ALBA)
      X(2,2) = -SIN(ALBBM)
C OCR: "AA ** COS(BA)" -> "AA * COS(BA)"
      Y(1) = ABM * COS(BBM) + ABK * COS(BBK) - AA * COS(BA) -
     *ABAN * COS(FI2 + PI)
      Y(2) = ABM * SIN(BBM) + ABK * SIN(BBK) - AA * SIN(BA) -
     *ABAN * SIN(FI2 + PI)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      ABAT = ABS(Y(1))
      BBAT = DUGL4(ALBA, PI, Y(1))
      ABBM = ABS(Y(2))
      BBBM = DUGL4(ALBBM, PI, Y(2))
      ABX = ABM * COS(BBM) + ABK * COS(BBK) + ABBM * COS(BBBM)
      ABY = ABM * SIN(BBM) + ABK * SIN(BBK) + ABBM * SIN(BBBM)
C OCR: "AE = SQRT" -> "AB = SQRT"
      AB = SQRT(ABX ** 2 + ABY ** 2)
      BB = DUGL5(ABX, ABY)
      E2 = DOMEGA(RZ2, ABAT, (BBAT - FI2))
      RETURN
      END
