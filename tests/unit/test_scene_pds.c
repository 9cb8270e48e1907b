/* test_scene_pds — the attribute-mapping statements of the scene language:
 * TEXTURE, BUMP, ATTR ... TEXTURE/BUMP, PDS blocks of every kind, FACE.
 * Each statement is checked against the definition it must build, every
 * malformed definition against its exact diagnostic; images come from a
 * stub loader that makes small synthetic rasters. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/image_png.h"
#include "scene/scene_parse.h"
#include "model/scene_map.h"
#include "scene/scene_parser.h"
#include "util/mem.h"
#include "support.h"
#include "scene_test.h"

/* A complete view, light and object, so that a deck parses to the end. */
#define TAIL "EYE 0 -10 0\nLOOKAT 0 0 0\nLIGHT 0 -10 10\nSPHERE S 1\nOBJECT S\n"
#define ATTRS "ATTR RED COLOR 1 0 0\nATTR BLUE COLOR 0 0 1\n"   /* ids 1 and 2 */

/* ---- stub loader ----------------------------------------------------------
 * Every image is 3 x 2 pixels; pixel (x, y) has index (x + y) % 3, which is
 * its grey value (1 channel) or the colour red, green, blue (3 channels).
 * "bad.png" fails; "lying.png" breaks the contract with 2 channels. */
static const uint8_t stub_rgb[3][3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 } };
static int stub_calls;

static int stub_image(void *ctx, const char *name, int channels, image *out, diag *err)
{
    int x, y, k, r;
    (void)ctx;
    stub_calls++;
    if (strcmp(name, "bad.png") == 0)
        return diag_at(err, DIAG_IO, name, 0, 0, "not a PNG file");
    if (channels == IMAGE_INDEXED)
        channels = 1;
    r = image_alloc(out, 3, 2, channels, name, err);
    if (r)
        return r;
    for (y = 0; y < 2; y++)
        for (x = 0; x < 3; x++)
            for (k = 0; k < channels; k++)
                out->px[(y * 3 + x) * channels + k] =
                    channels == 1 ? (uint8_t)((x + y) % 3) : stub_rgb[(x + y) % 3][k];
    if (strcmp(name, "lying.png") == 0)
        out->channels = 2;
    return 0;
}

static const scene_loader stub = { stub_image, NULL, NULL };

static scene *parse_ok(const char *text) { return st_parse_ok(text, &stub); }

static const scene_map *map_named(const scene *s, const char *name)
{
    size_t i;
    for (i = 0; i < s->nmaps; i++)
        if (strcmp(s->maps[i]->name, name) == 0)
            return s->maps[i];
    fail_msg("no PDS %s", name);
    return NULL;
}

static void assert_xf(const pds_cpg_node *n, double a, double b, double c, double d, double e,
                      double f)
{
    const double want[6] = { a, b, c, d, e, f };
    int i;
    for (i = 0; i < 6; i++)
        assert_true(fabs(n->xf[i] - want[i]) < 1e-15);
}

/* ---- TEXTURE, BUMP, ATTR ------------------------------------------------- */

static void test_scene_pds_texture_bump_attr(void **state)
{
    scene *s;
    (void)state;
    stub_calls = 0;
    s = parse_ok("TEXTURE GRANITE IMAGE granite.png\n"
                 "texture wood image Wood.PNG repeat 4 2\n"
                 "BUMP RIPPLE WAVES AMPLITUDE 0.02 FREQUENCY 90 0\n"
                 "BUMP GRAIN noise SEED 2000000000 FREQUENCY 16 0.5 AMPLITUDE -3\n"
                 "BUMP EGG BUMPS AMPLITUDE 1e6\nBUMP PIT DIMPLES AMPLITUDE 0.1\n"
                 "ATTR STONE COLOR 1 1 1 TEXTURE GRANITE\n"
                 "ATTR OAK BUMP GRAIN COLOR 1 1 1 TEXTURE WOOD DIFFUSE 0.5\n"
                 "ATTR GRANITE COLOR 1 1 1 BUMP RIPPLE\n" TAIL);
    assert_int_equal(stub_calls, 2);
    assert_int_equal(s->ntextures, 2);
    assert_string_equal(s->textures[0].name, "GRANITE");
    assert_int_equal(s->textures[0].img.width, 3);
    assert_int_equal(s->textures[0].img.height, 2);
    assert_int_equal(s->textures[0].img.channels, 3);
    assert_memory_equal(s->textures[0].img.px + 3, stub_rgb[1], 3);
    assert_true(s->textures[0].repeat[0] == 1 && s->textures[0].repeat[1] == 1);
    assert_true(s->textures[1].repeat[0] == 4 && s->textures[1].repeat[1] == 2);
    assert_int_equal(s->textures[1].loc.line, 2);
    assert_int_equal(s->nbumps, 4);
    assert_int_equal(s->bumps[0].pattern, BUMP_WAVES);
    assert_true(s->bumps[0].amplitude == 0.02);
    assert_true(s->bumps[0].freq[0] == 90 && s->bumps[0].freq[1] == 0);
    assert_true(s->bumps[3].freq[0] == 8 && s->bumps[3].freq[1] == 8);
    assert_int_equal(s->bumps[0].seed, 1);
    assert_int_equal(s->bumps[1].pattern, BUMP_NOISE);
    assert_true(s->bumps[1].amplitude == -3);
    assert_true(s->bumps[1].freq[0] == 16 && s->bumps[1].freq[1] == 0.5);
    assert_int_equal(s->bumps[1].seed, 2000000000u);
    assert_int_equal(s->bumps[2].pattern, BUMP_BUMPS);
    assert_int_equal(s->bumps[3].pattern, BUMP_DIMPLES);
    assert_int_equal(s->bumps[3].loc.line, 6);
    /* DEFAULT, STONE, OAK, GRANITE: names of textures and attributes differ */
    assert_int_equal(s->nattrs, 4);
    assert_int_equal(s->attrs[0].texture, -1);
    assert_int_equal(s->attrs[0].bump, -1);
    assert_int_equal(s->attrs[1].texture, 0);
    assert_int_equal(s->attrs[1].bump, -1);
    assert_int_equal(s->attrs[2].texture, 1);
    assert_int_equal(s->attrs[2].bump, 1);
    assert_true(s->attrs[2].diffuse == 0.5);
    assert_int_equal(s->attrs[3].texture, -1);
    assert_int_equal(s->attrs[3].bump, 0);
    scene_free(s);
}

/* The paper's attribute kinds: the optical model named by MODEL (with the
 * defaults a mirror and a transparent attribute get), LOCAL placement,
 * a height image and grooves along region boundaries. */
