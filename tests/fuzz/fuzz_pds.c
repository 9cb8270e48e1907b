/* fuzz_pds — builds a PDS definition of any kind from the input bytes,
 * validates it, compiles it in every numeric mode and locates a few points.
 * Must never crash, leak, hang or trip the sanitizers. Byte 0 picks the kind;
 * the rest is read as a stream of small numbers (see take()). */
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "pds/pds_modes.h"
#include "model/pds_def.h"

typedef struct stream { const uint8_t *p; size_t n; } stream;

static unsigned take(stream *s)
{
    unsigned v;
    if (!s->n)
        return 0;
    v = *s->p++;
    s->n--;
    return v;
}

/* A coordinate in -0.5..1.5 in steps of 1/64, often on a dyadic boundary. */
static double coord(stream *s) { return ((double)take(s) - 32) / 128.0; }
static int32_t id(stream *s) { return (int32_t)take(s) % 9 - 1; }

/* A PDS for nested leaves: a pixel array with a transparent cell. */
static const pds_def *sub_pds(void)
{
    static pds_def sub;
    static int ready;
    static const int32_t cells[4] = { 1, PDS_NONE, 2, 3 };
    static const scene_loc L = { 9, 9 };
    if (!ready) {
        pds_def_init(&sub, PDS_PIXELS, L);
        if (pds_pixels_set(&sub.pixels, 2, 2, cells, 4) == 0)
            ready = 1;
    }
    return &sub;
}

static void build(pds_def *d, stream *s)
{
    static const scene_loc L = { 1, 1 };
    unsigned i, n;
    switch (d->kind) {
    case PDS_CPG:
        n = take(s) % 24 + 1;
        for (i = 0; i < n && s->n; i++) {
            unsigned op = take(s) % 8, k, m;
            size_t kids[4];
            double pts[16];
            switch (op) {
            case 0: pds_cpg_rect(d, coord(s), coord(s), coord(s), coord(s), id(s), L); break;
            case 1: pds_cpg_ellipse(d, coord(s), coord(s), coord(s), coord(s), id(s), L); break;
            case 2:
                m = take(s) % 8 + 1;
                for (k = 0; k < 2 * m; k++)
                    pts[k] = coord(s);
                pds_cpg_polygon(d, pts, m, id(s), L);
                break;
            case 7:
                pds_cpg_nested(d, take(s) % 4 ? sub_pds() : d, L);
                break;
            case 6:
                if (d->cpg.nnodes) {
                    size_t node = take(s) % d->cpg.nnodes;
                    switch (take(s) % 4) {
                    case 0: pds_cpg_translate(d, node, coord(s), coord(s)); break;
                    case 1: pds_cpg_rotate(d, node, take(s) * 7.0); break;
                    case 2: pds_cpg_scale(d, node, coord(s) * 4, coord(s) * 4); break;
                    default: pds_cpg_shear(d, node, coord(s), coord(s));
                    }
                }
                break;
            default:
                m = take(s) % 4 + 1;
                for (k = 0; k < m; k++)
                    kids[k] = take(s) % (d->cpg.nnodes + 2);
                pds_cpg_op_node(d, (pds_cpg_op)(PDS_CPG_UNION + op % 3), kids, m,
                                take(s) % 2 ? PDS_INHERIT : id(s), L);
            }
        }
        if (d->cpg.nnodes && take(s) % 4 == 0)
            d->cpg.root = take(s) % (d->cpg.nnodes + 1);
        break;
    case PDS_PIXELS:
    case PDS_QUADTREE: {
        int32_t cells[256];
        int w = (int)take(s) % 17, h = (int)take(s) % 17;
        size_t c = take(s);
        for (i = 0; i < 256; i++)
            cells[i] = id(s);
        if (d->kind == PDS_QUADTREE) {
            if (take(s) % 2) {
                int32_t code[256];
                n = take(s);
                for (i = 0; i < n; i++)
                    code[i] = take(s) % 3 == 0 ? PDS_QT_SPLIT : id(s);
                pds_quadtree_code(d, code, n);
            } else {
                d->quad.from_pixels = 1;
                pds_pixels_set(&d->quad.pixels, w, h, cells, c);
            }
        } else
            pds_pixels_set(&d->pixels, w, h, cells, c);
        break;
    }
    case PDS_TILING: {
        int32_t attrs[4];
        d->tiling.shape = (pds_tile_shape)(take(s) % 5);
        d->tiling.rule = (pds_tile_rule)(take(s) % 3);
        d->tiling.size[0] = coord(s);
        d->tiling.size[1] = coord(s);
        d->tiling.offset = coord(s);
        d->tiling.mortar = coord(s) / 8;
        d->tiling.mortar_attr = id(s);
        d->tiling.step[0] = (long)take(s) - 128;
        d->tiling.step[1] = (long)take(s) * 100000L;
        d->tiling.step[2] = -(long)take(s);
        d->tiling.seed = take(s);
        n = take(s) % 5;
        for (i = 0; i < n; i++)
            attrs[i] = id(s);
        pds_tiling_attrs(d, attrs, n);
        break;
    }
    case PDS_MOSAIC:
        n = take(s);
        for (i = 0; i < n; i++)
            pds_mosaic_seed(d, coord(s), coord(s), id(s));
        d->mosaic.mortar = coord(s) / 4;
        d->mosaic.mortar_attr = id(s);
        break;
    default:
        d->curves.tolerance = take(s) % 2 ? 1e-3 : coord(s) / 64;
        n = take(s) % 4 + 1;
        for (i = 0; i < n; i++) {
            double pts[2 * 32];
            unsigned m = take(s) % 32 + 1, k;
            for (k = 0; k < 2 * m; k++)
                pts[k] = coord(s);
            pds_curve_add(d, (int)(take(s) % 2), pts, m, id(s), L);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const pds_mode_ops *const modes[4] = {
        &q16_pds_mode_ops, &q32_pds_mode_ops, &f32_pds_mode_ops, &f64_pds_mode_ops
    };
    static const scene_loc L = { 1, 1 };
    stream s;
    pds_def d;
    int m;
    if (size < 1)
        return 0;
    s.p = data + 1;
    s.n = size - 1;
    pds_def_init(&d, (pds_kind)(data[0] % PDS_KIND_COUNT), L);
    build(&d, &s);
    for (m = 0; m < 4; m++) {
        void *p = NULL;
        diag err;
        int k;
        diag_init(&err);
        if (modes[m]->compile(&d, "fuzz", &p, &err))
            continue;
        for (k = 0; k < 64; k++)
            modes[m]->locate(p, (k % 8) / 7.0, (k / 8) / 7.0);
        modes[m]->locate(p, -1e300, 1e300);
        modes[m]->free(p);
    }
    pds_def_free(&d);
    return 0;
}
