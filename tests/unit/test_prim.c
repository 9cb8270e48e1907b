/* test_prim — seeded property tests of the five primitives in every numeric
 * mode, against an independent double-precision classification: hit points
 * lie on the surface, (u,v) and faces are in range, the span list agrees
 * with inside/outside, and a ray re-spawned from a hit never re-hits the
 * convex surface it left. Also: face names, bad dimensions. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include "tracer_test.h"
#include "geom/geom.h"
#include "num/fx.h"

/* Allowed distance of a hit point from the surface, deck units, for a scene
 * whose normalised half-extent is about 10 deck units (docs/numerics.md). */
static double prim_tol(const char *mode)
{
    if (!strcmp(mode, "q16")) return 1e-3;
    if (!strcmp(mode, "f32") || !strcmp(mode, "hfp32")) return 5e-4;
    return 1e-6;
}

static const char *const prim_decl[PRIM_KIND_COUNT] = {
    "SPHERE P 1.3", "CYLINDER P 0.9 2.1", "BLOCK P 1.7 1.1 2.3", "CONE P 1.2 0.4 1.9", "HALFSPACE P"};

typedef struct prim_fail { long surf, uv, inside, respawn_out, respawn_in, hits; } prim_fail;

static void prim_check_scene(const probe_ops *ops, const scene *sc, uint64_t *s, prim_fail *f)
{
    const scene_prim *sp = &sc->prims[0];
    double tol = prim_tol(ops->name);
    void *cs;
    diag err;
    int k, j;
    diag_init(&err);
    assert_int_equal(ops->compile(sc, &cs, &err), 0);
    for (k = 0; k < 300; k++) {
        double o[3], tgt[3], d[3], l = 0, t[2], d2[3], dn, q[3], sd;
        int face[2], i, has;
        probe_hit h, h1, h2;
        for (i = 0; i < 3; i++) {
            o[i] = test_uniform(s, -7, 7);
            tgt[i] = test_uniform(s, -2.5, 2.5);
            d[i] = tgt[i] - o[i];
            l += d[i] * d[i];
        }
        l = sqrt(l);
        for (i = 0; i < 3; i++)
            d[i] /= l;
        has = ops->prim_span(cs, 0, o, d, t, face);
        /* inside/outside along the ray against the span [t0, t1) */
        for (j = 0; j < 16; j++) {
            double tt = test_uniform(s, 0, 20), p[3];
            int in_span = has && tt >= t[0] && tt < t[1];
            for (i = 0; i < 3; i++)
                p[i] = o[i] + tt * d[i];
            tt_to_object(sp, p, q);
            sd = tt_sdf(sp, q);
            if (fabs(sd) > 4 * tol && (sd < 0) != in_span) {
                if (f->inside++ < 3)
                    printf("# %s kind %d: t=%.6f sdf=%.3g span=%d [%.6f,%.6f)\n", ops->name, sp->shape->kind,
                           tt, sd, has, has ? t[0] : 0, has ? t[1] : 0);
            }
        }
        if (!ops->hit(cs, o, d, &h))
            continue;
        f->hits++;
        tt_to_object(sp, h.p, q);
        sd = tt_sdf(sp, q);
        /* the direction is rounded too, so the error grows with distance */
        if (fabs(sd) > 2 * tol * (1 + h.t / 10) || h.face < 0 || h.face >= prim_face_count(sp->shape->kind)) {
            if (f->surf++ < 3)
                printf("# %s kind %d: hit off the surface by %.3g (face %d)\n", ops->name, sp->shape->kind, sd, h.face);
        }
        if (!(h.sf.u >= 0 && h.sf.u <= 1 && h.sf.v >= 0 && h.sf.v <= 1))
            f->uv++;
        /* re-spawn from the hit point in a random direction */
        tt_random_dir(s, d2);
        dn = d2[0] * h.sf.n[0] + d2[1] * h.sf.n[1] + d2[2] * h.sf.n[2];
        if (fabs(dn) < 0.05)
            continue;
        i = ops->respawn(cs, o, d, d2, &h1, &h2);
        if (dn > 0 && i != 0) {
            if (f->respawn_out++ < 3)
                printf("# %s kind %d: outward re-spawn re-hit face %d at t=%.3g\n", ops->name,
                       sp->shape->kind, h2.face, h2.t);
        }
        if (dn < 0 && sp->shape->kind != PRIM_HALFSPACE && (i != 1 || h2.entering || !(h2.t > 0))) {
            if (f->respawn_in++ < 3)
                printf("# %s kind %d: inward re-spawn did not find the exit (%d)\n", ops->name, sp->shape->kind, i);
        }
    }
    ops->free(cs);
}