static void test_scene_pds_models_local_grooves(void **state)
{
    scene *s;
    (void)state;
    stub_calls = 0;
    s = parse_ok("TEXTURE LABEL IMAGE granite.png REPEAT 1 1 LOCAL\n"
                 "BUMP JOINTS GROOVES WIDTH 0.01 AMPLITUDE 0.003\n"
                 "BUMP RELIEF IMAGE wood.png AMPLITUDE 0.02 LOCAL\n"
                 "ATTR M COLOR 1 1 1 MODEL MIRROR\n"
                 "ATTR G COLOR 1 1 1 MODEL TRANSPARENT MIRROR 0.1\n"
                 "ATTR B COLOR 1 1 1 model blinn SPECULAR 0.5 TEXTURE LABEL BUMP JOINTS\n"
                 "ATTR L COLOR 1 1 1 MODEL LAMBERT\n" TAIL);
    assert_int_equal(stub_calls, 2);
    assert_int_equal(s->textures[0].local, 1);
    assert_int_equal(s->bumps[0].pattern, BUMP_GROOVES);
    assert_true(s->bumps[0].width == 0.01 && s->bumps[0].amplitude == 0.003);
    assert_int_equal(s->bumps[1].pattern, BUMP_IMAGE);
    assert_int_equal(s->bumps[1].local, 1);
    assert_int_equal(s->bumps[1].img.width, 3);
    assert_true(s->bumps[1].freq[0] == 1 && s->bumps[1].freq[1] == 1);
    assert_int_equal(s->attrs[1].model, SHADE_MIRROR);
    assert_true(s->attrs[1].mirror == 1);
    assert_int_equal(s->attrs[2].model, SHADE_TRANSPARENT);
    assert_true(fabs(s->attrs[2].transmit - 0.9) < 1e-12 && s->attrs[2].ior == 1.5 && s->attrs[2].mirror == 0.1);
    assert_int_equal(s->attrs[3].model, SHADE_BLINN);
    assert_int_equal(s->attrs[4].model, SHADE_LAMBERT);
    assert_int_equal(s->attrs[0].model, SHADE_PHONG);
    scene_free(s);
}

/* ---- CPG ----------------------------------------------------------------- */

static void test_scene_pds_cpg(void **state)
{
    scene *s;
    const scene_map *p, *q;
    const pds_cpg *g;
    (void)state;
    s = parse_ok(ATTRS
                 "PDS P CPG\n"
                 "RECT R 0 0 0.5 0.5 ATTR RED TRANSLATE 0.1 0.2\n"
                 "  ellipse E 0.5 0.5 0.2 0.1 ROTATE 90 ATTR BLUE\n"
                 "CIRCLE C 0.5 0.5 0.25 ATTR NONE SCALE 2 SCALE 1 0.5\n"
                 "POLYGON G 0 0 1 0 -\n"
                 "          0.5 1 ATTR RED SHEAR 0.5 0\n"
                 "UNION U R E C ATTR BLUE\n"
                 "DIFF D U G\n"
                 "INTERSECTION I2 D\n"
                 "ROOT D\n"
                 "END\n"
                 "PDS Q CPG\nNEST N P TRANSLATE 0.25 0.25 SCALE 0.5\nRECT B 0 0 1 1\n"
                 "UNION TOP N B\nEND\n" TAIL);
    assert_int_equal(s->nmaps, 2);
    p = map_named(s, "P");
    q = map_named(s, "Q");
    assert_ptr_equal(p, s->maps[0]);
    assert_int_equal(p->loc.line, 3);
    assert_int_equal(p->def.kind, PDS_CPG);
    g = &p->def.cpg;
    assert_int_equal(g->nnodes, 7);
    assert_int_equal(g->root, 5);                       /* ROOT D, not the last node */
    assert_int_equal(g->nodes[0].op, PDS_CPG_RECT);
    assert_true(g->nodes[0].p[0] == 0 && g->nodes[0].p[2] == 0.5 && g->nodes[0].p[3] == 0.5);
    assert_int_equal(g->nodes[0].attr, 1);
    assert_int_equal(g->nodes[0].loc.line, 4);
    assert_int_equal(g->nodes[0].loc.col, 1);
    assert_xf(&g->nodes[0], 1, 0, 0.1, 0, 1, 0.2);
    assert_int_equal(g->nodes[1].op, PDS_CPG_ELLIPSE);
    assert_true(g->nodes[1].p[2] == 0.2 && g->nodes[1].p[3] == 0.1);
    assert_int_equal(g->nodes[1].attr, 2);
    assert_int_equal(g->nodes[1].loc.col, 3);
    assert_xf(&g->nodes[1], 0, -1, 0, 1, 0, 0);
    assert_int_equal(g->nodes[2].op, PDS_CPG_ELLIPSE);  /* a circle */
    assert_true(g->nodes[2].p[2] == 0.25 && g->nodes[2].p[3] == 0.25);
    assert_int_equal(g->nodes[2].attr, PDS_NONE);
    assert_xf(&g->nodes[2], 2, 0, 0, 0, 1, 0);
    assert_int_equal(g->nodes[3].op, PDS_CPG_POLYGON);   /* continued card */
    assert_int_equal(g->nodes[3].count, 3);
    assert_true(g->pts[2 * g->nodes[3].first + 4] == 0.5 && g->pts[2 * g->nodes[3].first + 5] == 1);
    assert_xf(&g->nodes[3], 1, 0.5, 0, 0, 1, 0);
    assert_int_equal(g->nodes[4].op, PDS_CPG_UNION);
    assert_int_equal(g->nodes[4].count, 3);
    assert_int_equal(g->kids[g->nodes[4].first], 0);
    assert_int_equal(g->kids[g->nodes[4].first + 2], 2);
    assert_int_equal(g->nodes[4].attr, 2);               /* ATTR overrides */
    assert_int_equal(g->nodes[5].op, PDS_CPG_DIFF);
    assert_int_equal(g->nodes[5].attr, PDS_INHERIT);
    assert_int_equal(g->kids[g->nodes[5].first + 1], 3);
    assert_int_equal(g->nodes[6].op, PDS_CPG_INTER);     /* alias */
    assert_int_equal(g->nodes[6].count, 1);
    g = &q->def.cpg;
    assert_int_equal(g->nodes[0].op, PDS_CPG_NESTED);
    assert_ptr_equal(g->nodes[0].sub, &p->def);
    assert_xf(&g->nodes[0], 0.5, 0, 0.125, 0, 0.5, 0.125);
    assert_int_equal(g->root, 2);                        /* default: the last */
    scene_free(s);
}

/* A union tree over 10,000 leaves, 19,999 nodes in all. */
static void test_scene_pds_cpg_many_nodes(void **state)
{
    size_t cap = 1 << 20, len = 0, n = 10000, level, i, next = 0;
    char *deck = malloc(cap);
    scene *s;
    (void)state;
    assert_non_null(deck);
    len += (size_t)sprintf(deck + len, "ATTR RED COLOR 1 0 0\nPDS BIG CPG\n");
    for (i = 0; i < n; i++)
        len += (size_t)sprintf(deck + len, "RECT N%zu %g %g %g %g ATTR RED\n", i, (i % 100) * 0.01,
                               (double)(i / 100) * 0.01, (i % 100) * 0.01 + 0.01,
                               (double)(i / 100) * 0.01 + 0.01);
    /* pairs of the previous level, an odd one out carried up by a 1-ary union */
    for (level = n, next = n, i = 0; level > 1; level = (level + 1) / 2) {
        size_t k, first = next - level;
        for (k = 0; k < level; k += 2, next++)
            if (k + 1 < level)
                len += (size_t)sprintf(deck + len, "UNION N%zu N%zu N%zu\n", next, first + k,
                                       first + k + 1);
            else
                len += (size_t)sprintf(deck + len, "UNION N%zu N%zu\n", next, first + k);
        assert_true(len < cap - 1000);
        i++;
    }
    len += (size_t)sprintf(deck + len, "END\n" TAIL);
    s = parse_ok(deck);
    assert_int_equal(s->maps[0]->def.cpg.nnodes, next);
    assert_true(next >= 2 * n - 1);
    assert_int_equal(s->maps[0]->def.cpg.root, next - 1);
    assert_true(i <= 14);                               /* log2(10000) levels */
    scene_free(s);
    free(deck);
}

