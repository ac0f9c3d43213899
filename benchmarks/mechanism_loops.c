/* mechanism_loops.c -- hand-written C baselines of bench_mechanism.py (issue 19).
 *
 * The same mechanisms as the benchmark's sarkp.Mechanism, with the same outputs in the same
 * layout (one array per quantity, position-major as the Mechanism returns them), written as
 * one would by hand: closed-form circle intersection, Cramer's rule, one sincos per
 * position, no error estimates, no status beyond "does not reach".
 *
 * sixbar: program X's six-bar (crank O-A, RRR group A-B-C with B on the left of A->C, the
 *   lever point D = C - (RCD/RCB)(B - C), RRP group D-E with E on the horizontal guide
 *   y = yg ahead of D's foot).  Outputs for the moving points A, B, D, E and the links
 *   crank, A-B, C-B, D-E, slider E:
 *     pos[i][4][2], vel[i][4][2], acc[i][4][2], dir[i][5][2] (cos, sin), om[i][5], ep[i][5]
 *   level 1: positions, 2: + velocities, 3: + accelerations.
 * fourbar_forces: the four-bar of benchmarks/fourbar.c's geometry with the crank massless,
 *   masses m2, m3 at S2 = A + f2 (B - A), S3 = C + f3 (B - C), inertias J2, J3, gravity g,
 *   a torque T3 on C-B: kinematics, then the RRR group's reactions by moments about B
 *   (a 2x2 system in R_B), the crank's balancing moment.  Outputs per position:
 *     out[i][0..8] = R_O (x, y), R_A, R_B, R_C (x, y each: O on the crank by the frame, A on
 *     A-B by the crank, B on C-B by A-B, C on C-B by the frame), M_b.
 *
 * fourbar_mech: the four-bar (crank O-A, RRR group A-B-C, B on the left of A->C) with the
 *   Mechanism's outputs in its layout, for a like-with-like comparison (fourbar.c forms the
 *   book's polar outputs instead): points A, B and links crank, A-B, C-B:
 *     pos[i][2][2], vel[i][2][2], acc[i][2][2], dir[i][3][2] (cos, sin), om[i][3], ep[i][3];
 *   level 1: positions (and directions), 2: + velocities (and omegas), 3: + accelerations.
 * rpr_mech: the inverted slider-crank (crank O-A, RPR group: a slider pivoted at A slides
 *   along link 3, which turns about C; A at h from link 3's axis, B the foot of the
 *   perpendicular from A on it, on the left of A->C), the Mechanism's outputs of
 *   Mechanism.rpr in its layout: points A, B and links crank, the slider, link 3 (the
 *   slider turns with link 3):
 *     pos[i][2][2], vel[i][2][2], acc[i][2][2], dir[i][3][2], om[i][3], ep[i][3]; level as
 *   fourbar_mech.  Link 3's unknowns by Cramer's rule: v_A = w3 k x (A - C) + s' e3 and
 *   a_A = e3 k x (A - C) - w3^2 (A - C) + s'' e3 + 2 w3 s' k x e3 (C fixed).
 * fourbar_forces_full: fourbar_forces' mechanism with what Mechanism.solve(need="forces")
 *   stores: fourbar_mech's twenty numbers per position, then
 *     react[i][4][3] (O, A, B, C: fx, fy and the couple, 0 for a revolute), mb[i], and the
 *     reduced inertia and moment jred[i] = m2 |v_S2|^2 + J2 w2^2 + m3 |v_S3|^2 + J3 w3^2,
 *     mred[i] = -g (m2 v_S2y + m3 v_S3y) + T3 w3, both per unit crank speed.
 *
 * Built by bench_mechanism.py: cc -O3 -march=native -shared -fPIC mechanism_loops.c -lm.
 */
#include <math.h>

