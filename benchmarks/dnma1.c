/* DNMA1's statics written by hand (benchmarks/bench_forces.py): the reactions of an RRR
 * group by the vector method, per position: the sines and cosines of FI2, FI3, G2, G3,
 * the moments about B, Cramer's rule for the 2x2 system, three atan2 for the directions.
 * No input checks, no status: the floor a compiled loop of this formula can reach.
 * out: 6 rows of n (RA, GA, RB, GB, RC, GC); returns the number of singular positions. */
#include <math.h>

long dnma1_loop(long n, const double *l2, const double *fi2, const double *l3,
                const double *fi3, double bs2, double bs3, double m2, double q2, double g2,
                double m3, double q3, double g3, double *out)
{
    long bad = 0;
    for (long i = 0; i < n; i++) {
        double c2 = cos(fi2[i]), s2 = sin(fi2[i]), c3 = cos(fi3[i]), s3 = sin(fi3[i]);
        double qx2 = q2 * cos(g2), qy2 = q2 * sin(g2), qx3 = q3 * cos(g3), qy3 = q3 * sin(g3);
        double rat = (m2 - bs2 * (qx2 * s2 - qy2 * c2)) / l2[i];
        double rct = (m3 - bs3 * (qx3 * s3 - qy3 * c3)) / l3[i];
        double b1 = -(qx2 + qx3 - rat * s2 - rct * s3), b2 = -(qy2 + qy3 + rat * c2 + rct * c3);
        double det = c2 * s3 - c3 * s2;
        if (det == 0.0) { bad++; continue; }
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
    }
    return bad;
}
