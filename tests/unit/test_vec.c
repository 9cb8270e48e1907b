/* test_vec — the Q16.16 forms of the geom/vec.h helpers that sum in 64
 * bits and saturate once, against the step-by-step saturating forms they
 * replace (one num_* operation at a time): the same values over random
 * inputs within the ranges of docs/numerics.md; and the unit vectors
 * against their exact values. Checked in the q16 build. */
#define NUM_MODE q16
#define NUM_MODE_q16
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "geom/vec.h"
#include "support.h"

/* Uniform in [-m, m]. */
static double vt_uniform(uint64_t *s, double m)
{
    return m * (2.0 * (double)(test_rand(s) >> 11) / 9007199254740992.0 - 1.0);
}

/* A random matrix scaled to Frobenius norm 1, as prim_compile stores
 * minv_s, with entries of random magnitude (thin and flat primitives). */
static mat3 vt_minv(uint64_t *s)
{
    double m[9], f = 0;
    mat3 a;
    int i;
    for (i = 0; i < 9; i++) {
        m[i] = vt_uniform(s, 1) * pow(2.0, -(double)(test_rand(s) % 20));
        f += m[i] * m[i];
    }
    for (i = 0; i < 9; i++)
        a.m[i] = num_from_d(m[i] / sqrt(f));
    return a;
}

/* A random vector of norm below lim, its size spread over many octaves. */
static vec3 vt_vec(uint64_t *s, double lim)
{
    double m = lim / sqrt(3.0) * pow(2.0, -(double)(test_rand(s) % 24));
    return vec3_make(num_from_d(vt_uniform(s, m)), num_from_d(vt_uniform(s, m)), num_from_d(vt_uniform(s, m)));
}

static vec3 ref_mat3_mul(const mat3 *a, vec3 v)
{
    return vec3_make(fx16_add(fx16_add(fx16_mul(a->m[0], v.x), fx16_mul(a->m[1], v.y)), fx16_mul(a->m[2], v.z)),
                     fx16_add(fx16_add(fx16_mul(a->m[3], v.x), fx16_mul(a->m[4], v.y)), fx16_mul(a->m[5], v.z)),
                     fx16_add(fx16_add(fx16_mul(a->m[6], v.x), fx16_mul(a->m[7], v.y)), fx16_mul(a->m[8], v.z)));
}

static num vt_any(uint64_t *s);

static void vt_assert_vec_equal(vec3 a, vec3 b)
{
    assert_int_equal(a.x, b.x);
    assert_int_equal(a.y, b.y);
    assert_int_equal(a.z, b.z);
}

/* mat3_mul with rows of norm at most 1 and |v| < 32768. */
static void test_vec_mat3_mul_matches_chained(void **state)
{
    uint64_t s = test_seed("test_vec_mat3_mul_matches_chained");
    unsigned long before = fx_overflows;
    int i;
    (void)state;
    for (i = 0; i < 1000000; i++) {
        mat3 a = vt_minv(&s);
        vec3 v = vt_vec(&s, 32767);
        vt_assert_vec_equal(mat3_mul(&a, v), ref_mat3_mul(&a, v));
    }
    assert_true(fx_overflows == before);
}

/* mat3_mul of a matrix with one nonzero entry a row is that entry's product
 * (prim_map's shortcut), over the whole range of v. */
static void test_vec_mat3_mul_single_entries(void **state)
{
    uint64_t s = test_seed("test_vec_mat3_mul_single_entries");
    int i, r;
    (void)state;
    for (i = 0; i < 1000000; i++) {
        mat3 a = vt_minv(&s);
        vec3 v = vec3_make(vt_any(&s), vt_any(&s), vt_any(&s)), want;
        num c[3], w[3];
        int col[3];
        c[0] = v.x; c[1] = v.y; c[2] = v.z;
        for (r = 0; r < 3; r++) {
            col[r] = (int)(test_rand(&s) % 3);
            a.m[3 * r + (col[r] + 1) % 3] = a.m[3 * r + (col[r] + 2) % 3] = 0;
            w[r] = fx16_mul(a.m[3 * r + col[r]], c[col[r]]);
        }
        want = vec3_make(w[0], w[1], w[2]);
        vt_assert_vec_equal(mat3_mul(&a, v), want);
    }
}

/* vec3_madd_sub with a + t*d within range, d a unit vector, any c. */
static void test_vec_madd_sub_matches_chained(void **state)
{
    uint64_t s = test_seed("test_vec_madd_sub_matches_chained");
    int i;
    (void)state;
    for (i = 0; i < 1000000; i++) {
        vec3 a = vt_vec(&s, 16000), c = vt_vec(&s, 56000), d, want;
        num t = num_from_d(vt_uniform(&s, 16000 * pow(2.0, -(double)(test_rand(&s) % 24))));
        while (vec3_unit(vt_vec(&s, 2), &d, NULL, NULL))
            ;
        want = vec3_sub(vec3_add(a, vec3_make(fx16_mul(d.x, t), fx16_mul(d.y, t), fx16_mul(d.z, t))), c);
        vt_assert_vec_equal(vec3_madd_sub(a, t, d, c), want);
    }
}

/* A component of random size: any bit length, sign, sometimes 0 or an end
 * of the range. */
