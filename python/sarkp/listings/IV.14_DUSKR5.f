C LISTING IV.14 DUSKR5: BELOKONEV 1990, BOOK LINES L2308-2378
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DUSKR5(XC3, YC3, XVM, YVM, FIM, WM, EM, T2, AC3,
     *BC3, AC2MK, BC2MK, AC23K, BC23K, AAA, AC2C3R, BC2C3R, AC2CMR,
     *BC2CMR, AC2, BC2)
C ОПРЕДЕЛЕНИЕ УСКОРЕНИЙ ЗВЕНЬЕВ СТРУКТУРНОЙ ГРУППЫ
C 5-ГО ВИДА.
C XC3, YC3, AC3, BC3 — КООРДИНАТЫ, ВЕКТОР УСКОРЕНИЯ И ЕГО
C НАПРАВЛЯЮЩИЙ УГОЛ, FIM, WM, EM — ЗАКОН ДВИЖЕНИЯ
C ЗВЕНА M.
C XVM, YVM — КООРДИНАТЫ МГНОВЕННОГО ЦЕНТРА ВРАЩЕНИЯ
C ЗВЕНА M.
C AC2MK, AC23K — ВЕКТОРЫ КОРИОЛИСОВЫХ УСКОРЕНИЙ.
C BC2MK, BC23K — ИХ НАПРАВЛЯЮЩИЕ УГЛЫ.
C T2 — УГЛОВОЙ РАЗМЕР ЗВЕНА 2.
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2, 2), Y(2)
C OCR: "SQRT(WM *" -> "SQRT(WM **"
      ACM = SQRT((XC3 - XVM) ** 2 + (YC3 - YVM) ** 2) * SQRT(WM **
     *4 + EM ** 2)
      IF(EM.EQ.0.0)GO TO 1
      DLT = PID2 + ATAN(WM ** 2/ABS(EM))
      GO TO 2
1     DLT = PID2
2     BCM = DUGL3(DUGL2(XVM, YVM, XC3, YC3), PID2 + DLT, EM)
      X(1, 1) = COS(FIM + T2)
      X(1, 2) = -COS(FIM)
      X(2, 1) = SIN(FIM + T2)
      X(2, 2) = -SIN(FIM)
      Y(1) = ACM * COS(BCM) + AC2MK * COS(BC2MK) - AC3 * COS(BC3) -
     *AC23K * COS(BC23K)
      Y(2) = ACM * SIN(BCM) + AC2MK * SIN(BC2MK) - AC3 * SIN(BC3) -
     *AC23K * SIN(BC23K)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      BC2C3R = DUGL4(FIM + T2, PI, Y(1))
      AC2C3R = ABS(Y(1))
      BC2CMR = DUGL4(FIM, PI, Y(2))
      AC2CMR = ABS(Y(2))
      CALL DSMVKT(AC3, BC3, AC23K, BC23K, A, B)
      CALL DSMVKT(A, B, AC2C3R, BC2C3R, AC2, BC2)
      RETURN
      END
