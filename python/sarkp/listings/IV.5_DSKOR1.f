C LISTING IV.5 DSKOR1: BELOKONEV 1990, BOOK LINES L1692-1719
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSKOR1(RZ2, FI2, RZ3, FI3, VA, ALA, VC, ALC, AAA,
     *VBA, ALBA, VBC, ALBC, VB, ALB, W2, W3)
C ОПРЕДЕЛЕНИЕ ЛИНЕЙНЫХ И УГЛОВЫХ СКОРОСТЕЙ ЗВЕНЬЕВ
C ГРУППЫ 1-ГО ВИДА.
C VA, ALA, VC, ALC — МОДУЛИ И НАПРАВЛЯЮЩИЕ УГЛЫ ВЕКТОРОВ
C СКОРОСТЕЙ ПРИСОЕДИНИТЕЛЬНЫХ ТОЧЕК.
C RZ2, FI2, RZ3, FI3 — РАЗМЕРЫ ЗВЕНЬЕВ И НАПРАВЛЯЮЩИЕ УГЛЫ.
C ИСПОЛЗУЮТСЯ ПОДПРОГРАММЫ GELG, DUGL3, DOMEGA, DSMVKT.
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2, 2), Y(2)
      X(1, 1) = COS(FI2 + PID2)
      X(1, 2) = -COS(FI3 + PID2)
      X(2, 1) = SIN(FI2 + PID2)
      X(2, 2) = -SIN(FI3 + PID2)
      Y(1) = VC * COS(ALC) - VA * COS(ALA)
      Y(2) = VC * SIN(ALC) - VA * SIN(ALA)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      ALBA = DUGL3(FI2, PID2, Y(1))
      VBA = ABS(Y(1))
      ALBC = DUGL3(FI3, PID2, Y(2))
      VBC = ABS(Y(2))
      CALL DSMVKT(VA, ALA, VBA, ALBA, VB, ALB)
      W2 = DOMEGA(RZ2, VBA, (ALBA - FI2))
      W3 = DOMEGA(RZ3, VBC, (ALBC - FI3))
      RETURN
      END
