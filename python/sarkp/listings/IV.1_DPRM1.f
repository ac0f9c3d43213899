C LISTING IV.1 DPRM1: BELOKONEV 1990, BOOK LINES L1479-1504
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DPRM1(XA, YA, XC, YC, RZ2, RZ3, P, AAA, FI2, FI3, XB, YB)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ ЛИНЕЙНЫХ И УГЛОВЫХ ПЕРЕМЕЩЕНИЙ
C ЗВЕНЬЕВ ГРУППЫ 1-ГО ВИДА.
C XA, YA, XC, YC — КООРДИНАТЫ ТОЧЕК ПРИСОЕДИНИТЕЛЬНЫХ
C ЭЛЕМЕНТОВ.
C RZ2, RZ3 — РАЗМЕРЫ ЗВЕНЬЕВ, P — УСЛОВИЕ СБОРКИ.
      CALL DVKT(XA, YA, XC, YC, RZAC, FIAC)
      FIAC = DUGOL(FIAC)
      UGBAC = ARCOS((RZ2 ** 2 + RZAC ** 2 - RZ3 ** 2)/(2.0 * RZ2 *
     *RZAC))
      UGBCA = ARCOS((RZ3 ** 2 + RZAC ** 2 - RZ2 ** 2)/(2.0 * RZ3 *
     *RZAC))
      FI2 = DUGOL(FIAC - P * UGBAC)
      FI3 = DUGOL(FIAC + P * UGBCA - P * PI)
      XB = XA + RZ2 * COS(FI2)
      YB = YA + RZ2 * SIN(FI2)
      RETURN
      END