static num vt_any(uint64_t *s)
{
    uint64_t r = test_rand(s);
    switch (r % 16) {
    case 0: return 0;
    case 1: return FX16_MAX;
    case 2: return FX16_MIN;
    case 3: return (num)(r >> 60) - 8;
    default: return (num)((int32_t)(r >> 32) >> (r >> 8) % 32);
    }
}

/* One output of vec3_unit against its exact value x (long double): within
 * 0.5 units plus rel times x, or, where x is beyond the range by more than
 * that, saturated. *sat counts the saturations expected; returns 1 where x
 * lies so near the end of the range that either may happen. */
static int vt_assert_near(num got, long double x, long double rel, unsigned long *sat)
{
    long double tol = 0.5L + rel * x;
    if (x > (long double)FX16_MAX + tol) {
        assert_int_equal(got, FX16_MAX);
        ++*sat;
        return 0;
    }
    assert_true(fabsl((long double)got - x) <= tol || (got == FX16_MAX && x > (long double)FX16_MAX - tol));
    return x > (long double)FX16_MAX - tol;
}

/* vec3_unit against the exact values (long double) for vectors of every
 * size, powers of two, equal components and the ends of the range
 * included: each unit component within 0.5 + 2^-13 units, the length and
 * its reciprocal within 0.5 units plus 2^-29 of the value, saturated (and
 * counted) exactly where the value is out of range; the zero vector
 * refused with the outputs untouched. */
static void test_vec_unit_exact(void **state)
{
    uint64_t s = test_seed("test_vec_unit_exact");
    vec3 u = vec3_make(7, 7, 7);
    num l = 7, r = 7;
    int i;
    (void)state;
    if (!test_long_double_ok())
        skip();
    assert_int_equal(vec3_unit(vec3_make(0, 0, 0), &u, &l, &r), -1);
    assert_true(u.x == 7 && u.y == 7 && u.z == 7 && l == 7 && r == 7);
    for (i = 0; i < 2000000; i++) {
        vec3 v = vec3_make(vt_any(&s), vt_any(&s), vt_any(&s));
        long double c[3], g[3], len;
        unsigned long before, sat = 0;
        int k, edge;
        if (i % 8 == 0)
            v.y = v.z = v.x;
        else if (i % 8 == 1)
            v = vec3_make((num)1 << (i / 8 % 31), 0, -((num)1 << (i / 16 % 31)));
        if (v.x == 0 && v.y == 0 && v.z == 0)
            continue;
        before = fx_overflows;
        assert_int_equal(vec3_unit(v, &u, &l, &r), 0);
        c[0] = v.x; c[1] = v.y; c[2] = v.z;
        g[0] = u.x; g[1] = u.y; g[2] = u.z;
        len = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        for (k = 0; k < 3; k++)
            assert_true(fabsl(g[k] - c[k] / len * 65536) <= 0.5L + 0x1p-13L);
        edge = vt_assert_near(l, len, 0x1p-29L, &sat);
        edge |= vt_assert_near(r, 0x1p32L / len, 0x1p-29L, &sat);
        assert_true(edge || fx_overflows - before == sat);
    }
}

/* vec3_unit_near against the exact unit vector (long double): near-unit
 * vectors up to and past the edge of its series' window, each component
 * within 0.50004 units of 2^-16 (the series without its x^2 term misses by
 * up to 0.023 units at the window's edge); outside the window exactly
 * vec3_unit's; the zero vector refused. */
static void test_vec_unit_near_exact(void **state)
{
    uint64_t s = test_seed("test_vec_unit_near_exact");
    long i, inside = 0;
    vec3 u;
    (void)state;
    if (!test_long_double_ok())
        skip();
    assert_int_equal(vec3_unit_near(vec3_make(0, 0, 0), &u), -1);
    for (i = 0; i < 3000000; i++) {
        double a = vt_uniform(&s, 1), b = vt_uniform(&s, 3.141592653589793), r = sqrt(1 - a * a);
        double len = 1 + vt_uniform(&s, 1) * ldexp(1, -9 - (int)(i % 8));    /* |v|^2 - 1 up to 2^-8 */
        vec3 v = vec3_make(num_from_d(r * cos(b) * len), num_from_d(r * sin(b) * len), num_from_d(a * len)), w;
        int64_t ss = (int64_t)v.x * v.x + (int64_t)v.y * v.y + (int64_t)v.z * v.z;
        long double l = sqrtl((long double)ss), c[3], g[3];
        int k;
        assert_int_equal(vec3_unit_near(v, &u), 0);
        if (ss < ((int64_t)1 << 32) - ((int64_t)1 << 22) || ss > ((int64_t)1 << 32) + ((int64_t)1 << 22)) {
            assert_int_equal(vec3_unit(v, &w, NULL, NULL), 0);
            vt_assert_vec_equal(u, w);
            continue;
        }
        inside++;
        c[0] = v.x; c[1] = v.y; c[2] = v.z;
        g[0] = u.x; g[1] = u.y; g[2] = u.z;
        for (k = 0; k < 3; k++)
            assert_true(fabsl(g[k] - c[k] / l * 65536) <= 0.50004L);
    }
    assert_true(inside > 1000000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vec_mat3_mul_matches_chained),
        cmocka_unit_test(test_vec_mat3_mul_single_entries),
        cmocka_unit_test(test_vec_madd_sub_matches_chained),
        cmocka_unit_test(test_vec_unit_exact),
        cmocka_unit_test(test_vec_unit_near_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
