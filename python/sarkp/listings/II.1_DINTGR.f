C LISTING II.1 DINTGR: BELOKONEV 1990, BOOK LINES L433-480
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "DINTGR(M, N, NOMER, Y, FINT)" -> "DINTGR(M, H, NOMER, Y, FINT)" (the body and every call use the step H; ERRATA E-DINTGR-1)
      SUBROUTINE DINTGR(M, H, NOMER, Y, FINT)
C ПРОГРАММА ЧИСЛЕННОГО ИНТЕГРИРОВАНИЯ ФУНКЦИИ, ЗАДАННОЙ МАССИВОМ ЧИСЕЛ.
C В ЗАВИСИМОСТИ ОТ ЗНАЧЕНИЯ ПЕРЕМЕННОЙ NOMER ПРОГРАММА
C ИСПОЛЬЗУЕТ:
C МЕТОД СИМПСОНА, — NOMER = 1.
C МЕТОД ТРАПЕЦИЙ, — NOMER = 2.
C МЕТОД ПРЯМОУГОЛЬНИКОВ, — NOMER = 3.
C Y(M) — МАССИВ ЗНАЧЕНИЙ ПРОИЗВОДНОЙ ФУНКЦИИ.
C FINT(M) — МАССИВ ЗНАЧЕНИЙ ПЕРВООБРАЗНОЙ ФУНКЦИИ.
C M — РАЗМЕРНОСТЬ МАССИВОВ. H — ШАГ ИНТЕГРИРОВАНИЯ.
      DIMENSION Y(M), FINT(M)
      FINT(1) = 0.0
      GO TO (10, 13, 16), NOMER
10    WRITE(3, 11)
11    FORMAT(29H ИСПОЛЬЗУЕТСЯ МЕТОД СИМПСОНА)
      FINT(2) = H * (Y(1) + Y(2))/2.0
      FINT(3) = (Y(1) + 4. * Y(2) + Y(3)) * H/3.0
      DO 12 K = 4, M
      FINT(K) = FINT(K - 2) + (Y(K - 2) + 4.0 * Y(K - 1) + Y(K)) * H/3.0
12    CONTINUE
      RETURN
13    WRITE(3, 14)
14    FORMAT(28H ИСПОЛЬЗУЕТСЯ МЕТОД ТРАПЕЦИЙ)
      DO 15 K = 2, M
      FINT(K) = FINT(K - 1) + 0.5 * H * (Y(K - 1) + Y(K))
15    CONTINUE
      RETURN
16    WRITE(3, 17)
17    FORMAT(35H ИСПОЛЬЗУЕТСЯ МЕТОД ПРЯМОУГОЛЬНИКОВ)
      DO 18 K = 2, M
      FINT(K) = FINT(K - 1) + H * Y(K)
18    CONTINUE
      RETURN
      END