int sixbar(long n, int level, const double *phi, double roa, double rab, double rcb,
           double rcd, double rde, double xc, double yc, double yg, double w1,
           double *pos, double *vel, double *acc, double *dir, double *om, double *ep)
{
    int bad = 0;
    const double d2 = rab * rab - rcb * rcb, rab2 = rab * rab, q = rcd / rcb;
    for (long i = 0; i < n; i++) {
        double s = sin(phi[i]), c = cos(phi[i]);
        double xa = roa * c, ya = roa * s;
        double dx = xc - xa, dy = yc - ya, l2 = dx * dx + dy * dy;
        double k1 = 0.5 * (l2 + d2) / l2, h2 = rab2 / l2 - k1 * k1;
        if (!(h2 >= 0.0)) { bad = 1; continue; }
        double k2 = sqrt(h2);
        double ux = k1 * dx - k2 * dy, uy = k1 * dy + k2 * dx;      /* B - A */
        double xb = xa + ux, yb = ya + uy;
        double wx = xb - xc, wy = yb - yc;                           /* B - C */
        double rx = -q * wx, ry = -q * wy;                           /* D - C */
        double xd = xc + rx, yd = yc + ry;
        double h = yg - yd, e2 = rde * rde - h * h;
        if (!(e2 >= 0.0)) { bad = 1; continue; }
        double fx = sqrt(e2), fy = h;                                /* E - D */
        double *p = pos + 8 * i, *dr = dir + 10 * i;
        p[0] = xa; p[1] = ya; p[2] = xb; p[3] = yb; p[4] = xd; p[5] = yd;
        p[6] = xd + fx; p[7] = yg;
        dr[0] = c; dr[1] = s; dr[2] = ux / rab; dr[3] = uy / rab; dr[4] = wx / rcb;
        dr[5] = wy / rcb; dr[6] = fx / rde; dr[7] = fy / rde; dr[8] = 1.0; dr[9] = 0.0;
        if (level < 2)
            continue;
        double det = uy * wx - ux * wy;
        double vax = -w1 * ya, vay = w1 * xa;
        double om2 = (vax * wx + wy * vay) / det, om3 = (uy * vay + vax * ux) / det;
        double vdx = -om3 * ry, vdy = om3 * rx;
        double om4 = -vdy / fx;
        double *v = vel + 8 * i, *o = om + 5 * i;
        v[0] = vax; v[1] = vay; v[2] = -om3 * wy; v[3] = om3 * wx; v[4] = vdx; v[5] = vdy;
        v[6] = vdx - om4 * fy; v[7] = 0.0;
        o[0] = w1; o[1] = om2; o[2] = om3; o[3] = om4; o[4] = 0.0;
        if (level < 3)
            continue;
        double bx = w1 * w1 * xa + om2 * om2 * ux - om3 * om3 * wx,
               by = w1 * w1 * ya + om2 * om2 * uy - om3 * om3 * wy;
        double ep2 = -(bx * wx + wy * by) / det, ep3 = -(uy * by + bx * ux) / det;
        double adx = -ep3 * ry - om3 * om3 * rx, ady = ep3 * rx - om3 * om3 * ry;
        double ep4 = (om4 * om4 * fy - ady) / fx;
        double *a = acc + 8 * i, *g = ep + 5 * i;
        a[0] = -w1 * w1 * xa; a[1] = -w1 * w1 * ya;
        a[2] = -ep3 * wy - om3 * om3 * wx; a[3] = ep3 * wx - om3 * om3 * wy;
        a[4] = adx; a[5] = ady;
        a[6] = adx - ep4 * fy - om4 * om4 * fx; a[7] = 0.0;
        g[0] = 0.0; g[1] = ep2; g[2] = ep3; g[3] = ep4; g[4] = 0.0;
    }
    return bad;
}

static double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

