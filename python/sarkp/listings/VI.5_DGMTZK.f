C LISTING VI.5 DGMTZK: BELOKONEV 1990, BOOK LINES L4245-4308
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DGMTZK(M, Z, BETA, X, AAA, D, S, DB, SB, DA, SA, DF)
C ОПРЕДЕЛЕНИЕ ГЕОМЕТРИЧЕСКИХ РАЗМЕРОВ ЗУБЧАТОГО
C КОЛЕСА.
C ЗАДАНЫ:
C МОДУЛЬ ЗАЦЕПЛЕНИЯ — M, ЧИСЛО ЗУБЬЕВ — Z, УГОЛ ИХ
C НАКЛОНА — BETA, КОЭФФИЦИЕНТ СМЕЩЕНИЯ — X,
C ОПРЕДЕЛЯЮТСЯ ДИАМЕТРЫ И ТОЛЩИНЫ ЗУБЬЕВ ПО
C ОКРУЖНОСТЯМ: ДЕЛИТЕЛЬНОЙ, ОСНОВНОЙ, ВЕРШИН И ВПАДИН.
C РЕЗУЛЬТАТЫ ПЕЧАТАЮТСЯ ПРИ AAA = 0.0.
      REAL M
      PI = 3.14159
      ALFA = ATAN(TAN(PI/9.0)/COS(BETA))
      P = PI * M
      D = M * Z/COS(BETA)
      DB = D * COS(ALFA)
      DF = D - 2.0 * (1.25 - X) * M
      PB = P * COS(ALFA)
      S = P/2.0 + 2.0 * X * M * TAN(ALFA)
      DA = M * (Z + 2.0 + 2.0 * X)
      ALFAA = ARCOS(DB/DA)
      SA = DA * (PI/2.0 * Z) + 2.0 * X * TAN(ALFA)/Z + TAN(ALFA) -
     *ALFA - TAN(ALFAA) + ALFAA
      SB = DB * (PI / (2.0 * Z) + 2.0 * X * TAN(ALFA)/Z + TAN(ALFA) -
     *ALFA)
C OCR: ", NE," -> ".NE."
      IF(AAA.NE.0.0)RETURN
      WRITE(3,1)
1     FORMAT(20X, 40H ГЕОМЕТРИЧЕСКИЕ РАЗМЕРЫ ЗУБЧАТОГО
C OCR: "      КОЛЕСА)" -> "     *КОЛЕСА)" (continuation mark lost)
     *КОЛЕСА)
      WRITE(3,2)
2     FORMAT(20X, 20H ИСХОДНЫЕ ПАРАМЕТРЫ:)
      WRITE(3,3)M, Z, BETA, X
3     FORMAT(1X, 'МОДУЛЬ ЗАЦЕПЛЕНИЯ M = ', F5.2,
     *'ЧИСЛО ЗУБЬЕВ Z = ', F3.0/
     *'УГОЛ НАКЛОНА ЗУБЬЕВ BETA = ', F6.4,
     *'КОЭФФИЦИЕНТ СМЕЩЕНИЯ X = ', F6.3//)
C OCR: "WRITE(3.4)" -> "WRITE(3,4)"
      WRITE(3,4)D, S
4     FORMAT(1X, 'ДИАМЕТР ДЕЛИТЕЛЬНОЙ ОКРУЖНОСТИ D = ', F7.2,
     *'ТОЛЩИНА ЗУБА ПО ДЕЛИТЕЛЬНОЙ ОКРУЖНОСТИ S = ', F7.4)
C OCR: "WRITE(2.5)" -> "WRITE(3,5)"
      WRITE(3,5)DB, SB
5     FORMAT(1X, 'ДИАМЕТР ОСНОВНОЙ ОКРУЖНОСТИ DB = ', F7.2,
     *'ТОЛЩИНА ЗУБА ПО ОСНОВНОЙ ОКРУЖНОСТИ SB = ', F7.4/)
C OCR: "WRITE(3.6)" -> "WRITE(3,6)"
      WRITE(3,6)DA, SA
6     FORMAT(1X, 'ДИАМЕТР ОКРУЖНОСТИ ВЕРШИН DA = ', F7.2,
     *'ТОЛЩИНА ЗУБА ПО ОКРУЖНОСТИ ВЕРШИНЫ SA = ', F7.4/)
C OCR: "WRITE(3.7)" -> "WRITE(3,7)"
      WRITE(3,7)DF
7     FORMAT(1X, 'ДИАМЕТР ОКРУЖНОСТИ ВПАДИН DF = ', F7.2/)
      RETURN
      END
