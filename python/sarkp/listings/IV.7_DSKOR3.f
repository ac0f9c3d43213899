C LISTING IV.7 DSKOR3: BELOKONEV 1990, BOOK LINES L1805-1854
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSKOR3(XA, YA, XC, YC, VA, ALA, VC, ALC, FI3, AAA,
     *VA3A, ALA3A, VA3C, ALA3C, VA3, ALA3, W3)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ СКОРОСТЕЙ ДЛЯ ЗВЕНЬЕВ СТРУКТУРНОЙ ГРУППЫ
C 3-ГО ВИДА
C XA, YA, XC, YC — КООРДИНАТЫ ПРИСОЕДИНИТЕЛЬНЫХ ТОЧЕК.
C VA, ALA, VC, ALC — ВЕКТОРЫ ИХ СКОРОСТЕЙ И НАПРАВЛЯЮЩИЕ
C УГЛЫ.
C FI3 — НАПРАВЛЯЮЩИЙ УГОЛ ЗВЕНА 3.
      DIMENSION X(2, 2), Y(2)
      RZAC = SQRT((XA - XC) ** 2 + (YA - YC) ** 2)
      FICA = DUGL2(XC, YC, XA, YA)
      X(1, 1) = COS(FI3)
      X(1, 2) = -COS(FICA + PID2)
      X(2, 1) = SIN(FI3)
      X(2, 2) = -SIN(FICA + PID2)
      Y(1) = VC * COS(ALC) - VA * COS(ALA)
      Y(2) = VC * SIN(ALC) - VA * SIN(ALA)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      ALA3A = DUGL4(FI3, PI, Y(1))
      VA3A = ABS(Y(1))
      ALA3C = DUGL3(FICA, PID2, Y(2))
      VA3C = ABS(Y(2))
      W3 = DOMEGA(RZAC, VA3C, ALA3C - FI3)
      CALL DSMVKT(VA, ALA, VA3A, ALA3A, VA3, ALA3)
      RETURN
      END
