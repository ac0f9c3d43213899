/* DZKNDV's formula (corrected mode), hand-written: the reference loop of
   bench_dynamics.py.  The trapezoid work AS, ASUM (the cycle's work removed), EV, DEC,
   E0 in closed form from the two points where DEC has its extremes, one pass that
   computes WPR and finds its extremes (the check), EPR by backward differences.
   Returns 0, or 1 when WPR's extremes are not at DEC's (then the caller would iterate;
   never on the benchmark's cases) or there is no real root (a stall). */
#include <math.h>

int dzkndv(int m, double w1, double isc, const double *mpr, const double *ispr,
           double *as, double *asum, double *ev, double *dec, double *wpr,
           double *epr)
{
    const double h = 2.0 * M_PI / (m - 1), hh = 0.5 * h, hw = 0.5 * w1 * w1;
    as[0] = 0.0;
    for (int k = 1; k < m; k++) as[k] = as[k - 1] + hh * (mpr[k - 1] + mpr[k]);
    const double dad = as[m - 1] / (m - 1), ev1 = ispr[0] * hw;
    int k1 = 0, k2 = 0;
    double amin = 0.0;
    for (int k = 0; k < m; k++) {
        asum[k] = as[k] - dad * k;
        ev[k] = ispr[k] * hw;
        dec[k] = (asum[k] - ev[k]) + ev1;
        if (dec[k] > dec[k1]) k1 = k;
        if (dec[k] < dec[k2]) k2 = k;
        if (asum[k] < amin) amin = asum[k];
    }
    const double j1 = isc + ispr[k1], j2 = isc + ispr[k2];
    const double qa = j1 - j2, da = asum[k1] - asum[k2];
    const double disc = 16.0 * w1 * w1 * j1 * j2 + 8.0 * qa * da;
    if (!(disc >= 0.0)) return 1;
    const double d = -2.0 * (qa * w1 * w1 - 2.0 * da) / (2.0 * w1 * (j1 + j2) + sqrt(disc));
    const double e0 = 0.5 * ((0.5 * j1 * (w1 + d) * (w1 + d) - asum[k1])
                             + (0.5 * j2 * (w1 - d) * (w1 - d) - asum[k2]));
    if (e0 < -amin) return 1;
    double wmax = 0.0, wmin = INFINITY;
    for (int k = 0; k < m; k++) {
        double e = 2.0 * (e0 + asum[k]) / (isc + ispr[k]);
        wpr[k] = sqrt(e > 0.0 ? e : 0.0);
        wmax = wpr[k] > wmax ? wpr[k] : wmax;
        wmin = wpr[k] < wmin ? wpr[k] : wmin;
    }
    for (int k = 1; k < m; k++) epr[k] = (wpr[k] - wpr[k - 1]) / h;
    epr[0] = epr[1];
    return (wpr[k1] >= wmax && wpr[k2] <= wmin) ? 0 : 1;
}
