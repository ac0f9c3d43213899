C LISTING II.4 DUGL2: BELOKONEV 1990, BOOK LINES L572-587
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      FUNCTION DUGL2(X1, Y1, X2, Y2)
C ОПРЕДЕЛЕНИЕ НАПРАВЛЕНИЯ ВЕКТОРА ПО КООРДИНАТАМ ТОЧЕК
C ЕГО НАЧАЛА — X1, Y1 И КОНЦА — X2, Y2.
      DL = SQRT((X2 - X1)** 2 + (Y2 - Y1)** 2)
      A = ARCOS((X2 - X1)/DL)
      B = Y2 - Y1
      DUGL2 = SIGN(A, B)
      RETURN
      END
