/* DNMA1's statics written by hand (benchmarks/bench_forces.py): the reactions of an RRR
 * group by the vector method, per position: the sines and cosines of FI2, FI3, G2, G3,
 * the moments about B, Cramer's rule for the 2x2 system, three atan2 for the directions.
 * No input checks, no status: the floor a compiled loop of this formula can reach.
 * out: 6 rows of n (RA, GA, RB, GB, RC, GC); returns the number of singular positions.
 *
 * dnma1_loop takes every input per position (arrays of n), as a routine that is given
 * loads varying with the position (inertia loads) must; dnma1_const takes the loads
 * (BS2 ... G3) once, so that the compiler hoists their sines and cosines out of the loop
 * (two sincos per position instead of four). */
#include <math.h>

static inline long one(long i, long n, double l2, double fi2, double l3, double fi3,
                       double bs2, double bs3, double m2, double qx2, double qy2, double m3,
                       double qx3, double qy3, double *out)
{
    double c2 = cos(fi2), s2 = sin(fi2), c3 = cos(fi3), s3 = sin(fi3);
    double rat = (m2 - bs2 * (qx2 * s2 - qy2 * c2)) / l2;
    double rct = (m3 - bs3 * (qx3 * s3 - qy3 * c3)) / l3;
    double b1 = -(qx2 + qx3 - rat * s2 - rct * s3), b2 = -(qy2 + qy3 + rat * c2 + rct * c3);
    double det = c2 * s3 - c3 * s2;
    if (det == 0.0) return 1;
    double y1 = (b1 * s3 - c3 * b2) / det, y2 = (c2 * b2 - s2 * b1) / det;
    double rax = y1 * c2 - rat * s2, ray = y1 * s2 + rat * c2;
    double rcx = y2 * c3 - rct * s3, rcy = y2 * s3 + rct * c3;
    double rbx = -(rax + qx2), rby = -(ray + qy2);
    out[i] = sqrt(rax * rax + ray * ray);
    out[n + i] = atan2(ray, rax);
    out[2 * n + i] = sqrt(rbx * rbx + rby * rby);
    out[3 * n + i] = atan2(rby, rbx);
    out[4 * n + i] = sqrt(rcx * rcx + rcy * rcy);
    out[5 * n + i] = atan2(rcy, rcx);
    return 0;
}

long dnma1_loop(long n, const double *l2, const double *fi2, const double *l3,
                const double *fi3, const double *bs2, const double *bs3, const double *m2,
                const double *q2, const double *g2, const double *m3, const double *q3,
                const double *g3, double *out)
{
    long bad = 0;
    for (long i = 0; i < n; i++)
        bad += one(i, n, l2[i], fi2[i], l3[i], fi3[i], bs2[i], bs3[i], m2[i],
                   q2[i] * cos(g2[i]), q2[i] * sin(g2[i]), m3[i], q3[i] * cos(g3[i]),
                   q3[i] * sin(g3[i]), out);
    return bad;
}

long dnma1_const(long n, const double *l2, const double *fi2, const double *l3,
                 const double *fi3, double bs2, double bs3, double m2, double q2, double g2,
                 double m3, double q3, double g3, double *out)
{
    long bad = 0;
    for (long i = 0; i < n; i++)
        bad += one(i, n, l2[i], fi2[i], l3[i], fi3[i], bs2, bs3, m2, q2 * cos(g2),
                   q2 * sin(g2), m3, q3 * cos(g3), q3 * sin(g3), out);
    return bad;
}
