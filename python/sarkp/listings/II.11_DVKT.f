C LISTING II.11 DVKT: BELOKONEV 1990, BOOK LINES L664-680
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C TABLE 33 (L6267-6330) NUMBERS IT II.10.
      SUBROUTINE DVKT(X1, Y1, X2, Y2, RZ, FI)
C ОПРЕДЕЛЕНИЕ МОДУЛЯ И НАПРАВЛЯЮЩЕГО УГЛА НАПРАВЛЕН-
C НОГО ОТРЕЗКА ПО КООРДИНАТАМ ЕГО НАЧАЛЬНОЙ И КОНЕЧНОЙ
C ТОЧЕК.
      RZ = SQRT((X2 - X1) ** 2 + (Y2 - Y1) ** 2)
C OCR: ", EQ," -> ".EQ."
      IF(RZ.EQ.0.0)GO TO 1
      A = ARCOS((X2 - X1)/RZ)
      B = Y2 - Y1
      FI = SIGN(A, B)
      RETURN
1     FI = 0.0
      RETURN
      END
