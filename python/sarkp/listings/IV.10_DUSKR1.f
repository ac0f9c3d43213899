C LISTING IV.10 DUSKR1: BELOKONEV 1990, BOOK LINES L2017-2049
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DUSKR1(AA, BA, AC, BC, RZ2, FI2, RZ3, FI3, W2, W3,
     *AAA, ABAT, BBAT, ABCT, BBCT, AB, BB, E2, E3)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ ЛИНЕЙНЫХ И УГЛОВЫХ УСКОРЕНИЙ ЗВЕНЬЕВ
C 1-ГО ВИДА ГРУППЫ.
C AA, BA, AC, BC — МОДУЛИ И НАПРАВЛЯЮЩИЕ УГЛЫ ВЕКТОРОВ
C УСКОРЕНИЙ ПРИСОЕДИНИТЕЛЬНЫХ ТОЧЕК.
C RZ2, FI2, RZ3, FI3 — РАЗМЕРЫ ЗВЕНЬЕВ И НАПРАВЛЯЮЩИЕ УГЛЫ.
C W2, W3 — УГЛОВЫЕ СКОРОСТИ ЗВЕНЬЕВ,
      DIMENSION X(2, 2), Y(2)
      X(1, 1) = COS(FI2 + PID2)
      X(1, 2) = -COS(FI3 + PID2)
      X(2, 1) = SIN(FI2 + PID2)
      X(2, 2) = -SIN(FI3 + PID2)
      Y(1) = AC * COS(BC) + W3 ** 2 * RZ3 * COS(FI3 - PI) - AA * COS
     *(BA) - W2 ** 2 * RZ2 * COS(FI2 - PI)
      Y(2) = AC * SIN(BC) + W3 ** 2 * RZ3 * SIN(FI3 - PI) - AA * SIN(BA)
     *- W2 ** 2 * RZ2 * SIN(FI2 - PI)
C OCR: "8.0001" -> "0.0001"
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      BBAT = DUGL3(FI2, PID2, Y(1))
      ABAT = ABS(Y(1))
      BBCT = DUGL3(FI3, PID2, Y(2))
      ABCT = ABS(Y(1))
      CALL DSMVKT(AA, BA, W2 ** 2 * RZ2, FI2 - PI, A, B)
      CALL DSMVKT(A, B, ABAT, BBAT, AB, BB)
C OCR: "E2 = DOMEQA" -> "E2 = DOMEGA"
      E2 = DOMEGA(RZ2, ABAT, BBAT - FI2)
C OCR: "E3 = DOMEQA" -> "E3 = DOMEGA"
      E3 = DOMEGA(RZ3, ABCT, BBCT - FI3)
      RETURN
      END
