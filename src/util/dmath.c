/* dmath — 3x3 matrix routines in double precision (see dmath.h). */
#include "util/dmath.h"

/* Inverse of a 3x3 matrix by cofactors; -1 when it is singular relative to
 * its own scale (|det| tiny against the product of its row norms). */
int dmath_m3_inverse(const double *m, double *inv)
{
    double c[9], det, scale = 1.0;
    int i;
    c[0] = m[4] * m[8] - m[5] * m[7];
    c[1] = m[2] * m[7] - m[1] * m[8];
    c[2] = m[1] * m[5] - m[2] * m[4];
    c[3] = m[5] * m[6] - m[3] * m[8];
    c[4] = m[0] * m[8] - m[2] * m[6];
    c[5] = m[2] * m[3] - m[0] * m[5];
    c[6] = m[3] * m[7] - m[4] * m[6];
    c[7] = m[1] * m[6] - m[0] * m[7];
    c[8] = m[0] * m[4] - m[1] * m[3];
    det = m[0] * c[0] + m[1] * c[3] + m[2] * c[6];
    for (i = 0; i < 3; i++)
        scale *= dmath_len3(m + 3 * i);
    if (!(fabs(det) > 1e-12 * scale) || !isfinite(det))
        return -1;
    for (i = 0; i < 9; i++)
        inv[i] = c[i] / det;
    return 0;
}

/* Largest singular value of m: square root of the largest eigenvalue of the
 * symmetric m^T m, by the closed-form (trigonometric) 3x3 eigen solution. */
double dmath_m3_spectral_norm(const double *m)
{
    double b[9], q, p1, p2, p, bm[9], r, phi, det;
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            b[3 * i + j] = 0;
            for (k = 0; k < 3; k++)
                b[3 * i + j] += m[3 * k + i] * m[3 * k + j];
        }
    p1 = b[1] * b[1] + b[2] * b[2] + b[5] * b[5];
    q = (b[0] + b[4] + b[8]) / 3;
    p2 = (b[0] - q) * (b[0] - q) + (b[4] - q) * (b[4] - q) + (b[8] - q) * (b[8] - q) + 2 * p1;
    p = sqrt(p2 / 6);
    if (p == 0)
        return sqrt(q);
    for (i = 0; i < 9; i++)
        bm[i] = (b[i] - (i % 4 == 0 ? q : 0)) / p;
    det = bm[0] * (bm[4] * bm[8] - bm[5] * bm[7]) - bm[1] * (bm[3] * bm[8] - bm[5] * bm[6])
        + bm[2] * (bm[3] * bm[7] - bm[4] * bm[6]);
    r = det / 2;
    phi = r <= -1 ? DMATH_PI / 3 : r >= 1 ? 0 : acos(r) / 3;
    return sqrt(q + 2 * p * cos(phi));
}
