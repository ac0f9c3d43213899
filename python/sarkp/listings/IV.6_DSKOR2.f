C LISTING IV.6 DSKOR2: BELOKONEV 1990, BOOK LINES L1740-1772
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSKOR2(VA, ALA, VBM, ALBM, RZ2, FI2, FIM, AAA,
     *VBBM, ALBBM, VB, ALB, W2)
      COMMON/PRMTR/PI, PID2
C ОПРЕДЕЛЕНИЕ СКОРОСТЕЙ ЗВЕНЬЕВ СТРУКТУРНОЙ ГРУППЫ
C 2-ГО ВИДА.
C VA, ALA, ALBM — ВЕКТОРЫ СКОРОСТЕЙ И НАПРАВЛЯЮЩИЕ
C УГЛЫ ДЛЯ ПРИСОЕДИНИТЕЛЬНЫХ ЭЛЕМЕНТОВ.
C RZ2, FI2, FIM — ДЛИНА И НАПРАВЛЯЮЩИЙ УГОЛ ЗВЕНА 2, УГОЛ
C НАПРАВЛЯЮЩЕЙ.
      DIMENSION X(2, 2), Y(2)
      X(1, 1) = COS(FI2 + PID2)
      X(1, 2) = -COS(FIM)
      X(2, 1) = SIN(FI2 + PID2)
      X(2, 2) = -SIN(FIM)
      Y(1) = VBM * COS(ALBM) - VA * COS(ALA)
      Y(2) = VBM * SIN(ALBM) - VA * SIN(ALA)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      ALBA = DUGL3(FI2, PID2, Y(1))
      VBA = ABS(Y(1))
      ALBBM = DUGL4(FIM, PI, Y(2))
      VBBM = ABS(Y(2))
C OCR: "DOMECA" -> "DOMEGA"
      W2 = DOMEGA(RZ2, VBA, ALBA - FI2)
      CALL DSMVKT(VA, ALA, VBA, ALBA, VB, ALB)
      RETURN
      END
