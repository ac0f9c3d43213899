C LISTING VI.1 DZBPL: BELOKONEV 1990, BOOK LINES L3720-3798
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: heading printed IV.1.
      SUBROUTINE DZBPL(KS, P, Q, L2, L3, Z1MIN, Z1MAX, SHEMA)
C OCR: "ОПРЕДЕЛЕНИЕМ ЧИСЕЛ" -> "ОПРЕДЕЛЕНИЕ ЧИСЕЛ"
C ОПРЕДЕЛЕНИЕ ЧИСЕЛ ЗУБЬЕВ КОЛЕС ПЛАНЕТАРНЫХ
C МНОГОСАТЕЛЛИТНЫХ МЕХАНИЗМОВ ПО УСЛОВИЯМ СООСНОСТИ,
C СБОРКИ И СОСЕДСТВА
C ВСЕ ВЫЧИСЛЕНИЯ ПРОВОДЯТСЯ С ЦЕЛОЧИСЛЕННЫМИ
C ПЕРЕМЕННЫМИ.
C KS — КОЛИЧЕСТВО САТЕЛЛИТНЫХ БЛОКОВ.
C P И Q — ЦЕЛЫЕ ЧИСЛА, ОПРЕДЕЛЯЮЩИЕ ПЕРЕДАТОЧНОЕ
C ОТНОШЕНИЕ i_{1H} = P/Q .
C L2 И L3 — ПРОСТЫЕ ЧИСЛА, ОПРЕДЕЛЯЮЩИЕ СООТНОШЕНИЕ
C ЗУБЬЕВ В КОЛЕСАХ САТЕЛЛИТНОГО БЛОКА: Z_2 : Z_3 = L_2 : L_3 .
C Z1MIN, Z1MAX — ПРЕДЕЛЬНЫЕ ЧИСЛА ЗУБЬЕВ ВЕДУЩЕГО
C КОЛЕСА, ДОПУСКАЕМЫЕ ИЗ УСЛОВИЙ ПОДРЕЗА, ЗАКЛИНИВАНИЯ
C ИЛИ НАИБОЛЬШИХ ГАБАРИТНЫХ РАЗМЕРОВ МЕХАНИЗМА.
C ZKRN — КРИТИЧЕСКОЕ ПО УСЛОВИЮ ЗАКЛИНИВАНИЯ ЧИСЛО
C ЗУБЬЕВ КОЛЕСА С НАРУЖНЫМ ЗАЦЕПЛЕНИЕМ.
C ZKRW — КРИТИЧЕСКОЕ ПО УСЛОВИЮ ЗАКЛИНИВАНИЯ ЧИСЛО
C ЗУБЬЕВ КОЛЕСА С ВНУТРЕННИМ ЗАЦЕПЛЕНИЕМ.
C DZ — ДОПУСТИМАЯ РАЗНОСТЬ ЗУБЬЕВ КОЛЕСА ВНУТРЕННЕГО
C OCR: "ЗАЩЕПЛЕНИЯ ПО" -> "ЗАЦЕПЛЕНИЯ ПО"
C ЗАЦЕПЛЕНИЯ ПО УСЛОВИЮ ИНТЕРФЕРЕНЦИИ ЗУБЬЕВ.
C SHEMA — ОБОЗНАЧЕНИЕ СХЕМЫ ПЛАНЕТАРНОГО РЕДУКТОРА.
      INTEGER P, Q, Z1MIN, Z1MAX, ZKRN, ZKRW, DZ, SHEMA, COT,
     *COK, CO, C1, Z1, Z2, Z3, Z4
      COMMON/ZUB/ZKRN, ZKRW, DZ, Z1, Z2, Z3, Z4
      COT = Z1MIN * IABS(P)/(KS * Q)
      COK = Z1MAX * IABS(P)/(KS * Q)
      CO = COT
1     C1 = (KS * CO * Q)/IABS(P)
      IF(C1 - Z1MIN) 3, 2, 2
2     IF((C1 * IABS(P) - KS * Q * CO).NE.0) GO TO 3
      Z1 = C1
      IF(SHEMA.EQ.2) GO TO 4
      IF(SHEMA.EQ.3) GO TO 5
      Z2 = (Z1 * (P * L3 - Q * L3 - Q * L2))/(Q * (L2 + L3))
      Z2 = IABS(Z2)
      Z3 = Z2 * L3/L2
      Z4 = Z1 * L3 * (P - Q)/(L2 * Q)
      PRINT 20, COT, COK, CO, C1, Z1, Z2, Z3, Z4, SHEMA
20    FORMAT(1X, 9I10)
      IF((L2 - L3).NE.0) GO TO 7
      IF((Z2 - ZKRN).LT.0) GO TO 3
7     IF((Z3 - ZKRN).LT.0) GO TO 3
      IF((Z4 - ZKRW).LT.0) GO TO 3
4     Z2 = (Z1 * (P * L3 - Q * L3 + Q * L2))/(Q * (L3 - L2))
      Z2 = IABS(Z2)
      Z3 = Z2 * L3/L2
      Z4 = (Z1 * L3 * (Q - P))/(L2 * Q)
      PRINT 20, COT, COK, CO, C1, Z1, Z2, Z3, Z4, SHEMA
C OCR: "ZKRH" -> "ZKRN"
      IF((Z2 - ZKRN).LT.0) GO TO 3
C OCR: "ZKRH" -> "ZKRN"
      IF((Z3 - ZKRN).LT.0) GO TO 3
      IF((Z4 - ZKRN).LT.0) GO TO 3
      GO TO 6
5     Z2 = (Z1 * (P * L3 - Q * L3 + Q * L2))/(Q * (L2 - L3))
      Z2 = IABS(Z2)
      Z3 = Z2 * L3/L2
      PRINT 20, COT, COK, CO, C1, Z1, Z2, Z3, Z4, SHEMA
      IF((Z1 - ZKRW).LT.0) GO TO 3
      IF((Z2 - ZKRN).LT.0) GO TO 3
      IF((Z1 - Z2).LT.DZ) GO TO 3
      IF((Z4 - ZKRW).LT.0) GO TO 3
      IF((Z3 - ZKRN).LT.0) GO TO 3
      IF((Z4 - Z3).LT.DZ) GO TO 3
      GO TO 6
3     CO = CO + 1
      IF((CO - COK).LE.0) GO TO 1
      WRITE(3, 10)
10    FORMAT(1X, 'ПРИ ЗАДАНЫХ УСЛОВИЯХ ПОДБОР ЧИСЕЛ'
     *'ЗУБЬЕВ НЕВОЗМОЖЕН')
      RETURN
C OCR: "Z2, Z3, Z3, KS" -> "Z2, Z3, Z4, KS"
6     WRITE(3, 11)SHEMA, Z1, Z2, Z3, Z4, KS
C OCR: "РЕДУКТОРА/'" -> "РЕДУКТОРА'/"; "11/" -> "I1/"; "' Z1 = I, 13.' Z3 = ', 13." -> "' Z1 = ', I3, ' Z2 = ', I3, ' Z3 = ', I3," (the Z2 item lost; uncertain); "13/" -> "I3/"; "12)" -> "I2)"
11    FORMAT(1X, 'ЧИСЛА ЗУБЬЕВ ПЛАНЕТАРНОГО РЕДУКТОРА'/
     *1X, 'SHEMA =', I1/' Z1 = ', I3, ' Z2 = ', I3, ' Z3 = ', I3,
     *' Z4 = ', I3/
     *'КОЛИЧЕСТВО БЛОКОВ САТЕЛЛИТОВ KS = ', I2)
      RETURN
      END