static void test_prim_properties_all_modes(void **state)
{
    uint64_t s = test_seed("test_prim_properties_all_modes");
    int m, kind, n;
    (void)state;
    for (m = 0; m < TT_MODES; m++)
        for (kind = 0; kind < PRIM_KIND_COUNT; kind++) {
            prim_fail f;
            unsigned long ov0 = fx_overflows;
            memset(&f, 0, sizeof f);
            for (n = 0; n < (m == 1 ? 3 : 12); n++) {
                char tail[256], deck[1024];
                scene *sc;
                tt_random_tail(&s, tail, sizeof tail);
                snprintf(deck, sizeof deck, "EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\n%s %s\nOBJECT P\n",
                         prim_decl[kind], tail);
                sc = tt_parse(deck);
                assert_non_null(sc);
                prim_check_scene(tt_mode(m), sc, &s, &f);
                scene_free(sc);
            }
            printf("# %s %s: %ld hits; failures surf=%ld uv=%ld inside=%ld respawn_out=%ld respawn_in=%ld\n",
                   tt_mode(m)->name, prim_decl[kind], f.hits, f.surf, f.uv, f.inside, f.respawn_out,
                   f.respawn_in);
            assert_true(f.hits > 0 || kind == PRIM_HALFSPACE);
            assert_int_equal(f.surf + f.uv + f.inside + f.respawn_out + f.respawn_in, 0);
            /* no saturation for any of these rays, inside or grazing */
            assert_int_equal(fx_overflows - ov0, 0);
        }
}

