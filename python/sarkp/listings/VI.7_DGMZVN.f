C LISTING VI.7 DGMZVN: BELOKONEV 1990, BOOK LINES L4512-4631
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DGMZVN(M, Z1, Z2, X1, X2, ZO2, DO, XO, DAO, AAA)
C ГЕОМЕТРИЧЕСКИЙ РАСЧЕТ ЭВОЛЬВЕНТНОГО ВНУТРЕННЕГО
C ЗАЦЕПЛЕНИЯ.
C ЗАДАНЫ:
C M — МОДУЛЬ ЗАЦЕПЛЕНИЯ.
C И1 И Z2 — ЧИСЛА ЗУБЬЕВ КОЛЕС.
C X1 И X2 — КОЭФФИЦЕНТЫ СМЕЩЕНИЯ.
C ЗАДАЮТСЯ ПАРАМЕТРЫ ДОЛБЯКА:
C ZO2 — ЧИСЛО ЗУБЬЕВ, DO — ДЕЛИТЕЛЬНЫЙ ДИАМЕТР, XO —
C КОЭФФИЦИЕНТ СМЕЩЕНИЯ ИСХОДНОГО КОНТУРА, DAO —
C ДИАМЕТР ВЕРШИН.
C РЕЗУЛЬТАТЫ ПЕЧАТАЮТСЯ ПРИ AAA = 0.0.
C ПАРАМЕТРЫ СТАНОЧНОГО ЗАЦЕПЛЕНИЯ ДОЛБЯКА.
C С КОЛЕСАМИ НА ПЕЧАТЬ НЕ ВЫВОДЯТСЯ.
      COMMON/ZVN/A, XD, ALFA, AW, D1, D2, DW1, DW2, XY, XUR, DA1,
     *DA2, DF1, DF, H1, H2, SA1, SA2, EALFA
      REAL M, INVALW, INVO2, K2
      PI = 3.14159
      A = M * (Z2 - Z1) / 2.0
      ALFA = PI / 9.0
      XD = X2 - X1
      INVALW = TAN(ALFA) - ALFA + 2.0 * XD * TAN(ALFA) / (Z2 - Z1)
C OCR: "DUGINV(INVALW, PI/18, 0, 0.00001)" -> "DUGINV(INVALW, PI/18.0, 0.00001)"
      ALFAW = DUGINV(INVALW, PI/18.0, 0.00001)
      AW = A * COS(ALFA) / COS(ALFAW)
      D1 = M * Z1
      D2 = M * Z2
      U = Z2 / Z1
      DW1 = 2.0 * AW / (U - 1.0)
      DW2 = 2.0 * AW * U / (U - 1.0)
      XY = (AW - A) / M
      XUR = XD - XY
      INVO2 = 2.0 * (X2 - XO) * TAN(ALFA) / (Z2 - ZO2) + TAN(ALFA) -
     *ALFA
