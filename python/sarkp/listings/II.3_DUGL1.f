C LISTING II.3 DUGL1: BELOKONEV 1990, BOOK LINES L551-569
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      FUNCTION DUGL1(X1, Y1, X2, Y2)
C ОПРЕДЕЛЕНИЕ НАПРАВЛЯЮЩЕГО УГЛА ВЕКТОРА КАК СУЩЕСТ-
C ВЕННО ПОЛОЖИТЕЛЬНОЙ ВЕЛИЧИНЫ ПО КООРДИНАТАМ ТОЧЕК
C НАЧАЛА — X1, Y1, И КОНЦА — X2, Y2 ОТРЕЗКА.
      PI = 3.14159
      R = SQRT((X2 - X1)** 2 + (Y2 - Y1)** 2)
      A = ARCOS((X2 - X1)/R)
      B = Y2 - Y1
      C = SIGN(A,B)
      IF(C.LT.0.)GO TO 1
      DUGL1 = C
      RETURN
1     DUGL1 = C + 2.0 * PI
      RETURN
      END
