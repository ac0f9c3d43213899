C LISTING II.6 DUGL4: BELOKONEV 1990, BOOK LINES L601-612
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      FUNCTION DUGL4(UGOL1, UGOLD, VEL)
C ОПРЕДЕЛЕНИЕ НАПРАВЛЕНИЯ ВЕКТОРА НА ЛИНИИ ЕГО
C ДЕЙСТВИЯ.
C UGOL1 — УГОЛ, ОПРЕДЕЛЯЮЩИЙ ЛИНИЮ ДЕЙСТВИЯ ВЕКТОРА.
C UGOLD — ДОПОЛНЯЮЩИЙ УГОЛ.
C VEL — ОПРЕДЕЛЯЮЩИЙ ПАРАМЕТР.
C OCR: "IF(VEL)109,110,111" -> "IF(VEL)109,110,110" (no label 111 exists; ERRATA E-DUGL4-1)
      IF(VEL)109,110,110
109   DUGL4 = UGOL1 - UGOLD
      RETURN
110   DUGL4 = UGOL1
      RETURN
      END
