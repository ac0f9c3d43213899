C LISTING IV.8 DSKOR4: BELOKONEV 1990, BOOK LINES L1879-1916
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSKOR4(RVBM, FIVBM, FIM, RVBN, FIVBN, FIN, WM,
C OCR: "AAA, VBVM, ALBVM, VBBN" -> "AAA, VBBM, ALBBM, VBBN" (ERRATA E-DSKOR4-1)
     *WN, AAA, VBBM, ALBBM, VBBN, ALBBN, VB, ALB)
C ОПРЕДЕЛЕНИЕ СКОРОСТЕЙ ЗВЕНЬЕВ СТРУКТУРНОЙ ГРУППЫ
C 4-ГО ВИДА.
C RVBM, FIVBM, RVBN, FIVBN — РАДИУСЫ-ВЕКТОРЫ
C И НАПРАВЛЯЮЩИЕ УГЛЫ ТОЧКИ В ОТНОСИТЕЛЬНО МГНОВЕННЫХ
C ЦЕНТРОВ ВРАЩЕНИЯ ЗВЕНЬЕВ М И N.
C FIM, FIN И WM, WN — УГЛЫ ОРИЕНТАЦИИ НАПРАВЛЯЮЩИХ М И N
C И ИХ УГЛОВЫЕ СКОРОСТИ.
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2, 2), Y(2)
      VBM = ABS(WM) * RVBM
C OCR: "ALBVM = DUGL3" -> "ALBM = DUGL3" (ERRATA E-DSKOR4-2)
      ALBM = DUGL3(FIVBM, PID2, WM)
      ALBN = DUGL3(FIVBN, PID2, WN)
      X(1, 1) = COS(FIM)
      X(1, 2) = -COS(FIN)
      X(2, 1) = SIN(FIM)
      X(2, 2) = -SIN(FIN)
C OCR: "—" -> "-"
      Y(1) = ABS(WM) * COS(ALBN) * RVBN - ABS(WM) * COS(ALBM) *
     *RVBM
C OCR: "—" -> "-"
      Y(2) = ABS(WN) * RVBN * SIN(ALBN) - ABS(WM) * RVBM * SIN(ALBM)
C OCR: "2, 1, 8, 0, 0, 1, IER" -> "2, 1, 0.0001, IER"
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      ALBBM = DUGL4(FIM, PI, Y(1))
      VBBM = ABS(Y(1))
      ALBBN = DUGL4(FIN, PI, Y(2))
      VBBN = ABS(Y(2))
      CALL DSMVKT(VBM, ALBM, VBBM, ALBBM, VB, ALB)
      RETURN
      END
