C LISTING V.3 DPRFPL: BELOKONEV 1990, BOOK LINES L3213-3257
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DPRFPL(N, GAMMA, W, FI, A, V, S, XA, YA, R1,
     *DELTA, ROK, RKSH)
C СИНТЕЗ ПРОФИЛЯ КУЛАЧКА МЕХАНИЗМА С ПОСТУПАТЕЛЬНО
C ДВИЖУЩИМСЯ ПЛОСКИМ ТОЛКАТЕЛЕМ.
C ПРИ ОБРАЩЕНИИ ОПИСАТЬ МАССИВЫ:
C A(N) — УСКОРЕНИЯ, V(N) — СКОРОСТИ, S(N) — ПЕРЕМЕЩЕНИЯ
C ТОЛКАТЕЛЯ.
C N — РАЗМЕРНОСТЬ МАССИВОВ, W — УГЛОВАЯ СКОРОСТЬ
C КУЛАЧКА.
C GAMMA — ПРОЕКТИРОВОЧНЫЙ УГОЛ, БОЛЬШИЙ PI/4.
C РЕЗУЛЬТАТЫ:
C RKSH — РАДИУС КУЛАЧКОВОЙ ШАЙБЫ.
C XA(N), YA(N) — КООРДИНАТЫ ПРОФИЛЯ В ДЕКАРТОВЫХ
C КООРДИНАТАХ.
C R1(N), DELTA(N) — КООРДИНАТЫ ПРОФИЛЯ В ПОЛЯРНЫХ
C КООРДИНАТАХ.
C ROK(N) — РАДИУСЫ КРИВИЗНЫ ТОЧЕК ПРОФИЛЯ КУЛАЧКА, ДЛЯ
C КОТОРЫХ ВЫЧИСЛЯЮТСЯ КООРДИНАТЫ.
      REAL MNMM
      DIMENSION FI(N), A(N), V(N), S(N), XA(N), YA(N), R1(N),
     *DELTA(N), ROK(N)
      I = 0
      MNMM = A(1)
      DO 10 K = 1, N
      I = I + 1
      IF(A(K).GE.MNMM) GO TO 10
      MNMM = A(K)
      L = I
10    CONTINUE
      D2SDFI = MNMM/W ** 2
      RKSH = ABS(-(D2SDFI/TAN(GAMMA) + S(L)))
      DO 11 K = 1, N
      DSDFI = V(K)/W
      D2SDFI = A(K)/W ** 2
      XA(K) = (RKSH + S(K)) * SIN(FI(K)) + DSDFI * COS(FI(K))
      YA(K) = (RKSH + S(K)) * COS(FI(K)) - DSDFI * SIN(FI(K))
      R1(K) = SQRT((RKSH + S(K)) ** 2 + DSDFI ** 2)
      DELTA(K) = ATAN(XA(K)/YA(K))
      ROK(K) = RKSH + S(K) + D2SDFI
11    CONTINUE
      RETURN
      END
