/* scene_xform — affine transforms and their statement items (see
 * scene_xform.h). */
#include "scene/scene_xform.h"
#include "util/dmath.h"
#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

void scene_xform_identity(double m[16])
{
    int i;
    for (i = 0; i < 16; i++)
        m[i] = (i % 5 == 0) ? 1.0 : 0.0;
}

/* The bits of the first n entries of the top three rows of m (n 3: the
 * linear part, 4: all) that differ from the identity's; 0 when they are
 * its entries exactly (+0, not -0). Branch-free: cheaper than comparing. */
static uint64_t scene_xform_off_identity(const double m[16], int n)
{
    static const double one = 1.0;
    uint64_t acc = 0, u, bone;
    int i, j;
    memcpy(&bone, &one, sizeof bone);
    for (i = 0; i < 3; i++)
        for (j = 0; j < n; j++) {
            memcpy(&u, &m[4 * i + j], sizeof u);
            acc |= i == j ? u ^ bone : u;
        }
    return acc;
}

int scene_xform_is_identity(const double m[16])
{
    return m[0] == 1 && scene_xform_off_identity(m, 4) == 0;
}

/* Only the top three rows are formed, each sum in the order the full
 * product adds it: b's last row (0 0 0 1) contributes a[i][3] to column 3
 * and a[i][3] * 0 elsewhere, which changes no sum (started from +0, a sum
 * is never -0); a's last row gives b's again.
 * Where a factor's linear part is exactly the identity's (a translation,
 * or the identity itself), each of its sums has one term x times 1, which is x,
 * and the others finite times a zero, a zero: started from +0, such a sum
 * is x + 0.0 (x, or +0 for -0), whatever the order. So a's rows then give
 * b's entries + 0.0, a[i][3] added to column 3 as before; b's columns
 * give a's entries + 0.0, column 3 formed in full. */
void scene_xform_mul(double out[16], const double a[16], const double b[16])
{
    double r[12];
    int i, j;
    if (a[0] == 1 && scene_xform_off_identity(a, 3) == 0) {
        for (i = 0; i < 12; i++)
            r[i] = b[i] + 0.0;
        for (i = 0; i < 3; i++)
            r[4 * i + 3] += a[4 * i + 3];
    } else if (b[0] == 1 && scene_xform_off_identity(b, 3) == 0) {
        for (i = 0; i < 3; i++) {
            const double *ai = a + 4 * i;
            for (j = 0; j < 3; j++)
                r[4 * i + j] = ai[j] + 0.0;
            r[4 * i + 3] = 0.0 + ai[0] * b[3] + ai[1] * b[7] + ai[2] * b[11];
            r[4 * i + 3] += ai[3];
        }
    } else {
        for (i = 0; i < 3; i++) {
            const double *ai = a + 4 * i;
            for (j = 0; j < 4; j++)
                r[4 * i + j] = 0.0 + ai[0] * b[j] + ai[1] * b[4 + j] + ai[2] * b[8 + j];
            r[4 * i + 3] += ai[3];
        }
    }
    memcpy(out, r, sizeof r);
    out[12] = out[13] = out[14] = 0;
    out[15] = 1;
}

/* 1 if x is finite and of magnitude at most SCENE_XFORM_MAX_ABS. */
static int scene_xform_in_range(double x)
{
    return fabs(x) <= SCENE_XFORM_MAX_ABS;
}

int scene_xform_ok(const double m[16])
{
    double det, norms = 1;
    int i;
    for (i = 0; i < 16; i++)
        if (!scene_xform_in_range(m[i]))
            return 0;
    for (i = 0; i < 3; i++) {
        double n = sqrt(m[i * 4] * m[i * 4] + m[i * 4 + 1] * m[i * 4 + 1] +
                        m[i * 4 + 2] * m[i * 4 + 2]);
        if (!(n >= 1 / SCENE_XFORM_MAX_ABS))     /* shrunk to nothing */
            return 0;
        norms *= n;
    }
    det = m[0] * (m[5] * m[10] - m[6] * m[9])
        - m[1] * (m[4] * m[10] - m[6] * m[8])
        + m[2] * (m[4] * m[9] - m[5] * m[8]);
    return norms > 0 && fabs(det) > 1e-12 * norms;
}

enum { SCENE_XFORM_TRANSLATE, SCENE_XFORM_ROTATE, SCENE_XFORM_SCALE, SCENE_XFORM_MATRIX };

/* The transform item t starts (SCENE_XFORM_...), or -1: chosen by the
 * first letter, then compared in full. */
static int scene_xform_kind(const scene_lex_tok *t)
{
    static const char *const word[] = { "TRANSLATE", "ROTATE", "SCALE", "MATRIX" };
    int k;
    if (!t)
        return -1;
    switch (toupper((unsigned char)t->text[0])) {
    case 'T': k = SCENE_XFORM_TRANSLATE; break;
    case 'R': k = SCENE_XFORM_ROTATE; break;
    case 'S': k = SCENE_XFORM_SCALE; break;
    case 'M': k = SCENE_XFORM_MATRIX; break;
    default: return -1;
    }
    return scene_cur_is(t, word[k]) ? k : -1;
}