int fourbar_forces(long n, const double *phi, double roa, double rab, double rcb,
                   double xc, double yc, double w1, double m2, double j2, double f2,
                   double m3, double j3, double f3, double g, double t3, double *out)
{
    int bad = 0;
    const double d2 = rab * rab - rcb * rcb, rab2 = rab * rab;
    for (long i = 0; i < n; i++) {
        double s = sin(phi[i]), c = cos(phi[i]);
        double xa = roa * c, ya = roa * s;
        double dx = xc - xa, dy = yc - ya, l2 = dx * dx + dy * dy;
        double k1 = 0.5 * (l2 + d2) / l2, h2 = rab2 / l2 - k1 * k1;
        if (!(h2 >= 0.0)) { bad = 1; continue; }
        double k2 = sqrt(h2);
        double ux = k1 * dx - k2 * dy, uy = k1 * dy + k2 * dx;      /* B - A */
        double wx = xa + ux - xc, wy = ya + uy - yc;                 /* B - C */
        double det = uy * wx - ux * wy;
        double vax = -w1 * ya, vay = w1 * xa;
        double om2 = (vax * wx + wy * vay) / det, om3 = (uy * vay + vax * ux) / det;
        double bx = w1 * w1 * xa + om2 * om2 * ux - om3 * om3 * wx,
               by = w1 * w1 * ya + om2 * om2 * uy - om3 * om3 * wy;
        double ep2 = -(bx * wx + wy * by) / det, ep3 = -(uy * by + bx * ux) / det;
        /* accelerations of the centres (a_A = -w1^2 A) */
        double a2x = -w1 * w1 * xa + f2 * (-ep2 * uy - om2 * om2 * ux),
               a2y = -w1 * w1 * ya + f2 * (ep2 * ux - om2 * om2 * uy);
        double a3x = f3 * (-ep3 * wy - om3 * om3 * wx), a3y = f3 * (ep3 * wx - om3 * om3 * wy);
        /* loads: gravity + d'Alembert forces, and moments about B */
        double F2x = -m2 * a2x, F2y = -m2 * (a2y + g), F3x = -m3 * a3x, F3y = -m3 * (a3y + g);
        double M2 = cross((f2 - 1.0) * ux, (f2 - 1.0) * uy, F2x, F2y) - j2 * ep2;
        double M3 = cross((f3 - 1.0) * wx, (f3 - 1.0) * wy, F3x, F3y) - j3 * ep3 + t3;
        /* link 2: R_A + F2 - R_B = 0 and (A - B) x R_A + M2 = 0; link 3: R_B + R_C + F3 = 0
           and (C - B) x R_C + M3 = 0.  With R_A = R_B - F2, R_C = -R_B - F3:
           (A - B) x R_B = (A - B) x F2 - M2,  (C - B) x R_B = -(C - B) x F3 + M3 */
        double p1 = cross(-ux, -uy, F2x, F2y) - M2, p2 = -cross(-wx, -wy, F3x, F3y) + M3;
        /* (-ux) Ry - (-uy) Rx = p1 ; (-wx) Ry - (-wy) Rx = p2 */
        double dd = uy * (-wx) - (-ux) * wy;
        double rbx = (p1 * (-wx) - (-ux) * p2) / dd, rby = (uy * p2 - wy * p1) / dd;
        double rax = rbx - F2x, ray = rby - F2y, rcx = -rbx - F3x, rcy = -rby - F3y;
        double *o = out + 9 * i;
        o[0] = rax; o[1] = ray;                /* the crank is massless: R_O = R_A */
        o[2] = rax; o[3] = ray; o[4] = rbx; o[5] = rby; o[6] = rcx; o[7] = rcy;
        o[8] = cross(xa, ya, rax, ray);       /* M_b = A x R_A: the crank's balance */
    }
    return bad;
}

int fourbar_mech(long n, int level, const double *phi, double roa, double rab, double rcb,
                 double xc, double yc, double w1, double *pos, double *vel, double *acc,
                 double *dir, double *om, double *ep)
{
    int bad = 0;
    const double d2 = rab * rab - rcb * rcb, rab2 = rab * rab;
    for (long i = 0; i < n; i++) {
        double s = sin(phi[i]), c = cos(phi[i]);
        double xa = roa * c, ya = roa * s;
        double dx = xc - xa, dy = yc - ya, l2 = dx * dx + dy * dy;
        double k1 = 0.5 * (l2 + d2) / l2, h2 = rab2 / l2 - k1 * k1;
        if (!(h2 >= 0.0)) { bad = 1; continue; }
        double k2 = sqrt(h2);
        double ux = k1 * dx - k2 * dy, uy = k1 * dy + k2 * dx;      /* B - A */
        double wx = xa + ux - xc, wy = ya + uy - yc;                 /* B - C */
        double *p = pos + 4 * i, *dr = dir + 6 * i;
        p[0] = xa; p[1] = ya; p[2] = xa + ux; p[3] = ya + uy;
        dr[0] = c; dr[1] = s; dr[2] = ux / rab; dr[3] = uy / rab; dr[4] = wx / rcb;
        dr[5] = wy / rcb;
        if (level < 2)
            continue;
        double det = uy * wx - ux * wy;
        double vax = -w1 * ya, vay = w1 * xa;
        double om2 = (vax * wx + wy * vay) / det, om3 = (uy * vay + vax * ux) / det;
        double *v = vel + 4 * i;
        v[0] = vax; v[1] = vay; v[2] = -om3 * wy; v[3] = om3 * wx;
        om[3 * i] = w1; om[3 * i + 1] = om2; om[3 * i + 2] = om3;
        if (level < 3)
            continue;
        double bx = w1 * w1 * xa + om2 * om2 * ux - om3 * om3 * wx,
               by = w1 * w1 * ya + om2 * om2 * uy - om3 * om3 * wy;
        double ep2 = -(bx * wx + wy * by) / det, ep3 = -(uy * by + bx * ux) / det;
        double *a = acc + 4 * i;
        a[0] = -w1 * w1 * xa; a[1] = -w1 * w1 * ya;
        a[2] = -ep3 * wy - om3 * om3 * wx; a[3] = ep3 * wx - om3 * om3 * wy;
        ep[3 * i] = 0.0; ep[3 * i + 1] = ep2; ep[3 * i + 2] = ep3;
    }
    return bad;
}

