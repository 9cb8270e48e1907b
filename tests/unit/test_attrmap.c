/* test_attrmap — attribute mapping in the renderer: bump normals (unit,
 * outside, the right tilt), texture sampling, refraction against Snell's law
 * and total internal reflection in every mode, and the PDS lookup of
 * Algorithm 1 step 3 end to end on a face with a bound PDS. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include "tracer_test.h"
#include "attr/attr_bump.h"
#include "attr/attr_texture.h"
#include "model/pds_region.h"
#include "model/scene_map.h"
#include "util/dmath.h"
#include "util/mem.h"

static double at_dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void at_random_unit(uint64_t *rng, double *v)
{
    double l;
    do {
        v[0] = test_uniform(rng, -1, 1);
        v[1] = test_uniform(rng, -1, 1);
        v[2] = test_uniform(rng, -1, 1);
        l = sqrt(at_dot(v, v));
    } while (l < 0.1 || l > 1);
    v[0] /= l; v[1] /= l; v[2] /= l;
}

/* Every pattern, random frames and amplitudes up to absurd ones: the normal
 * is unit length and never turns more than acos(ATTR_BUMP_MIN_COS) away
 * from the surface normal. */
static void test_bump_normals_unit_and_outside(void **state)
{
    uint64_t rng = test_seed("bump_normals");
    int pat, i, k;
    (void)state;
    for (pat = 0; pat < BUMP_PATTERN_COUNT; pat++) {
        scene_bump b;
        double moved = 0;
        memset(&b, 0, sizeof b);
        b.pattern = (bump_pattern)pat;
        b.freq[0] = 7;
        b.freq[1] = 3;
        b.seed = 9;
        for (i = 0; i < 20000; i++) {
            geom_surface sf;
            double t[3], n[3];
            memset(&sf, 0, sizeof sf);
            at_random_unit(&rng, sf.n);
            at_random_unit(&rng, t);
            /* tangents: t and n x t, scaled arbitrarily */
            for (k = 0; k < 3; k++)
                sf.dpdu[k] = (t[k] - at_dot(t, sf.n) * sf.n[k]) * test_uniform(&rng, 0.01, 50);
            sf.dpdv[0] = sf.n[1] * sf.dpdu[2] - sf.n[2] * sf.dpdu[1];
            sf.dpdv[1] = sf.n[2] * sf.dpdu[0] - sf.n[0] * sf.dpdu[2];
            sf.dpdv[2] = sf.n[0] * sf.dpdu[1] - sf.n[1] * sf.dpdu[0];
            for (k = 0; k < 3; k++)
                sf.dpdv[k] *= test_uniform(&rng, -3, 3);
            sf.u = test_uniform(&rng, 0, 1);
            sf.v = test_uniform(&rng, 0, 1);
            b.amplitude = pow(10, test_uniform(&rng, -6, 3)) * (i & 1 ? 1 : -1);
            attr_bump_normal(&b, test_uniform(&rng, 0.1, 10), &sf, n);
            assert_true(fabs(sqrt(at_dot(n, n)) - 1) < 1e-12);
            assert_true(at_dot(n, sf.n) >= ATTR_BUMP_MIN_COS - 1e-12);
            moved += 1 - at_dot(n, sf.n);
        }
        assert_true(moved > 100);   /* the patterns do perturb */
        assert_true(fabs(attr_bump_height(&b, 0.3, 0.7)) <= 1);
    }
}

/* On the plane z = 0 with u along x and v along y, WAVES across u rising in
 * +u must tilt the normal towards -x (Blinn: N' = n - h_u P_u/|P_u|^2 ...),
 * by the slope's angle. */
