/* test_scene_parse — the scene language: every statement, exact diagnostics,
 * card columns, continuation, transforms checked against independent
 * arithmetic, expansion and nesting limits, an allocation-failure sweep and
 * the decks in scenes/. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include "image/image_png.h"
#include "scene/scene_parse.h"
#include "model/scene_map.h"
#include "scene/scene_parser.h"
#include "scene/scene_xform.h"
#include "util/mem.h"
#include "support.h"
#include "scene_test.h"

/* A complete view, light and object, appended where a test needs a valid deck. */
#define TAIL "EYE 0 -10 0\nLOOKAT 0 0 0\nLIGHT 0 -10 10\n"

static scene *parse_ok(const char *text) { return st_parse_ok(text, NULL); }
static void expect_error(const char *text, const char *want) { st_expect_error(text, NULL, want); }

/* Appends a printf-formatted line to a growing buffer (test helper). */
static void addf(char **buf, size_t *len, size_t *cap, const char *fmt, ...)
{
    va_list ap;
    int n;
    for (;;) {
        va_start(ap, fmt);
        n = vsnprintf(*buf + *len, *cap - *len, fmt, ap);
        va_end(ap);
        if ((size_t)n < *cap - *len)
            break;
        *cap = *cap * 2 + (size_t)n;
        *buf = realloc(*buf, *cap);
        assert_non_null(*buf);
    }
    *len += (size_t)n;
}

static void apply(const double m[12], const double p[3], double out[3])
{
    int i;
    for (i = 0; i < 3; i++)
        out[i] = m[i * 4] * p[0] + m[i * 4 + 1] * p[1] + m[i * 4 + 2] * p[2] + m[i * 4 + 3];
}

static void assert_point(const double m[12], double x, double y, double z,
                         double ex, double ey, double ez)
{
    double p[3] = { x, y, z }, q[3];
    apply(m, p, q);
    assert_true(fabs(q[0] - ex) < 1e-12 && fabs(q[1] - ey) < 1e-12 && fabs(q[2] - ez) < 1e-12);
}

/* ---- statements ---------------------------------------------------------- */

static void test_scene_parse_view_statements(void **state)
{
    scene *s;
    (void)state;
    s = parse_ok("EYE 1 2 3\nLOOKAT 4 5 6.5\nUP 0 1 0\nFOV 45.5\nSIZE 640 480\n"
                 "AMBIENT 0.1 0.2 0.3\nBACKGROUND 0.4 0.5 0.6\nDEPTH 7\n"
                 "LIGHT 0 0 9\nSPHERE A 1\nOBJECT A\n");
    assert_true(s->view.eye[0] == 1 && s->view.eye[1] == 2 && s->view.eye[2] == 3);
    assert_true(s->view.look[0] == 4 && s->view.look[1] == 5 && s->view.look[2] == 6.5);
    assert_true(s->view.up[0] == 0 && s->view.up[1] == 1 && s->view.up[2] == 0);
    assert_true(s->view.fov_deg == 45.5);
    assert_int_equal(s->view.width, 640);
    assert_int_equal(s->view.height, 480);
    assert_true(s->ambient[0] == 0.1 && s->ambient[1] == 0.2 && s->ambient[2] == 0.3);
    assert_true(s->background[0] == 0.4 && s->background[1] == 0.5 && s->background[2] == 0.6);
    assert_int_equal(s->max_depth, 7);
    assert_string_equal(s->source, "t.scene");
    scene_free(s);
}

static void test_scene_parse_defaults(void **state)
{
    scene *s;
    (void)state;
    s = parse_ok("SPHERE A 1\nOBJECT A\n" TAIL);
    assert_true(s->view.up[0] == 0 && s->view.up[1] == 0 && s->view.up[2] == 1);
    assert_true(s->view.fov_deg == 40);
    assert_int_equal(s->view.width, 512);
    assert_int_equal(s->view.height, 512);
    assert_true(s->ambient[0] == 0.1 && s->ambient[2] == 0.1);
    assert_true(s->background[0] == 0 && s->background[1] == 0 && s->background[2] == 0);
    assert_int_equal(s->max_depth, 5);
    assert_int_equal(s->nattrs, 1);
    assert_string_equal(s->attrs[0].name, "DEFAULT");
    assert_true(s->attrs[0].color[0] == 0.8 && s->attrs[0].ambient == 1 &&
                s->attrs[0].diffuse == 0.8 && s->attrs[0].specular == 0 &&
                s->attrs[0].exponent == 20 && s->attrs[0].mirror == 0 &&
                s->attrs[0].transmit == 0 && s->attrs[0].ior == 1);
    assert_int_equal(s->prims[0].attr, 0);
    assert_true(s->lights[0].intensity == 1 && s->lights[0].color[1] == 1);
    assert_null(s->maps);
    assert_int_equal(s->nmaps, 0);
    scene_free(s);
}

static void test_scene_parse_light_and_attr(void **state)
{
    scene *s;
    const scene_attr *a;
    (void)state;
    s = parse_ok(TAIL "LIGHT 1 2 3 INTENSITY 0.5 COLOR 0.1 0.2 0.3\n"
                 "ATTR GLASS COLOR 0.2 0.3 0.4 AMBIENT 0.5 DIFFUSE 0.6 SPECULAR 0.7 -\n"
                 "  EXPONENT 33\nATTR GLASS2 IOR 1.5 TRANSMIT 0.9 MIRROR 0.1 COLOR 1 1 1\n"
                 "SPHERE A 1 ATTR glass2\nOBJECT A\n");
    assert_int_equal(s->nlights, 2);
    assert_true(s->lights[1].pos[0] == 1 && s->lights[1].pos[2] == 3);
    assert_true(s->lights[1].intensity == 0.5 && s->lights[1].color[2] == 0.3);
    assert_int_equal(s->lights[1].loc.line, 4);
    assert_int_equal(s->nattrs, 3);
    a = &s->attrs[1];
    assert_string_equal(a->name, "GLASS");
    assert_true(a->color[0] == 0.2 && a->color[2] == 0.4 && a->ambient == 0.5 &&
                a->diffuse == 0.6 && a->specular == 0.7 && a->exponent == 33 &&
                a->mirror == 0 && a->transmit == 0 && a->ior == 1);
    a = &s->attrs[2];
    /* DIFFUSE not written: what MIRROR and TRANSMIT leave of 1 */
    assert_true(a->ior == 1.5 && a->transmit == 0.9 && a->mirror == 0.1 && a->diffuse == 0);
    assert_int_equal(a->loc.line, 7);
    assert_int_equal(s->prims[0].attr, 2);
    scene_free(s);
}

/* Collects the warnings of a parse, formatted. */
typedef struct warnings {
    int n;
    char text[4][512];
} warnings;

static void collect_warning(void *ctx, const diag *w)
{
    warnings *ws = ctx;
    if (ws->n < 4)
        diag_format_warning(w, ws->text[ws->n], sizeof ws->text[0]);
    ws->n++;
}

/* Energy conservation at parse: the issue's deck (MIRROR 0.9 TRANSMIT 0.9
 * with DEPTH 32, which never finished) is scaled to sum 1 with a warning at
 * the attribute's name; a DIFFUSE left to its default gives way silently;
 * coefficients that conserve energy are kept exactly. */
