C LISTING VIII.2 DMHVK: BELOKONEV 1990, BOOK LINES L6052-6082
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DMHVK(N, DELTA, ISC, W1, DEC, IMHVK)
C ОПРЕДЕЛЕНИЕ МОМЕНТА ИНЕРЦИИ МАХОВИКА.
C N — РАЗМЕРНОСТЬ МАССИВОВ. DELTA — КОЭФФИЦИЕНТ
C НЕРАВНОМЕРНОСТИ ХОДА МАШИНЫ
C ISC — ПОСТОЯННАЯ СОСТАВЛЯЮЩАЯ ПРИВЕДЕННОГО МОМЕНТА
C ИНЕРЦИИ МЕХАНИЗМА.
C W1 — УГЛОВАЯ СКОРОСТЬ ЗВЕНА ПРИВЕДЕНИЯ
C РЕЗУЛЬТАТ:
C DEC — МАССИВ ЗНАЧЕНИЙ ВЕЛИЧИНЫ КОЛЕБАНИЯ КИНЕТИЧЕ-
C СКОЙ ЭНЕРГИИ ЗВЕНЬЕВ С ПОСТОЯННЫМ ПРИВЕДЕННЫМ
C МОМЕНТОМ ИНЕРЦИИ.
C IMHVK — МОМЕНТ ИНЕРЦИИ МЕХОВИКА.
      REAL ISC, IMHVK
      DIMENSION DEC(N)
      C1 = DEC(1)
      C2 = DEC(1)
      DO 2 K = 2, N
      C1 = AMAX1(C1, DEC(K))
      C2 = AMIN1(C2, DEC(K))
2     CONTINUE
      IMHVK = (C1 + ABS(C2))/DELTA/W1 ** 2 - ISC
      RETURN
      END
