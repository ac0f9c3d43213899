C LISTING IV.3 DPRM3: BELOKONEV 1990, BOOK LINES L1577-1598
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "FIZ" -> "FI3"
      SUBROUTINE DPRM3(XA, YA, XC, YC, RZ2, T, P, AAA, RZAC, FI3, FICA)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ ЛИНЕЙНЫХ И УГЛОВЫХ ПЕРЕМЕЩЕНИЙ В
C СТРУКТУРНОЙ ГРУППЕ 3-ГО ВИДА.
C XA, YA, XC, YC — КООРДИНАТЫ ПРИСОЕДИНИТЕЛЬНЫХ ТОЧЕК,
C RZ2, T — ЛИНЕЙНЫЙ И УГЛОВОЙ РАЗМЕРЫ ЗВЕНА 2,
C P — УСЛОВИЕ СБОРКИ.
      RZAC = SQRT((XA - XC) ** 2 + (YA - YC) ** 2)
      FICA = DUGL2(XC, YC, XA, YA)
      UGBCA = ARSIN(RZ2 * SIN(T)/RZAC)
C OCR: "FIZ" -> "FI3"
      FI3 = FICA + P * UGBCA
      RETURN
      END