static void test_scene_parse_energy(void **state)
{
    static const char deck[] = TAIL "DEPTH 32\nATTR GLASS COLOR 1 1 1 DIFFUSE 0.2 MIRROR 0.9 TRANSMIT 0.9 IOR 1.5\n"
                               "ATTR A COLOR 1 1 1 MIRROR 0.3\nATTR B COLOR 1 1 1 DIFFUSE 0.5 MIRROR 0.5\n"
                               "SPHERE S 1 ATTR GLASS\nOBJECT S\n";
    warnings ws;
    scene_loader ld = {NULL, &ws, collect_warning};
    recsrc src;
    recsrc_mem m;
    scene *s = NULL;
    diag err;
    const scene_attr *a;
    (void)state;
    memset(&ws, 0, sizeof ws);
    diag_init(&err);
    recsrc_from_memory(&src, &m, "t.scene", deck, strlen(deck));
    assert_int_equal(scene_parse_with(&src, &ld, &s, &err), 0);
    assert_int_equal(ws.n, 1);
    assert_string_equal(ws.text[0], "t.scene:5:6: warning: ATTR GLASS: DIFFUSE 0.2 + MIRROR 0.9 + TRANSMIT 0.9 = 2 "
                                    "sends on more light than arrives; scaled by 0.5 to DIFFUSE 0.1, MIRROR 0.45, "
                                    "TRANSMIT 0.45");
    a = &s->attrs[1];
    assert_true(fabs(a->diffuse - 0.1) < 1e-12 && fabs(a->mirror - 0.45) < 1e-12 && fabs(a->transmit - 0.45) < 1e-12);
    a = &s->attrs[2];
    assert_true(a->mirror == 0.3 && fabs(a->diffuse - 0.7) < 1e-12);
    a = &s->attrs[3];
    assert_true(a->mirror == 0.5 && a->diffuse == 0.5);
    scene_free(s);
}

static void test_scene_parse_primitives(void **state)
{
    scene *s;
    int i;
    (void)state;
    s = parse_ok(TAIL "SPHERE S 1.5\nCYLINDER C 2 3\nBLOCK B 1 2 3\nCONE K 1 0 4\n"
                 "HALFSPACE H\nOBJECT S\nOBJECT C\nOBJECT B\nOBJECT K\nOBJECT H\n");
    assert_int_equal(s->nprims, 5);
    assert_int_equal(s->nroots, 5);
    assert_int_equal(s->prims[0].shape->kind, PRIM_SPHERE);
    assert_true(s->prims[0].shape->dim[0] == 1.5);
    assert_int_equal(s->prims[1].shape->kind, PRIM_CYLINDER);
    assert_true(s->prims[1].shape->dim[0] == 2 && s->prims[1].shape->dim[1] == 3);
    assert_int_equal(s->prims[2].shape->kind, PRIM_BLOCK);
    assert_true(s->prims[2].shape->dim[0] == 1 && s->prims[2].shape->dim[1] == 2 && s->prims[2].shape->dim[2] == 3);
    assert_int_equal(s->prims[3].shape->kind, PRIM_CONE);
    assert_true(s->prims[3].shape->dim[0] == 1 && s->prims[3].shape->dim[1] == 0 && s->prims[3].shape->dim[2] == 4);
    assert_int_equal(s->prims[4].shape->kind, PRIM_HALFSPACE);
    assert_string_equal(s->prims[3].shape->name, "K");
    assert_int_equal(s->prims[3].shape->loc.line, 7);
    assert_int_equal(s->prims[3].shape->loc.col, 1);
    for (i = 0; i < 5; i++) {
        int k;
        assert_int_equal(s->nodes[s->roots[i]].op, CSG_LEAF);
        assert_int_equal(s->nodes[s->roots[i]].prim, i);
        for (k = 0; k < SCENE_MAX_FACES; k++)
            assert_int_equal(s->prims[i].shape->face_map[k], -1);
        assert_point(s->prims[i].world_from_object, 1, 2, 3, 1, 2, 3);
    }
    scene_free(s);
}

/* DIFF A B C = (A - B) - C; each OBJECT its own copies, which share their
 * definition's shape. */
static void test_scene_parse_csg_fold(void **state)
{
    scene *s;
    const scene_node *r, *l;
    (void)state;
    s = parse_ok(TAIL "SPHERE A 1\nSPHERE B 1\nSPHERE C 1\nDIFF D A B C\n"
                 "UNION U D A\nINTERSECT I A B\nOBJECT U\nOBJECT I\nOBJECT D\n");
    assert_int_equal(s->nprims, 4 + 2 + 3);
    assert_int_equal(s->nnodes, 7 + 3 + 5);
    assert_int_equal(s->nroots, 3);
    r = &s->nodes[s->roots[0]];
    assert_int_equal(r->op, CSG_UNION);
    assert_int_equal(s->nodes[r->right].op, CSG_LEAF);
    assert_string_equal(s->prims[s->nodes[r->right].prim].shape->name, "A");
    l = &s->nodes[r->left];                         /* D = (A - B) - C */
    assert_int_equal(l->op, CSG_DIFF);
    assert_string_equal(s->prims[s->nodes[l->right].prim].shape->name, "C");
    l = &s->nodes[l->left];
    assert_int_equal(l->op, CSG_DIFF);
    assert_string_equal(s->prims[s->nodes[l->left].prim].shape->name, "A");
    assert_string_equal(s->prims[s->nodes[l->right].prim].shape->name, "B");
    assert_int_equal(s->nshapes, 3);
    assert_ptr_equal(s->prims[s->nodes[l->left].prim].shape, s->prims[s->nodes[r->right].prim].shape);
    assert_ptr_not_equal(s->prims[s->nodes[l->left].prim].shape, s->prims[s->nodes[l->right].prim].shape);
    r = &s->nodes[s->roots[1]];
    assert_int_equal(r->op, CSG_INTER);
    assert_true(s->nodes[r->left].prim != s->nodes[s->roots[0]].right);
    r = &s->nodes[s->roots[2]];
    assert_int_equal(r->op, CSG_DIFF);
    scene_free(s);
}

/* TRANSLATE then ROTATE: the point moves first, then turns. Definition
 * transforms act first, then each enclosing use, then the OBJECT's. */
static void test_scene_parse_transform_order(void **state)
{
    scene *s;
    (void)state;
    s = parse_ok(TAIL "SPHERE A 1 TRANSLATE 1 0 0 ROTATE Z 90\n"
                 "SPHERE B 1 ROTATE Z 90 TRANSLATE 1 0 0\n"
                 "UNION U A SCALE 2 B TRANSLATE 0 0 5\n"
                 "OBJECT U ROTATE X 90\n");
    /* A: (1,0,0) -> (2,0,0) -> (0,2,0) -> scale (0,4,0) -> rot X (0,0,4) */
    assert_point(s->prims[0].world_from_object, 1, 0, 0, 0, 0, 4);
    /* B: (1,0,0) -> (0,1,0) -> (1,1,0) -> (1,1,5) -> rot X (1,-5,1) */
    assert_point(s->prims[1].world_from_object, 1, 0, 0, 1, -5, 1);
    scene_free(s);
    s = parse_ok(TAIL "BLOCK A 1 1 1 SCALE 2 3 4 ROTATE AXIS 1 1 1 120 -\n"
                 "MATRIX 1 0 0 10 0 1 0 20 0 0 1 30\nOBJECT A\n");
    /* (1,1,1) -> (2,3,4) -> x->y, y->z, z->x: (4,2,3) -> (14,22,33) */
    assert_point(s->prims[0].world_from_object, 1, 1, 1, 14, 22, 33);
    scene_free(s);
}