static void test_bump_tilt_direction(void **state)
{
    scene_bump b;
    geom_surface sf;
    double n[3], slope;
    (void)state;
    memset(&b, 0, sizeof b);
    memset(&sf, 0, sizeof sf);
    b.pattern = BUMP_WAVES;
    b.amplitude = 0.01;
    b.freq[0] = 1;
    b.freq[1] = 0;
    sf.n[2] = 1;
    sf.dpdu[0] = 2;     /* 2 units of x per unit of u */
    sf.dpdv[1] = 1;
    sf.u = 0;           /* h = sin(2 pi u): slope 2 pi per u at u = 0 */
    sf.v = 0.5;
    attr_bump_normal(&b, 1.0, &sf, n);
    slope = 0.01 * 2 * 3.14159265358979 / 2;   /* dz/dx */
    assert_true(n[0] < 0);
    assert_true(fabs(n[0] / n[2] + slope) < 1e-6);
    assert_true(fabs(n[1]) < 1e-12);
    /* a degenerate frame keeps the normal */
    memset(sf.dpdu, 0, sizeof sf.dpdu);
    attr_bump_normal(&b, 1.0, &sf, n);
    assert_true(n[0] == 0 && n[1] == 0 && n[2] == 1);
}

/* A 2 x 2 texture: texel centres give the texel's colour exactly, v runs up
 * from the bottom row, REPEAT tiles and the edges wrap without a seam. */
static void test_texture_sampling(void **state)
{
    static const uint8_t px[12] = {255, 0, 0,  0, 255, 0,      /* top: red, green */
                                   0, 0, 255,  255, 255, 255}; /* bottom: blue, white */
    scene_texture t;
    double c[3], c2[3];
    (void)state;
    memset(&t, 0, sizeof t);
    t.img.width = t.img.height = 2;
    t.img.channels = 3;
    t.img.px = (uint8_t *)px;
    t.repeat[0] = t.repeat[1] = 1;
    attr_texture_rgb(&t, 0.25, 0.25, c);     /* bottom left: blue */
    assert_true(c[0] == 0 && c[1] == 0 && c[2] == 1);
    attr_texture_rgb(&t, 0.75, 0.75, c);     /* top right: green */
    assert_true(c[0] == 0 && c[1] == 1 && c[2] == 0);
    attr_texture_rgb(&t, 0.5, 0.75, c);      /* between red and green */
    assert_true(fabs(c[0] - 0.5) < 1e-12 && fabs(c[1] - 0.5) < 1e-12 && c[2] == 0);
    attr_texture_rgb(&t, 0.0, 0.3, c);       /* wraps: u = 0 and u = 1 agree */
    attr_texture_rgb(&t, 1.0, 0.3, c2);
    assert_true(fabs(c[0] - c2[0]) < 1e-12 && fabs(c[1] - c2[1]) < 1e-12 && fabs(c[2] - c2[2]) < 1e-12);
    t.repeat[0] = 2;                         /* two copies across u */
    attr_texture_rgb(&t, 0.125, 0.25, c);
    attr_texture_rgb(&t, 0.625, 0.25, c2);
    assert_true(c[2] == 1 && c2[2] == 1);
    attr_texture_rgb(&t, NAN, 0.25, c);      /* NaN counts as 0: no crash */
    assert_true(c[0] >= 0 && c[0] <= 1);
}

/* Region frames (pds_region): a rotated, scaled rectangle's own square and
 * the distance to its outline, computed here from the rectangle's corners;
 * a brick tiling's cells; a union takes the first operand's frame. */
