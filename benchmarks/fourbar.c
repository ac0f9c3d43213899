/* fourbar.c -- the hand-written C baseline of bench_kinematics.py (issue 9).
 *
 * Full kinematics of a crank-rocker four-bar (crank OA about O = (0, 0), RRR group A-B-C,
 * C fixed), at n crank angles phi[i], crank speed w1 constant (eps1 = 0).  The outputs are
 * the book's (DKNMA1's) polar outputs, so that the work compared is the same:
 *   out[0..11][i] = FI2, FI3, XB, YB, W2, W3, E2, E3, VB, ALB, AB, BB
 * (angles in [0, 2*pi) as the book's DUGOL gives them).  B is on the left of A -> C, the
 * branch of DPRM1's P = -1 (DKNMA1's P = +1) and of the mpmath reference.
 *
 * Method: closed-form circle intersection (one division, one square root), Cramer's rule
 * for the two 2x2 systems (velocities, accelerations: the same matrix), one sincos per
 * position, atan2/hypot only for the polar outputs.  level 1: positions only, 2: and
 * velocities, 3: and accelerations (the outputs of the levels not computed are left as
 * they are).  A position where the links do not reach gets NaN and status 1.
 *
 * Built by bench_kinematics.py: cc -O3 -march=native -shared -fPIC fourbar.c -lm.
 */
#include <math.h>

static double angle0(double y, double x)      /* atan2 in [0, 2*pi) */
{
    double a = atan2(y, x);
    return a < 0.0 ? a + 2.0 * M_PI : a;
}

int fourbar(long n, int level, const double *phi, double roa, double rab, double rcb,
            double xc, double yc, double w1, double *out)
{
    double *fi2 = out, *fi3 = out + n, *xb = out + 2 * n, *yb = out + 3 * n,
           *w2 = out + 4 * n, *w3 = out + 5 * n, *e2 = out + 6 * n, *e3 = out + 7 * n,
           *vb = out + 8 * n, *alb = out + 9 * n, *ab = out + 10 * n, *bb = out + 11 * n;
    const double d2 = rab * rab - rcb * rcb, rab2 = rab * rab;
    int bad = 0;
    for (long i = 0; i < n; i++) {
        double s = sin(phi[i]), c = cos(phi[i]);           /* one sincos */
        double xa = roa * c, ya = roa * s;
        double dx = xc - xa, dy = yc - ya, l2 = dx * dx + dy * dy;
        double k1 = 0.5 * (l2 + d2) / l2, h2 = rab2 / l2 - k1 * k1;
        if (!(h2 >= 0.0)) {
            fi2[i] = fi3[i] = xb[i] = yb[i] = NAN;
            bad = 1;
            continue;
        }
        double k2 = sqrt(h2);
        double ux = k1 * dx - k2 * dy, uy = k1 * dy + k2 * dx;     /* B - A */
        double x = xa + ux, y = ya + uy;
        double wx = x - xc, wy = y - yc;                            /* B - C */
        xb[i] = x;
        yb[i] = y;
        fi2[i] = angle0(uy, ux);
        fi3[i] = angle0(wy, wx);
        if (level < 2)
            continue;
        /* vA + w2 k x u = w3 k x w:  [-uy wy; ux -wx] (w2, w3) = -vA */
        double det = uy * wx - ux * wy;
        double vax = -w1 * ya, vay = w1 * xa;
        double om2 = (vax * wx + wy * vay) / det, om3 = (uy * vay + vax * ux) / det;
        double vbx = -om3 * wy, vby = om3 * wx;
        w2[i] = om2;
        w3[i] = om3;
        vb[i] = hypot(vbx, vby);
        alb[i] = angle0(vby, vbx);
        if (level < 3)
            continue;
        /* aA + e2 k x u - w2^2 u = e3 k x w - w3^2 w, aA = -w1^2 (xa, ya) */
        double rx = w1 * w1 * xa + om2 * om2 * ux - om3 * om3 * wx,
               ry = w1 * w1 * ya + om2 * om2 * uy - om3 * om3 * wy;
        double ep2 = -(rx * wx + wy * ry) / det, ep3 = -(uy * ry + rx * ux) / det;
        double abx = -ep3 * wy - om3 * om3 * wx, aby = ep3 * wx - om3 * om3 * wy;
        e2[i] = ep2;
        e3[i] = ep3;
        ab[i] = hypot(abx, aby);
        bb[i] = angle0(aby, abx);
    }
    return bad;
}