/* Seeded property: a random chain of transforms on a definition, an operand
 * and an OBJECT equals applying each step to the point in turn. */
/* A deck's numbers take strtod's value bit for bit: random decimal items
 * (signs, leading zeros, up to 12 integer and 25 fractional digits, a bare
 * leading or trailing point, exponents) and the edges of the fast path
 * (2^53 in the digits, 22 fractional digits), each as a TRANSLATE. */
static void test_scene_parse_numbers_as_strtod(void **state)
{
    static const char *const edge[] = {
        "0.1", "0.3", "-0.0", "+.5", "2.", "999999.9999999999", "0.9007199254740991",
        "0.9007199254740993", "0.0000000000000000000001", "1.0000000000000000000001",
        "0.00000000000000000000001", "123456.7890123456789", "5e-324", "1e6", "0.1e1"};
    uint64_t seed = test_seed("test_scene_parse_numbers_as_strtod");
    int deck, i;
    (void)state;
    for (deck = 0; deck < 8; deck++) {
        char *buf = NULL, item[2000][48];
        size_t len = 0, cap = 0;
        int n = 0;
        scene *sc;
        addf(&buf, &len, &cap, "%s", TAIL);
        while (n < 2000) {
            char *q = item[n];
            int k, ni = (int)(test_rand(&seed) % 13), nf = (int)(test_rand(&seed) % 26);
            int point = ni == 0 || test_rand(&seed) % 4 != 0;
            if (deck == 0 && n < (int)(sizeof edge / sizeof edge[0])) {
                strcpy(q, edge[n]);
            } else {
                *q = "+- "[test_rand(&seed) % 3];
                q += *q != ' ';
                for (k = 0; k < ni; k++)
                    *q++ = (char)('0' + test_rand(&seed) % (k < 6 && test_rand(&seed) % 3 ? 1 : 10));
                if (point) {
                    *q++ = '.';
                    for (k = 0; k < nf; k++)
                        *q++ = (char)('0' + test_rand(&seed) % 10);
                }
                if (q[-1] == '.' && (ni == 0 || q[-2] < '0' || q[-2] > '9'))
                    *q++ = '7';                       /* a digit in the mantissa */
                if (test_rand(&seed) % 8 == 0)
                    q += sprintf(q, "e%d", (int)(test_rand(&seed) % 30) - 20);
                *q = '\0';
                if (!(fabs(strtod(item[n], NULL)) <= 1e6))
                    continue;                         /* out of a deck's range */
            }
            addf(&buf, &len, &cap, "SPHERE S%d 1 TRANSLATE %s 0 0\nOBJECT S%d\n", n, item[n], n);
            n++;
        }
        sc = parse_ok(buf);
        for (i = 0; i < n; i++) {
            double want = 0.0 + strtod(item[i], NULL);   /* T * I keeps it, -0 as +0 */
            if (memcmp(&sc->prims[i].world_from_object[3], &want, sizeof want))
                fail_msg("%s read as %.17g, strtod gives %.17g", item[i],
                         sc->prims[i].world_from_object[3], want);
        }
        scene_free(sc);
        free(buf);
    }
}

/* scene_xform_mul gives the full 4x4 product bit for bit on affine
 * matrices: entries from a pool of signed zeros, ones, exact and inexact
 * values, products that overflow, and in half the cases one factor a
 * translation (linear part the identity); where the full product is not
 * finite, neither passes scene_xform_ok. A product times the identity is
 * the product again (it holds no -0), as the OBJECT expansion assumes. */
static void test_scene_parse_xform_mul_is_full_product(void **state)
{
    static const double pool[] = {0.0, -0.0, 1.0, -1.0, 0.5, -3.0, 1e-300, 1e200, -1e200};
    uint64_t seed = test_seed("test_scene_parse_xform_mul_is_full_product");
    int iter, i, j, k;
    (void)state;
    for (iter = 0; iter < 100000; iter++) {
        double a[16], b[16], full[16], got[16];
        int finite = 1;
        scene_xform_identity(a);
        scene_xform_identity(b);
        for (i = 0; i < 12; i++) {
            uint64_t r = test_rand(&seed);
            a[i] = r % 3 ? pool[r % 9] : test_uniform(&seed, -10, 10);
            r = test_rand(&seed);
            b[i] = r % 3 ? pool[r % 7] : test_uniform(&seed, -10, 10);
        }
        if (iter % 4 == 1 || iter % 4 == 2) {         /* a translation: its own path */
            double *t = iter % 4 == 1 ? a : b;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++)
                    t[i * 4 + j] = i == j ? 1.0 : 0.0;
        }
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) {
                double s = 0;
                for (k = 0; k < 4; k++)
                    s += a[i * 4 + k] * b[k * 4 + j];
                full[i * 4 + j] = s;
                finite &= isfinite(s) != 0;
            }
        memcpy(got, a, sizeof got);
        scene_xform_mul(got, got, b);                     /* aliasing a */
        if (finite) {
            double id[16], again[16];
            assert_memory_equal(got, full, sizeof got);
            scene_xform_identity(id);
            scene_xform_mul(again, got, id);
            assert_memory_equal(again, got, sizeof got);
        } else
            assert_false(scene_xform_ok(got) || scene_xform_ok(full));
    }
}

static void test_scene_parse_transform_property(void **state)
{
    uint64_t seed = test_seed("test_scene_parse_transform_property");
    int iter;
    (void)state;
    for (iter = 0; iter < 200; iter++) {
        char *buf = NULL;
        size_t len = 0, cap = 0;
        double p[3], q[3], got[3];
        int part, k;
        scene *s;
        addf(&buf, &len, &cap, "%s", TAIL);
        p[0] = test_uniform(&seed, -5, 5);
        p[1] = test_uniform(&seed, -5, 5);
        p[2] = test_uniform(&seed, -5, 5);
        memcpy(q, p, sizeof q);
        for (part = 0; part < 3; part++) {
            static const char *const head[] = { "SPHERE A 1", "\nUNION U A", "\nOBJECT U" };
            addf(&buf, &len, &cap, "%s", head[part]);
            for (k = (int)(test_rand(&seed) % 4); k > 0; k--) {
                int kind = (int)(test_rand(&seed) % 3);
                double a = floor(test_uniform(&seed, -50, 50)) / 8;   /* exact in decimal */
                double b = floor(test_uniform(&seed, -50, 50)) / 8;
                double c = floor(test_uniform(&seed, -50, 50)) / 8;
                if (kind == 0) {
                    addf(&buf, &len, &cap, " -\n TRANSLATE %.3f %.3f %.3f", a, b, c);
                    q[0] += a; q[1] += b; q[2] += c;
                } else if (kind == 1) {
                    double ang = a * 7.2, r = ang * 3.14159265358979323846 / 180;
                    double x = q[0], y = q[1];
                    addf(&buf, &len, &cap, " -\n ROTATE Z %.4f", ang);
                    q[0] = x * cos(r) - y * sin(r);
                    q[1] = x * sin(r) + y * cos(r);
                } else {
                    if (a == 0) a = 1;
                    addf(&buf, &len, &cap, " -\n SCALE %.3f", a);
                    q[0] *= a; q[1] *= a; q[2] *= a;
                }
            }
            if (part == 1)
                addf(&buf, &len, &cap, " A");   /* the second operand */
            addf(&buf, &len, &cap, "\n");
        }
        s = parse_ok(buf);
        apply(s->prims[0].world_from_object, p, got);
        for (k = 0; k < 3; k++)
            assert_true(fabs(got[k] - q[k]) < 1e-9 * (1 + fabs(q[k])));
        scene_free(s);
        free(buf);
    }
}

