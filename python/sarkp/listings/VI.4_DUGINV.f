C LISTING VI.4 DUGINV: BELOKONEV 1990, BOOK LINES L4153-4164, L4201-4217
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: a page of Fig. 44 interrupts the listing
      FUNCTION DUGINV(INVX, XNACH, TCHNST)
C ОПРЕДЕЛЕНИЕ УГЛА ЗАЦЕПЛЕНИЯ ПО ЗНАЧЕНИЮ ЕГО
C ИНВОЛЮТЫ.
C ПРИ ОБРАЩЕНИИ ДОЛЖНЫ БЫТЬ ЗАДАНЫ:
C INVX — ЗНАЧЕНИЕ ИНВОЛЮТЫ ОПРЕДЕЛЯЕМОГО УГЛА X,
C XNACH — НАЧАЛЬНОЕ ЗНАЧЕНИЕ УГЛА X ПРИ ЧИСЛЕННОМ
C РЕШЕНИИ УРАВНЕНИЯ ЭВОЛЬВЕНТНОЙ ФУНКЦИИ
C ИТЕРАЦИОННЫМ МЕТОДОМ,
C ТСНСТ — ЗАДАВАЕМАЯ ТОЧНОСТЬ ОПРЕДЕЛЕНИЯ УГЛА X ПО
C ЗНАЧЕНИЯМ ИНВОЛЮТЫ.
C ТОЧНОСТЬЮ ДО СЕКУНДЫ ОБЕСПЕЧИВАЕТСЯ
C ПРИ ТСНСТ = 0.00001.
      REAL INVX
      X = XNACH
1     X1 = ATAN(X + INVX)
      D = ABS(X1 - X)
      IF((D - TCHNST).LT.0.0) GO TO 2
      X = X1
      GO TO 1
2     DUGINV = X1
      RETURN
      END
