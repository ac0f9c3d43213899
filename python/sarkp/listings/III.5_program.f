C LISTING III.5 PROGRAM: BELOKONEV 1990, BOOK LINES L1270-1296
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "ПОДСПРОГРАММЫ" -> "ПОДПРОГРАММЫ"
C ПРИМЕР ГЛАВНОЙ ПРОГРАММЫ, ИСПОЛЬЗУЮЩЕЙ РАЗНЫЕ ПОДПРОГРАММЫ
C СИНТЕЗА ШАРНИРНОГО ЧЕТЫРЕХЗВЕННОГО МЕХАНИЗМА.
C OCR: "F11" -> "FI1"; "F13" -> "FI3"
      DIMENSION FI1(3), FI3(3), AD(3)
C OCR: "F11" -> "FI1"; "F13" -> "FI3"
      DATA CD/0.6/, FI1/0.349, 1.047, 1.745/, FI3/0.524, 1.57, 2.793/, AD/0.9,
     *0.9, 0.9/
      PI = 3.14159
C OCR: "F11" -> "FI1"; "F13" -> "FI3"
      CALL DSNTZR(AD, CD, FI1, FI3, 0.0, AB, BD)
      CALL DSNTZ1(1.5, PI/6., (PI/6.) * 5., 0.5, 0.75, -1., 0.0, L1, L2, LO)
      CALL DSNTZ2(1.5, PI/6., 0.5, 0.75, PI/18., PI/3., 0.0, L1, L2, LO)
      CALL DSNTZ3(0.2, 0.4, 0.6, 0.5, 0.8, 0.85, 1.343, 0.6, PI/3, PI/9., 0.0,
     *L1, L2, LO)
C ПРИМЕР СИНТЕЗА КРИВОШИПНО-ПОЛЗУННОГО МЕХАНИЗМА.
C OCR: "F11" -> "FI1"; "F13" -> "FI3"
      READ(1, 1)CD, FI1, FI3, AD
1     FORMAT(F6.3, 9F7.4)
C OCR: "F11" -> "FI1"; "F13" -> "FI3"
      CALL DSNTZR(AD, CD, FI1, FI3, 0.0, AB, BD)
      STOP
      END
