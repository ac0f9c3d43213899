C LISTING II.10 DOMEGA: BELOKONEV 1990, BOOK LINES L648-660
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C TABLE 33 (L6267-6330) NUMBERS IT II.8.
      FUNCTION DOMEGA(RAZMER,VEKTOR,UGOL)
C ОПРЕДЕЛЕНИЕ УГЛОВОЙ СКОРОСТИ ИЛИ УГЛОВОГО УСКОРЕНИЯ
C RAZMER — ДЛИНА ЗВЕНА.
C VEKTOR — ОПРЕДЕЛЯЮЩИЙ ВЕКТОР СКОРОСТИ ИЛИ УСКОРЕНИЯ.
C UGOL — ЛОГИЧЕСКИЙ ПРИЗНАК.
      A = VEKTOR/RAZMER
      DOMEGA = SIGN(A, UGOL)
      RETURN
      END