/* Rotation by deg degrees about the unit axis u (right-hand rule). */
static void scene_xform_rotation(double m[16], const double u[3], double deg,
                                 int principal)
{
    double a = dmath_rad(deg);
    double s = sin(a), k = 1 - cos(a), cs = cos(a);
    scene_xform_identity(m);
    m[0] = cs + u[0] * u[0] * k;
    m[1] = u[0] * u[1] * k - u[2] * s;
    m[2] = u[0] * u[2] * k + u[1] * s;
    m[4] = u[1] * u[0] * k + u[2] * s;
    m[5] = cs + u[1] * u[1] * k;
    m[6] = u[1] * u[2] * k - u[0] * s;
    m[8] = u[2] * u[0] * k - u[1] * s;
    m[9] = u[2] * u[1] * k + u[0] * s;
    m[10] = cs + u[2] * u[2] * k;
    /* quarter turns about X, Y or Z are exact permutations (sin and cos of
     * the rounded pi/2 are not exactly 1 and 0) */
    if (principal && fmod(deg, 90.0) == 0) {
        int i;
        for (i = 0; i < 16; i++)
            m[i] = floor(m[i] + 0.5);
    }
}

int scene_xform_parse(scene_cur *c, double m[16])
{
    const scene_lex_tok *kw = scene_cur_peek(c);
    const scene_lex_tok *t;
    double t4[16], v[12];
    int i, rc = 0, kind = scene_xform_kind(kw);
    if (kind < 0)
        return -1;
    scene_xform_identity(t4);
    c->pos++;
    if (kind == SCENE_XFORM_TRANSLATE) {
        if (scene_cur_numbers(c, v, 3))
            return DIAG_INPUT;
        t4[3] = v[0]; t4[7] = v[1]; t4[11] = v[2];
    } else if (kind == SCENE_XFORM_ROTATE) {
        double u[3] = { 0, 0, 0 }, len;
        t = scene_cur_peek(c);
        if (scene_cur_accept(c, "X")) u[0] = 1;
        else if (scene_cur_accept(c, "Y")) u[1] = 1;
        else if (scene_cur_accept(c, "Z")) u[2] = 1;
        else if (scene_cur_accept(c, "AXIS")) {
            if (scene_cur_numbers(c, u, 3))
                return DIAG_INPUT;
            len = dmath_len3(u);
            if (!(len > 0))
                return scene_cur_error(c, t, "ROTATE axis must not be zero");
            for (i = 0; i < 3; i++)
                u[i] /= len;
        } else if (!t)
            return scene_cur_error(c, NULL, "ROTATE needs X, Y, Z or AXIS");
        else
            return scene_cur_error(c, t, "ROTATE needs X, Y, Z or AXIS, found %s", t->text);
        if (scene_cur_number(c, &v[0], NULL))
            return DIAG_INPUT;
        scene_xform_rotation(t4, u, v[0], !scene_cur_is(t, "AXIS"));
    } else if (kind == SCENE_XFORM_SCALE) {
        int n = 1;
        const scene_lex_tok *at[3];
        if (scene_cur_number(c, &v[0], &at[0]))
            return DIAG_INPUT;
        if (scene_cur_numeric(scene_cur_peek(c))) {
            n = 3;
            if (scene_cur_number(c, &v[1], &at[1]) || scene_cur_number(c, &v[2], &at[2]))
                return DIAG_INPUT;
        } else {
            v[1] = v[2] = v[0];
            at[1] = at[2] = at[0];
        }
        for (i = 0; i < n; i++)
            if (v[i] == 0)
                return scene_cur_error(c, at[i], "SCALE factor must not be zero");
        t4[0] = v[0]; t4[5] = v[1]; t4[10] = v[2];
    } else {  /* MATRIX */
        if (scene_cur_numbers(c, v, 12))
            return DIAG_INPUT;
        memcpy(t4, v, sizeof v);
        if (!scene_xform_ok(t4))
            return scene_cur_error(c, kw, "MATRIX is singular");
    }
    scene_xform_mul(t4, t4, m);
    /* m is the identity or passed this test, and holds no -0: a
     * translation leaves all but its column 3 as they were, so only that
     * column can fail */
    if (kind == SCENE_XFORM_TRANSLATE
            ? !(scene_xform_in_range(t4[3]) && scene_xform_in_range(t4[7]) &&
                scene_xform_in_range(t4[11]))
            : !scene_xform_ok(t4))
        rc = scene_cur_error(c, kw, "transforms give a degenerate or out-of-range matrix");
    else
        memcpy(m, t4, sizeof t4);
    return rc;
}