/* The ATTR nearest the primitive wins: its own, then the innermost use. */
static void test_scene_parse_attr_inheritance(void **state)
{
    scene *s;
    (void)state;
    s = parse_ok(TAIL "ATTR R COLOR 1 0 0\nATTR G COLOR 0 1 0\nATTR B COLOR 0 0 1\n"
                 "SPHERE OWN 1 ATTR R\nSPHERE BARE 1\n"
                 "UNION U OWN BARE BARE ATTR G\nOBJECT U ATTR B\nOBJECT U\n");
    assert_int_equal(s->nprims, 6);
    assert_int_equal(s->prims[0].attr, 1);   /* own R */
    assert_int_equal(s->prims[1].attr, 3);   /* from OBJECT: B */
    assert_int_equal(s->prims[2].attr, 2);   /* operand ATTR G */
    assert_int_equal(s->prims[3].attr, 1);
    assert_int_equal(s->prims[4].attr, 0);   /* DEFAULT */
    assert_int_equal(s->prims[5].attr, 2);
    scene_free(s);
}

/* Columns 73-80 are ignored whatever they hold when column 72 or 73 is
 * blank; short and long lines work. */
static void test_scene_parse_sequence_columns(void **state)
{
    static const char *const cards[][2] = {
        { "EYE 0 -10 0", "BAD 9999" },
        { "LOOKAT 0 0 0", "))" },
        { "LIGHT 0 -10 10", "0003 and far beyond column 80: 1 2 3 FROB" },
        { "*23456789012345678901234567890123456789012345678901234567890123456789012", "SEQ" },
        { "SPHERE A 1", "9\x07\xff" },
        { "OBJECT A", "" },
    };
    char deck[2048];
    size_t len = 0, i;
    scene *s;
    (void)state;
    for (i = 0; i < sizeof cards / sizeof cards[0]; i++)
        len += (size_t)snprintf(deck + len, sizeof deck - len, "%-72s%s\n", cards[i][0], cards[i][1]);
    assert_int_equal(deck[72], 'B');
    s = parse_ok(deck);
    assert_int_equal(s->nprims, 1);
    assert_true(s->view.eye[1] == -10);
    scene_free(s);
    /* an item running into column 73: test_scene_parse_column72 */
}

static void test_scene_parse_continuation(void **state)
{
    scene *s;
    (void)state;
    s = parse_ok(TAIL "CYLINDER C -\n* a comment between the cards\n   2 -\n  3 TRANSLATE 1 -\n"
                 "-\n 2 3\nOBJECT C\n");
    assert_true(s->prims[0].shape->dim[0] == 2 && s->prims[0].shape->dim[1] == 3);
    assert_point(s->prims[0].world_from_object, 0, 0, 0, 1, 2, 3);
    scene_free(s);
    /* a blank card may not follow a continued card */
    expect_error(TAIL "SPHERE A 1 -\n\nOBJECT A\n",
                 "t.scene:4:12: error: continued statement has no continuation card");
    /* a "-" glued to an item is a sign, not a continuation */
    expect_error(TAIL "SPHERE A 1 TRANSLATE 1 2 -3-\n",
                 "t.scene:4:26: error: SPHERE: expected a number, found -3-");
}

static void test_scene_parse_case_insensitive(void **state)
{
    scene *s;
    (void)state;
    s = parse_ok("eye 0 -10 0\nLookAt 0 0 0\nlight 0 -10 10 color 1 1 1\n"
                 "attr Red Color 1 0 0\nsphere Ball 1e0 attr RED rotate z 90 Scale 2\n"
                 "Union u BALL ball\nobject U attr red\n");
    assert_int_equal(s->nprims, 2);
    assert_string_equal(s->prims[0].shape->name, "BALL");
    assert_string_equal(s->attrs[1].name, "RED");
    assert_int_equal(s->prims[0].attr, 1);
    scene_free(s);
}

static void test_scene_parse_names(void **state)
{
    scene *s;
    char deck[256];
    (void)state;
    /* 16 significant characters, and the characters allowed in a name */
    s = parse_ok(TAIL "SPHERE ABCDEFGHIJKLMNOP 1\nSPHERE A_1$#@ 2\nOBJECT abcdefghijklmnop\n"
                 "OBJECT a_1$#@\n");
    assert_string_equal(s->prims[0].shape->name, "ABCDEFGHIJKLMNOP");
    assert_string_equal(s->prims[1].shape->name, "A_1$#@");
    scene_free(s);
    /* attributes and solids have separate name spaces */
    s = parse_ok(TAIL "ATTR X COLOR 1 1 1\nSPHERE X 1 ATTR X\nOBJECT X\n");
    scene_free(s);
    snprintf(deck, sizeof deck, "%s", "SPHERE A 1 ATTR DEFAULT\nOBJECT A\n" TAIL);
    s = parse_ok(deck);
    assert_int_equal(s->prims[0].attr, 0);
    scene_free(s);
}

/* ---- diagnostics --------------------------------------------------------- */

