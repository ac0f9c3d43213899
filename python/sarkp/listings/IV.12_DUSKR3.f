C LISTING IV.12 DUSKR3: BELOKONEV 1990, BOOK LINES L2150-2182
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DUSKR3(AA, BA, AC, BC, FI3, W3, RZAC, FICA, AA3AK,
C OCR: "BAZAR" -> "BA3AR"
     *BA3AK, AAA, AA3AR, BA3AR, AA3CT, BA3CT, E3, AA3, BA3)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ ЛИНЕЙНЫХ И УГЛОВЫХ УСКОРЕНИЙ В
C СТРУКТУРНОЙ ГРУППЕ 3-ГО ВИДА.
C AA, BA, AC, BC — УСКОРЕНИЯ ПРИСОЕДИНИТЕЛЬНЫХ ТОЧЕК.
C FI3, W3 — НАПРАВЛЯЮЩИЙ УГОЛ И УГЛОВАЯ СКОРОСТЬ ЗВЕНА 3.
C AA3AK, BAZAK — КОРИОЛИСОВО УСКОРЕНИЕ ДВИЖЕНИЯ ТОЧКИ
C A3 ОТНОСИТЕЛЬНО ТОЧКИ A2.
      DIMENSION X(2, 2), Y(2)
      X(1, 1) = COS(FI3)
      X(2, 2) = -SIN(FICA + PID2)
      X(2, 1) = SIN(FI3)
      X(1, 2) = -COS(FICA + PID2)
      Y(1) = AC * COS(BC) + W3 ** 2 * RZAC * COS(FICA - PI) - AA *
C OCR: "BAZAK" -> "BA3AK"
     *COS(BA) - AA3AK * COS(BA3AK)
      Y(2) = AC * SIN(BC) + W3 ** 2 * RZAC * SIN(FICA - PI) - AA * SIN
C OCR: "BAZAK" -> "BA3AK"
     *(BA) - AA3AK * SIN(BA3AK)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      BA3AR = DUGL4(FI3, PI, Y(1))
      AA3AR = ABS(Y(1))
      BA3CT = DUGL3(FICA, PID2, Y(2))
      AA3CT = ABS(Y(2))
C OCR: "—" -> "-"
      E3 = DOMEGA(RZAC, AA3CT, BA3CT - FICA)
C OCR: "—" -> "-"
      CALL DSMVKT(AC, BC, W3 ** 2 * RZAC, FICA - PI, A, B)
C OCR: "DSMVWT" -> "DSMVKT"
      CALL DSMVKT(A, B, AA3CT, BA3CT, AA3, BA3)
      RETURN
      END
