C LISTING II.12 DSMVKT: BELOKONEV 1990, BOOK LINES L684-698
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C TABLE 33 (L6267-6330) NUMBERS IT II.9.
      SUBROUTINE DSMVKT(L1, FI1, L2, FI2, L, FI)
C ОПРЕДЕЛЕНИЕ МОДУЛЯ L И НАПРАВЛЯЮЩЕГО УГЛА FI
C ВЕКТОРА СУММЫ ДВУХ ВЕКТОРОВ, ЗАДАННЫХ
C МОДУЛЯМИ L1, L2, И НАПРАВЛЯЮЩИМИ УГЛАМИ FI1 I FI2
      REAL L, L1, L2, LX, LY
      LX = L1 * COS(FI1) + L2 * COS(FI2)
      LY = L1 * SIN(FI1) + L2 * SIN(FI2)
      L = SQRT(LX ** 2 + LY ** 2)
      FI = DUGL5(LX, LY)
      RETURN
      END