/* ---- pixel arrays and quadtrees ------------------------------------------ */

static void test_scene_pds_pixels_keyed(void **state)
{
    scene *s;
    const pds_pixels *px;
    const pds_quadtree *qt;
    static const int32_t want[] = { 1, 1, 2, PDS_NONE, 2, 1, PDS_NONE, 2, 1, 1, 1, 1 };
    (void)state;
    s = parse_ok(ATTRS
                 "PDS CHECK PIXELS 4 3\n"
                 "KEY r RED\nKEY # BLUE\nKEY . NONE\n"
                 "ROW rr#.\n"
                 "ROW #r .#\n"
                 "ROW r r -\n"
                 "    rr\n"
                 "END\n"
                 "PDS QT QUADTREE 2 2\nKEY b BLUE\nKEY R RED\nROW bR\nROW RR\nEND\n"
                 "PDS QC QUADTREE\nCODE SPLIT RED NONE -\n BLUE\nCODE SPLIT RED RED BLUE BLUE\nEND\n"
                 TAIL);
    px = &map_named(s, "CHECK")->def.pixels;
    assert_int_equal(map_named(s, "CHECK")->def.kind, PDS_PIXELS);
    assert_int_equal(px->width, 4);
    assert_int_equal(px->height, 3);
    assert_int_equal(px->ncells, 12);
    assert_memory_equal(px->cells, want, sizeof want);
    qt = &map_named(s, "QT")->def.quad;
    assert_int_equal(qt->from_pixels, 1);
    assert_int_equal(qt->pixels.width, 2);
    assert_int_equal(qt->pixels.cells[0], 2);
    assert_int_equal(qt->pixels.cells[1], 1);
    qt = &map_named(s, "QC")->def.quad;
    assert_int_equal(qt->from_pixels, 0);
    assert_int_equal(qt->ncode, 9);
    assert_int_equal(qt->code[0], PDS_QT_SPLIT);
    assert_int_equal(qt->code[2], PDS_NONE);
    assert_int_equal(qt->code[3], 2);
    assert_int_equal(qt->code[4], PDS_QT_SPLIT);
    assert_int_equal(qt->code[8], 2);
    scene_free(s);
}

static void test_scene_pds_pixels_image(void **state)
{
    scene *s;
    const pds_pixels *px;
    /* stub pixel (x, y) has index (x + y) % 3 */
    static const int32_t rgb_want[] = { 1, 0, 2, 0, 2, 1 };     /* red RED, green DEFAULT, blue BLUE */
    static const int32_t grey_want[] = { 2, PDS_NONE, 1, PDS_NONE, 1, 2 };
    (void)state;
    s = parse_ok(ATTRS
                 "PDS COL PIXELS IMAGE map.png\n"
                 "KEY #ff0000 RED\nKEY #00FF00 DEFAULT\nKEY #0000Ff BLUE\nEND\n"
                 "PDS GREY PIXELS IMAGE grey.png\nINDEX BLUE NONE RED\nEND\n"
                 "PDS QI QUADTREE IMAGE grey.png\nINDEX BLUE NONE RED BLUE\nEND\n" TAIL);
    px = &map_named(s, "COL")->def.pixels;
    assert_int_equal(px->width, 3);
    assert_int_equal(px->height, 2);
    assert_memory_equal(px->cells, rgb_want, sizeof rgb_want);
    px = &map_named(s, "GREY")->def.pixels;
    assert_memory_equal(px->cells, grey_want, sizeof grey_want);
    assert_int_equal(map_named(s, "QI")->def.quad.from_pixels, 1);
    px = &map_named(s, "QI")->def.quad.pixels;
    assert_memory_equal(px->cells, grey_want, sizeof grey_want);
    scene_free(s);
}

/* ---- tilings, mosaics, curves -------------------------------------------- */

static void test_scene_pds_tiling(void **state)
{
    scene *s;
    const pds_tiling *t;
    (void)state;
    s = parse_ok(ATTRS
                 "PDS WALL TILING BRICK 0.25 0.125 OFFSET 0.25 MORTAR 0.01 NONE -\n"
                 "         CYCLE 1 -2 0\n"
                 "TILES RED BLUE NONE\nEND\n"
                 "PDS FLOOR TILING HEX 0.1 HASH 2147483647\nTILES RED\nEND\n"
                 "PDS CHESS TILING SQUARE 0.125\nTILES RED BLUE\nEND\n"
                 "PDS TRI TILING TRIANGLE 0.5 MORTAR 0 BLUE\nTILES BLUE\nEND\n" TAIL);
    t = &map_named(s, "WALL")->def.tiling;
    assert_int_equal(t->shape, PDS_TILE_BRICK);
    assert_true(t->size[0] == 0.25 && t->size[1] == 0.125 && t->offset == 0.25);
    assert_true(t->mortar == 0.01);
    assert_int_equal(t->mortar_attr, PDS_NONE);
    assert_int_equal(t->rule, PDS_RULE_CYCLE);
    assert_true(t->step[0] == 1 && t->step[1] == -2 && t->step[2] == 0);
    assert_int_equal(t->nattrs, 3);
    assert_int_equal(t->attrs[1], 2);
    assert_int_equal(t->attrs[2], PDS_NONE);
    t = &map_named(s, "FLOOR")->def.tiling;
    assert_int_equal(t->shape, PDS_TILE_HEX);
    assert_int_equal(t->rule, PDS_RULE_HASH);
    assert_int_equal(t->seed, 2147483647u);
    t = &map_named(s, "CHESS")->def.tiling;
    assert_true(t->size[0] == 0.125 && t->size[1] == 0.125);      /* h defaults to w */
    assert_true(t->step[0] == 1 && t->step[1] == 1 && t->step[2] == 0);
    t = &map_named(s, "TRI")->def.tiling;
    assert_int_equal(t->shape, PDS_TILE_TRIANGLE);
    assert_int_equal(t->mortar_attr, 2);
    scene_free(s);
}

/* splitmix64 written out again, for the SCATTER reference. */
static double ref_uniform(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}

