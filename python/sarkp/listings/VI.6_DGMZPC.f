C LISTING VI.6 DGMZPC: BELOKONEV 1990, BOOK LINES L4410-4454
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DGMZPC(M, Z1, Z2, BETA, X1, X2, BW, AAA)
C ГЕОМЕТРИЧЕСКИЙ РАСЧЕТ ЭВОЛЬВЕНТНОГО ЗАЦЕПЛЕНИЯ.
C ЗАДАНЫ:
C M — МОДУЛЬ ЗАЦЕПЛЕНИЯ.
C Z1 И Z2 — ЧИСЛА ЗУБЬЕВ КОЛЕС.
C BETA — УГОЛ НАКЛОНА ЗУБЬЕВ.
C X1 И X2 — КОЭФФИЦИЕНТ СМЕЩЕНИЯ.
C BW — РАБОЧАЯ ШИРИНА ЗУБЧАТОГО ВЕНЦА.
C РЕЗУЛЬТАТЫ ПЕЧАТАЮТСЯ ПРИ AAA = 0.0
      REAL M, INVALW
      COMMON/ZPC/A, XS, ALFAW, AW, XY, XUR, E
      PI = 3.14159
      ALFA = PI/9.0
      ALFAT = ATAN(TAN(ALFA)/COS(BETA))
      A = (Z1 + Z2) * M / (2.0 * COS(BETA))
      XS = X1 + X2
      INVALW = (2.0 * XS * TAN(ALFA)) / (Z1 + Z2) + TAN(ALFAT) - ALFAT
C OCR: "DUGINY(INVALW, PI/18.0, 0.0, 0.0, 0.0)" -> "DUGINV(INVALW, PI/18.0, 0.00001)"
      ALFAW = DUGINV(INVALW, PI/18.0, 0.00001)
      AW = (Z1 + Z2) * M * COS(ALFAT) / 2.0 * COS(BETA) * COS(ALFAW)
      XY = (AW - A) / M
      XUR = XS - XY
      DA1 = M * Z1 + 2.0 * (1.0 + X1 - XUR) * M
      DA2 = M * Z2 + 2.0 * (1.0 + X2 - XUR) * M
      ALA1 = ARCOS(M * Z1 * COS(ALFA) / DA1)
      ALA2 = ARCOS(M * Z2 * COS(ALFA) / DA2)
      EALFA = (Z1 * TAN(ALA1) + Z2 * TAN(ALA2) - (Z1 + Z2) * TAN
     *(ALFAW)) / (2.0 * PI)
      EBETA = BW * SIN(BETA) / (PI * M)
      E = EALFA + EBETA
      IF(AAA.NE.0.0) RETURN
C OCR: "WRITE(3.1)" -> "WRITE(3,1)"
      WRITE(3,1) A, XS, ALFAW, AW, XY, XUR, E
C OCR: "      I FORMAT(" -> "1     FORMAT("
1     FORMAT(10X, 'ОСНОВНЫЕ ПАРАМЕТРЫ ЗАЦЕПЛЕНИЯ'//
     *'ДЕЛИТЕЛЬНОЕ МЕЖОСЕВОЕ РАССТОЯНИЕ — A = ', F10.4/
     *'КОЭФФИЦИЕНТ СУММАРНОГО СМЕЩЕНИЯ — XS = ', F7.4/
     *'УГОЛ ЗАЦЕПЛЕНИЯ', 18X, ' — ALFAW = ', F7.4/
C OCR: "' — AW', F10.4" -> "' — AW = ', F10.4"
     *'МЕЖОСЕВОЕ РАССТОЯНИЕ', 15X, ' — AW = ', F10.4/
C OCR: "— XY', F7.4" -> "— XY = ', F7.4"
     *'КОЭФФИЦИЕНТ ВОСПРИНИМАЕМОГО СМЕЩЕНИЯ — XY = ', F7.4/
C OCR: "— XUR', F7.4" -> "— XUR = ', F7.4"
     *'КОЭФФИЦИЕНТ УРАВНИТЕЛЬНОГО СМЕЩЕНИЯ — XUR = ', F7.4/
     *'КОЭФФИЦИЕНТ ПЕРЕКРЫТИЯ', 15X, 'E = ', F7.4//)
      RETURN
      END
