C LISTING IV.2 DPRM2: BELOKONEV 1990, BOOK LINES L1531-1556
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DPRM2(XA, YA, XK, YK, FIM, RZ2, RZ3, T, AAA, XB,
     *YB, FI2)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ ЛИНЕЙНЫХ И УГЛОВЫХ ПЕРЕМЕЩЕНИЙ ЗВЕНЬЕВ
C ГРУППЫ 2-ГО ВИДА.
C XA, YA, XK, YK, FIM — КООРДИНАТЫ ПРИСОЕДИНИТЕЛЬНЫХ
C ЭЛЕМЕНТОВ ЗВЕНЬЕВ.
C RZ2, RZ3, T — ЛИНЕЙНЫЕ И УГЛОВЫЕ РАЗМЕРЫ ЗВЕНЬЕВ.
C FIM ВЫБИРАЕТСЯ ПО АВ ОТ А К В.
      UK1 = TAN(FIM)
      XO1 = ((XA + UK1 ** 2 * XK) - UK1 * (YK - YA)) / (UK1 ** 2 + 1.0)
      YO1 = ((YK + UK1 ** 2 * YA) - UK1 * (XK - XA)) / (UK1 ** 2 + 1.0)
      R = SQRT((XA - XO1) ** 2 + (YA - YO1) ** 2) - RZ3 * SIN(T)
      FIR = DUGL2(XA, YA, XO1, YO1)
      B = SQRT(RZ2 ** 2 - R ** 2)
      X = R * COS(FIR) + B * COS(FIM)
      Y = R * SIN(FIR) + B * SIN(FIM)
      FI2 = DUGL5(X, Y)
      XB = XA + RZ2 * COS(FI2)
      YB = YA + RZ2 * SIN(FI2)
      RETURN
      END
