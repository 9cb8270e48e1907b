/* test_oracle — every numeric mode's ray/primitive span against the Fortran
 * REAL(16) oracle (tests/oracle/geom_oracle.f90) on seeded random rays and
 * random similarity transforms, with a stated error bound per mode.
 * The oracle binary is found beside this test: BUILD/oracle/geom_oracle. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include <unistd.h>
#include "tracer_test.h"

#define ORACLE_SCENES 8
#define ORACLE_RAYS 150

static char oracle_path[1024];

/* Error bound on t (deck units) for a scene of half-extent about 10 deck
 * units, at ray parameter t (the rounded direction adds an error that grows
 * with distance). See docs/numerics.md. */
static double oracle_bound(const char *mode, double t)
{
    double base = !strcmp(mode, "q16") ? 3e-4 : !strcmp(mode, "f32") ? 1e-5
                : !strcmp(mode, "q32") ? 1e-8 : !strcmp(mode, "hfp32") ? 5e-5 : 1e-11;
    return base * (1 + fabs(t) / 10);
}

static const char *const oracle_decl[PRIM_KIND_COUNT] = {
    "SPHERE P 1.3", "CYLINDER P 0.9 2.1", "BLOCK P 1.7 1.1 2.3", "CONE P 1.2 0.4 1.9", "HALFSPACE P"};

typedef struct oracle_ray { double o[3], d[3]; } oracle_ray;

/* |cos| of the angle between unit direction d and the surface normal of sp
 * at world point p, from central differences of the independent classifier. */
static double oracle_cos(const scene_prim *sp, const double *p, const double *d)
{
    double g[3], gl = 0, gd = 0, h = 1e-6;
    int i;
    for (i = 0; i < 3; i++) {
        double a[3], b[3], qa[3], qb[3];
        memcpy(a, p, sizeof a);
        memcpy(b, p, sizeof b);
        a[i] += h;
        b[i] -= h;
        tt_to_object(sp, a, qa);
        tt_to_object(sp, b, qb);
        g[i] = tt_sdf(sp, qa) - tt_sdf(sp, qb);
        gl += g[i] * g[i];
        gd += g[i] * d[i];
    }
    return gl > 0 ? fabs(gd) / sqrt(gl) : 0;
}