static void test_region_frames_and_edges(void **state)
{
    uint64_t rng = test_seed("region_frames");
    pds_def d;
    pds_region r;
    size_t k[2];
    int i;
    double c = cos(0.5), s = sin(0.5);
    (void)state;
    pds_def_init(&d, PDS_CPG, (scene_loc){ 0, 0 });
    k[0] = (size_t)pds_cpg_rect(&d, 0, 0, 1, 1, 3, (scene_loc){ 0, 0 });
    pds_cpg_scale(&d, k[0], 0.3, 0.2);
    pds_cpg_rotate(&d, k[0], dmath_deg(0.5));
    pds_cpg_translate(&d, k[0], 0.4, 0.3);
    k[1] = (size_t)pds_cpg_rect(&d, 0, 0, 1, 1, 4, (scene_loc){ 0, 0 });
    pds_cpg_op_node(&d, PDS_CPG_UNION, k, 2, PDS_INHERIT, (scene_loc){ 0, 0 });
    for (i = 0; i < 500; i++) {
        /* a point at local (a, b) of the rectangle: face = R (0.3 a, 0.2 b) + t */
        double a = test_uniform(&rng, 0.01, 0.99), b = test_uniform(&rng, 0.01, 0.99);
        double x = 0.3 * a, y = 0.2 * b, u = c * x - s * y + 0.4, v = s * x + c * y + 0.3;
        double e = fmin(fmin(0.3 * a, 0.3 * (1 - a)), fmin(0.2 * b, 0.2 * (1 - b)));
        assert_int_equal(pds_region_at(&d, u, v, &r), 1);
        assert_true(fabs(r.frame[0] - a) < 1e-12 && fabs(r.frame[1] - b) < 1e-12);
        assert_true(fabs(r.edge - e) < 1e-12);
    }
    assert_int_equal(pds_region_at(&d, 0.05, 0.95, &r), 1);   /* the second operand */
    assert_true(fabs(r.frame[0] - 0.05) < 1e-12 && fabs(r.edge - 0.05) < 1e-12);
    pds_def_free(&d);
    pds_def_init(&d, PDS_TILING, (scene_loc){ 0, 0 });
    d.tiling.shape = PDS_TILE_BRICK;
    d.tiling.size[0] = 0.25;
    d.tiling.size[1] = 0.125;
    pds_region_at(&d, 0.3, 0.15, &r);          /* row 1, shifted by 0.125 */
    assert_true(fabs(r.frame[0] - 0.7) < 1e-12 && fabs(r.frame[1] - 0.2) < 1e-12);
    assert_true(fabs(r.edge - 0.025) < 1e-12);
    pds_def_free(&d);
}

/* Grooves along tile edges: flat in the middle of a tile, the surface
 * falling towards each edge (the normal leans towards the edge), and a
 * LOCAL texture filling its region: its bottom-left quarter shows the
 * image's bottom-left texel. */
static void test_grooves_and_local_texture(void **state)
{
    static const uint8_t px[12] = {255, 0, 0,  0, 255, 0,
                                   0, 0, 255,  255, 255, 255};
    scene_bump b;
    scene_texture t;
    geom_surface sf;
    pds_def d;
    double n[3], col[3];
    (void)state;
    pds_def_init(&d, PDS_TILING, (scene_loc){ 0, 0 });
    memset(&b, 0, sizeof b);
    memset(&sf, 0, sizeof sf);
    b.pattern = BUMP_GROOVES;
    b.amplitude = 0.01;
    b.width = 0.02;
    sf.n[2] = 1;
    sf.dpdu[0] = 1;
    sf.dpdv[1] = 1;
    sf.u = 0.125;                 /* the middle of tile (0, 0): flat */
    sf.v = 0.125;
    attr_bump_normal_at(&b, &d, 1.0, &sf, n);
    assert_true(n[0] == 0 && n[1] == 0 && n[2] == 1);
    sf.u = 0.255;                 /* just right of the edge u = 0.25 */
    attr_bump_normal_at(&b, &d, 1.0, &sf, n);
    assert_true(n[0] < -0.1 && fabs(n[1]) < 1e-9);
    sf.u = 0.245;                 /* just left of it */
    attr_bump_normal_at(&b, &d, 1.0, &sf, n);
    assert_true(n[0] > 0.1);
    attr_bump_normal_at(&b, NULL, 1.0, &sf, n);   /* no PDS: flat */
    assert_true(n[0] == 0 && n[2] == 1);
    pds_def_free(&d);

    memset(&t, 0, sizeof t);
    t.img.width = t.img.height = 2;
    t.img.channels = 3;
    t.img.px = (uint8_t *)px;
    t.repeat[0] = t.repeat[1] = 1;
    t.local = 1;
    pds_def_init(&d, PDS_CPG, (scene_loc){ 0, 0 });
    pds_cpg_rect(&d, 0.2, 0.6, 0.4, 0.9, 1, (scene_loc){ 0, 0 });
    attr_texture_rgb_at(&t, &d, 0.25, 0.675, col);     /* region's (0.25, 0.25) */
    assert_true(col[0] < 1e-9 && col[1] < 1e-9 && col[2] > 1 - 1e-9);
    attr_texture_rgb_at(&t, &d, 0.35, 0.825, col);     /* region's (0.75, 0.75) */
    assert_true(col[0] < 1e-9 && col[1] > 1 - 1e-9 && col[2] < 1e-9);
    t.local = 0;                                       /* the face's (u,v) instead */
    attr_texture_rgb_at(&t, &d, 0.25, 0.675, col);
    assert_true(col[0] > 0.4 && col[2] < 0.6);
    pds_def_free(&d);
}

