C LISTING II.5 DUGL3: BELOKONEV 1990, BOOK LINES L590-599
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      FUNCTION DUGL3(UGOL1, UGOLD, VEL)
C ОПРЕДЕЛЕНИЕ НАПРАВЛЕНИЯ ВЕКТОРА ПО ОПРЕДЕЛЯЮЩЕМУ
C ПАРАМЕТРУ.
C UGOL1 — УГОЛ, ОТНОСИТЕЛЬНО КОТОРОГО ОПРЕДЕЛЯЕТСЯ
C ПЕРВОНАЧАЛЬНОЕ НАПРАВЛЕНИЕ ВЕКТОРА.
C UGOLD — ДОПОЛНЯЮЩИЙ УГОЛ.
C VEL — ОПРЕДЕЛЯЮЩИЙ ПАРАМЕТР.
      DUGL3 = UGOL1 + SIGN(UGOLD, VEL)
      RETURN
      END
