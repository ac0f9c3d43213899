C LISTING V.4 DPRFLK: BELOKONEV 1990, BOOK LINES L3270-3320
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "DPRFLK(N, W1, ETAO, F1, RO," -> "DPRFLK(N, W1, ETAO, FI, RO,"
      SUBROUTINE DPRFLK(N, W1, ETAO, FI, RO, L, R, E2, W2, PSI,
     *XA, YA, R1, DELTA, RKRZVN, ALFA)
C СИНТЕЗ ПРОФИЛЯ КУЛАЧКА МЕХАНИЗМА С КАЧАЮЩИМСЯ
C ТОЛКАТЕЛЕМ.
C ПРИ ОБРАЩЕНИИ ОПИСАТЬ МАССИВЫ:
C FI(N) — УГЛЫ ПОВОРОТА КУЛАЧКА, E2(N) — УГЛОВЫЕ УСКОРЕНИЯ
C ТОЛКАТЕЛЯ, W2(N) — УГЛОВЫЕ СКОРОСТИ ТОЛКАТЕЛЯ.
C OCR: "RSI(N) —" -> "PSI(N) —"
C PSI(N) — УГЛОВЫЕ ПЕРЕМЕЩЕНИЯ ТОЛКАТЕЛЯ.
C N — РАЗМЕРНОСТЬ МАССИВОВ, W1 — УГЛОВАЯ СКОРОСТЬ
C КУЛАЧКА.
C RO, L, R — РАДИУС КУЛАЧКОВОЙ ШАЙБЫ, МЕЖСОСЕВЫЕ
C РАССТОЯНИЯ И ДЛИНА ТОЛКАТЕЛЯ СООТВЕТСТВЕННО.
C ETAO — НАЧАЛЬНОЕ ПОЛОЖЕНИЕ ТОЛКАТЕЛЯ.
C РЕЗУЛЬТАТЫ:
C XA, YA — КООРДИНАТЫ ПРОФИЛЯ КУЛАЧКА В ДЕКАРТОВЫХ
C КООРДИНАТАХ.
C R1, DELTA — КООРДИНАТЫ ПРОФИЛЯ КУЛАЧКА В ПОЛЯРНЫХ
C КООРДИНАТАХ.
C ALFA — УГЛЫ ДАВЛЕНИЯ В ТОЧКАХ ПРОФИЛЯ, ДЛЯ КОТОРЫХ
C ВЫЧИСЛЯЮТСЯ КООРДИНАТЫ.
C RKRZVN — РАДИУСЫ КРИВИЗНЫ В ЭТИХ ТОЧКАХ.
      REAL L
      DIMENSION FI(N), E2(N), W2(N), PSI(N), XA(N), YA(N), R1(N),
     *DELTA(N), ALFA(N), RKRZVN(N)
      DO 10 K = 1, N
      DPSIFI = W2(K)/W1
      D2PSIF = E2(K)/W1 ** 2
      XA(K) = L * COS(FI(K)) - R * COS(FI(K) + (PSI(K) + ETAO))
      YA(K) = -L * SIN(FI(K)) + R * SIN(FI(K) + (PSI(K) + ETAO))
      R1(K) = SQRT(L ** 2 - 2 * L * R * COS(PSI(K) + ETAO) + R ** 2)
      DELTA(K) = ATAN(XA(K)/YA(K))
      ALFA(K) = ATAN(R * (1.0 + DPSIFI)/L/SIN(PSI(K) + ETAO) -
     *1.0/TAN(PSI(K) + ETAO))
      C1 = (L ** 2 + R ** 2 * (1.0 + DPSIFI) ** 2 - 2.0 * L * R * (1 +
C OCR: "*DPSIFI) * COS(PSI(K) + COS(PSI(K) + ETAO)) ** (3.0/2.0))" -> "*DPSIFI) * COS(PSI(K) + ETAO)) ** (3.0/2.0)" (ERRATA E-DPRFLK-2)
     *DPSIFI) * COS(PSI(K) + ETAO)) ** (3.0/2.0)
      C2 = L ** 2 + R ** 2 * (1.0 + DPSIFI) ** 3 - L * R * (COS(PSI(K) +
     *ETAO) * (1.0 + DPSIFI) * (2.0 + DPSIFI) + D2PSIF * SIN(PSI(K) +
     *ETAO))
      RKRZVN(K) = C1/C2
10    CONTINUE
      RETURN
      END