static void test_scene_parse_error_texts(void **state)
{
    static const struct { const char *deck, *want; } cases[] = {
        { "FROB 1 2\n", "t.scene:1:1: error: unknown statement FROB" },
        { "EYE 1 2\n", "t.scene:1:8: error: EYE: missing number" },
        { "EYE 1 2 3 4\n", "t.scene:1:11: error: EYE: extra operand 4" },
        { "EYE 1 2 1.2.3\n", "t.scene:1:9: error: EYE: expected a number, found 1.2.3" },
        { "EYE 1 2 1e\n", "t.scene:1:9: error: EYE: expected a number, found 1e" },
        { "EYE 1 2 0x10\n", "t.scene:1:9: error: EYE: expected a number, found 0x10" },
        { "EYE 1 NaN 3\n", "t.scene:1:7: error: EYE: NaN is not a finite number" },
        { "EYE 1 -inf 3\n", "t.scene:1:7: error: EYE: -inf is not a finite number" },
        { "EYE 1 +Infinity 3\n", "t.scene:1:7: error: EYE: +Infinity is not a finite number" },
        { "EYE 1 2e6 3\n", "t.scene:1:7: error: EYE: 2e6 is out of range (magnitude above 1e6)" },
        { "EYE 1 -1000000.5 3\n",
          "t.scene:1:7: error: EYE: -1000000.5 is out of range (magnitude above 1e6)" },
        { "EYE 1 1e999 3\n", "t.scene:1:7: error: EYE: 1e999 is out of range (magnitude above 1e6)" },
        { "  SPHERE ABCDEFGHIJKLMNOPQ 1\n",
          "t.scene:1:10: error: SPHERE: name ABCDEFGHIJKLMNOPQ is longer than 16 characters" },
        { "SPHERE 9A 1\n",
          "t.scene:1:8: error: SPHERE: bad name 9A (a letter, then letters, digits or _ $ # @)" },
        { "SPHERE A.B 1\n",
          "t.scene:1:8: error: SPHERE: bad name A.B (a letter, then letters, digits or _ $ # @)" },
        { "SPHERE scale 1\n", "t.scene:1:8: error: SPHERE: scale is a reserved word, not a name" },
        { "SPHERE\n", "t.scene:1:7: error: SPHERE: missing name" },
        { "SPHERE A 1\nSPHERE a 2\n", "t.scene:2:8: error: SPHERE: a is already defined on record 1" },
        { "SPHERE A 1\nUNION A A A\n", "t.scene:2:7: error: UNION: A is already defined on record 1" },
        { "UNION U A B\n", "t.scene:1:9: error: UNION: A is used before it is defined" },
        { "OBJECT Q\n", "t.scene:1:8: error: OBJECT: Q is used before it is defined" },
        { "SPHERE A 0\n", "t.scene:1:10: error: SPHERE: radius must be positive" },
        { "CYLINDER C 1 -2\n", "t.scene:1:14: error: CYLINDER: height must be positive" },
        { "CONE K -1 1 1\n", "t.scene:1:8: error: CONE: radius must be 0 or more" },
        { "CONE K 0 0 1\n", "t.scene:1:10: error: CONE: radii must not both be zero" },
        { "CONE K 1 0 0\n", "t.scene:1:12: error: CONE: height must be positive" },
        { "BLOCK B 1 0 1\n", "t.scene:1:11: error: BLOCK: size must be positive" },
        { "HALFSPACE H 1\n", "t.scene:1:13: error: HALFSPACE: extra operand 1" },
        { "SPHERE A 1 MATRIX 1 0 0 0 0 1 0 0 1 0 0 0\n",
          "t.scene:1:12: error: SPHERE: MATRIX is singular" },
        { "SPHERE A 1 MATRIX 1 0 0 0 0 1 0 0 0 0 1\n", "t.scene:1:40: error: SPHERE: missing number" },
        { "SPHERE A 1 SCALE 1 0 1\n", "t.scene:1:20: error: SPHERE: SCALE factor must not be zero" },
        { "SPHERE A 1 SCALE 0\n", "t.scene:1:18: error: SPHERE: SCALE factor must not be zero" },
        { "SPHERE A 1 SCALE 1 2\n", "t.scene:1:21: error: SPHERE: missing number" },
        { "SPHERE A 1 ROTATE W 30\n",
          "t.scene:1:19: error: SPHERE: ROTATE needs X, Y, Z or AXIS, found W" },
        { "SPHERE A 1 ROTATE\n", "t.scene:1:18: error: SPHERE: ROTATE needs X, Y, Z or AXIS" },
        { "SPHERE A 1 ROTATE AXIS 0 0 0 30\n",
          "t.scene:1:19: error: SPHERE: ROTATE axis must not be zero" },
        { "SPHERE A 1 SCALE 1e6 SCALE 1e6 SCALE 1e6\n",
          "t.scene:1:32: error: SPHERE: transforms give a degenerate or out-of-range matrix" },
        { "SPHERE A 1 SCALE 1e6 SCALE 1e6\nOBJECT A SCALE 10\n",
          "t.scene:2:8: error: OBJECT: transforms make primitive A degenerate or out of range" },
        { "SPHERE A 1 ATTR RED\n", "t.scene:1:17: error: SPHERE: RED is used before it is defined" },
        { "SPHERE A 1 ATTR DEFAULT ATTR DEFAULT\n", "t.scene:1:25: error: SPHERE: ATTR given twice" },
        { "SPHERE A 1 ATTR\n", "t.scene:1:16: error: SPHERE: missing name" },
        { "SPHERE A 1 FOO\n", "t.scene:1:12: error: SPHERE: extra operand FOO" },
        { "SPHERE A 1\nUNION U A\n", "t.scene:2:10: error: UNION: needs at least two operands" },
        { "SPHERE A 1\nDIFFERENCE U A 5\n",
          "t.scene:2:16: error: DIFF: bad name 5 (a letter, then letters, digits or _ $ # @)" },
        { "SPHERE A 1\nOBJECT A B\n", "t.scene:2:10: error: OBJECT: extra operand B" },
        { "FOV 180\n", "t.scene:1:5: error: FOV: angle must be above 0 and below 180 degrees" },
        { "FOV 0\n", "t.scene:1:5: error: FOV: angle must be above 0 and below 180 degrees" },
        { "SIZE 0 10\n", "t.scene:1:6: error: SIZE: width must be a whole number from 1 to 16384" },
        { "SIZE 10 2.5\n", "t.scene:1:9: error: SIZE: height must be a whole number from 1 to 16384" },
        { "SIZE 10 16385\n", "t.scene:1:9: error: SIZE: height must be a whole number from 1 to 16384" },
        { "DEPTH 33\n", "t.scene:1:7: error: DEPTH: depth must be a whole number from 0 to 32" },
        { "AMBIENT 0.1 1.5 0\n", "t.scene:1:13: error: AMBIENT: a colour component must be between 0 and 1" },
        { "BACKGROUND 0 0 -0.1\n",
          "t.scene:1:16: error: BACKGROUND: a colour component must be between 0 and 1" },
        { "EYE 1 2 3\n  EYE 1 2 3\n", "t.scene:2:3: error: EYE given twice (first on record 1)" },
        { "LOOK 1 2 3\nLOOKAT 1 2 3\n", "t.scene:2:1: error: LOOKAT given twice (first on record 1)" },
        { "UP 0 0 0\n", "t.scene:1:4: error: UP: direction must not be zero" },
        { "LIGHT 1 2 3 COLOR 1 1 1 COLOR 1 1 1\n", "t.scene:1:25: error: LIGHT: COLOR given twice" },
        { "LIGHT 1 2 3 SHINY\n", "t.scene:1:13: error: LIGHT: expected COLOR or INTENSITY, found SHINY" },
        { "LIGHT 1 2 3 INTENSITY -1\n", "t.scene:1:23: error: LIGHT: INTENSITY must not be negative" },
        { "ATTR R DIFFUSE 0.5\n", "t.scene:1:19: error: ATTR: COLOR is required" },
        { "ATTR R COLOR 1 1 1 MIRROR 2\n", "t.scene:1:27: error: ATTR: MIRROR must be between 0 and 1" },
        { "ATTR R COLOR 1 1 1 IOR 0.5\n", "t.scene:1:24: error: ATTR: IOR must be between 1 and 10" },
        { "ATTR R COLOR 1 1 1 EXPONENT 0\n", "t.scene:1:29: error: ATTR: EXPONENT must be between 1 and 10000" },
        { "ATTR R COLOR 1 1 1 IOR 1 IOR 1\n", "t.scene:1:26: error: ATTR: IOR given twice" },
        { "ATTR DEFAULT COLOR 1 1 1\n", "t.scene:1:6: error: ATTR: DEFAULT is built in and cannot be redefined" },
        { "ATTR R COLOR 1 1 1\nATTR r COLOR 1 1 1\n",
          "t.scene:2:6: error: ATTR: r is already defined on record 1" },
        { "ATTR R COLOR 1 1 1 GLOSS 3\n", "t.scene:1:20: error: ATTR: expected COLOR, AMBIENT, "
          "DIFFUSE, SPECULAR, EXPONENT, MIRROR, TRANSMIT, IOR, TEXTURE, BUMP or MODEL, found GLOSS" },
        { "EYE 1 2 3 \x07\n", "t.scene:1:11: error: invalid character X'07'" },
        { "EYE 1 2 3 \xc3\xa9\n", "t.scene:1:11: error: invalid character X'C3'" },
        { "EYE 1 2 -\n* comment\n\n", "t.scene:1:9: error: continued statement has no continuation card" },
        { "LOOKAT 0 0 0\nLIGHT 1 1 1\nSPHERE A 1\nOBJECT A\n", "t.scene: error: scene has no EYE statement" },
        { "EYE 0 0 9\nLIGHT 1 1 1\nSPHERE A 1\nOBJECT A\n", "t.scene: error: scene has no LOOKAT statement" },
        { "EYE 0 0 9\nLOOKAT 0 0 0\nSPHERE A 1\nOBJECT A\n", "t.scene: error: scene has no LIGHT statement" },
        { TAIL "SPHERE A 1\n", "t.scene: error: scene has no OBJECT statement" },
        { "", "t.scene: error: scene has no EYE statement" },
        { "EYE 1 2 3\n LOOKAT 1 2 3\nLIGHT 0 0 0\nSPHERE A 1\nOBJECT A\n",
          "t.scene:2:2: error: LOOKAT: point is the EYE point" },
        { "SPHERE A 1 SCALE 1e-6 SCALE 1e-6 SCALE 1e-6\n",
          "t.scene:1:34: error: SPHERE: transforms give a degenerate or out-of-range matrix" },
        { "EYE 0 0 9\nLOOKAT 0 0 0\nLIGHT 0 0 0\nSPHERE A 1\nOBJECT A\n",
          "t.scene:2:1: error: UP is parallel to the line of sight" },
        { "EYE 0 9 0\nLOOKAT 0 0 0\nUP 0 -2 0\nLIGHT 0 0 0\nSPHERE A 1\nOBJECT A\n",
          "t.scene:3:1: error: UP is parallel to the line of sight" },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        expect_error(cases[i].deck, cases[i].want);
}

/* A record source that fails after its first record. */
static int failing_next(void *ctx, const char **rec, size_t *len, diag *err)
{
    int *calls = ctx;
    (void)err;
    if ((*calls)++ > 0)
        return -1;
    *rec = "EYE 1 2 3";
    *len = 9;
    return 1;
}

static void test_scene_parse_read_error(void **state)
{
    int calls = 0;
    recsrc src;
    scene *s = NULL;
    diag err;
    char buf[256];
    (void)state;
    src.next = failing_next;
    src.ctx = &calls;
    src.name = "r.scene";
    src.records = 0;
    diag_init(&err);
    assert_int_equal(scene_parse(&src, &s, &err), DIAG_IO);
    assert_null(s);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "r.scene:2: error: read error");
}

