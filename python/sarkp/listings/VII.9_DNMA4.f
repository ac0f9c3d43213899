C LISTING VII.9 DNMA4: BELOKONEV 1990, BOOK LINES L5415-5460
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C NOTE: no heading printed; the number is Table 33's
      SUBROUTINE DNMA4(FIM, ETA2, FIN, ETA3, BS2, BS3, M2, Q2,
     *G2, M3, Q3, G3, RA, HA, GA, RB, GB, RC, HC, GC)
C ОПРЕДЕЛЕНИЕ РЕАКЦИЙ В КИНЕМАТИЧЕСКИХ ПАРАХ
C СТРУКТУРНОЙ ГРУППЫ ЧЕТВЕРТОГО ВИДА.
C FIM, ETA2, FIN, ETA3 — УГЛЫ ОРИЕНТАЦИИ НАПРАВЛЯЮЩИХ
C ЗВЕНЬЕВ 2 И 3 И ИХ УГЛОВЫЕ РАЗМЕРЫ.
C BS2, BS3 — РАССТОЯНИЯ ОТ ЦЕНТРА ПРОМЕЖУТОЧНОГО ШАРНИРА
C ДО ТОЧЕК ПРИВЕДЕНИЯ СИЛ ЗВЕНЬЕВ 2 И 3.
C M2, Q2, G2 И M3, Q3, G3 — МОМЕНТЫ И РАВНОДЕЙСТВУЮЩИЕ
C ВНЕШНИХ СИЛ, ДЕЙСТВУЮЩИХ НА ЗВЕНЬЯ 2 И 3.
C РЕЗУЛЬТАТ RA, HA, RB, HB, RC, HC.
      REAL M2, M3
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2, 2), Y(2)
      X(1, 1) = COS(FIM + PID2)
      X(1, 2) = COS(FIN + PID2)
      X(2, 1) = SIN(FIM + PID2)
      X(2, 2) = SIN(FIN + PID2)
      Y(1) = -(Q2 * COS(G2) + Q3 * COS(G3))
      Y(2) = -(Q2 * SIN(G2) + Q3 * SIN(G3))
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      RA = ABS(Y(1))
      GA = DUGL3(FIM, PID2, Y(1))
      RC = ABS(Y(2))
      GC = DUGL3(FIN, PID2, Y(2))
      SM = M2 + Q2 * COS(G2) * BS2 * SIN(PI + FIM + ETA2) - Q2 *
     *SIN(G2) * BS2 * COS(PI + FIM + ETA2)
      HA = -SM/RA
      SM = M3 + Q3 * COS(G3) * BS3 * SIN(PI + FIN + ETA3) - Q3 *
     *SIN(G3) * BS3 * COS(PI + FIM + ETA3)
      HC = -SM/RC
      RX = -(RA * COS(GA) + Q2 * COS(G2))
      RY = -(RA * SIN(GA) + Q2 * SIN(G2))
      RB = SQRT(RX ** 2 + RY ** 2)
      GB = DUGL5(RX, RY)
      RETURN
      END
