C LISTING V.2 DPRFLP: BELOKONEV 1990, BOOK LINES L3149-3189
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: Table 33 spells it DPRFLD
      SUBROUTINE DPRFLP(N, RO, EXCNTR, W, FI, A, V, S, XA, YA, R1,
     *DELTA, ALFA, ROK)
C СИНТЕЗ ПРОФИЛЯ КУЛАЧКА С ПОСТУПАТЕЛЬНО ДВИЖУЩИМСЯ
C ТОЛКАТЕЛЕМ.
C ПРИ ОБРАЩЕНИИ ОПИСАТЬ МАССИВЫ:
C A(N) — УСКОРЕНИЯ, V(N) — СКОРОСТИ, S(N) — ПЕРЕМЕЩЕНИЯ
C ТОЛКАТЕЛЯ.
C ОСНОВНЫЕ РАЗМЕРЫ МЕХАНИЗМА:
C RO — РАДИУС КУЛАЧКОВОЙ ШАЙБЫ, EXCNTR — ЭКСЦЕНТРИСИТЕТ;
C ДВИЖЕНИЕ КУЛАЧКА:
C FI(N) — УГЛЫ ПОВОРОТА КУЛАЧКА,
C W — УГЛОВАЯ СКОРОСТЬ КУЛАЧКА.
C РЕЗУЛЬТАТЫ:
C XA(N), YA(N) — КООРДИНАТЫ ПРОФИЛЯ В ДЕКАРТОВЫХ
C КООРДИНАТАХ,
C R1(N), DELTA(N) — КООРДИНАТЫ ПРОФИЛЯ В ПОЛЯРНЫХ
C КООРДИНАТАХ,
C ALFA(N), ROK(N) — УГЛЫ ДАВЛЕНИЯ И РАДИУСЫ КРИВИЗНЫ
C В ТОЧКАХ ПРОФИЛЯ, ДЛЯ КОТОРЫХ ВЫЧИСЛЯЮТСЯ
C КООРДИНАТЫ.
C OCR: "R1(N), *DELTA(N)," -> "R1(N), DELTA(N)," (a stray continuation mark)
      DIMENSION FI(N), A(N), V(N), S(N), XA(N), YA(N), R1(N), DELTA(N),
     *ALFA(N), ROK(N)
      DO 5 K = 1, N
      D2SDFI = V(K)/W
      DSDFI = A(K)/W ** 2
      XA(K) = EXCNTR * COS(FI(K)) + (RO + S(K)) * SIN(FI(K))
      YA(K) = -EXCNTR * SIN(FI(K)) + (RO + S(K)) * COS(FI(K))
      R1(K) = SQRT(XA(K) ** 2 + YA(K) ** 2)
      DELTA(K) = ATAN(XA(K)/YA(K))
      ALFA(K) = ATAN((DSDFI - EXCNTR)/(RO + S(K)))
      C = RO + S(K)
      OMEGA = (C * COS(ALFA(K)) + DSDFI * SIN(ALFA(K)) * (COS(ALFA
C OCR: "** - D 2 SDFI * (COS(ALFA(K)))/C ** 2" -> "** 2 - D2SDFI * (COS(ALFA(K))) ** 3)/C ** 2" (exponents and a parenthesis lost)
     *(K))) ** 2 - D2SDFI * (COS(ALFA(K))) ** 3)/C ** 2
      ROK(K) = 1.0/OMEGA
5     CONTINUE
      RETURN
      END