/* A height image: a left-to-right ramp tilts the normal against +u by
 * the ramp's slope (amplitude times 2 per image width). */
static void test_bump_height_image(void **state)
{
    uint8_t px[3 * 64];
    scene_bump b;
    geom_surface sf;
    double n[3];
    int i;
    (void)state;
    for (i = 0; i < 64; i++)
        px[3 * i] = px[3 * i + 1] = px[3 * i + 2] = (uint8_t)(i * 4);
    memset(&b, 0, sizeof b);
    memset(&sf, 0, sizeof sf);
    b.pattern = BUMP_IMAGE;
    b.amplitude = 0.01;
    b.freq[0] = b.freq[1] = 1;
    b.img.width = 64;
    b.img.height = 1;
    b.img.channels = 3;
    b.img.px = px;
    sf.n[2] = 1;
    sf.dpdu[0] = 1;
    sf.dpdv[1] = 1;
    sf.u = 0.5;
    sf.v = 0.5;
    attr_bump_normal(&b, 1.0, &sf, n);
    /* grey rises 4/255 per texel of 1/64: dh/du = 2 * 4 * 64 / 255 */
    assert_true(fabs(-n[0] / n[2] - 0.01 * 2 * 4 * 64 / 255.0) < 1e-6);
    b.img.px = NULL;
}

/* Refraction in every mode: sin(theta_t) = eta sin(theta_i), t in the plane
 * of d and n, and total internal reflection exactly beyond the critical
 * angle (tested with a margin of 1e-3 in sin). */
static void test_refraction_snell_and_tir(void **state)
{
    static const double etas[] = {1 / 1.5, 1.5, 1 / 1.33, 1.33, 1.0};
    static const double tol[4] = {2e-4, 1e-8, 1e-6, 1e-12};
    uint64_t rng = test_seed("refraction");
    int m, i;
    (void)state;
    for (m = 0; m < 4; m++) {
        const probe_ops *ops = tt_mode(m);
        double worst = 0;
        for (i = 0; i < 5000; i++) {
            double n[3], d[3], t[3], c[3], eta = etas[i % 5], cosi, sini, sint;
            int k;
            int r;
            at_random_unit(&rng, n);
            at_random_unit(&rng, d);
            cosi = -at_dot(d, n);
            if (cosi < 0) {
                for (k = 0; k < 3; k++)
                    d[k] = -d[k];
                cosi = -cosi;
            }
            if (cosi < 1e-3)
                continue;
            sini = sqrt(1 - cosi * cosi);
            r = ops->refract(d, n, eta, t);
            if (eta * sini > 1 + 1e-3) {
                assert_int_equal(r, 1);
                continue;
            }
            if (eta * sini > 1 - 1e-3)
                continue;
            assert_int_equal(r, 0);
            assert_true(fabs(sqrt(at_dot(t, t)) - 1) < tol[m] * 4);
            assert_true(at_dot(t, n) < 0);                  /* goes through */
            c[0] = d[1] * n[2] - d[2] * n[1];               /* coplanar with d, n */
            c[1] = d[2] * n[0] - d[0] * n[2];
            c[2] = d[0] * n[1] - d[1] * n[0];
            assert_true(fabs(at_dot(c, t)) < tol[m] * 4);
            c[0] = t[1] * n[2] - t[2] * n[1];               /* |t x n| = sin t */
            c[1] = t[2] * n[0] - t[0] * n[2];
            c[2] = t[0] * n[1] - t[1] * n[0];
            sint = sqrt(at_dot(c, c));
            if (fabs(sint - eta * sini) > worst)
                worst = fabs(sint - eta * sini);
        }
        printf("# %s: worst |sin t - eta sin i| = %.2e\n", ops->name, worst);
        assert_true(worst < tol[m]);
    }
}