int rpr_mech(long n, int level, const double *phi, double roa, double xc, double yc,
             double h, double w1, double *pos, double *vel, double *acc, double *dir,
             double *om, double *ep)
{
    int bad = 0;
    for (long i = 0; i < n; i++) {
        double s = sin(phi[i]), c = cos(phi[i]);
        double xa = roa * c, ya = roa * s;
        double rx = xa - xc, ry = ya - yc, d2 = rx * rx + ry * ry;  /* A - C */
        double q = d2 - h * h;                                       /* |B - C|^2 */
        if (!(q > 0.0)) { bad = 1; continue; }
        double sl = sqrt(q), rd = 1.0 / d2;
        /* B - C = (sl/d) (sl u - h n), u = (C - A)/d reversed: e3 = (B - C)/sl */
        double ex = (sl * rx + h * ry) * rd, ey = (sl * ry - h * rx) * rd;
        double xb = xc + sl * ex, yb = yc + sl * ey;
        double *p = pos + 4 * i, *dr = dir + 6 * i;
        p[0] = xa; p[1] = ya; p[2] = xb; p[3] = yb;
        dr[0] = c; dr[1] = s; dr[2] = ex; dr[3] = ey; dr[4] = ex; dr[5] = ey;
        if (level < 2)
            continue;
        /* [-ry ex; rx ey] (w3, s') = v_A */
        double det = -ry * ey - ex * rx, rdet = 1.0 / det;
        double vax = -w1 * ya, vay = w1 * xa;
        double w3 = (vax * ey - ex * vay) * rdet, sv = (-ry * vay - rx * vax) * rdet;
        double nx = -ey, ny = ex;
        double *v = vel + 4 * i;
        v[0] = vax; v[1] = vay;
        v[2] = w3 * sl * nx + sv * ex; v[3] = w3 * sl * ny + sv * ey;
        om[3 * i] = w1; om[3 * i + 1] = w3; om[3 * i + 2] = w3;
        if (level < 3)
            continue;
        double bx = -w1 * w1 * xa + w3 * w3 * rx - 2.0 * w3 * sv * nx,
               by = -w1 * w1 * ya + w3 * w3 * ry - 2.0 * w3 * sv * ny;
        double e3 = (bx * ey - ex * by) * rdet, sa = (-ry * by - rx * bx) * rdet;
        double *a = acc + 4 * i;
        a[0] = -w1 * w1 * xa; a[1] = -w1 * w1 * ya;
        a[2] = e3 * sl * nx - w3 * w3 * sl * ex + sa * ex + 2.0 * w3 * sv * nx;
        a[3] = e3 * sl * ny - w3 * w3 * sl * ey + sa * ey + 2.0 * w3 * sv * ny;
        ep[3 * i] = 0.0; ep[3 * i + 1] = e3; ep[3 * i + 2] = e3;
    }
    return bad;
}

