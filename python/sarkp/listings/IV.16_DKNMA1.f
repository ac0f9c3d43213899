C LISTING IV.16 DKNMA1: BELOKONEV 1990, BOOK LINES L2553-2656
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DKNMA1(XA, YA, XC, YC, RZ2, RZ3, VA, ALA, VC, ALC,
     *AA, BA, AC, BC, P, ANALOG, XB, YB, FI2, FI3, VBA, ALBA, VBC, ALBC,
C OCR: "ABCN, ABAN, AVAT, BVAT, AVCT, BVCT, AB, VB, E2," -> "ABCN, ABAN, ABAT, BBAT, ABCT, BBCT, AB, BB, E2,"
     *VB, ALB, W2, W3, ABCN, ABAN, ABAT, BBAT, ABCT, BBCT, AB, BB, E2,
     *E3)
      COMMON /PRMTR/PI, PID2
C ПАРАМЕТРЫ В ОПЕРАТОРЕ ДО ПЕРЕМЕННОЙ ANALOG ДОЛЖНЫ
C БЫТЬ ОПИСАНЫ ДО ОБРАЩЕНИЯ К ПОДПРОГРАММЕ, ПОСЛЕ
C ПЕРЕМЕННОЙ — РЕЗУЛЬТАТ РАБОТЫ ПОДПРОГРАММЫ.
C XA, YA, XB, YB, XC, YC — КООРДИНАТЫ ЦЕНТРОВ ШАРНИРОВ
C КИНЕМАТИЧЕСКИХ ПАР.
C VA, ALA, AA, BA — МОДУЛИ И НАПРАВЛЯЮЩИЕ УГЛЫ ВЕКТОРОВ
C СКОРОСТИ И УСКОРЕНИЯ ТОЧКИ A.
C ДЛЯ ДРУГИХ ТОЧЕК — АНАЛОГИЧНО.
C N И T — ИНДЕКСЫ НОРМАЛЬНОЙ И ТАНГЕНЦИАЛЬНОЙ
C СОСТАВЛЯЮЩИХ ВЕКТОРА УСКОРЕНИЯ.
C W И E — УГЛОВАЯ СКОРОСТЬ И УГЛОВОЕ УСКОРЕНИЕ.
C RZ — РАССТОЯНИЕ МЕЖДУ ЦЕНТРАМИ ШАРНИРОВ.
C ИСПОЛЬЗУЮТСЯ ПОДПРОГРАММЫ UGL1, UGL2, UGL3, UGL5, OMEGA,
C GELG.
      DIMENSION X(2,2), Y(2)
      RAC = SQRT((XA - XC) ** 2 + (YA - YC) ** 2)
      DX = XC - XA
      FI = ATAN((YC - YA)/DX)
      FIK = DUGL1(YC, YA, DX, FI) - PI/2.0
      UGBAC = ARCOS((RZ2 ** 2 + RAC ** 2 - RZ3 ** 2)/2.0/RZ2/RAC)
      XB1 = P * RZ2 * SIN(UGBAC)
      YB1 = RAC - RZ2 * COS(UGBAC)
      XB = XB1 * COS(FIK) - YB1 * SIN(FIK) + XC
      YB = XB1 * SIN(FIK) + YB1 * COS(FIK) + YC
      FI2 = DUGL2(XA, YA, XB, YB)
      FI3 = DUGL2(XC, YC, XB, YB)
      X(1,1) = COS(FI2 + PI/2.0)
      X(1,2) = -COS(FI3 + PI/2.0)
      X(2,1) = SIN(FI2 + PI/2.0)
      X(2,2) = -SIN(FI3 + PI/2.0)
      Y(1) = VC * COS(ALC) - VA * COS(ALA)
      Y(2) = VC * SIN(ALC) - VA * SIN(ALA)
      CALL GELG(Y, X, 2,1, 0.0001, IER)
      ALBA = DUGL3(FI2, PI/2.0, Y(1))
      ALBC = DUGL3(FI3, PI/2.0, Y(2))
      VBA = ABS(Y(1))
      VBC = ABS(Y(2))
      PRX = VA * COS(ALA) + VBA * COS(ALBA)
      PRY = VA * SIN(ALA) + VBA * SIN(ALBA)
      VB = SQRT(PRX ** 2 + PRY ** 2)
      ALB = DUGL5(PRX, PRY)
      W2 = DOMEGA(RZ2, VBA, (ALBA - FI2))
      W3 = DOMEGA(RZ3, VBC, (ALBC - FI3))
      IF(ANALOG.EQ.1.0)RETURN
      ABAN = W2 ** 2 * RZ2
      ABCN = W3 ** 2 * RZ3
      X(1,1) = COS(FI2 + PI/2.0)
      X(1,2) = -COS(FI3 + PI/2.0)
      X(2,1) = SIN(FI2 + PI/2.0)
      X(2,2) = -SIN(FI3 + PI/2.0)
      Y(1) = AC * COS(BC) + ABCN * COS(FI3 + PI) - AA * COS(BA) -
     *ABAN * COS(FI2 + PI)
      Y(2) = AC * SIN(BC) + ABCN * SIN(FI3 + PI) - AA * SIN(BA) -
     *ABAN * SIN(FI2 + PI)
      CALL GELG(Y, X, 2,1, 0.0001, IER)
      BBAT = DUGL3(FI2, PI/2.0, Y(1))
      BBCT = DUGL3(FI3, PI/2.0, Y(2))
      ABAT = ABS(Y(1))
      ABCT = ABS(Y(2))
      PRX = AA * COS(BA) + ABAN * COS(FI2 + PI) + ABAT * COS(BBAT)
      PRY = AA * SIN(BA) + ABAN * SIN(FI2 + PI) + ABAT * SIN(BBAT)
      AB = SQRT(PRX ** 2 + PRY ** 2)
      BB = DUGL5(PRX, PRY)
      E2 = DOMEGA(RZ2, ABAT, (BBAT - FI2))
      E3 = DOMEGA(RZ3, ABCT, (BBCT - FI3))
      RETURN
      END