/* Every face of every primitive, placed by a random rotation and shift,
 * hit by random rays: (u,v) lies in [0,1]^2, and (u,v) is continuous with
 * the derivatives as its rate: for a second hit a small step away on the
 * same face, p2 - p1 = dpdu du + dpdv dv to first order (f64; the mapping
 * is evaluated in double, so q16, whose hit points are quantised to 2^-16,
 * is held to the range). */
static void test_face_uv_range_and_continuity(void **state)
{
    static const char *const decl[] = {"SPHERE P 1.3", "CYLINDER P 1 2", "BLOCK P 2 3 1",
                                       "CONE P 1.5 0.5 2", "CONE P 0 1 2", "HALFSPACE P"};
    static const int modes[] = {0, 3};          /* q16, f64 */
    uint64_t rng = test_seed("face_uv");
    int faces_seen[6][6];
    size_t k, m;
    (void)state;
    memset(faces_seen, 0, sizeof faces_seen);
    for (k = 0; k < sizeof decl / sizeof decl[0]; k++)
        for (m = 0; m < 2; m++) {
            const probe_ops *ops = tt_mode(modes[m]);
            double worst = 0;
            int trial, compared = 0;
            for (trial = 0; trial < 4; trial++) {
                char deck[512];
                scene *sc;
                void *cs;
                diag err;
                int i;
                snprintf(deck, sizeof deck,
                         "EYE 30 -30 20\nLOOKAT 0 0 0\nLIGHT 0 0 20\n%s ROTATE AXIS %.3f %.3f %.3f %.1f -\n"
                         "TRANSLATE %.2f %.2f %.2f\nOBJECT P\n", decl[k], test_uniform(&rng, 0.1, 1),
                         test_uniform(&rng, -1, 1), test_uniform(&rng, -1, 1), test_uniform(&rng, 0, 360),
                         test_uniform(&rng, -1, 1), test_uniform(&rng, -1, 1), test_uniform(&rng, -1, 1));
                sc = tt_parse(deck);
                assert_non_null(sc);
                diag_init(&err);
                assert_int_equal(ops->compile(sc, &cs, &err), 0);
                for (i = 0; i < 3000; i++) {
                    double o[3], d[3], d2[3], dp[3], r[3], len;
                    probe_hit h, h2;
                    int j;
                    at_random_unit(&rng, o);
                    for (j = 0; j < 3; j++) {
                        o[j] *= 12;
                        d[j] = test_uniform(&rng, -2, 2) - o[j];
                    }
                    len = sqrt(at_dot(d, d));
                    for (j = 0; j < 3; j++)
                        d[j] /= len;
                    if (!ops->hit(cs, o, d, &h))
                        continue;
                    assert_true(h.sf.u >= 0 && h.sf.u <= 1 && h.sf.v >= 0 && h.sf.v <= 1);
                    faces_seen[k][h.face] = 1;
                    if (modes[m] == 0)
                        continue;
                    for (j = 0; j < 3; j++)
                        d2[j] = d[j] + test_uniform(&rng, -1e-6, 1e-6);
                    len = sqrt(at_dot(d2, d2));
                    for (j = 0; j < 3; j++)
                        d2[j] /= len;
                    if (!ops->hit(cs, o, d2, &h2) || h2.face != h.face ||
                        fabs(h2.sf.u - h.sf.u) > 0.5 ||    /* the u seam of round faces, */
                        fabs(h2.sf.v - h.sf.v) > 0.5)      /* the tile edges of a plane */
                        continue;
                    for (j = 0; j < 3; j++) {
                        dp[j] = h2.sf.p[j] - h.sf.p[j];
                        r[j] = dp[j] - h.sf.dpdu[j] * (h2.sf.u - h.sf.u) - h.sf.dpdv[j] * (h2.sf.v - h.sf.v);
                    }
                    if (sqrt(at_dot(dp, dp)) < 1e-9 || sqrt(at_dot(dp, dp)) > 1e-3)   /* grazing */
                        continue;
                    compared++;
                    if (sqrt(at_dot(r, r)) / sqrt(at_dot(dp, dp)) > worst)
                        worst = sqrt(at_dot(r, r)) / sqrt(at_dot(dp, dp));
                }
                ops->free(cs);
                scene_free(sc);
            }
            if (modes[m] == 3) {
                printf("# %s: worst first-order residual %.2e of the step over %d pairs\n",
                       decl[k], worst, compared);
                assert_true(compared > 100);   /* the check is not vacuous */
                assert_true(worst < 5e-3);   /* second-order terms near apexes and poles */
            }
        }
    /* every face was hit (the point cap of "CONE P 0 1 2" cannot be) */
    for (k = 0; k < sizeof decl / sizeof decl[0]; k++) {
        static const int nfaces[] = {1, 3, 6, 3, 2, 1};
        int f;
        for (f = 0; f < nfaces[k]; f++)
            assert_true(faces_seen[k][f]);
    }
}

