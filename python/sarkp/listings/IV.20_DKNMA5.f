C LISTING IV.20 DKNMA5: BELOKONEV 1990, BOOK LINES L2931-3001
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DKNMA5(XA, YA, FIM, XC, YC, RZ3, ETA2, ETA3,
     *XR, YR, WM, EM, VC3, ALC3, AC3, BC3, ANALOG, VC2C3, ALC2C3,
C OCR: "VC2CM, ALC2CM, VC, AC, AC2C3K" -> "VC2CM, ALC2CM, VC, ALC, AC2C3K"
     *VC2CM, ALC2CM, VC, ALC, AC2C3K, BC2C3K, AC2CMK, BC2CMK,
     *AC2C3R, BC2C3R, AC2CMR, BC2CMR, AC, BC)
      COMMON/PRMTR/PI, PID2
C ПАРАМЕТРЫ В ОПЕРАТОРЕ ДО ПЕРЕМЕННОЙ ANALOG ДОЛЖНЫ БЫТЬ ОПРЕДЕЛЕННЫ ДО ОБРАЩЕНИЯ К ПОДПРОГРАММЕ, ПОСЛЕ
C НЕЕ — РЕЗУЛЬТАТЫ РАБОТЫ ПОДПРОГРАММЫ.
C FIM — УГОЛ ОРИЕНТАЦИИ НАПРАВЛЯЮЩЕЙ, ЗАКРЕПЛЕННОЙ НА С ЗВЕНЕ М.
C A, XA, YA — ТОЧКА, ЛЕЖАЩАЯ НА ОСИ НАПРАВЛЯЮЩЕЙ, И ЕЕ
C КООРДИНАТЫ.
C С — ЦЕНТР ШАРНИРА ВРАЩАТЕЛЬНОЙ КИНЕМАТИЧЕСКОЙ ПАРЫ, С КОТОРОЙ ЗВЕНО 3 ПРИСОЕДИНЯЕТСЯ К КИНЕМАТИЧЕСКОЙ ЦЕПИ
C МЕХАНИЗМА, XC, YC — ЕГО КООРДИНАТЫ.
C XR, YR — КООРДИНАТЫ МГНОВЕННОГО ЦЕНТРА ВРАЩЕНИЯ ЗВЕНА С М.
C ETA2, RZ3, ETA3 — ЛИНЕЙНЫЕ И УГЛОВЫЕ РАЗМЕРЫ ЗВЕНЬЕВ С 2 И 3.
C R, K — ИНДЕКСЫ ОТНОСИТЕЛЬНОЙ И КОРИОЛИСОВОЙ СОСТАВЛЯЮЩИХ ВЕКТОРОВ.
      DIMENSION X(2,2), Y(2)
      RC = SQRT((XC - XR) ** 2 + (YC - YR) ** 2)
      VCM = ABS(WM) * RC
      FIRC = DUGL2(RC, PID2, WM)
C OCR: "ALMC = DUGL3" -> "ALCM = DUGL3"
      ALCM = DUGL3(FIRC, PID2, WM)
      X(1,1) = COS(FIM + ETA2)
      X(1,2) = -COS(FIM)
      X(2,1) = SIN(FIM + ETA2)
      X(2,2) = -SIN(FIM)
      Y(1) = VCM * COS(ALCM) - VC3 * COS(ALC3)
      Y(2) = VCM * SIN(ALCM) - VC3 * SIN(ALC3)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      VC2C3 = ABS(Y(1))
C OCR: "DUGL4(FIM + ETA2), PI" -> "DUGL4((FIM + ETA2), PI"
      ALC2C3 = DUGL4((FIM + ETA2), PI, Y(1))
      VC2CM = ABS(Y(2))
      ALC2CM = DUGL4(FIM, PI, Y(2))
      CALL DSMVKT(VCM, ALCM, VC2CM, ALC2CM, VC, ALC)
      IF(ANALOG.EQ.1.0)RETURN
      ACM = RC * SQRT(WM ** 4 + EM ** 2)
      IF(EM.NE.0.0)GO TO 1
      BCM = 0.0
      GO TO 2
1     BCM = DUGL3(FIRC, (PI - ATAN(EM/WM ** 2)), EM)
2     AC2C3K = 2.0 * VC2C3 * ABS(WM)
      BC2C3K = DUGL3(ALC2C3, PID2, WM)
      BC2CMK = DUGL3(ALC2CM, PID2, WM)
      AC2CMK = 2.0 * VC2CM * ABS(WM)
      X(1,1) = COS(ALC2C3)
      X(1,2) = -COS(ALC2CM)
      X(2,1) = SIN(ALC2C3)
      X(2,2) = -SIN(ALC2CM)
      Y(1) = ACM * COS(BCM) + AC2CMK * COS(BC2CMK) - AC3 * COS(BC3) -
     *AC2C3K * COS(BC2C3K)
      Y(2) = ACM * SIN(BCM) + AC2CMK * SIN(BC2CMK) - AC3 * SIN(BC3) -
     *AC2C3K * SIN(BC2C3K)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      AC2C3R = ABS(Y(1))
      BC2C3R = DUGL4(ALC2C3, PI, Y(1))
      AC2CMR = ABS(Y(2))
      BC2CMR = DUGL4(ALC2CM, PI, Y(2))
      CALL DSMVKT(ACM, BCM, AC2CMK, BC2CMK, A, B)
      CALL DSMVKT(A, B, AC2CMR, BC2CMR, AC, BC)
      RETURN
      END
