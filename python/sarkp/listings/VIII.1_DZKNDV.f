C LISTING VIII.1 DZKNDV: BELOKONEV 1990, BOOK LINES L5935-5990
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DZKNDV(M, ZM, W1, ISC, MPR, ISPR, AAA, AS, ASUM,
     *EV, DEC, WPR, EPR)
C ОПРЕДЕЛЕНИЕ ЗАКОНА ДВИЖЕНИЯ ЗВЕНА ПРИВЕДЕНИЯ
C MPR, ISPR — МАССИВЫ ЗНАЧЕНИЙ МОМЕНТА ПРИВЕДЕННОЙ СИЛЫ
C И ПРИВЕДЕННОГО МОМЕНТА ИНЕРЦИИ.
C AS, ASUM, EV — МАССИВЫ ЗНАЧЕНИЙ РАБОТЫ СИЛ СОПРОТИВЛЕ-
C НИЯ, СУММАРНОЙ РАБОТЫ И КИНЕТИЧЕСКОЙ ЭНЕРГИИ
C ЗВЕНЬЕВ С ПЕРЕМЕННЫМ ПРИВЕДЕННЫМ МОМЕНТОМ ИНЕРЦИИ
C WPR, EPR — МАССИВЫ ЗНАЧЕНИЙ УГЛОВОЙ СКОРОСТИ И
C УГЛОВОГО УСКОРЕНИЯ ЗВЕНА ПРИВЕДЕНИЯ.
C M, ZM — РАЗМЕРНОСТЬ МАССИВОВ В РАЗНЫХ ФОРМАХ ЗАПИСИ.
C W1 — СРЕДНЯЯ СКОРОСТЬ ЗВЕНА ПРИВЕДЕНИЯ.
C ISC — ПОСТОЯННАЯ СОСТАВЛЯЮЩАЯ ПРИВЕДЕННОГО МОМЕНТА
C ИНЕРЦИИ МЕХАНИЗМА.
      REAL MPR, ISPR, ISC
      DIMENSION MPR(M), ISPR(M), AS(M), ASUM(M), EV(M),
     *DEC(M), WPR(M), EPR(M)
      PI = 3.14159
      H = 2.0 * PI / (ZM - 1.0)
      CALL DINTGR(M, H, 2, MPR, AS)
      DAD = AS(M) / (ZM - 1.0)
      Z = -1.0
      DO 5 K = 1, M
      Z = Z + 1.0
      ASUM(K) = AS(K) - DAD * Z
      EV(K) = ISPR(K) * W1 ** 2/2.0
      DEC(K) = ASUM(K) - EV(K)
5     CONTINUE
      DDD = DEC(1)
      DO 6 K = 1, M
      DEC(K) = DEC(K) - DDD
6     CONTINUE
      C1 = DEC(1)
      C2 = DEC(1)
      DO 7 K = 2, M
      C1 = AMAX1(C1, DEC(K))
      C2 = AMIN1(C2, DEC(K))
7     CONTINUE
      DECSR = (C1 + C2)/2.0
      DO 8 K = 1, M
      WPR(K) = W1 + (DEC(K) - DECSR)/W1/ISC
8     CONTINUE
      CALL DFRNCL(M, H, EPR, WPR)
      RETURN
      END