static void test_scene_parse_light_limit(void **state)
{
    char *buf = NULL;
    size_t len = 0, cap = 0;
    int i;
    scene *s;
    (void)state;
    addf(&buf, &len, &cap, "EYE 0 -10 0\nLOOKAT 0 0 0\nSPHERE A 1\nOBJECT A\n");
    for (i = 0; i < 64; i++)
        addf(&buf, &len, &cap, "LIGHT %d 0 9\n", i);
    s = parse_ok(buf);
    assert_int_equal(s->nlights, 64);
    scene_free(s);
    addf(&buf, &len, &cap, " LIGHT 0 0 9\n");
    expect_error(buf, "t.scene:69:2: error: LIGHT: more than 64 lights");
    free(buf);
}

static void test_scene_parse_item_limit(void **state)
{
    char *buf = NULL;
    size_t len = 0, cap = 0;
    int i;
    (void)state;
    addf(&buf, &len, &cap, "EYE");                  /* item 1 */
    for (i = 1; i < 600; i++)
        addf(&buf, &len, &cap, i % 20 == 0 ? " 1 -\n" : " 1");
    addf(&buf, &len, &cap, "\n");
    /* 21 items on card 1, then 20 per card: item 513 is the 12th of
     * card 26, at column 2 * 12 = 24 */
    expect_error(buf, "t.scene:26:24: error: statement has more than 512 items");
    free(buf);
}

/* ---- expansion and nesting limits ---------------------------------------- */

static void test_scene_parse_expansion_limit(void **state)
{
    char *buf = NULL;
    size_t len = 0, cap = 0;
    int i;
    scene *s;
    (void)state;
    addf(&buf, &len, &cap, TAIL "SPHERE S0 1\n");
    for (i = 1; i <= 60; i++)
        addf(&buf, &len, &cap, "UNION S%d S%d S%d TRANSLATE 1 0 0\n", i, i - 1, i - 1);
    addf(&buf, &len, &cap, "OBJECT S16\n");                /* 65536 primitives */
    s = parse_ok(buf);
    assert_int_equal(s->nprims, 65536);
    assert_int_equal(s->nnodes, 2 * 65536 - 1);
    scene_free(s);
    addf(&buf, &len, &cap, "OBJECT S15\n");                /* 98304 in all: fits */
    s = parse_ok(buf);
    assert_int_equal(s->nprims, 98304);
    scene_free(s);
    len -= strlen("OBJECT S15\n");
    addf(&buf, &len, &cap, "OBJECT S16\n");
    expect_error(buf, "t.scene:66:8: error: OBJECT: S16 brings the scene to more than "
                      "100000 primitives");
    len -= strlen("OBJECT S16\nOBJECT S16\n");
    addf(&buf, &len, &cap, "OBJECT S60\n");                /* 2^60: counts saturate */
    expect_error(buf, "t.scene:65:8: error: OBJECT: S60 brings the scene to more than "
                      "100000 primitives");
    free(buf);
}

static void test_scene_parse_deep_nesting(void **state)
{
    char *buf = NULL;
    size_t len = 0, cap = 0;
    int i;
    scene *s;
    (void)state;
    addf(&buf, &len, &cap, TAIL "SPHERE S0 1\n");
    for (i = 1; i < 64; i++)
        addf(&buf, &len, &cap, "INTER S%d S0 S%d\n", i, i - 1);
    addf(&buf, &len, &cap, "OBJECT S63\n");
    s = parse_ok(buf);                 /* 64 levels: the limit */
    assert_int_equal(s->nprims, 64);
    scene_free(s);
    len -= strlen("OBJECT S63\n");
    for (i = 64; i <= 10000; i++)
        addf(&buf, &len, &cap, "INTER S%d S0 S%d\n", i, i - 1);
    addf(&buf, &len, &cap, "OBJECT S10000\n");
    expect_error(buf, "t.scene:68:14: error: INTER: S63 would nest solids more than 64 deep");
    free(buf);
}

/* The table limits on attributes, solids and operands. */
static void test_scene_parse_table_limits(void **state)
{
    char *buf = NULL;
    size_t len = 0, cap = 0;
    int i, j;
    (void)state;
    for (i = 1; i < 4096; i++)                 /* DEFAULT is the 4096th */
        addf(&buf, &len, &cap, "ATTR A%d COLOR 1 1 1\n", i);
    addf(&buf, &len, &cap, "ATTR TOOMANY COLOR 1 1 1\n");
    expect_error(buf, "t.scene:4096:6: error: ATTR: more than 4096 attributes");
    len = 0;
    for (i = 0; i < 65536; i++)
        addf(&buf, &len, &cap, "HALFSPACE H%d\n", i);
    addf(&buf, &len, &cap, "HALFSPACE TOOMANY\n");
    expect_error(buf, "t.scene:65537:11: error: HALFSPACE: more than 65536 solids");
    len = 0;
    addf(&buf, &len, &cap, "SPHERE A 1\n");
    for (i = 0; i < 200; i++) {                /* 200 x 500 operands */
        addf(&buf, &len, &cap, "UNION U%d -\n", i);
        for (j = 0; j < 500; j++)
            addf(&buf, &len, &cap, j % 20 == 19 && j < 499 ? " A -\n" : " A");
        addf(&buf, &len, &cap, "\n");
    }
    addf(&buf, &len, &cap, "UNION LAST A A\n");
    expect_error(buf, "t.scene:5202:12: error: UNION: more than 100000 operands in all");
    free(buf);
}