static void test_scene_pds_mosaic(void **state)
{
    scene *s, *s2;
    const pds_mosaic *m;
    uint64_t x = 42;
    size_t i;
    (void)state;
    s = parse_ok(ATTRS
                 "PDS STONES MOSAIC MORTAR 0.02 BLUE\n"
                 "SEED 0.5 0.5 RED\nSEED 0 1 NONE\n"
                 "SCATTER 1000 42 RED BLUE DEFAULT\nEND\n"
                 "PDS PLAIN MOSAIC\nSCATTER 1 0 RED\nEND\n" TAIL);
    m = &map_named(s, "STONES")->def.mosaic;
    assert_true(m->mortar == 0.02);
    assert_int_equal(m->mortar_attr, 2);
    assert_int_equal(m->nseeds, 1002);
    assert_true(m->seeds[0] == 0.5 && m->seeds[3] == 1);
    assert_int_equal(m->attrs[0], 1);
    assert_int_equal(m->attrs[1], PDS_NONE);
    for (i = 0; i < 1000; i++) {
        double u = ref_uniform(&x), v = ref_uniform(&x);
        assert_true(m->seeds[2 * (i + 2)] == u && m->seeds[2 * (i + 2) + 1] == v);
        assert_true(u >= 0 && u < 1 && v >= 0 && v < 1);
        assert_int_equal(m->attrs[i + 2], (int32_t)((i + 1) % 3));   /* RED BLUE DEFAULT */
    }
    assert_int_equal(map_named(s, "PLAIN")->def.mosaic.nseeds, 1);
    assert_int_equal(map_named(s, "PLAIN")->def.mosaic.mortar_attr, PDS_NONE);
    /* the same deck gives the same seeds */
    s2 = parse_ok(ATTRS "PDS STONES MOSAIC MORTAR 0.02 BLUE\nSEED 0.5 0.5 RED\nSEED 0 1 NONE\n"
                  "SCATTER 1000 42 RED BLUE DEFAULT\nEND\n" TAIL);
    assert_memory_equal(s2->maps[0]->def.mosaic.seeds, m->seeds, 2 * 1002 * sizeof(double));
    scene_free(s2);
    scene_free(s);
}

static void test_scene_pds_curves(void **state)
{
    scene *s;
    const pds_curves *k;
    (void)state;
    s = parse_ok(ATTRS
                 "PDS BLOB CURVES TOLERANCE 0.001\n"
                 "BSPLINE RED 0.3 0.3 0.7 0.3 0.7 0.7 0.3 0.7\n"
                 "POLYLINE NONE 0.1 0.1 0.9 0.1 -\n"
                 "              0.9 0.9 0.1 0.9\n"
                 "END\n"
                 "PDS FINE CURVES\nPOLYLINE BLUE 0 0 1 0 1 1\nEND\n"
                 "PDS STRIPY CURVES TOLERANCE 0.0005 STRIPS WIDTH 0.01\nPOLYLINE BLUE 0 0 1 0 1 1\nEND\n"
                 "PDS BALLARD CURVES STRIPS\nPOLYLINE BLUE 0 0 1 0 1 1\nEND\n" TAIL);
    k = &map_named(s, "BLOB")->def.curves;
    assert_true(k->tolerance == 0.001);
    assert_int_equal(k->ncurves, 2);
    assert_int_equal(k->curves[0].bspline, 1);
    assert_int_equal(k->curves[0].count, 4);
    assert_int_equal(k->curves[0].attr, 1);
    assert_int_equal(k->curves[0].loc.line, 4);
    assert_int_equal(k->curves[1].bspline, 0);
    assert_int_equal(k->curves[1].attr, PDS_NONE);
    assert_true(k->pts[2 * k->curves[1].first + 5] == 0.9);
    assert_true(map_named(s, "FINE")->def.curves.tolerance == PDS_CURVE_TOLERANCE);
    assert_int_equal(map_named(s, "FINE")->def.curves.strips, 0);
    k = &map_named(s, "STRIPY")->def.curves;
    assert_true(k->strips == 1 && k->strip_width == 0.01 && k->tolerance == 0.0005);
    k = &map_named(s, "BALLARD")->def.curves;
    assert_true(k->strips == 1 && k->strip_width == 0);
    scene_free(s);
}

/* ---- FACE ---------------------------------------------------------------- */

static void test_scene_pds_face(void **state)
{
    scene *s;
    size_t i;
    int k;
    (void)state;
    s = parse_ok("PDS P CPG\nRECT R 0 0 1 1\nEND\nPDS Q TILING SQUARE 0.5\nTILES DEFAULT\nEND\n"
                 "CYLINDER CAN 1 2\nBLOCK BOX 1 1 1\nHALFSPACE FLOOR\nCONE K 1 0 1\n"
                 "FACE CAN SIDE P\nface can top q\nFACE BOX ZMAX Q\nFACE BOX xmin P\n"
                 "FACE FLOOR PLANE P\nFACE K BOTTOM Q\n"
                 "UNION U CAN BOX\nOBJECT U\nOBJECT CAN\nOBJECT FLOOR\nOBJECT K\n"
                 "EYE 0 -10 0\nLOOKAT 0 0 0\nLIGHT 0 -10 10\n");
    assert_int_equal(s->nprims, 5);
    for (i = 0; i < s->nprims; i++) {
        const scene_prim *pr = &s->prims[i];
        int want[SCENE_MAX_FACES] = { -1, -1, -1, -1, -1, -1 };
        if (strcmp(pr->shape->name, "CAN") == 0)
            want[0] = 0, want[1] = 1;
        else if (strcmp(pr->shape->name, "BOX") == 0)
            want[5] = 1, want[0] = 0;
        else if (strcmp(pr->shape->name, "FLOOR") == 0)
            want[0] = 0;
        else if (strcmp(pr->shape->name, "K") == 0)
            want[2] = 1;
        for (k = 0; k < SCENE_MAX_FACES; k++)
            assert_int_equal(pr->shape->face_map[k], want[k]);
    }
    scene_free(s);
    /* a deck without FACE leaves every face unbound */
    s = parse_ok(TAIL);
    for (k = 0; k < SCENE_MAX_FACES; k++)
        assert_int_equal(s->prims[0].shape->face_map[k], -1);
    scene_free(s);
}

/* ---- diagnostics --------------------------------------------------------- */

#define CPG_OPEN ATTRS "PDS P CPG\n"          /* the block opens on record 3 */

