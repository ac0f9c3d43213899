C LISTING V.1 DKLCHK: BELOKONEV 1990, BOOK LINES L3053-3100
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DKLCHK(N, PRM, VLST, AKSLRT)
C ОПРЕДЕЛЕНИЕ ОСНОВНЫХ РАЗМЕРОВ КУЛАЧКОВОГО МЕХАНИЗМА.
C ПЕРЕД ОБРАЩЕНИЕМ ОПИСАТЬ МАССИВЫ:
C PRM(N) — ПЕРЕМЕЩЕНИЕ ТОЛКАТЕЛЯ.
C VLST(N) — СКОРОСТЕЙ ТОЛКАТЕЛЯ.
C AKSLRT(N) — УСКОРЕНИЕ ТОЛКАТЕЛЯ.
C N — РАЗМЕРНОСТЬ МАССИВОВ.
C ALD — УГОЛ ДАВЛЕНИЯ, БЕТА — УГОЛ, ПРИНИМАЕМЫЙ ИЗ УСЛОВИЯ НЕЗАКЛИНИВАНИЯ ТОЛКАТЕЛЯ (РАВЕН НУЛЮ ДЛЯ ЦЕНТРАЛЬНОГО МЕХАНИЗМА).
C W1 — УГЛОВАЯ СКОРОСТЬ КУЛАЧКА.
C RSCNTR — МЕЖЦЕНТРОВОЕ РАССТОЯНИЕ.
C RZMR — ДЛИНА ТОЛКАТЕЛЯ.
C RSCNTR, RZMR — ОПРЕДЕЛЯЮТСЯ ТОЛЬКО ДЛЯ МЕХАНИЗМА С КАЧАЮЩИМСЯ ТОЛКАТЕЛЕМ.
C INDEX = 1 — ПРИНИМАЕТСЯ ДЛЯ МЕХАНИЗМА С ПОСТУПАТЕЛЬНО
C ДВИЖУЩИМСЯ ТОЛКАТЕЛЕМ.
C INDEX = 2 — ДЛЯ МЕХАНИЗМА С КАЧАЮЩИМСЯ ТОЛКАТЕЛЕМ.
C РЕЗУЛЬТАТЫ: RO, EXCST — ДЛЯ INDEX = 1.
C RO, ETAO — ДЛЯ INDEX = 2
      REAL MKSMM, IFI
      COMMON/KLCHK/ALD, BETA, W1, RSCNTR, RZMR, INDEX, RO,
     *EXCST, ETAO
      DIMENSION PRM(N), VLST(N), AKSLRT(N)
      MKSMM = VLST(1)
      I = 1
      DO 10 K = 1,N
      I = I + 1
      IF(VLST(K) - MKSMM)10,10,11
11    MKSMM = VLST(K)
      L = I - 1
10    CONTINUE
      S = PRM(L)
      IFI = MKSMM/W1
      GO TO(20, 30), INDEX
20    RO = (IFI/TAN(ALD) - S) * SIN(ALD)/SIN(ALD + BETA)
      EXCST = RO * SIN(BETA)
      RETURN
30    ETAO = IFI/TAN(ALD) - S
      RO = SQRT(RSCNTR ** 2 + RZMR ** 2 - 2.0 * RSCNTR * RZMR *
     *COS(ETAO))
      RETURN
      END
