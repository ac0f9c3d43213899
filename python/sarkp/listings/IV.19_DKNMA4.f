C LISTING IV.19 DKNMA4: BELOKONEV 1990, BOOK LINES L2831-2927
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
C OCR: "RZ2, ETA2, RZ3" -> "RZ2, ETA2, RZ3,"
      SUBROUTINE DKNMA4(FIM, XA, YA, FIN, XC, YC, RZ2, ETA2, RZ3,
C OCR: "WM, MN, EM" -> "WM, WN, EM"
     *ETA3, WM, WN, EM, EN, ANALOG, XB, YB, VB2R, ALB2R, VB3R, ALB3R,
C OCR: "AB3R, BB3R, AB, BB" -> "AB3R, BB3R, AB, BB)"
     *VB, ALB, AB2K, BB2K, AB3K, BB3K, AB2R, BB2R, AB3R, BB3R, AB, BB)
      COMMON/PRMTR/PI, PID2
C ПАМАЕТРЫ В ОПЕРАТОРЕ ДО ПЕРЕМЕННОЙ ANALOG ДОЛЖНЫ
C БЫТЬ ОПРЕДЕЛЕННЫ ДО ОБРАЩЕНИЯ К ПОДПРОГРАММЕ.
C ПОСЛЕ НЕЕ — РЕЗУЛЬТАТЫ РАБОТЫ ПОДПРОГРАММЫ.
C FIM, FIN — УГЛЫ ОРИЕНТАЦИИ НАПРАВЛЯЮЩИХ,
C ЗАКРЕПЛЕННЫХ НА ЗВЕНЬЯХ М, N.
C ЗАКОНЫ ДВИЖЕНИЯ ЭТИХ ЗВЕНЬЕВ ЗАДАЮТСЯ ЗНАЧЕНИЯМИ
C УГЛОВОЙ СКОРОСТИ W И УГЛОВОГО УСКОРЕНИЯ E
C С СООТВЕТСТВУЮЩИМИ ИНДЕКСАМИ.
C XA, YA И XC, YC — КООРДИНАТЫ ТОЧЕК ПЕРЕСЕЧЕНИЯ ОСЕЙ
C НАПРАВЛЯЮЩИХ ЗВЕНЬЕВ M И N С ОСЯМИ ЗВЕНЬЕВ 2 И 3.
C ИЛИ ТОЧЕК ЛЕЖАЩИХ НА ОСЯХ НАПРАВЛЯЮЩИХ.
C RZ, ETA — ЛИНЕЙНЫЕ И УГЛОВЫЕ РАЗМЕРЫ ЗВЕНЬЕВ.
C С — ЦЕНТР ШАРНИРА ВНУТРЕННЕЙ КИНЕМАТИЧЕСКОЙ ПАРЫ.
C R, K — ИНДЕКСЫ ОТНОСИТЕЛЬНОЙ И КОРИОЛИСОВОЙ
C СОСТАВЛЯЮЩИХ ВЕКТОРОВ.
      DIMENSION X(2, 2), Y(2)
      UK1 = TAN(FIM)
      UK2 = TAN(FIN)
      X(1,1) = 1.0
      X(1,2) = -UK1
      X(2,1) = 1.0
      X(2,2) = -UK2
      Y(1) = YA + RZ2 * SIN(ETA2)/COS(FIM) - UK1 * XA
      Y(2) = YC + RZ3 * SIN(ETA3)/COS(FIN) - UK2 * XC
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      XB = Y(2)
      YB = Y(1)
      RAB = SQRT((XB - XA) ** 2 + (YB - YA) ** 2)
      CB = SQRT((XB - XC) ** 2 + (YB - YC) ** 2)
      FI2 = DUGL2(XA, YA, XB, YB)
      FI3 = DUGL2(XC, YC, XB, YB)
      VBM = ABS(WM) * RAB
      ALBM = DUGL3(FI2, PID2, WM)
      VBN = ABS(WN) * CB
      ALBN = DUGL3(FI3, PID2, WN)
      X(1,1) = COS(FIM)
      X(1,2) = -COS(FIN)
      X(2,1) = SIN(FIM)
      X(2,2) = -SIN(FIN)
      Y(1) = VBN * COS(ALBN) - VBM * COS(ALBM)
      Y(2) = VBN * SIN(ALBN) - VBM * SIN(ALBM)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      VB2R = ABS(Y(1))
      ALB2R = DUGL4(FIM, PI, Y(1))
      VB3R = ABS(Y(2))
      ALB3R = DUGL4(FIN, PI, Y(2))
      VBX = VBM * COS(ALBM) + VB2R * COS(ALB2R)
      VBY = VBM * SIN(ALBM) + VB2R * SIN(ALB2R)
      VB = SQRT(VBX ** 2 + VBY ** 2)
      ALB = DUGL5(VBX, VBY)
      IF(ANALOG.EQ.1.0) RETURN
C OCR: "ABM = PAB *" -> "ABM = RAB *"
      ABM = RAB * SQRT(WM ** 4 + EM ** 2)
      ABN = CB * SQRT(WN ** 4 + EN ** 2)
      IF(WN.EQ.0.0)GO TO 5
      BBN = DUGL3(FI3, (PI - ATAN(ABS(EN)/WN ** 2)), EN)
      GO TO 6
5     BBN = 0.0
6     IF(WM.EQ.0.0)GO TO 7
      BBM = DUGL3(FI2, (PI - ATAN(ABS(EM)/WM ** 2)), EM)
      GO TO 8
7     BBM = 0.0
8     AB2K = 2.0 * VB2R * ABS(WM)
      AB3K = 2.0 * VB3R * ABS(WN)
      BB2K = DUGL3(ALB2R, PID2, WM)
      BB3K = DUGL3(ALB3R, PID2, WN)
      X(1,1) = COS(ALB2R)
      X(1,2) = -COS(ALB3R)
      X(2,1) = SIN(ALB2R)
      X(2,2) = -SIN(ALB3R)
C OCR: "COS(BBM) --" -> "COS(BBM) -"
      Y(1) = ABN * COS(BBN) + AB3K * COS(BB3K) - ABM * COS(BBM) -
     *AB2K * COS(BB2K)
      Y(2) = ABN * SIN(BBN) + AB3K * SIN(BB3K) - ABM * SIN(BBM) -
     *AB2K * SIN(BB2K)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      AB2R = ABS(Y(1))
      BB2R = DUGL4(ALB2R, PI, Y(1))
      AB3R = ABS(Y(2))
      BB3R = DUGL4(ALB3R, PI, Y(2))
      ABX = ABM * COS(BBM) + AB2K * COS(BB2K) + AB2R * COS(BB2R)
      ABY = ABM * SIN(BBM) + AB2K * SIN(BB2K) + AB2R * SIN(BB2R)
      AB = SQRT(ABX ** 2 + ABY ** 2)
      BB = DUGL5(VBX, VBY)
      RETURN
      END
