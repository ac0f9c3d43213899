C LISTING VI.2 PROGRAM: BELOKONEV 1990, BOOK LINES L3808-3852
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C ОПРЕДЕЛЕНИЕ ЗУБЬЕВ КОЛЕС ПЛАНЕТАРНЫХ РЕДУКТОРОВ,
      INTEGER ZKRN, ZKRW, DZ, Z1, Z3, Z4
      COMMON/ZUB/ZKRN, ZKRW, DZ, Z1, Z2, Z3, Z4
      ZKRN = 20
      ZKRW = 85
      DZ = 8
C РЕДУКТОР ПО ПЕРВОЙ СХЕМЕ
      CALL DZBPL(2, 4, 1, 1, 1, 13, 35, 1)
      CALL DZBPL(3, 4, 1, 1, 1, 13, 35, 1)
      CALL DZBPL(2, 4, 1, 2, 1, 13, 35, 1)
      CALL DZBPL(2, 4, 1, 4, 3, 13, 35, 1)
      CALL DZBPL(2, 4, 1, 4, 3, 13, 45, 1)
      CALL DZBPL(3, 4, 1, 4, 3, 13, 45, 1)
      CALL DZBPL(2, 11, 1, 4, 3, 13, 35, 1)
      CALL DZBPL(3, 23, 2, 4, 3, 13, 35, 1)
      CALL DZBPL(3, 26, 5, 1, 1, 17, 43, 1)
C РЕДУКТОР ПО ВТОРОЙ СХЕМЕ
      CALL DZBPL(3, -19, 1, 25, 6, 13, 30, 2)
      CALL DZBPL(2, -19, 1, 25, 6, 13, 30, 2)
      CALL DZBPL(3, 19, 1, 25, 6, 13, 30, 2)
      CALL DZBPL(2, 1, 19, 7, 8, 15, 50, 2)
      CALL DZBPL(2, 1, 10, 3, 1, 13, 50, 2)
C РЕДУКТОР ПО ТРЕТЬЕЙ СХЕМЕ
      CALL DZBPL(2, 1, 10, 3, 2, 20, 200, 3)
      CALL DZBPL(2, 1, 10, 2, 3, 20, 200, 3)
      CALL DZBPL(2, 1, 25, 4, 3, 30, 200, 3)
      CALL DZBPL(2, 1, 25, 3, 4, 30, 200, 3)
      CALL DZBPL(3, 1, 13, 2, 3, 20, 200, 3)
      STOP
      END