int fourbar_forces_full(long n, const double *phi, double roa, double rab, double rcb,
                        double xc, double yc, double w1, double m2, double j2, double f2,
                        double m3, double j3, double f3, double g, double t3, double *pos,
                        double *vel, double *acc, double *dir, double *om, double *ep,
                        double *react, double *mb, double *jred, double *mred)
{
    int bad = 0;
    const double d2 = rab * rab - rcb * rcb, rab2 = rab * rab;
    for (long i = 0; i < n; i++) {
        double s = sin(phi[i]), c = cos(phi[i]);
        double xa = roa * c, ya = roa * s;
        double dx = xc - xa, dy = yc - ya, l2 = dx * dx + dy * dy;
        double k1 = 0.5 * (l2 + d2) / l2, h2 = rab2 / l2 - k1 * k1;
        if (!(h2 >= 0.0)) { bad = 1; continue; }
        double k2 = sqrt(h2);
        double ux = k1 * dx - k2 * dy, uy = k1 * dy + k2 * dx;      /* B - A */
        double wx = xa + ux - xc, wy = ya + uy - yc;                 /* B - C */
        double det = uy * wx - ux * wy;
        double vax = -w1 * ya, vay = w1 * xa;
        double om2 = (vax * wx + wy * vay) / det, om3 = (uy * vay + vax * ux) / det;
        double bx = w1 * w1 * xa + om2 * om2 * ux - om3 * om3 * wx,
               by = w1 * w1 * ya + om2 * om2 * uy - om3 * om3 * wy;
        double ep2 = -(bx * wx + wy * by) / det, ep3 = -(uy * by + bx * ux) / det;
        double *p = pos + 4 * i, *v = vel + 4 * i, *a = acc + 4 * i, *dr = dir + 6 * i;
        p[0] = xa; p[1] = ya; p[2] = xa + ux; p[3] = ya + uy;
        v[0] = vax; v[1] = vay; v[2] = -om3 * wy; v[3] = om3 * wx;
        a[0] = -w1 * w1 * xa; a[1] = -w1 * w1 * ya;
        a[2] = -ep3 * wy - om3 * om3 * wx; a[3] = ep3 * wx - om3 * om3 * wy;
        dr[0] = c; dr[1] = s; dr[2] = ux / rab; dr[3] = uy / rab; dr[4] = wx / rcb;
        dr[5] = wy / rcb;
        om[3 * i] = w1; om[3 * i + 1] = om2; om[3 * i + 2] = om3;
        ep[3 * i] = 0.0; ep[3 * i + 1] = ep2; ep[3 * i + 2] = ep3;
        /* the centres' velocities and accelerations, the loads and the reactions as in
           fourbar_forces */
        double v2x = vax - f2 * om2 * uy, v2y = vay + f2 * om2 * ux;
        double v3x = -f3 * om3 * wy, v3y = f3 * om3 * wx;
        double a2x = -w1 * w1 * xa + f2 * (-ep2 * uy - om2 * om2 * ux),
               a2y = -w1 * w1 * ya + f2 * (ep2 * ux - om2 * om2 * uy);
        double a3x = f3 * (-ep3 * wy - om3 * om3 * wx), a3y = f3 * (ep3 * wx - om3 * om3 * wy);
        double F2x = -m2 * a2x, F2y = -m2 * (a2y + g), F3x = -m3 * a3x, F3y = -m3 * (a3y + g);
        double M2 = cross((f2 - 1.0) * ux, (f2 - 1.0) * uy, F2x, F2y) - j2 * ep2;
        double M3 = cross((f3 - 1.0) * wx, (f3 - 1.0) * wy, F3x, F3y) - j3 * ep3 + t3;
        double p1 = cross(-ux, -uy, F2x, F2y) - M2, p2 = -cross(-wx, -wy, F3x, F3y) + M3;
        double dd = uy * (-wx) - (-ux) * wy;
        double rbx = (p1 * (-wx) - (-ux) * p2) / dd, rby = (uy * p2 - wy * p1) / dd;
        double rax = rbx - F2x, ray = rby - F2y, rcx = -rbx - F3x, rcy = -rby - F3y;
        double *r = react + 12 * i;
        r[0] = rax; r[1] = ray; r[2] = 0.0; r[3] = rax; r[4] = ray; r[5] = 0.0;
        r[6] = rbx; r[7] = rby; r[8] = 0.0; r[9] = rcx; r[10] = rcy; r[11] = 0.0;
        mb[i] = cross(xa, ya, rax, ray);
        double q2 = 1.0 / (w1 * w1);
        jred[i] = (m2 * (v2x * v2x + v2y * v2y) + j2 * om2 * om2 + m3 * (v3x * v3x + v3y * v3y)
                   + j3 * om3 * om3) * q2;
        mred[i] = (-g * (m2 * v2y + m3 * v3y) + t3 * om3) / w1;
    }
    return bad;
}