/* Thousands of definitions parse quickly (hashed names) and keep order. */
static void test_scene_parse_many_definitions(void **state)
{
    char *buf = NULL;
    size_t len = 0, cap = 0;
    int i;
    scene *s;
    (void)state;
    addf(&buf, &len, &cap, TAIL);
    for (i = 0; i < 20000; i++)
        addf(&buf, &len, &cap, "SPHERE B%d 1 TRANSLATE %d 0 0\n", i, i % 1000);
    for (i = 19999; i >= 0; i -= 7)
        addf(&buf, &len, &cap, "OBJECT b%d\n", i);
    s = parse_ok(buf);
    assert_int_equal(s->nprims, (20000 + 6) / 7);
    assert_string_equal(s->prims[1].shape->name, "B19992");
    assert_point(s->prims[1].world_from_object, 0, 0, 0, 19992 % 1000, 0, 0);
    scene_free(s);
    free(buf);
}

/* ---- allocation failures and the shipped decks --------------------------- */

static void test_scene_parse_oom_sweep(void **state)
{
    size_t len;
    char *text = test_read_file("scenes/csg.scene", &len);
    long n;
    (void)state;
    assert_non_null(text);
    for (n = 0;; n++) {
        recsrc src;
        recsrc_mem m;
        scene *s = NULL;
        diag err;
        int r;
        diag_init(&err);
        recsrc_from_memory(&src, &m, "csg.scene", text, len);
        mem_fail_after(n);
        r = scene_parse(&src, &s, &err);
        mem_fail_after(-1);
        if (r == 0) {
            assert_non_null(s);
            assert_int_equal(s->nprims, 6);
            scene_free(s);
            break;
        }
        assert_int_equal(r, DIAG_IO);
        assert_null(s);
        assert_string_equal(err.msg, "out of memory");
        assert_true(n < 1000);
    }
    assert_true(n > 5);      /* the sweep did fail several allocations */
    mem_free(text);
}

/* Images named by the shipped decks live beside them in scenes/. */
static int scenes_image(void *ctx, const char *name, int channels, image *out, diag *err)
{
    char path[512];
    (void)ctx;
    snprintf(path, sizeof path, "scenes/%s", name);
    return image_read_png(path, channels, out, err);
}

static scene *parse_file(const char *path)
{
    scene_loader ld = {scenes_image, NULL, NULL};
    size_t len;
    char *text = test_read_file(path, &len);
    recsrc src;
    recsrc_mem m;
    scene *s = NULL;
    diag err;
    int r;
    assert_non_null(text);
    diag_init(&err);
    recsrc_from_memory(&src, &m, path, text, len);
    r = scene_parse_with(&src, &ld, &s, &err);
    if (r) {
        char buf[1024];
        diag_format(&err, buf, sizeof buf);
        fprintf(stderr, "%s\n", buf);
    }
    assert_int_equal(r, 0);
    mem_free(text);
    return s;
}

static void test_scene_parse_shipped_scenes(void **state)
{
    scene *s;
    const scene_node *n;
    (void)state;
    s = parse_file("scenes/fig1.scene");
    assert_int_equal(s->nprims, 5);
    assert_int_equal(s->nroots, 5);
    assert_int_equal(s->nlights, 2);
    assert_int_equal(s->nattrs, 17);
    assert_int_equal(s->nmaps, 4);
    assert_int_equal(s->nbumps, 2);
    assert_int_equal(s->prims[0].shape->kind, PRIM_CYLINDER);
    assert_string_equal(s->attrs[14].name, "CHROME");
    assert_true(s->attrs[14].mirror == 0.75 && s->attrs[14].exponent == 80);  /* continued card */
    assert_true(s->view.eye[2] > s->prims[0].shape->dim[1]);    /* seen from above the top face */
    /* the cylinder's SIDE and TOP carry PDS, its BOTTOM does not */
    assert_string_equal(s->maps[s->prims[0].shape->face_map[0]]->name, "SIDEMAP");
    assert_string_equal(s->maps[s->prims[0].shape->face_map[1]]->name, "TOPMAP");
    assert_int_equal(s->prims[0].shape->face_map[2], -1);
    scene_free(s);

    s = parse_file("scenes/csg.scene");
    assert_int_equal(s->nprims, 6);
    assert_int_equal(s->nroots, 2);
    n = &s->nodes[s->roots[0]];                          /* ((ROUND - X) - Y) - Z */
    assert_int_equal(n->op, CSG_DIFF);
    assert_int_equal(s->nodes[s->nodes[s->nodes[n->left].left].left].op, CSG_INTER);
    /* the bore turned onto x: its axis end (0,0,3) in object space lands on +x */
    assert_point(s->prims[2].world_from_object, 0, 0, 3, 1.5, 0, 0);
    assert_point(s->prims[3].world_from_object, 0, 0, 3, 0, -1.5, 0);
    assert_point(s->prims[4].world_from_object, 0, 0, 3, 0, 0, 1.5);
    scene_free(s);

    s = parse_file("scenes/coincident.scene");
    assert_int_equal(s->nprims, 3);
    assert_true(s->prims[1].shape->dim[1] == s->prims[0].shape->dim[2]);   /* caps on the faces */
    assert_point(s->prims[1].world_from_object, 0, 0, 1, 1, 1, 1);
    scene_free(s);
}

/* Every deck in scenes/ parses and is made of 80-column cards whose
 * sequence fields (columns 77-80) increase. */
static void test_scene_parse_every_deck(void **state)
{
    DIR *d = opendir("scenes");
    struct dirent *e;
    int decks = 0;
    (void)state;
    assert_non_null(d);
    while ((e = readdir(d)) != NULL) {
        char path[512], *text, *line;
        size_t len, n = strlen(e->d_name);
        long prev = -1;
        if (n < 6 || strcmp(e->d_name + n - 6, ".scene") != 0)
            continue;
        snprintf(path, sizeof path, "scenes/%s", e->d_name);
        scene_free(parse_file(path));
        text = test_read_file(path, &len);
        assert_non_null(text);
        for (line = text; line < text + len;) {
            char *nl = memchr(line, '\n', (size_t)(text + len - line));
            long seq;
            assert_non_null(nl);
            if (nl - line != 80)
                fprintf(stderr, "%s: a card of %d columns\n", path, (int)(nl - line));
            assert_int_equal(nl - line, 80);
            seq = strtol(line + 76, NULL, 10);
            assert_true(seq > prev);
            prev = seq;
            line = nl + 1;
        }
        mem_free(text);
        decks++;
    }
    closedir(d);
    assert_true(decks >= 3);
}

/* Column 72: an item crossing into the sequence field is refused at its
 * column (the two cuts the card rules used to make silently), or warned
 * about when 73-80 hold a sequence number; items ending by column 72,
 * comment cards and text wholly in 73-80 are unaffected. */
