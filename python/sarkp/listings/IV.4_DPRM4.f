C LISTING IV.4 DPRM4: BELOKONEV 1990, BOOK LINES L1622-1655
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DPRM4(XVM, YVM, XA, YA, FIM, XVN, YVN, XC, YC,
     *FIN, RZ2, T2, RZ3, T3, AAA, XB, YB, RVBM, FIVBM, RVBN, FIVBN)
C ОПРЕДЕЛЕНИЕМ ЛИНЕЙНЫХ КООРДИНАТ ЗВЕНЬЕВ СТРУКТУРНОЙ
C ГРУППЫ 4-ГО ВИДА.
C XVM, YVM И XVN, YVN — КООРДИНАТЫ МГНОВЕННЫХ ЦЕНТРОВ
C ВРАЩЕНИЯ ЗВЕНЬЕВ С НАПРАВЛЯЮЩИМИ М И N.
C XA, YA, FIM И XC, YC, FIN — КООРДИНАТЫ НАПРАВЛЯЮЩИХ М И N.
C RZ2, T2 И RZ3, T3 — ЛИНЕЙНЫЕ И УГЛОВЫЕ РАЗМЕРЫ ЗВЕНЬЕВ
C 2 И 3.
C RVBM, FIVBM, RVBN, FIVBN — РАДИУСЫ—ВЕКТОРЫ ТОЧКИ В ОТ
C МГНОВЕННЫХ ЦЕНТРОВ И ИХ НАПРАВЛЯЮЩИЕ УГЛЫ,
      COMMON/PRMTR/PI,PID2
      DIMENSION X(2, 2), Y(2)
C OCR: "X(1, 1) = 1, 0" -> "X(1, 1) = 1.0"
      X(1, 1) = 1.0
      X(1, 2) = TAN(FIM)
C OCR: "X(2, 1) = 1, 0" -> "X(2, 1) = 1.0"
      X(2, 1) = 1.0
      Y(1) = YA + RZ2 * SIN(T2)/COS(FIM) - TAN(FIM) * XA
      Y(2) = YC + RZ3 * SIN(T3)/COS(FIN) - TAN(FIN) * XC
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      YB = Y(1)
      XB = Y(2)
      RVBM = SQRT((XB - XVM) ** 2 + (YB - YVM) ** 2)
      FIV = DUGL2(XVM, YVM, XB, YB)
      FIVBM = DUGOL(FIV)
      RVBN = SQRT((XB - XVN) ** 2 + (YB - YVN) ** 2)
      FIV = DUGL2(XVN, YVN, XB, YB)
      FIVBN = DUGOL(FIV)
      RETURN
      END
