C LISTING III.6 DSNTZK: BELOKONEV 1990, BOOK LINES L1408-1437
C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".
      SUBROUTINE DSNTZK(KW3, S, H, Q, AAA, L1, LO, L3)
      PI = 3.14159
      REAL KW3, L1, LO, L3, LYAMDA
C ОПРЕДЕЛЕНИЕ РАЗМЕРОВ ЗВЕНЬЕВ КУЛИСНОГО МЕХАНИЗМА.
C ПРИ ОБРАЩЕНИИ К ПОДПРОГРАММЕ ОПРЕДЕЛИТЬ:
C KW3 — КОЭФФИЦИЕНТ ИЗМЕНЕНИЯ СРЕДНЕЙ СКОРОСТИ КУЛИСЫ.
C S — ХОД КУЛИСЫ,
C H — ЗАПАС ХОДА ПОЛЗУНА,
C OCR: "=θ.θ—" -> "=0.0—"
C Q =0.0— ПРИЗНАК ВРАЩАЮЩЕЙСЯ КУЛИСЫ,
C РЕЗУЛЬТАТ: L1 — ДЛИНА КРИВОШИПА,
C LO — МЕЖЦЕНТРОВОЕ РАССТОЯНИЕ, L3 — ДЛИНА КУЛИСЫ.
C OCR: "2.θ" -> "2.0"
      BETA = PI/2.0* ((KW3 - 1.)/(KW3 + 1.))
C OCR: "θ.θ" -> "0.0"
C OCR: ", EQ," -> ".EQ."
      IF(Q.EQ.0.0)GO TO 1
      LYAMDA = SIN(BETA)
C OCR: "2.θ" -> "2.0"
      L3 = S/(2.0* LYAMDA)
      GO TO 2
1     LYAMDA = 1./SIN(BETA)
      L3 = S/2.
2     LO = (L3 - H)/(1 + LYAMDA)
      L1 = LYAMDA * LO
C OCR: "AAA.NE.θ.θ" -> "AAA.NE.0.0"
      IF(AAA.NE.0.0)RETURN
      WRITE(3, 3)L1, LO, L3
3     FORMAT(1X, 'ДЛИНА КРИВОШИПА L1 = ', F6.4,
     *'МЕЖЦЕНТРОВОЕ РАССТОЯНИЕ LO = ', F6.4,
     *'ДЛИНА КУЛИСЫ L3 = ', F6.4)
      RETURN
      END