/* Faces and (u,v) at known points of an untransformed primitive, f64 mode. */
static void test_prim_face_mapping(void **state)
{
    static const struct {
        const char *decl;
        double o[3], d[3];
        int face;
        double u, v;
    } c[] = {
        {"CYLINDER P 1 2", {0.5, 0.5, 5}, {0, 0, -1}, PRIM_FACE_CYL_TOP, 0.75, 0.75},
        {"CYLINDER P 1 2", {0.5, 0.5, -5}, {0, 0, 1}, PRIM_FACE_CYL_BOTTOM, 0.25, 0.75},
        {"CYLINDER P 1 2", {5, 0, 0.5}, {-1, 0, 0}, PRIM_FACE_CYL_SIDE, 0.0, 0.25},
        {"CYLINDER P 1 2", {0, 5, 1}, {0, -1, 0}, PRIM_FACE_CYL_SIDE, 0.25, 0.5},
        {"BLOCK P 2 4 8", {5, 1, 2}, {-1, 0, 0}, PRIM_FACE_BLOCK_XMAX, 0.25, 0.25},
        {"BLOCK P 2 4 8", {-5, 1, 2}, {1, 0, 0}, PRIM_FACE_BLOCK_XMIN, 0.75, 0.25},
        {"BLOCK P 2 4 8", {0.5, -5, 2}, {0, 1, 0}, PRIM_FACE_BLOCK_YMIN, 0.25, 0.25},
        {"BLOCK P 2 4 8", {0.5, 9, 2}, {0, -1, 0}, PRIM_FACE_BLOCK_YMAX, 0.75, 0.25},
        {"BLOCK P 2 4 8", {0.5, 1, 20}, {0, 0, -1}, PRIM_FACE_BLOCK_ZMAX, 0.25, 0.25},
        {"BLOCK P 2 4 8", {0.5, 1, -20}, {0, 0, 1}, PRIM_FACE_BLOCK_ZMIN, 0.75, 0.25},
        {"SPHERE P 2", {0, 0, 9}, {0, 0, -1}, PRIM_FACE_SPHERE_SURFACE, 0.0, 1.0},
        {"SPHERE P 2", {0, -9, 0}, {0, 1, 0}, PRIM_FACE_SPHERE_SURFACE, 0.75, 0.5},
        {"CONE P 2 1 3", {0.5, 0, 9}, {0, 0, -1}, PRIM_FACE_CONE_TOP, 0.75, 0.5},
        {"CONE P 2 1 3", {9, 0, 1.5}, {-1, 0, 0}, PRIM_FACE_CONE_SIDE, 0.0, 0.5},
        {"HALFSPACE P", {2.25, -3.5, 9}, {0, 0, -1}, PRIM_FACE_HALFSPACE_PLANE, 0.25, 0.5},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof c / sizeof c[0]; i++) {
        char deck[512];
        scene *sc;
        void *cs;
        diag err;
        probe_hit h;
        diag_init(&err);
        snprintf(deck, sizeof deck, "EYE 30 -30 20\nLOOKAT 0 0 0\nLIGHT 0 0 20\n%s\nOBJECT P\n", c[i].decl);
        sc = tt_parse(deck);
        assert_non_null(sc);
        assert_int_equal(f64_probe_ops.compile(sc, &cs, &err), 0);
        assert_true(f64_probe_ops.hit(cs, c[i].o, c[i].d, &h));
        if (h.face != c[i].face || fabs(h.sf.u - c[i].u) > 1e-9 || fabs(h.sf.v - c[i].v) > 1e-9)
            printf("# case %zu (%s): face %d u %.6f v %.6f\n", i, c[i].decl, h.face, h.sf.u, h.sf.v);
        assert_int_equal(h.face, c[i].face);
        assert_true(fabs(h.sf.u - c[i].u) < 1e-9);
        assert_true(fabs(h.sf.v - c[i].v) < 1e-9);
        /* tangent frame: dpdu x dpdv points along the outward normal */
        {
            const double *a = h.sf.dpdu, *b = h.sf.dpdv;
            double x[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
            if (x[0] || x[1] || x[2])
                assert_true(x[0] * h.sf.n[0] + x[1] * h.sf.n[1] + x[2] * h.sf.n[2] > 0);
        }
        f64_probe_ops.free(cs);
        scene_free(sc);
    }
}

/* Grazing, tangent, in-plane, along-edge and through-apex rays: any hit
 * must lie on the surface, and no mode may saturate. */
static void test_prim_stress_grazing(void **state)
{
    static const struct { const char *decl; double o[3], d[3]; } c[] = {
        {"SPHERE P 1", {-5, 1, 0}, {1, 0, 0}},
        {"SPHERE P 1", {-5, 0.9999999, 0}, {1, 0, 0}},
        {"SPHERE P 1", {-5, 0, 1.0000001}, {1, 0, 0}},
        {"SPHERE P 1", {0, 0, 0}, {0, 0, 1}},
        {"BLOCK P 1 1 1", {-5, 0.5, 1}, {1, 0, 0}},
        {"BLOCK P 1 1 1", {-5, 0, 0}, {1, 0, 0}},
        {"BLOCK P 1 1 1", {-5, -5, 0.5}, {1, 1, 0}},
        {"BLOCK P 1 1 1", {-4, -4, -4}, {1, 1, 1}},
        {"CYLINDER P 1 1", {1, 0, -5}, {0, 0, 1}},
        {"CYLINDER P 1 1", {0, 0, -5}, {0, 0, 1}},
        {"CYLINDER P 1 1", {-5, 1, 0.5}, {1, 0, 0}},
        {"CYLINDER P 1 1", {-5, 0, 1}, {1, 0, 0}},
        {"CONE P 1 0 1", {0, 0, 5}, {0, 0, -1}},
        {"CONE P 1 0 1", {-5, 0, 1}, {1, 0, 0}},
        {"CONE P 1 0 1", {-1, 0, -5}, {0, 0, 1}},
        {"CONE P 1 0 1", {-2, 0, 2}, {1, 0, -1}},
        {"CONE P 0 1 1", {0, 0, -5}, {0, 0, 1}},
        {"HALFSPACE P", {-5, 0, 0}, {1, 0, 0}},
        {"HALFSPACE P", {-5, 0, 1}, {1, 0, -1e-6}},
    };
    size_t i;
    int m;
    (void)state;
    for (m = 0; m < TT_MODES; m++)
        for (i = 0; i < sizeof c / sizeof c[0]; i++) {
            char deck[512];
            scene *sc;
            void *cs;
            diag err;
            probe_hit h;
            double t[2], q[3];
            int face[2];
            unsigned long ov0 = fx_overflows;
            const probe_ops *ops = tt_mode(m);
            snprintf(deck, sizeof deck, "EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\n%s\nOBJECT P\n", c[i].decl);
            sc = tt_parse(deck);
            assert_non_null(sc);
            diag_init(&err);
            assert_int_equal(ops->compile(sc, &cs, &err), 0);
            (void)ops->prim_span(cs, 0, c[i].o, c[i].d, t, face);
            if (ops->hit(cs, c[i].o, c[i].d, &h)) {
                tt_to_object(&sc->prims[0], h.p, q);
                if (fabs(tt_sdf(&sc->prims[0], q)) > 2 * prim_tol(ops->name) * (1 + h.t / 10))
                    printf("# %s case %zu (%s): hit %.3g off the surface\n", ops->name, i, c[i].decl,
                           tt_sdf(&sc->prims[0], q));
                assert_true(fabs(tt_sdf(&sc->prims[0], q)) <= 2 * prim_tol(ops->name) * (1 + h.t / 10));
            }
            assert_int_equal(fx_overflows - ov0, 0);
            ops->free(cs);
            scene_free(sc);
        }
}

static void test_prim_face_names(void **state)
{
    (void)state;
    assert_string_equal(prim_face_name(PRIM_CYLINDER, PRIM_FACE_CYL_TOP), "TOP");
    assert_string_equal(prim_face_name(PRIM_BLOCK, PRIM_FACE_BLOCK_ZMAX), "ZMAX");
    assert_string_equal(prim_face_name(PRIM_CONE, PRIM_FACE_CONE_SIDE), "SIDE");
    assert_string_equal(prim_face_name(PRIM_SPHERE, 0), "SURFACE");
    assert_string_equal(prim_face_name(PRIM_HALFSPACE, 0), "PLANE");
    assert_null(prim_face_name(PRIM_SPHERE, 1));
    assert_null(prim_face_name(PRIM_BLOCK, -1));
    assert_int_equal(prim_face_count(PRIM_BLOCK), 6);
}

/* Compiling sc in ops fails with DIAG_INPUT and exactly message msg. */
static void prim_compile_fails(const probe_ops *ops, const scene *sc, const char *msg)
{
    void *cs;
    diag err;
    char buf[256];
    diag_init(&err);
    assert_int_equal(ops->compile(sc, &cs, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, msg);
}

/* A scene model built in C with a bad primitive: exact diagnostic. */
static void test_prim_rejects_bad_dimensions(void **state)
{
    scene *sc = tt_parse("EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\nSPHERE P 1\nOBJECT P\n");
    void *cs;
    diag err;
    (void)state;
    assert_non_null(sc);
    sc->shapes[0]->dim[0] = -1;
    prim_compile_fails(&q16_probe_ops, sc, "test.scene:4:1: error: primitive 'P': sphere radius must be positive");
    sc->shapes[0]->dim[0] = 1;
    sc->prims[0].world_from_object[0] = 0;
    sc->prims[0].world_from_object[5] = 0;
    prim_compile_fails(&f64_probe_ops, sc, "test.scene:4:1: error: primitive 'P': transform is singular");
    scene_free(sc);
    /* a half-space stays out of the scene's extent, so the primitive's own
     * checks see a non-finite transform: any entry, before the dimensions */
    sc = tt_parse("EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\nHALFSPACE P\nOBJECT P\n");
    assert_non_null(sc);
    sc->prims[0].world_from_object[11] = -HUGE_VAL;
    sc->shapes[0]->dim[2] = NAN;
    prim_compile_fails(&q16_probe_ops, sc, "test.scene:4:1: error: primitive 'P': transform is not finite");
    sc->prims[0].world_from_object[11] = 0;
    sc->prims[0].world_from_object[6] = NAN;
    prim_compile_fails(&f64_probe_ops, sc, "test.scene:4:1: error: primitive 'P': transform is not finite");
    sc->prims[0].world_from_object[6] = 0;
    prim_compile_fails(&f64_probe_ops, sc, "test.scene:4:1: error: primitive 'P': dimension is not finite");
    sc->shapes[0]->dim[2] = 0;
    diag_init(&err);
    assert_int_equal(f64_probe_ops.compile(sc, &cs, &err), 0);
    f64_probe_ops.free(cs);
    scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_prim_properties_all_modes),
        cmocka_unit_test(test_prim_face_mapping),
        cmocka_unit_test(test_prim_stress_grazing),
        cmocka_unit_test(test_prim_face_names),
        cmocka_unit_test(test_prim_rejects_bad_dimensions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
