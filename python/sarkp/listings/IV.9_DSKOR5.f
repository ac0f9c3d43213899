C LISTING IV.9 DSKOR5: BELOKONEV 1990, BOOK LINES L1947-1976
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSKOR5(XC3, YC3, XVM, YVM, FIM, T2, WM, VC3, ALC3,
     *AAA, VC2C3, ALC2C3, VC2CM, ALC2CM, VC2, ALC2)
C XC3, YC3, VC3, ALC3 — КООРДИНАТЫ, ВЕКТОР СКОРОСТИ И ЕГО
C НАПРАВЛЯЮЩИЙ УГОЛ ТОЧКИ C3.
C XVM, YVM, FIM, WM — КООРДИНАТЫ МГНОВЕННОГО ЦЕНТРА
C ВРАЩЕНИЯ ЗВЕНА M, НАПРАВЛЯЮЩИЙ УГОЛ И УГЛОВАЯ
C СКОРОСТЬ ЗВЕНА M.
C T2 — УГЛОВОЙ РАЗМЕР ЗВЕНА 2.
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2, 2), Y(2)
      VCM = ABS(WM) * SQRT((XC3 - XVM)** 2 + (YC3 - YVM)** 2)
      ALCM = DUGL3(DUGL2(XVM, YVM, XC3, YC3), PID2, WM)
      X(1, 1) = COS(FIM + T2)
      X(1, 2) = -COS(FIM)
      X(2, 1) = SIN(FIM + T2)
      X(2, 2) = -SIN(FIM)
      Y(1) = VCM * COS(ALCM) - VC3 * COS(ALC3)
      Y(2) = VCM * SIN(ALCM) - VC3 * SIN(ALC3)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      ALC2C3 = DUGL4(FIM + T2, PI, Y(1))
      VC2C3 = ABS(Y(1))
C OCR: "ALC3CM = DUGL4" -> "ALC2CM = DUGL4"
      ALC2CM = DUGL4(FIM, PI, Y(2))
      VC2CM = ABS(Y(2))
      CALL DSMVKT(VC3, ALC3, VC2C3, ALC2C3, VC2, ALC2)
      RETURN
      END