static void test_oracle_spans_within_bounds(void **state)
{
    uint64_t s = test_seed("test_oracle_spans_within_bounds");
    static oracle_ray rays[ORACLE_SCENES * PRIM_KIND_COUNT][ORACLE_RAYS];
    static scene *scenes[ORACLE_SCENES * PRIM_KIND_COUNT];
    char in[] = "/tmp/maprt-oracle-in-XXXXXX", out[64], cmd[2300];
    FILE *f;
    int fd, n, r, i, m;
    (void)state;
    if (access(oracle_path, X_OK) != 0) {
        /* the oracle is built only where a Fortran compiler is (mk/oracle.mk) */
        printf("# skipped: no oracle at %s: needs gfortran (apt-get install -y gfortran)\n",
               oracle_path);
        skip();
        return;
    }
    fd = mkstemp(in);
    assert_true(fd >= 0);
    f = fdopen(fd, "w");
    assert_non_null(f);
    for (n = 0; n < ORACLE_SCENES * PRIM_KIND_COUNT; n++) {
        char tail[256], deck[1024];
        const scene_prim *sp;
        tt_random_tail(&s, tail, sizeof tail);
        snprintf(deck, sizeof deck, "EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\n%s %s\nOBJECT P\n",
                 oracle_decl[n % PRIM_KIND_COUNT], tail);
        scenes[n] = tt_parse(deck);
        assert_non_null(scenes[n]);
        sp = &scenes[n]->prims[0];
        for (r = 0; r < ORACLE_RAYS; r++) {
            oracle_ray *ry = &rays[n][r];
            for (i = 0; i < 3; i++) {
                ry->o[i] = test_uniform(&s, -7, 7);
                ry->d[i] = test_uniform(&s, -2.5, 2.5) - ry->o[i];
            }
            fprintf(f, "%d %.17g %.17g %.17g", (int)sp->shape->kind, sp->shape->dim[0], sp->shape->dim[1],
                    sp->shape->dim[2]);
            for (i = 0; i < 12; i++)
                fprintf(f, " %.17g", sp->world_from_object[i]);
            fprintf(f, " %.17g %.17g %.17g %.17g %.17g %.17g\n", ry->o[0], ry->o[1], ry->o[2],
                    ry->d[0], ry->d[1], ry->d[2]);
        }
    }
    assert_int_equal(fclose(f), 0);
    snprintf(out, sizeof out, "%s.out", in);
    snprintf(cmd, sizeof cmd, "'%s' < '%s' > '%s'", oracle_path, in, out);
    assert_int_equal(system(cmd), 0);

    for (m = 0; m < TT_MODES; m++) {
        const probe_ops *ops = tt_mode(m);
        double maxerr[PRIM_KIND_COUNT] = {0}, worst = 0;
        long compared = 0, disagree = 0, over = 0, skipped = 0;
        f = fopen(out, "r");
        assert_non_null(f);
        for (n = 0; n < ORACLE_SCENES * PRIM_KIND_COUNT; n++) {
            void *cs;
            diag err;
            int kind = n % PRIM_KIND_COUNT;
            diag_init(&err);
            assert_int_equal(ops->compile(scenes[n], &cs, &err), 0);
            for (r = 0; r < ORACLE_RAYS; r++) {
                char word[8];
                double ot[2] = {0, 0}, t[2];
                int face[2], ohit, has, k;
                assert_int_equal(fscanf(f, "%7s", word), 1);
                ohit = !strcmp(word, "hit");
                if (ohit)
                    assert_int_equal(fscanf(f, "%lf %lf", &ot[0], &ot[1]), 2);
                has = ops->prim_span(cs, 0, rays[n][r].o, rays[n][r].d, t, face);
                if (ohit != has) {
                    /* allowed only for tangent rays: a sliver shorter than the bound */
                    if (!ohit || ot[1] - ot[0] > 2 * oracle_bound(ops->name, ot[0])) {
                        if (disagree++ < 3)
                            printf("# %s %s ray %d: oracle %s, mode %s\n", ops->name, oracle_decl[kind], r,
                                   ohit ? "hit" : "miss", has ? "hit" : "miss");
                    }
                    continue;
                }
                if (!ohit)
                    continue;
                for (k = 0; k < 2; k++) {
                    double e, p[3], u[3], l, c, b;
                    int j;
                    if (fabs(ot[k]) > 1e29 || ot[k] < -20)
                        continue;
                    l = sqrt(rays[n][r].d[0] * rays[n][r].d[0] + rays[n][r].d[1] * rays[n][r].d[1]
                             + rays[n][r].d[2] * rays[n][r].d[2]);
                    for (j = 0; j < 3; j++) {
                        u[j] = rays[n][r].d[j] / l;
                        p[j] = rays[n][r].o[j] + ot[k] * u[j];
                    }
                    /* a surface error e moves t by e / cos: grazing ends (under
                     * 3 degrees) are ill-conditioned and skipped */
                    c = oracle_cos(&scenes[n]->prims[0], p, u);
                    if (c < 0.05) {
                        skipped++;
                        continue;
                    }
                    b = oracle_bound(ops->name, ot[k]) / c;
                    e = fabs(t[k] - ot[k]);
                    compared++;
                    if (e > maxerr[kind]) maxerr[kind] = e;
                    if (e / b > worst) worst = e / b;
                    if (e > b)
                        over++;
                }
            }
            ops->free(cs);
        }
        fclose(f);
        printf("# %s: %ld ends compared; max |dt| sphere %.2g cylinder %.2g block %.2g cone %.2g "
               "half-space %.2g; worst/bound %.3f; %ld over, %ld hit/miss disagreements, %ld grazing ends skipped\n",
               ops->name, compared, maxerr[0], maxerr[1], maxerr[2], maxerr[3], maxerr[4], worst, over,
               disagree, skipped);
        assert_true(compared > 1000);
        assert_int_equal(over, 0);
        assert_int_equal(disagree, 0);
    }
    for (n = 0; n < ORACLE_SCENES * PRIM_KIND_COUNT; n++)
        scene_free(scenes[n]);
    remove(in);
    remove(out);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_oracle_spans_within_bounds),
    };
    /* argv[0] is BUILD/tests/test_oracle; the oracle is BUILD/oracle/geom_oracle */
    const char *slash = argc > 0 ? strrchr(argv[0], '/') : NULL;
    int dirlen = slash ? (int)(slash - argv[0]) : 0;
    snprintf(oracle_path, sizeof oracle_path, "%.*s/../oracle/geom_oracle", dirlen, slash ? argv[0] : ".");
    return cmocka_run_group_tests(tests, NULL, NULL);
}
