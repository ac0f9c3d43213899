C LISTING II.7 DUGL5: BELOKONEV 1990, BOOK LINES L614-628
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      FUNCTION DUGL5(PRX, PRY)
C ОПРЕДЕЛЕНИЕ НАПРАВЛЕНИЯ ВЕКТОРА ПО ЕГО ПРОЕКЦИЯМ
C PRX И PRY НА ОСИ АБСЦИСС И ОРДИНАТ.
      PI = 3.14159
      IF(ABS(PRX))112,110,112
112   D = PRY/PRX
C OCR: ", LT," -> ".LT."
      IF(PRX.LT.0.0) GO TO 113
      DUGL5 = ATAN(D)
      RETURN
113   DUGL5 = PI + ATAN(D)
      RETURN
110   A = PI/2.0
      DUGL5 = SIGN(A, PRY)
      RETURN
      END