static void test_scene_pds_error_texts(void **state)
{
    static const struct { const char *deck, *want; } cases[] = {
        /* blocks */
        { TAIL "PDS P CPG\nRECT R 0 0 1 1\n", "t.scene:6:1: error: PDS P has no END" },
        { "PDS P CPG\nRECT R 0 0 1 1\nSPHERE A 1\n",
          "t.scene:3:1: error: SPHERE: not allowed inside PDS P (END missing?)" },
        { "PDS Pp CPG\nPDS Q CPG\n", "t.scene:2:1: error: PDS: not allowed inside PDS Pp (END missing?)" },
        { "PDS P CPG\nintersect I X\n", "t.scene:2:13: error: INTER: X is used before it is defined" },
        { "PDS P CPG\nROW ab\n", "t.scene:2:1: error: ROW: not allowed in PDS P, a CPG block" },
        { "PDS P TILING SQUARE 0.5\nRECT R 0 0 1 1\n",
          "t.scene:2:1: error: RECT: not allowed in PDS P, a TILING block" },
        { "PDS P CPG\nFROB 1\n", "t.scene:2:1: error: unknown statement FROB" },
        { "RECT R 0 0 1 1\n", "t.scene:1:1: error: RECT: allowed only inside a PDS block" },
        { "END\n", "t.scene:1:1: error: END: allowed only inside a PDS block" },
        { "PDS P CPG\nRECT R 0 0 1 1\nEND 1\n", "t.scene:3:5: error: END: extra operand 1" },
        { "PDS P CPG\nRECT R 0 0 1 1\nEND\nPDS p TILING SQUARE 0.5\n",
          "t.scene:4:5: error: PDS: p is already defined on record 1" },
        { "PDS P FOO\n",
          "t.scene:1:7: error: PDS: expected CPG, PIXELS, TILING, MOSAIC, QUADTREE or CURVES, found FOO" },
        { "PDS P\n", "t.scene:1:6: error: PDS: missing CPG, PIXELS, TILING, MOSAIC, QUADTREE or CURVES" },
        { "PDS NONE CPG\n", "t.scene:1:5: error: PDS: NONE is a reserved word, not a name" },
        { "PDS P CPG 3\n", "t.scene:1:11: error: PDS: extra operand 3" },
        { "PDS P CPG\nEND\n", "t.scene:1:1: error: CPG defines no regions" },
        /* CPG nodes */
        { CPG_OPEN "POLYGON G 0 0 1 1 2 2\nEND\n", "t.scene:4:1: error: polygon encloses no area" },
        { CPG_OPEN "RECT A 0 0 1 1\n POLYGON G 0 0 1 1 ATTR RED\nEND\n",
          "t.scene:5:2: error: polygon needs at least 3 vertices, got 2" },
        { CPG_OPEN "POLYGON G 0 0 1 0 1 ATTR RED\n",
          "t.scene:4:21: error: POLYGON: expected a number, found ATTR" },
        { CPG_OPEN "POLYGON G 0 0 1 0 1 1 0 1 0 0.5 1 0.5\nEND\n",
          "t.scene:4:1: error: polygon edges 2 and 5 cross or touch (it must be simple)" },
        { CPG_OPEN "ELLIPSE E 0.5 0.5 0 0.1\nEND\n",
          "t.scene:4:1: error: ellipse is empty (radii 0 and 0.1 must be positive)" },
        { CPG_OPEN "CIRCLE C 0.5 0.5 -1\nEND\n",
          "t.scene:4:1: error: ellipse is empty (radii -1 and -1 must be positive)" },
        { CPG_OPEN "RECT R 0 0 0 1\nEND\n",
          "t.scene:4:1: error: rectangle is empty (it needs u0 < u1 and v0 < v1)" },
        { CPG_OPEN "RECT R 0 0 1 1 SCALE 0\nEND\n",
          "t.scene:4:1: error: rectangle transform is singular (it flattens the region)" },
        { CPG_OPEN "RECT R 0 0 1 1 TRANSLATE 100 0\nEND\n",
          "t.scene:4:1: error: rectangle reaches beyond -64..64 after its transforms" },
        { CPG_OPEN "RECT R 0 0 1\n", "t.scene:4:13: error: RECT: missing number" },
        { CPG_OPEN "RECT R 0 0 1 1 ROTATE Z 90\n", "t.scene:4:23: error: RECT: expected a number, found Z" },
        { CPG_OPEN "RECT R 0 0 1 1 ATTR GREEN\n", "t.scene:4:21: error: RECT: GREEN is used before it is defined" },
        { CPG_OPEN "RECT R 0 0 1 1 ATTR RED ATTR RED\n", "t.scene:4:25: error: RECT: ATTR given twice" },
        { CPG_OPEN "RECT R 0 0 1 1 FOO\n", "t.scene:4:16: error: RECT: extra operand FOO" },
        { CPG_OPEN "RECT A 0 0 1 1\nRECT a 0 0 1 1\n", "t.scene:5:6: error: RECT: a is already defined on record 4" },
        { CPG_OPEN "RECT A 0 0 1 1\nUNION U A B\n", "t.scene:5:11: error: UNION: B is used before it is defined" },
        { CPG_OPEN "RECT A 0 0 1 1\nUNION U A A\nEND\n",
          "t.scene:5:1: error: union operand 2 is already an operand elsewhere (CPG must be a tree)" },
        { CPG_OPEN "RECT A 0 0 1 1\nDIFF D ATTR RED\nEND\n",
          "t.scene:5:1: error: difference needs at least one operand" },
        { CPG_OPEN "NEST N Q\n", "t.scene:4:8: error: NEST: Q is used before it is defined" },
        { CPG_OPEN "NEST N P\n", "t.scene:4:8: error: NEST: P is used before it is defined" },
        { "PDS Q TILING SQUARE 0.5\nTILES NONE\nEND\n" CPG_OPEN "NEST N Q ATTR RED\n",
          "t.scene:7:10: error: NEST: extra operand ATTR" },
        { "PDS Q TILING SQUARE 0.5\nTILES NONE\nEND\n" CPG_OPEN "NEST N Q SCALE 1e-5\nEND\n",
          "t.scene:7:1: error: nested PDS is thinner than 1/8192 after its transforms" },
        { CPG_OPEN "RECT A 0 0 1 1\nROOT A\nROOT A\n", "t.scene:6:1: error: ROOT given twice (first on record 5)" },
        { CPG_OPEN "ROOT A\n", "t.scene:4:6: error: ROOT: A is used before it is defined" },
        /* pixel arrays */
        { ATTRS "PDS X PIXELS 4 3\nKEY a RED\nROW aaaa\nROW aaaa\nEND\n",
          "t.scene:3:1: error: pixel array is 4 x 3 (12 cells) but 8 values were given" },
        { ATTRS "PDS X PIXELS 4 3\nKEY a RED\nROW aaa\n",
          "t.scene:5:8: error: ROW: row has 3 characters but the array is 4 wide" },
        { ATTRS "PDS X PIXELS 4 3\nKEY a RED\nROW aa aaa\n",
          "t.scene:5:10: error: ROW: row is longer than 4 characters" },
        { ATTRS "PDS X PIXELS 4 3\nKEY a RED\nROW aa ba\n", "t.scene:5:8: error: ROW: b is not a KEY character" },
        { ATTRS "PDS X PIXELS 4 3\nKEY a RED\nROW aaaA\n", "t.scene:5:8: error: ROW: A is not a KEY character" },
        { ATTRS "PDS X PIXELS 2 1\nKEY a RED\nROW aa\nROW aa\n",
          "t.scene:6:1: error: ROW: more rows than the height of 1" },
        { ATTRS "PDS X PIXELS 2 1\nKEY ab RED\n", "t.scene:4:5: error: KEY: a key is one character, found ab" },
        { ATTRS "PDS X PIXELS 2 1\nKEY a RED\nKEY a BLUE\n", "t.scene:5:5: error: KEY: a is already a key on record 4" },
        { ATTRS "PDS X PIXELS 2 1\nKEY a\n", "t.scene:4:6: error: KEY: missing name" },
        { ATTRS "PDS X PIXELS 2 1\nKEY\n", "t.scene:4:4: error: KEY: missing key" },
        { "PDS X PIXELS 0 3\n", "t.scene:1:14: error: PDS: width must be a whole number from 1 to 32768" },
        { "PDS X PIXELS 4 2.5\n", "t.scene:1:16: error: PDS: height must be a whole number from 1 to 32768" },
        { "PDS X PIXELS 4\n", "t.scene:1:15: error: PDS: missing number" },
        { "PDS X PIXELS 2e6 1\n", "t.scene:1:14: error: PDS: 2e6 is out of range (magnitude above 1e6)" },
        { "PDS X PIXELS 32768 32768\n", "t.scene:1:20: error: PDS: 32768 x 32768 is more than 16777216 cells" },
        { "PDS X PIXELS IMAGE\n", "t.scene:1:19: error: PDS: missing file name" },
        /* quadtrees */
        { ATTRS "PDS Q QUADTREE\nCODE SPLIT RED\nEND\n",
          "t.scene:3:1: error: quadtree code ends before the tree is complete (3 more values needed)" },
        { ATTRS "PDS Q QUADTREE\nCODE RED RED\nEND\n",
          "t.scene:3:1: error: quadtree code has 1 values after the tree is complete" },
        { ATTRS "PDS Q QUADTREE\nCODE SPLIT RED GREEN\n", "t.scene:4:16: error: CODE: GREEN is used before it is defined" },
        { ATTRS "PDS Q QUADTREE\nCODE\n", "t.scene:4:5: error: CODE: missing name" },
        { ATTRS "PDS Q QUADTREE\nKEY a RED\n", "t.scene:4:1: error: KEY: not allowed in PDS Q, a QUADTREE CODE block" },
        { ATTRS "PDS Q QUADTREE 2 2\nKEY a RED\nROW aa\nEND\n",
          "t.scene:3:1: error: quadtree pixel array is 2 x 2 (4 cells) but 2 values were given" },
        /* tilings */
        { "PDS T TILING OCTAGON 0.5\n",
          "t.scene:1:14: error: PDS: expected SQUARE, BRICK, HEX or TRIANGLE, found OCTAGON" },
        { "PDS T TILING SQUARE 2\nTILES NONE\nEND\n", "t.scene:1:1: error: tile size 2 is out of range (1/8192..1)" },
        { "PDS T TILING BRICK 0.5 0.25 OFFSET 1\nTILES NONE\nEND\n",
          "t.scene:1:1: error: brick offset 1 must be in 0..1 (exclusive)" },
        { "PDS T TILING SQUARE 0.5 MORTAR 0.25 NONE\nTILES NONE\nEND\n",
          "t.scene:1:1: error: mortar width 0.25 must be at least 0 and below half the tile size" },
        { "PDS T TILING HEX 0.5 0.5\n", "t.scene:1:22: error: PDS: expected OFFSET, MORTAR, CYCLE or HASH, found 0.5" },
        { "PDS T TILING HEX 0.5 OFFSET 0.5\n", "t.scene:1:22: error: PDS: OFFSET is for BRICK tilings only" },
        { "PDS T TILING SQUARE 0.5 HASH 1 CYCLE 1 1 0\n", "t.scene:1:32: error: PDS: CYCLE and HASH exclude each other" },
        { "PDS T TILING SQUARE 0.5 HASH 1 HASH 2\n", "t.scene:1:32: error: PDS: HASH given twice" },
        { "PDS T TILING SQUARE 0.5 HASH -1\n", "t.scene:1:30: error: PDS: seed must be a whole number from 0 to 2147483647" },
        { "PDS T TILING SQUARE 0.5 CYCLE 1 1\n", "t.scene:1:34: error: PDS: missing number" },
        { "PDS T TILING SQUARE 0.5\nEND\n", "t.scene:1:1: error: tiling needs at least one tile attribute" },
        { "PDS T TILING SQUARE 0.5\nTILES NONE\nTILES NONE\n",
          "t.scene:3:1: error: TILES given twice (first on record 2)" },
        { "PDS T TILING SQUARE 0.5\nTILES\n", "t.scene:2:6: error: TILES: missing name" },
        /* mosaics */
        { "PDS M MOSAIC\nEND\n", "t.scene:1:1: error: mosaic needs at least one seed" },
        { "PDS M MOSAIC SEEDS\n", "t.scene:1:14: error: PDS: expected MORTAR, found SEEDS" },
        { "PDS M MOSAIC\nSEED 0.5 1.5 NONE\nEND\n", "t.scene:1:1: error: mosaic seed 1 lies outside the unit square" },
        { "PDS M MOSAIC\nSEED 0.5 0.5 NONE\nSEED 0.5 0.5 DEFAULT\nEND\n",
          "t.scene:1:1: error: mosaic seeds 1 and 2 coincide" },
        { "PDS M MOSAIC MORTAR 0.5 NONE\nSEED 0.5 0.5 NONE\nEND\n",
          "t.scene:1:1: error: mortar width 0.5 must be in 0..0.25" },
        { "PDS M MOSAIC\nSCATTER 0 1 NONE\n", "t.scene:2:9: error: SCATTER: count must be a whole number from 1 to 65536" },
        { "PDS M MOSAIC\nSCATTER 10 1\n", "t.scene:2:13: error: SCATTER: missing name" },
        { "PDS M MOSAIC\nSEED 0.5 0.5\n", "t.scene:2:13: error: SEED: missing name" },
        /* curves */
        { ATTRS "PDS C CURVES\nBSPLINE RED 0.1 0.1 0.9 0.9 0.9 0.1 0.1 0.9\nEND\n",
          "t.scene:4:1: error: B-spline curve intersects itself near (0.500, 0.500)" },
        { ATTRS "PDS C CURVES\nPOLYLINE RED 0.1 0.1 0.9 0.9 0.9 0.1 0.1 0.9\nEND\n",
          "t.scene:4:1: error: curve edges 1 and 3 cross or touch (it must be simple)" },
        { ATTRS "PDS C CURVES\nPOLYLINE RED 0.1 0.1 0.9 0.9\nEND\n",
          "t.scene:4:1: error: curve needs at least 3 points, got 2" },
        { ATTRS "PDS C CURVES\nBSPLINE RED 0.1 0.1 0.9\n", "t.scene:4:24: error: BSPLINE: missing number" },
        { ATTRS "PDS C CURVES\nBSPLINE 0.1 0.1 0.9 0.9\n",
          "t.scene:4:9: error: BSPLINE: bad name 0.1 (a letter, then letters, digits or _ $ # @)" },
        { ATTRS "PDS C CURVES TOLERANCE 0.5\nPOLYLINE RED 0 0 1 0 1 1\nEND\n",
          "t.scene:3:1: error: curve tolerance 0.5 is out of range (1e-06..0.01)" },
        { ATTRS "PDS C CURVES\nEND\n", "t.scene:3:1: error: curve PDS defines no curves" },
        /* FACE */
        { "FACE CAN SIDE P\n", "t.scene:1:6: error: FACE: CAN is used before it is defined" },
        { "SPHERE A 1\nSPHERE B 1\nUNION U A B\nFACE U SURFACE P\n",
          "t.scene:4:6: error: FACE: U is a CSG solid; faces belong to primitives" },
        { "CYLINDER CAN 1 1\nFACE CAN LID P\n",
          "t.scene:2:10: error: FACE: a CYLINDER has no face LID (it has SIDE, TOP, BOTTOM)" },
        { "BLOCK B 1 1 1\nFACE B SIDE P\n",
          "t.scene:2:8: error: FACE: a BLOCK has no face SIDE (it has XMIN, XMAX, YMIN, YMAX, ZMIN, ZMAX)" },
        { "HALFSPACE H\nFACE H TOP P\n", "t.scene:2:8: error: FACE: a HALFSPACE has no face TOP (it has PLANE)" },
        { "SPHERE A 1\nFACE A\n", "t.scene:2:7: error: FACE: missing face name" },
        { "SPHERE A 1\nFACE A SURFACE P\n", "t.scene:2:16: error: FACE: P is used before it is defined" },
        { "PDS P CPG\nRECT R 0 0 1 1\nEND\nCYLINDER CAN 1 1\nFACE CAN SIDE P\nFACE CAN side P\n",
          "t.scene:6:10: error: FACE: SIDE of CAN is already bound on record 5" },
        { "PDS P CPG\nRECT R 0 0 1 1\nEND\nCYLINDER CAN 1 1\nFACE CAN SIDE P X\n",
          "t.scene:5:17: error: FACE: extra operand X" },
        { "PDS P CPG\nRECT R 0 0 1 1\nEND\nCYLINDER CAN 1 1\nSPHERE B 1\nUNION U CAN B\n"
          "OBJECT U\nOBJECT CAN\nFACE CAN TOP P\n",
          "t.scene:9:6: error: FACE: CAN is already placed by OBJECT on record 7; bind its faces before" },
        /* TEXTURE, BUMP, ATTR without a loader */
        { "TEXTURE T IMAGE granite.png\n", "t.scene:1:17: error: TEXTURE: images cannot be read here" },
        { "PDS X PIXELS IMAGE a.png\n", "t.scene:1:20: error: PDS: images cannot be read here" },
        { "TEXTURE T granite.png\n", "t.scene:1:11: error: TEXTURE: expected IMAGE, found granite.png" },
        { "TEXTURE T\n", "t.scene:1:10: error: TEXTURE: missing IMAGE" },
        { "TEXTURE T IMAGE\n", "t.scene:1:16: error: TEXTURE: missing file name" },
        { "BUMP B RIPPLES AMPLITUDE 1\n",
          "t.scene:1:8: error: BUMP: expected WAVES, BUMPS, DIMPLES, NOISE, GROOVES or IMAGE, found RIPPLES" },
        { "BUMP B\n", "t.scene:1:7: error: BUMP: missing WAVES, BUMPS, DIMPLES, NOISE, GROOVES or IMAGE" },
        { "BUMP B GROOVES AMPLITUDE 1\n", "t.scene:1:27: error: BUMP: GROOVES needs WIDTH" },
        { "PDS C CURVES STRIPS WIDTH 2\n", "t.scene:1:27: error: PDS: strip WIDTH must be between 0 and 1" },
        { "PDS C CURVES BOXES\n", "t.scene:1:14: error: PDS: expected TOLERANCE or STRIPS, found BOXES" },
        { "BUMP B WAVES AMPLITUDE 1 WIDTH 0.1\n", "t.scene:1:35: error: BUMP: WIDTH applies to GROOVES only" },
        { "BUMP B GROOVES AMPLITUDE 1 WIDTH 0.6\n",
          "t.scene:1:34: error: BUMP: WIDTH must be above 0 and at most 0.5" },
        { "BUMP B GROOVES AMPLITUDE 1 WIDTH 0.1 LOCAL LOCAL\n", "t.scene:1:44: error: BUMP: LOCAL given twice" },
        { "BUMP B IMAGE\n", "t.scene:1:13: error: BUMP: missing file name" },
        { "ATTR A COLOR 1 1 1 MODEL GOURAUD\n",
          "t.scene:1:26: error: ATTR: expected PHONG, LAMBERT, BLINN, MIRROR or TRANSPARENT, found GOURAUD" },
        { "BUMP B WAVES\n", "t.scene:1:13: error: BUMP: AMPLITUDE is required" },
        { "BUMP B WAVES FREQUENCY 1 1\n", "t.scene:1:27: error: BUMP: AMPLITUDE is required" },
        { "BUMP B WAVES AMPLITUDE 0\n", "t.scene:1:24: error: BUMP: AMPLITUDE must not be zero" },
        { "BUMP B WAVES AMPLITUDE 2e6\n",
          "t.scene:1:24: error: BUMP: 2e6 is out of range (magnitude above 1e6)" },
        { "BUMP B WAVES AMPLITUDE 1 AMPLITUDE 2\n", "t.scene:1:26: error: BUMP: AMPLITUDE given twice" },
        { "BUMP B WAVES AMPLITUDE 1 FREQUENCY 0.0005 1\n",
          "t.scene:1:36: error: BUMP: FREQUENCY must be 0 or between 0.001 and 4096" },
        { "BUMP B WAVES AMPLITUDE 1 FREQUENCY 1 5000\n",
          "t.scene:1:38: error: BUMP: FREQUENCY must be 0 or between 0.001 and 4096" },
        { "BUMP B WAVES AMPLITUDE 1 FREQUENCY -1 1\n",
          "t.scene:1:36: error: BUMP: FREQUENCY must be 0 or between 0.001 and 4096" },
        { "BUMP B WAVES AMPLITUDE 1 FREQUENCY 0 0\n",
          "t.scene:1:38: error: BUMP: FREQUENCY 0 0 leaves the surface flat" },
        { "BUMP B WAVES AMPLITUDE 1 SEED 2147483648\n",
          "t.scene:1:31: error: BUMP: SEED must be a whole number from 0 to 2147483647" },
        { "BUMP B WAVES AMPLITUDE 1 SEED 1e999\n",
          "t.scene:1:31: error: BUMP: SEED must be a whole number from 0 to 2147483647" },
        { "BUMP B WAVES AMPLITUDE 1 SEED 1.5\n",
          "t.scene:1:31: error: BUMP: SEED must be a whole number from 0 to 2147483647" },
        { "BUMP B WAVES AMPLITUDE 1 SHINY\n",
          "t.scene:1:26: error: BUMP: expected AMPLITUDE, FREQUENCY, SEED, WIDTH or LOCAL, found SHINY" },
        { "BUMP B WAVES AMPLITUDE 1\nBUMP b NOISE AMPLITUDE 1\n",
          "t.scene:2:6: error: BUMP: b is already defined on record 1" },
        { "ATTR A COLOR 1 1 1 TEXTURE T\n", "t.scene:1:28: error: ATTR: T is used before it is defined" },
        { "BUMP B WAVES AMPLITUDE 1\nATTR A COLOR 1 1 1 BUMP B BUMP B\n",
          "t.scene:2:27: error: ATTR: BUMP given twice" },
        { "BUMP B WAVES AMPLITUDE 1\nATTR A COLOR 1 1 1 TEXTURE B\n",
          "t.scene:2:28: error: ATTR: B is used before it is defined" },
        { "SPHERE PDS 1\n", "t.scene:1:8: error: SPHERE: PDS is a reserved word, not a name" },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        st_expect_error(cases[i].deck, NULL, cases[i].want);
}

/* Errors that involve reading images through the stub loader. */
static void test_scene_pds_image_errors(void **state)
{
    static const struct { const char *deck, *want; } cases[] = {
        { "TEXTURE T IMAGE bad.png\n", "t.scene:1:17: error: TEXTURE: cannot read bad.png: not a PNG file" },
        { "TEXTURE T IMAGE lying.png\n",
          "t.scene:1:17: error: TEXTURE: cannot read lying.png: not a 3-channel image" },
        { "TEXTURE T IMAGE a.png REPEAT 0 1\n",
          "t.scene:1:30: error: TEXTURE: REPEAT must be a whole number from 1 to 1024" },
        { "TEXTURE T IMAGE a.png REPEAT 2 1025\n",
          "t.scene:1:32: error: TEXTURE: REPEAT must be a whole number from 1 to 1024" },
        { "TEXTURE T IMAGE a.png REPEAT 2\n", "t.scene:1:31: error: TEXTURE: missing number" },
        { "TEXTURE T IMAGE a.png 2\n", "t.scene:1:23: error: TEXTURE: extra operand 2" },
        { "TEXTURE T IMAGE a.png\nTEXTURE t IMAGE b.png\n",
          "t.scene:2:9: error: TEXTURE: t is already defined on record 1" },
        { ATTRS "PDS X PIXELS IMAGE bad.png\nINDEX RED\nEND\n",
          "t.scene:3:20: error: PDS: cannot read bad.png: not a PNG file" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nKEY #FF0000 RED\nKEY #00ff00 BLUE\nEND\n",
          "t.scene:3:1: error: pixel (2, 0) has colour #0000ff, which the colour map does not list" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nINDEX RED BLUE\nEND\n",
          "t.scene:3:1: error: pixel (2, 0) has index 2 but the index table has 2 entries" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nEND\n",
          "t.scene:3:1: error: PDS X: IMAGE needs KEY #RRGGBB lines or an INDEX line" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nKEY r RED\n",
          "t.scene:4:5: error: KEY: expected a colour #RRGGBB, found r" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nKEY #FF000G RED\n",
          "t.scene:4:5: error: KEY: expected a colour #RRGGBB, found #FF000G" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nKEY #ff0000 RED\nKEY #FF0000 BLUE\n",
          "t.scene:5:5: error: KEY: #FF0000 is already a key on record 4" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nKEY #ff0000 RED\nINDEX RED\n",
          "t.scene:5:1: error: INDEX: the image already has KEY colours (record 4)" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nINDEX RED\nKEY #ff0000 RED\n",
          "t.scene:5:1: error: KEY: the image already has an INDEX line (record 4)" },
        { ATTRS "PDS X PIXELS IMAGE a.png\nINDEX RED\nINDEX RED\n",
          "t.scene:5:1: error: INDEX given twice (first on record 4)" },
        { "PDS P PIXELS IMAGE a.png\nROW ab\n",
          "t.scene:2:1: error: ROW: not allowed in PDS P, a PIXELS IMAGE block" },
        { ATTRS "PDS X QUADTREE IMAGE a.png\nROW aa\n",
          "t.scene:4:1: error: ROW: not allowed in PDS X, a QUADTREE IMAGE block" },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        st_expect_error(cases[i].deck, &stub, cases[i].want);
}

/* An INDEX line of 257 entries, and more seeds than a mosaic may hold. */
static void test_scene_pds_limits(void **state)
{
    char *deck = malloc(1 << 16);
    size_t len = 0, i;
    (void)state;
    assert_non_null(deck);
    len += (size_t)sprintf(deck + len, "PDS X PIXELS IMAGE a.png\nINDEX");
    for (i = 0; i < 257; i++)
        len += (size_t)sprintf(deck + len, " NONE%s", i % 10 == 9 ? " -\n" : "");
    sprintf(deck + len, "\n");
    st_expect_error(deck, &stub, "t.scene:27:32: error: INDEX: more than 256 entries (grey values 0..255)");
    len = (size_t)sprintf(deck, "PDS M MOSAIC\n");
    for (i = 0; i < 17; i++)
        len += (size_t)sprintf(deck + len, "SCATTER 65536 %zu NONE\n", i);
    st_expect_error(deck, NULL, "t.scene:18:9: error: SCATTER: the mosaic would have more than 1048576 seeds");
    free(deck);
}

/* Every allocation of a deck using each statement fails in turn: the parse
 * reports it (out of memory, or the loader's failure) and leaks nothing. */
static void test_scene_pds_oom_sweep(void **state)
{
    static const char deck[] =
        ATTRS "TEXTURE T IMAGE a.png\nBUMP B WAVES AMPLITUDE 1\nATTR TB COLOR 1 1 1 TEXTURE T BUMP B\n"
        "PDS P CPG\nRECT R 0 0 1 1 ATTR RED\nPOLYGON G 0 0 1 0 0 1\nUNION U R G\nEND\n"
        "PDS Q CPG\nNEST N P\nEND\n"
        "PDS X PIXELS 2 1\nKEY a RED\nROW aa\nEND\n"
        "PDS Y PIXELS IMAGE a.png\nKEY #ff0000 RED\nKEY #00ff00 RED\nKEY #0000ff RED\nEND\n"
        "PDS Z QUADTREE\nCODE SPLIT RED RED RED RED\nEND\n"
        "PDS W TILING SQUARE 0.5\nTILES RED BLUE\nEND\n"
        "PDS M MOSAIC\nSCATTER 10 3 RED BLUE\nEND\n"
        "PDS C CURVES\nBSPLINE RED 0.3 0.3 0.7 0.3 0.7 0.7 0.3 0.7\nEND\n"
        "CYLINDER CAN 1 1\nFACE CAN SIDE P\nOBJECT CAN\n" TAIL;
    long n;
    (void)state;
    for (n = 0;; n++) {
        scene *s = NULL;
        diag err;
        int r;
        recsrc src;
        recsrc_mem m;
        diag_init(&err);
        recsrc_from_memory(&src, &m, "t.scene", deck, strlen(deck));
        mem_fail_after(n);
        r = scene_parse_with(&src, &stub, &s, &err);
        mem_fail_after(-1);
        if (r == 0) {
            assert_int_equal(s->nmaps, 8);
            assert_int_equal(s->prims[0].shape->face_map[0], 0);
            scene_free(s);
            break;
        }
        assert_null(s);
        if (r == DIAG_INPUT)
            assert_non_null(strstr(err.msg, "cannot read a.png: out of memory"));
        else
            assert_non_null(strstr(err.msg, "out of memory"));
        assert_true(n < 5000);
    }
    assert_true(n > 30);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_pds_texture_bump_attr),
        cmocka_unit_test(test_scene_pds_models_local_grooves),
        cmocka_unit_test(test_scene_pds_cpg),
        cmocka_unit_test(test_scene_pds_cpg_many_nodes),
        cmocka_unit_test(test_scene_pds_pixels_keyed),
        cmocka_unit_test(test_scene_pds_pixels_image),
        cmocka_unit_test(test_scene_pds_tiling),
        cmocka_unit_test(test_scene_pds_mosaic),
        cmocka_unit_test(test_scene_pds_curves),
        cmocka_unit_test(test_scene_pds_face),
        cmocka_unit_test(test_scene_pds_error_texts),
        cmocka_unit_test(test_scene_pds_image_errors),
        cmocka_unit_test(test_scene_pds_limits),
        cmocka_unit_test(test_scene_pds_oom_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