/* A block's YMIN face seen from the front carries a CPG: its left half
 * (u < 1/2) is region RED, the rest has no region and keeps the base
 * attribute. With ambient-only shading the pixels are the attributes'
 * colours, so every mode must show red on the left, grey on the right,
 * which also checks that (u,v) reads unmirrored from outside. */
static void test_render_face_pds_lookup(void **state)
{
    static const char deck[] =
        "EYE 1 -6 1\nLOOKAT 1 0 1\nUP 0 0 1\nFOV 30\nSIZE 32 32\n"
        "AMBIENT 1 1 1\nLIGHT 0 -10 10\n"
        "ATTR GREY COLOR 0.5 0.5 0.5 AMBIENT 1 DIFFUSE 0\n"
        "ATTR RED COLOR 1 0 0 AMBIENT 1 DIFFUSE 0\n"
        "BLOCK B 2 2 2 ATTR GREY\nOBJECT B\n";
    static const render_ops *const modes[] = {&q16_render_ops, &q32_render_ops,
                                              &f32_render_ops, &f64_render_ops};
    scene *sc = tt_parse(deck);
    scene_map *m;
    scene_loc loc = {1, 1};
    int i;
    (void)state;
    assert_non_null(sc);
    m = mem_calloc(1, sizeof *m);
    sc->maps = mem_calloc(1, sizeof *sc->maps);
    assert_true(m && sc->maps);
    strcpy(m->name, "HALF");
    pds_def_init(&m->def, PDS_CPG, loc);
    assert_true(pds_cpg_rect(&m->def, 0, 0, 0.5, 1, 2, loc) >= 0);   /* attrs[2] = RED */
    sc->maps[0] = m;
    sc->nmaps = 1;
    sc->shapes[0]->face_map[PRIM_FACE_BLOCK_YMIN] = 0;
    for (i = 0; i < 4; i++) {
        render_fb fb;
        render_stats st;
        render_opts o;
        diag err;
        const uint8_t *l, *r;
        memset(&o, 0, sizeof o);
        o.threads = 1;
        o.aa = 1;
        diag_init(&err);
        assert_int_equal(render_scene(sc, modes[i], &o, &fb, &st, &err), 0);
        l = fb.img.px + 3 * (16 * 32 + 10);
        r = fb.img.px + 3 * (16 * 32 + 22);
        assert_true(l[0] == 255 && l[1] == 0 && l[2] == 0);
        assert_true(r[0] == 128 && r[1] == 128 && r[2] == 128);
        /* one lookup per primary ray that hit the block's front face */
        assert_true(st.pds_lookups > 100 && st.pds_lookups <= 32 * 32);
        render_fb_free(&fb);
    }
    scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bump_normals_unit_and_outside),
        cmocka_unit_test(test_bump_tilt_direction),
        cmocka_unit_test(test_texture_sampling),
        cmocka_unit_test(test_region_frames_and_edges),
        cmocka_unit_test(test_grooves_and_local_texture),
        cmocka_unit_test(test_bump_height_image),
        cmocka_unit_test(test_refraction_snell_and_tir),
        cmocka_unit_test(test_face_uv_range_and_continuity),
        cmocka_unit_test(test_render_face_pds_lookup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
