C LISTING II.2 DFRNCL: BELOKONEV 1990, BOOK LINES L490-509
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: heading printed П.2.
      SUBROUTINE DFRNCL(M, H, FDIF, Y)
C ПРОГРАММА ЧИСЛЕННОГО ДИФФЕРЕНЦИРОВАНИЯ ФУНКЦИИ,
C ЗАДАННОЙ МАССИВОМ ЧИСЕЛ.
C Y(M) — МАССИВ ЗНАЧЕНИЙ ПЕРВООБРАЗНОЙ ФУНКЦИИ.
C FDIF(M) — МАССИВ ЗНАЧЕНИЙ ПРОИЗВОДНОЙ ФУНКЦИИ.
C M — РАЗМЕРНОСТЬ МАССИВОВ, H — ШАГ ДИФФЕРЕНЦИРОВАНИЯ,
      DIMENSION FDIF(M), Y(M)
      FDIF(1) = 0.0
      M1 = M - 1
      DO 20 K = 1, M1
      FDIF(K + 1) = (Y(K + 1) - Y(K))/H
20    CONTINUE
      RETURN
      END