C OCR: "DUGINV(INVO2, PI/18, 0, 0.00001)" -> "DUGINV(INVO2, PI/18.0, 0.00001)"
      ALFAO2 = DUGINV(INVO2, PI/18.0, 0.00001)
      AWO2 = (Z2 - ZO2) * M * COS(ALFA) / (2.0 * COS(ALFAO2))
      XYO2 = AWO2 / M - (Z2 - ZO2) / 2.0
      XURO2 = X2 - XO - XYO2
      K2 = 0.25 - 0.125 * X2
      DA1 = D1 + 2.0 * (1.0 + X1 + XUR - XURO2) * M
      DA2 = D2 - 2.0 * (1.0 - X2 + XUR - K2) * M
      DF1 = D1 - 2.0 * (1.25 - X1) * M
      DF2 = 2.0 * AWO2 + DAO
      H1 = (DA1 - DF1)/2.0
      H2 = (DF2 - DA2)/2.0
      ALA1 = ARCCOS(M * Z1 * COS(ALFA)/DA1)
      ALA2 = ARCCOS(M * Z2 * COS(ALFA)/DA2)
      EALFA = (Z1 * TAN(ALA1) - Z2 * TAN(ALA2) + (Z2 - Z1) * TAN
C OCR: "(2.0 * PISA1 = DA1 * ((0.5 * PI + 2.0 * X1 * TAN(ALFA)))/" -> "(2.0 * PI)" and "SA1 = DA1 * ((0.5 * PI + 2.0 * X1 * TAN(ALFA))/" (two statements run together)
     *(ALFAW))/(2.0 * PI)
      SA1 = DA1 * ((0.5 * PI + 2.0 * X1 * TAN(ALFA))/
     *Z1 + (TAN(ALFA) - ALFA) - (TAN(ALA1) - ALA1))
      SA2 = DA2 * ((0.5 * PI - 2.0 * X2 + TAN(ALFA))/Z2 - (TAN(ALFA) -
C OCR: "      ALFA) *" -> "     *ALFA) *" (continuation mark lost)
     *ALFA) * (TAN(ALA2) - ALA2))
      IF(AAA.NE.0.0)RETURN
C OCR: "WRITE(3.1)" -> "WRITE(3,1)"
      WRITE(3,1)A, XD, ALFAW, AW, D1, D2, XY, XUR, DA1, DA2, DF1, DF2
1     FORMAT(5X,'ОСНОВНЫЕ ПАРАМЕТРЫ ЗУБЧАТЫХ КОЛЕС С'/
     *5X, 'ВНУТРЕННИМ ЗАЦЕПЛЕНИЕМ.'/5X, 'КОЛЕСА НАРЕЗАЮТСЯ',
     *'ДОЛБЯКОМ'//
     *'ДЕЛИТЕЛЬНОЕ МЕЖКОСЕВОЕ РАССТОЯНИЕ — A = ', F10.4/
     *'КОЭФФИЦИЕНТ РАЗНОСТИ СМЕЩЕНИЙ — XD = ', F7.4/
     *'УГОЛ ЗАЦЕПЛЕНИЯ — ALFAW = ', F7.4/
     *'МЕЖКОСЕВОЕ РАССТОЯНИЕ — AW = ', F10.4/
     *'ДЕЛИТЕЛЬНЫЕ ДИАМЕТРЫ: '/
     *'ШЕСТЕРНИ — D1 = ', F10.4/
     *'КОЛЕСА — D2 = ', F10.4/
     *'КОЭФФИЦИЕНТ ВОСПРИНИМАЕМОГО СМЕЩЕНИЯ — XY = ', F7.4/
     *'КОЭФФИЦИЕНТ УРАВНИТЕЛЬНОГО СМЕЩЕНИЯ — XUR = ', F7.4/
     *'ДИАМЕТРЫ ВЕРШИН ЗУБЬЕВ: '/
     *'ШЕСТЕРНИ — DA1 = ', F10.4/
     *'КОЛЕСА — DA2 = ', F10.4/
     *'ДИАМЕТРЫ ВПАДИН ЗУБЬЕВ: '/
     *'ШЕСТЕРНИ — DF1 = ', F10.4/
     *'КОЛЕСА — DF2 = ', F10.4)
C OCR: "WRITE(3.2)" -> "WRITE(3,2)"
      WRITE(3,2)H1, H2, SA1, SA2, EALFA
2     FORMAT('ВЫСОТА ЗУБА: '/
     *'ШЕСТЕРНИ — H1 = ', F7.4/
     *'КОЛЕСА — H2 = ', F7.4/
     *'ТОЛЩИНА ЗУБА НА ОКРУЖНОСТИ ВЕРШИН: '/
     *'ШЕСТЕРНИ — SA1 = ', F10.4/
     *'КОЛЕСА — SA2 = ', F10.4/
     *'КОЭФФИЦИЕНТ ПЕРЕКРЫТИЯ — EALFA = ', F7.4//)
      RETURN
      END
