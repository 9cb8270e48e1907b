/* test_shade — the shading models of src/trace/shade.c against independent
 * formulas: the Fresnel reflectance against the angle form of Fresnel's
 * equations, integer powers against pow(), and each model's local term on
 * hand-built geometry (Lambert has no highlight, Phong and Blinn-Phong peak
 * where they should and differ off the peak, a mirror has no local term,
 * the transparent model's weights sum to its transmittance). Checked in the
 * f64 build; shading is double in every mode. */
#define NUM_MODE f64
#define NUM_MODE_f64
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "trace/shade.h"
#include "support.h"
#include "util/dmath.h"

/* Fresnel in angle form (Born & Wolf): Rs = sin^2(ti - tt) / sin^2(ti + tt),
 * Rp = tan^2(ti - tt) / tan^2(ti + tt), with sin tt = eta sin ti. */
static double ref_fresnel(double cos_i, double eta)
{
    double ti = acos(cos_i), st = eta * sin(ti), tt, rs, rp;
    if (st >= 1)
        return 1;
    tt = asin(st);
    if (ti == 0)
        return pow((1 - eta) / (1 + eta), 2);
    rs = pow(sin(ti - tt) / sin(ti + tt), 2);
    rp = pow(tan(ti - tt) / tan(ti + tt), 2);
    return 0.5 * (rs + rp);
}

static void test_shade_fresnel_matches_angle_form(void **state)
{
    uint64_t s = test_seed("test_shade_fresnel_matches_angle_form");
    int i;
    (void)state;
    assert_true(fabs(f64_shade_fresnel(1, 1 / 1.5) - 0.04) < 1e-12);   /* glass, normal incidence */
    assert_true(fabs(f64_shade_fresnel(1e-9, 1 / 1.5) - 1) < 1e-6);     /* grazing */
    assert_true(f64_shade_fresnel(0.3, 1.5) == 1);                      /* beyond the critical angle */
    for (i = 0; i < 2000; i++) {
        double c = test_uniform(&s, 0.01, 0.999), eta = test_uniform(&s, 0.3, 2.5);
        double want = ref_fresnel(c, eta), got = f64_shade_fresnel(c, eta);
        if (fabs(got - want) > 1e-9)
            fail_msg("cos %.17g eta %.17g: %.17g, angle form %.17g", c, eta, got, want);
    }
}

static void test_shade_pow_integer_exponents(void **state)
{
    uint64_t s = test_seed("test_shade_pow_integer_exponents");
    int i;
    (void)state;
    for (i = 0; i < 5000; i++) {
        double x = test_uniform(&s, 0, 1), n = (double)(test_rand(&s) % 10001);
        double want = pow(x, n), got = f64_shade_pow(x, n);
        if (!(fabs(got - want) <= 1e-12 * want + 1e-300))
            fail_msg("%.17g ^ %.0f: %.17g, pow %.17g", x, n, got, want);
    }
    assert_true(f64_shade_pow(0.5, 2.5) == pow(0.5, 2.5));    /* not whole: pow */
    assert_true(f64_shade_pow(0.7, 0) == 1);
}

/* One white light along ld, normal +z, viewer along -d. */
static void local(shade_model m, const double ld[3], const double d[3], double c[3])
{
    scene sc;
    scene_attr at;
    cscene cs;
    cscene_light li;
    double ns[3] = { 0, 0, 1 }, color[3] = { 0.5, 0.5, 0.5 }, pass = 1, ldir[1][3];
    memset(&sc, 0, sizeof sc);
    memset(&at, 0, sizeof at);
    memset(&cs, 0, sizeof cs);
    memset(&li, 0, sizeof li);
    li.rgb[0] = li.rgb[1] = li.rgb[2] = 1;
    cs.sc = &sc;
    cs.lights = &li;
    cs.nlights = 1;
    at.model = m;
    at.diffuse = 0.6;
    at.specular = 0.5;
    at.exponent = 20;
    memcpy(ldir[0], ld, sizeof ldir[0]);
    f64_shade_local(&cs, &at, color, ns, d, (const double (*)[3])ldir, &pass, c);
}

static void test_shade_models_local_terms(void **state)
{
    double r = sqrt(0.5), ld[3] = { r, 0, r }, mirror_d[3] = { r, 0, -r }, off_d[3], c[3], p[3], b[3];
    double a = 0.3;
    (void)state;
    /* The viewer on the mirror direction: Phong and Blinn both add ks. */
    local(SHADE_LAMBERT, ld, mirror_d, c);
    assert_true(fabs(c[0] - 0.6 * r * 0.5) < 1e-12);
    local(SHADE_PHONG, ld, mirror_d, p);
    local(SHADE_BLINN, ld, mirror_d, b);
    assert_true(fabs(p[0] - (c[0] + 0.5)) < 1e-12);
    assert_true(fabs(b[0] - (c[0] + 0.5)) < 1e-12);
    /* Off the peak by angle a in the plane: Phong's (R.V) = cos a, Blinn's
     * (N.H) = cos(a/2), each to the 20th. */
    off_d[0] = sin(DMATH_PI / 4 + a);
    off_d[1] = 0;
    off_d[2] = -cos(DMATH_PI / 4 + a);
    local(SHADE_PHONG, ld, off_d, p);
    local(SHADE_BLINN, ld, off_d, b);
    assert_true(fabs(p[0] - (c[0] + 0.5 * pow(cos(a), 20))) < 1e-12);
    assert_true(fabs(b[0] - (c[0] + 0.5 * pow(cos(a / 2), 20))) < 1e-12);
    local(SHADE_MIRROR, ld, mirror_d, c);
    assert_true(c[0] == 0 && c[1] == 0 && c[2] == 0);
}

static void test_shade_transparent_weights(void **state)
{
    scene_attr at;
    double color[3] = { 0.2, 0.4, 0.6 }, refl, trans, tint[3], c;
    (void)state;
    memset(&at, 0, sizeof at);
    at.model = SHADE_TRANSPARENT;
    at.transmit = 0.9;
    at.mirror = 0.05;
    at.ior = 1.5;
    for (c = 0.05; c <= 1; c += 0.05) {
        double f = f64_shade_fresnel(c, 1 / 1.5);
        f64_shade_weights(&at, color, c, 1 / 1.5, &refl, &trans, tint);
        assert_true(fabs(refl - (0.05 + 0.9 * f)) < 1e-15);
        assert_true(fabs(refl + trans - 0.95) < 1e-15);
        assert_true(tint[0] == 1 && tint[2] == 1);
    }
    at.model = SHADE_MIRROR;
    f64_shade_weights(&at, color, 0.5, 1, &refl, &trans, tint);
    assert_true(refl == 0.05 && tint[1] == 0.4);
    at.model = SHADE_PHONG;           /* the coefficients as given */
    f64_shade_weights(&at, color, 0.5, 1 / 1.5, &refl, &trans, tint);
    assert_true(refl == 0.05 && trans == 0.9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shade_fresnel_matches_angle_form),
        cmocka_unit_test(test_shade_pow_integer_exponents),
        cmocka_unit_test(test_shade_models_local_terms),
        cmocka_unit_test(test_shade_transparent_weights),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