static int col72_warnings;
static char col72_last[1024];
static void col72_warn(void *ctx, const diag *w)
{
    (void)ctx;
    col72_warnings++;
    snprintf(col72_last, sizeof col72_last, "%s:%ld:%ld: %s", w->file, w->line, w->col, w->msg);
}

static void test_scene_parse_column72(void **state)
{
    static const char head[] = "EYE 10 -10 8\nLOOKAT 0 0 0\nLIGHT 5 -5 10\n";
    const scene_loader ld = { NULL, NULL, col72_warn };
    char deck[1024];
    scene *s;
    (void)state;
    snprintf(deck, sizeof deck, "%s%-68s8.123456\nOBJECT B\n", head, "SPHERE B");
    expect_error(deck, "t.scene:4:69: error: item '8.123456' runs past column 72 and would be cut "
                       "to '8.12' (columns 73-80 are the sequence field, not read); end it by column "
                       "72, or end the card with ' -' and go on on the next card");
    snprintf(deck, sizeof deck, "%s%-70s1.5 ATTR RED\nOBJECT B\n", head, "SPHERE B");
    expect_error(deck, "t.scene:4:71: error: item '1.5' runs past column 72 and would be cut to "
                       "'1.' (columns 73-80 are the sequence field, not read); end it by column "
                       "72, or end the card with ' -' and go on on the next card");
    /* against a sequence number: parsed as written, with one warning */
    col72_warnings = 0;
    snprintf(deck, sizeof deck, "%s%-69s1.5FIG10040\nOBJECT B\n", head, "SPHERE B");
    s = st_parse_ok(deck, &ld);
    assert_true(s->prims[0].shape->dim[0] == 1.5);
    scene_free(s);
    assert_int_equal(col72_warnings, 1);
    assert_string_equal(col72_last, "t.scene:4:70: item '1.5' ends in column 72, against "
                        "the sequence number 'FIG10040' in columns 73-80; if it was meant to be "
                        "longer it has been cut (columns 73-80 are not read)");
    /* ending in column 72 before a blank, a comment, text only in 73-80 */
    col72_warnings = 0;
    snprintf(deck, sizeof deck, "%s%-69s1.5 FIG10040\n*%-71s%s\n%-72sANYTHING\nOBJECT B\n", head,
             "SPHERE B", "", "a comment crossing 72", "");
    s = st_parse_ok(deck, &ld);
    assert_true(s->prims[0].shape->dim[0] == 1.5);
    scene_free(s);
    assert_int_equal(col72_warnings, 0);
}

/* The deck's record count (recsrc.records) only sizes the parser's
 * arrays: a count too small, right, or far too large (the room then
 * stops at the documented limits) gives the same scene, and a deck of
 * objects followed by a long tail of comments, which the first objects'
 * rate overestimates, parses alike. */
static void test_scene_parse_record_hint(void **state)
{
    static const size_t hints[] = {0, 1, 0 /* exact, below */, 1000000000};
    char *deck = malloc(200000);
    size_t len = 0, records = 0, h, i;
    scene *ref = NULL;
    (void)state;
    assert_non_null(deck);
    len += (size_t)sprintf(deck + len, "EYE 0 -40 10\nLOOKAT 0 0 0\nLIGHT 0 -40 40\nSPHERE S 1\nBLOCK C 1 1 1\n"
                           "CYLINDER Y 0.3 2\nDIFF P S C Y\n");
    records = 7;
    for (i = 0; i < 700; i++, records += 2)
        len += (size_t)sprintf(deck + len, "OBJECT P TRANSLATE %zu 0 0 -\n ROTATE Z %zu\n", i % 40, i);
    for (i = 0; i < 3000; i++, records++)
        len += (size_t)sprintf(deck + len, "* a comment after the objects\n");
    for (h = 0; h < sizeof hints / sizeof hints[0]; h++) {
        recsrc src;
        recsrc_mem m;
        scene *s = NULL;
        diag err;
        diag_init(&err);
        recsrc_from_memory(&src, &m, "t.scene", deck, len);
        src.records = h == 2 ? records : hints[h];
        if (scene_parse_with(&src, NULL, &s, &err)) {
            char buf[512];
            diag_format(&err, buf, sizeof buf);
            fail_msg("%s", buf);
        }
        assert_int_equal(s->nprims, 2100);
        assert_int_equal(s->nroots, 700);
        if (!ref) {
            ref = s;
            continue;
        }
        assert_int_equal(s->nnodes, ref->nnodes);
        for (i = 0; i < s->nprims; i++)
            assert_memory_equal(s->prims[i].world_from_object, ref->prims[i].world_from_object,
                                sizeof s->prims[i].world_from_object);
        assert_memory_equal(s->nodes, ref->nodes, s->nnodes * sizeof *s->nodes);
        assert_memory_equal(s->roots, ref->roots, s->nroots * sizeof *s->roots);
        scene_free(s);
    }
    scene_free(ref);
    free(deck);
}

/* An unknown keyword names the nearest one, inside a block its body's. */
static void test_scene_parse_did_you_mean(void **state)
{
    (void)state;
    expect_error("EYE 1 2 3\nLOKAT 0 0 0\n", "t.scene:2:1: error: unknown statement LOKAT (did you mean LOOKAT?)");
    expect_error("EYE 1 2 3\nSPHRE S 1\n", "t.scene:2:1: error: unknown statement SPHRE (did you mean SPHERE?)");
    expect_error("EYE 1 2 3\nXYZZY 1\n", "t.scene:2:1: error: unknown statement XYZZY");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_parse_view_statements),
        cmocka_unit_test(test_scene_parse_defaults),
        cmocka_unit_test(test_scene_parse_light_and_attr),
        cmocka_unit_test(test_scene_parse_energy),
        cmocka_unit_test(test_scene_parse_primitives),
        cmocka_unit_test(test_scene_parse_csg_fold),
        cmocka_unit_test(test_scene_parse_transform_order),
        cmocka_unit_test(test_scene_parse_numbers_as_strtod),
        cmocka_unit_test(test_scene_parse_xform_mul_is_full_product),
        cmocka_unit_test(test_scene_parse_transform_property),
        cmocka_unit_test(test_scene_parse_attr_inheritance),
        cmocka_unit_test(test_scene_parse_sequence_columns),
        cmocka_unit_test(test_scene_parse_continuation),
        cmocka_unit_test(test_scene_parse_case_insensitive),
        cmocka_unit_test(test_scene_parse_names),
        cmocka_unit_test(test_scene_parse_error_texts),
        cmocka_unit_test(test_scene_parse_read_error),
        cmocka_unit_test(test_scene_parse_record_hint),
        cmocka_unit_test(test_scene_parse_light_limit),
        cmocka_unit_test(test_scene_parse_item_limit),
        cmocka_unit_test(test_scene_parse_expansion_limit),
        cmocka_unit_test(test_scene_parse_deep_nesting),
        cmocka_unit_test(test_scene_parse_table_limits),
        cmocka_unit_test(test_scene_parse_many_definitions),
        cmocka_unit_test(test_scene_parse_oom_sweep),
        cmocka_unit_test(test_scene_parse_shipped_scenes),
        cmocka_unit_test(test_scene_parse_every_deck),
        cmocka_unit_test(test_scene_parse_column72),
        cmocka_unit_test(test_scene_parse_did_you_mean),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
