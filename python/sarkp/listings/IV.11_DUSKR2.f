C LISTING IV.11 DUSKR2: BELOKONEV 1990, BOOK LINES L2077-2117
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "F12" -> "FI2"
      SUBROUTINE DUSKR2(AA, BA, ABM, BVM, ABK, BVK, RZ2, FI2, W2,
     *FIM, AAA, ABAT, VBAT, ABVM, BVBM, E2, AB, BB)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ УСКОРЕНИЙ ЗВЕНЬЕВ СТРУКТУРНОЙ ГРУППЫ
C 2-ГО ВИДА.
C AA, BA, ABM, BVM — ВЕКТОРЫ УСКОРЕНИЙ И НАПРАВЛЯЮЩИЕ
C УГЛЫ ДЛЯ ПРИСОЕДИНИТЕЛЬНЫХ ЭЛЕМЕНТОВ.
C ABK, BVK — ВЕКТОР И НАПРАВЛЯЮЩИЙ УГОЛ КОРИОЛИСОВА
C УСКОРЕНИЯ ПОЛЗУНА.
C RZ2, F12, FIM — ДЛИНА, НАПРАВЛЯЮЩИЙ УГОЛ ЗВЕНА 2, УГОЛ
C НАПРАВЛЯЮЩЕЙ.
C W2 — УГЛОВАЯ СКОРОСТЬ ЗВЕНА 2.
      DIMENSION X(2, 2), Y(2)
C OCR: "F12" -> "FI2"
      X(1, 1) = COS(FI2 + PID2)
      X(1, 2) = -COS(FIM)
C OCR: "F12" -> "FI2"
      X(2, 1) = SIN(FI2 + PID2)
      X(2, 2) = -SIN(FIM)
      Y(1) = ABM * COS(BVM) + ABK * COS(BVK) - AA * COS(BA) - W2 **
C OCR: "F12" -> "FI2"
     *2 * RZ2 * COS(FI2 - PI)
      Y(2) = ABM * SIN(BVM) + ABK * SIN(BVK) - AA * SIN(BA) -
C OCR: "F12" -> "FI2"
     *W2 ** 2 * RZ2 * SIN(FI2 - PI)
C OCR: "1ER" -> "IER"
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
C OCR: "F12" -> "FI2"
      VBAT = DUGL3(FI2, PID2, Y(1))
      ABAT = ABS(Y(1))
      BVBM = DUGL4(FIM, PI, Y(2))
      ABVM = ABS(Y(2))
C OCR: "F12" -> "FI2"
      E2 = DOMEGA(RZ2, ABAT, VBAT - FI2)
C OCR: "F12" -> "FI2"; "DSMVKI" -> "DSMVKT"
      CALL DSMVKT(AA, BA, W2 ** 2 * RZ2, FI2 - PI, A, B)
C OCR: "DSMVKI" -> "DSMVKT"
      CALL DSMVKT(A, B, ABAT, VBAT, AB, BB)
      RETURN
      END
