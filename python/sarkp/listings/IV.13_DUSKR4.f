C LISTING IV.13 DUSKR4: BELOKONEV 1990, BOOK LINES L2221-2273
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DUSKR4(RVBM, FIVBM, FIM, RVBN, FIVBN, FIN, WM,
C OCR: "AAA, ABVMR, BBVMR," -> "AAA, ABBMR, BBBMR,"
     *EM, WN, EN, ABBMK, BBBMK, ABBNK, BBBNK, AAA, ABBMR, BBBMR,
     *ABBNR, BBBNR, AB, BB)
C ОПРЕДЕЛЕНИЕ УСКОРЕНИЙ ЗВЕНЬЕВ СТРУКТУРНЫХ ГРУПП 4-ГО
C ВИДА.
C RVBM, FIVBM, RVBN, FIVBN — РАДИУСЫ-ВЕКТОРЫ И НАПРАВЛЯ-
C ЮЩИЕ УГЛЫ ТОЧКИ В ОТНОСИТЕЛЬНО МГНОВЕННЫХ ЦЕНТРОВ
C ВРАЩЕНИЯ ЗВЕНЬЕВ М И N.
C FIM, WM, EN И FMN, WN, EN — ЗАКОНЫ ДВИЖЕНИЯ ЗВЕНЬЕВ М И N.
C ABBMK, BBBMK, ABBNK, BBBNK — КОРИОЛИСОВЫ УСКОРЕНИЯ ДЛЯ
C ЗВЕНЬЕВ 2 И 3.
      COMMON/PRMTR/PI, PID2
      DIMENSION X(2, 2), Y(2)
      ABN = RVBN * SQRT(WN ** 4 + EN ** 2)
      ABM = RVBM * SQRT(WM ** 4 + EM ** 2)
      IF(EM.EQ.0.0)GO TO 1
      DLT = PID2 + ATAN(WM ** 2/ABS(EM))
      GO TO 2
1     DLT = PID2
2     BBM = DUGL3(FIVBM, PID2 + DLT, EM)
      IF(EN.EQ.0.0)GO TO 3
      DLTA = PID2 + ATAN(WN ** 2/ABS(EN))
      GO TO 4
3     DLTA = PID2
4     BBN = DUGL3(FIVBN, PID2 + DLTA, EN)
C OCR: "8     X(1, 1)" -> "      X(1, 1)" (a stray label; ERRATA E-DUSKR4-6)
      X(1, 1) = COS(FIM)
      X(1, 2) = -COS(FIN)
      X(2, 1) = SIN(FIM)
      X(2, 2) = -SIN(FIN)
      Y(1) = ABN * COS(BBN) + ABBNK * COS(BBBNK) - ABM * COS(BBM)
     *- ABBMK * COS(BBBMK)
      Y(2) = ABN * SIN(BBN) + ABBNK * SIN(BBBNK) - ABM * SIN(BBM) -
     *ABBMK * SIN(BBBMK)
      CALL GELG(Y, X, 2, 1, 0.0001, IER)
      BBBMR = DUGL4(FIM, PI, Y(1))
C OCR: "ABBMK = ABS(Y(1))" -> "ABBMR = ABS(Y(1))" (ERRATA E-DUSKR4-4)
      ABBMR = ABS(Y(1))
      BBBNR = DUGL4(FIN, PI, Y(2))
      ABBNR = ABS(Y(2))
C OCR: "DSMVKT(ABM, BVM," -> "DSMVKT(ABM, BBM,"
      CALL DSMVKT(ABM, BBM, ABBMK, BBBMK, A, B)
      CALL DSMVKT(A, B, ABBMR, BBBMR, AB, BB)
      RETURN
      END
