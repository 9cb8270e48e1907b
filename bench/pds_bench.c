/* pds_bench — planar division structure lookup rates, one core.
 *
 * For each PDS kind and size it compiles the structure in each requested
 * numeric mode, converts a fixed set of random (u,v) points once, then times
 * repeated lookups (pds_mode_ops.locate_many) until at least --seconds have
 * passed, three times, and keeps the fastest of the three (the machine may be
 * shared; the times are the process's CPU time). Output: one line per case,
 *     kind  size  mode  lookups_per_second  ns_per_lookup  mean_steps  bytes
 * mean_steps is the mean number of nodes / cells / edges a lookup visited.
 * --lookups K replaces the timing by exactly K lookups per case, once (for
 * cachegrind and callgrind, whose counts are deterministic).
 * Usage: pds_bench [--modes q16,f64] [--seconds S] [--quick] [--scan]
 *        [--cpg|--curves] [--n LIST] [--orders LIST] [--lookups K] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "pds/pds_modes.h"
#include "model/pds_def.h"
#include "util/mem.h"

#define NPTS 65536
#define PI 3.14159265358979323846

static const pds_mode_ops *const all_modes[] = {
    &q16_pds_mode_ops, &q32_pds_mode_ops, &f32_pds_mode_ops, &f64_pds_mode_ops
};
static int use_mode[4] = { 1, 0, 0, 1 };
static double min_seconds = 0.3;
static int scan_order;       /* 1: points in raster order, like a renderer */
static unsigned long fixed_lookups;   /* --lookups: 0 = timed */
static const char *cpg_sizes, *cpg_order_list;   /* --n, --orders: NULL = all */
static const scene_loc L0 = { 0, 0 };

static uint64_t rng = 0x243F6A8885A308D3ull;
static double uniform(void)
{
    rng ^= rng >> 12; rng ^= rng << 25; rng ^= rng >> 27;
    return (double)((rng * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);   /* CPU time: robust on a shared machine */
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void run(const char *kind, const char *size, const pds_def *def)
{
    static double uv[2 * NPTS];
    static int32_t out[NPTS];
    int mi, i;
    for (i = 0; i < NPTS; i++) {
        if (scan_order) {
            /* A 256 x 256 raster, row by row, pixel centres. */
            uv[2 * i] = ((i % 256) + 0.5) / 256;
            uv[2 * i + 1] = ((i / 256) + 0.5) / 256;
        } else {
            uv[2 * i] = uniform();
            uv[2 * i + 1] = uniform();
        }
    }
    for (mi = 0; mi < 4; mi++) {
        const pds_mode_ops *m = all_modes[mi];
        void *p;
        diag err;
        unsigned reps = 1, round;
        double t0, t, best;
        unsigned long steps = 0;
        if (!use_mode[mi])
            continue;
        diag_init(&err);
        if (m->compile(def, "bench", &p, &err)) {
            char buf[700];
            diag_format(&err, buf, sizeof buf);
            fprintf(stderr, "pds_bench: %s %s: %s\n", kind, size, buf);
            exit(1);
        }
        if (fixed_lookups) {
            size_t left = (size_t)fixed_lookups;
            t0 = now();
            for (; left >= NPTS; left -= NPTS)
                m->locate_many(p, uv, NPTS, 1, out);
            if (left)
                m->locate_many(p, uv, left, 1, out);
            t = now() - t0;
            printf("%-10s %-16s %-4s %12lu %8.1f %8s %10zu\n", kind, size, m->mode, fixed_lookups,
                   t * 1e9 / (double)fixed_lookups, "-", m->bytes(p));
            fflush(stdout);
            m->free(p);
            continue;
        }
        for (;;) {
            t0 = now();
            m->locate_many(p, uv, NPTS, reps, out);
            t = now() - t0;
            if (t >= min_seconds || reps >= (1u << 20))
                break;
            reps = t <= 0 ? reps * 16 : (unsigned)(reps * fmin(16, 1.2 * min_seconds / t) + 1);
        }
        best = t;
        for (round = 1; round < 3; round++) {
            t0 = now();
            m->locate_many(p, uv, NPTS, reps, out);
            t = now() - t0;
            best = t < best ? t : best;
        }
        t = best;
        for (i = 0; i < NPTS; i += NPTS / 4096)   /* a sample spread over all points */
            m->locate_steps(p, uv[2 * i], uv[2 * i + 1], &steps);
        printf("%-10s %-16s %-4s %12.0f %8.1f %8.1f %10zu\n", kind, size, m->mode,
               (double)NPTS * reps / t, t * 1e9 / ((double)NPTS * reps), steps / 4096.0, m->bytes(p));
        fflush(stdout);
        m->free(p);
    }
}

/* nx * ny grid of leaves cycling rectangle, ellipse, hexagon, in one
 * n-ary union, listed in spatial (row by row), reverse or shuffled order:
 * the order decides priority, and must not change the cost. */
static const char *const cpg_orders[3] = { "spatial", "reverse", "shuffled" };

/* Whether n is in the comma-separated list (NULL: every n). */
static int listed(const char *list, long n)
{
    char *end;
    if (!list)
        return 1;
    while (list && *list) {
        if (strtol(list, &end, 10) == n && (*end == ',' || !*end))
            return 1;
        list = strchr(list, ',');
        list = list ? list + 1 : NULL;
    }
    return 0;
}

static int listed_name(const char *list, const char *name)
{
    size_t k = strlen(name);
    const char *s;
    if (!list)
        return 1;
    for (s = strstr(list, name); s; s = strstr(s + 1, name))
        if ((s == list || s[-1] == ',') && (s[k] == ',' || !s[k]))
            return 1;
    return 0;
}
static void bench_cpg(int nx, int ny, int order)
{
    pds_def d;
    size_t *kids = mem_calloc((size_t)nx * (size_t)ny, sizeof *kids);
    double cw = 1.0 / nx, ch = 1.0 / ny;
    int i, j, k;
    char size[32];
    if (!listed(cpg_sizes, nx * ny) || !listed_name(cpg_order_list, cpg_orders[order])) {
        mem_free(kids);
        return;
    }
    pds_def_init(&d, PDS_CPG, L0);
    for (j = 0; j < ny; j++)
        for (i = 0; i < nx; i++) {
            double cu = (i + 0.5) * cw, cv = (j + 0.5) * ch, r = 0.4 * fmin(cw, ch);
            long idx;
            switch ((i + j) % 3) {
            case 0:
                idx = pds_cpg_rect(&d, cu - r, cv - r, cu + r, cv + r, (i + j) % 7, L0);
                break;
            case 1:
                idx = pds_cpg_ellipse(&d, cu, cv, r, 0.7 * r, (i + j) % 7, L0);
                break;
            default: {
                double pts[12];
                for (k = 0; k < 6; k++) {
                    pts[2 * k] = cu + r * cos(PI * k / 3);
                    pts[2 * k + 1] = cv + r * sin(PI * k / 3);
                }
                idx = pds_cpg_polygon(&d, pts, 6, (i + j) % 7, L0);
            }
            }
            kids[j * nx + i] = (size_t)idx;
        }
    {
        size_t n = (size_t)nx * (size_t)ny, a, b;
        for (a = 0; order == 1 && a < n / 2; a++) {
            size_t t = kids[a];
            kids[a] = kids[n - 1 - a];
            kids[n - 1 - a] = t;
        }
        for (a = n; order == 2 && a-- > 1;) {
            size_t t = kids[a];
            b = (size_t)(uniform() * (double)(a + 1));
            kids[a] = kids[b];
            kids[b] = t;
        }
        pds_cpg_op_node(&d, PDS_CPG_UNION, kids, n, PDS_INHERIT, L0);
    }
    snprintf(size, sizeof size, "N=%d,%s", nx * ny, cpg_orders[order]);
    run("cpg", size, &d);
    pds_def_free(&d);
    mem_free(kids);
}

/* Blocky random grid of side n: blocks of 2^b cells. */
static int32_t *grid(int n, int b)
{
    int32_t *c = mem_calloc((size_t)n * (size_t)n, sizeof *c);
    int i, j;
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++)
            c[j * n + i] = (int32_t)((((unsigned)(i >> b) * 2654435761u) ^ ((unsigned)(j >> b) * 40503u)) % 7);
    return c;
}

static void bench_pixels(int n)
{
    pds_def d;
    int32_t *c = grid(n, 0);
    char size[32];
    pds_def_init(&d, PDS_PIXELS, L0);
    pds_pixels_set(&d.pixels, n, n, c, (size_t)n * (size_t)n);
    snprintf(size, sizeof size, "%dx%d", n, n);
    run("pixels", size, &d);
    pds_def_free(&d);
    mem_free(c);
}

static void bench_quadtree(int depth)
{
    pds_def d;
    int n = 1 << depth;
    int32_t *c = grid(n, depth > 3 ? 2 : 0);
    char size[32];
    pds_def_init(&d, PDS_QUADTREE, L0);
    d.quad.from_pixels = 1;
    pds_pixels_set(&d.quad.pixels, n, n, c, (size_t)n * (size_t)n);
    snprintf(size, sizeof size, "depth=%d", depth);
    run("quadtree", size, &d);
    pds_def_free(&d);
    mem_free(c);
}

static void bench_tiling(pds_tile_shape shape, const char *name)
{
    pds_def d;
    int32_t attrs[3] = { 1, 2, 3 };
    pds_def_init(&d, PDS_TILING, L0);
    d.tiling.shape = shape;
    d.tiling.size[0] = d.tiling.size[1] = 1.0 / 16;
    d.tiling.mortar = 1.0 / 256;
    d.tiling.mortar_attr = 0;
    pds_tiling_attrs(&d, attrs, 3);
    run("tiling", name, &d);
    pds_def_free(&d);
}

/* n seeds, spread uniformly or (clustered) 7 in 8 of them in a 0.05 square. */
static void bench_mosaic(int n, int clustered)
{
    pds_def d;
    int i;
    char size[32];
    pds_def_init(&d, PDS_MOSAIC, L0);
    for (i = 0; i < n; i++) {
        int c = clustered && i % 8;
        double u = c ? 0.4 + 0.05 * uniform() : uniform(), v = c ? 0.4 + 0.05 * uniform() : uniform();
        pds_mosaic_seed(&d, u, v, i % 7);
    }
    d.mosaic.mortar = 0.1 / sqrt((double)n);
    d.mosaic.mortar_attr = 0;
    snprintf(size, sizeof size, "%s=%d", clustered ? "cluster" : "seeds", n);
    run("mosaic", size, &d);
    pds_def_free(&d);
}

/* One closed curve; strips: Ballard's strip trees answer membership
 * instead of the box hierarchy (docs/pds.md compares the two). */
static void bench_curve(int n, int bspline, int strips)
{
    pds_def d;
    double *pts = mem_calloc((size_t)n, 2 * sizeof *pts);
    int k;
    char size[32];
    for (k = 0; k < n; k++) {
        double a = 2 * PI * k / n, r = 0.3 + 0.1 * sin(7 * a) + (bspline ? 0 : 0.02 * sin(97 * a));
        pts[2 * k] = 0.5 + r * cos(a);
        pts[2 * k + 1] = 0.5 + r * sin(a);
    }
    pds_def_init(&d, PDS_CURVES, L0);
    pds_curve_add(&d, bspline, pts, (size_t)n, 1, L0);
    d.curves.strips = strips;
    snprintf(size, sizeof size, "%s=%d,%s", bspline ? "bspline" : "poly", n, strips ? "strips" : "boxes");
    run("curves", size, &d);
    pds_def_free(&d);
    mem_free(pts);
}

int main(int argc, char **argv)
{
    static const char usage[] = "pds_bench [--modes q16,q32,f32,f64] [--seconds S] [--quick] [--scan] [--cpg|--curves]\n"
                                "       [--n LIST] [--orders LIST] [--lookups K]";
    int i, quick = 0, only = 0;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--modes") && i + 1 < argc) {
            const char *s = argv[++i];
            int k;
            for (k = 0; k < 4; k++)
                use_mode[k] = strstr(s, all_modes[k]->mode) != NULL;
        } else if (!strcmp(argv[i], "--seconds") && i + 1 < argc)
            min_seconds = atof(argv[++i]);
        else if (!strcmp(argv[i], "--quick"))
            quick = 1;
        else if (!strcmp(argv[i], "--scan"))
            scan_order = 1;
        else if (!strcmp(argv[i], "--cpg"))
            only = 1;
        else if (!strcmp(argv[i], "--n") && i + 1 < argc)
            cpg_sizes = argv[++i];
        else if (!strcmp(argv[i], "--orders") && i + 1 < argc)
            cpg_order_list = argv[++i];
        else if (!strcmp(argv[i], "--lookups") && i + 1 < argc)
            fixed_lookups = strtoul(argv[++i], NULL, 10);
        else if (!strcmp(argv[i], "--curves"))
            only = 2;
        else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: %s\n"
                   "Lookup rates of every PDS kind on one core.\n"
                   "  --modes LIST  numeric modes to measure (default q16,f64)\n"
                   "  --seconds S   minimum timed run per case and round (default 0.3)\n"
                   "  --quick       skip the largest size of each kind\n"
                   "  --cpg         CPG only (N = 10..100,000 in three operand orders)\n"
                   "  --curves      curves only (box hierarchy and strip trees)\n"
                   "  --n LIST      CPG sizes to run, e.g. 10,10000 (default all)\n"
                   "  --orders LIST CPG operand orders: spatial,reverse,shuffled (default all)\n"
                   "  --lookups K   exactly K lookups per case, once, instead of the timed\n"
                   "                rounds (deterministic counts under cachegrind)\n"
                   "  --scan        points in raster order (256 x 256 pixel centres, row by\n"
                   "                row, as a renderer asks) instead of 65536 random points\n"
                   "Each case runs three rounds and reports the fastest.\n", usage);
            return 0;
        } else {
            fprintf(stderr, "usage: %s\n", usage);
            return 2;
        }
    }
    printf("%-10s %-16s %-4s %12s %8s %8s %10s\n", "kind", "size", "mode", "lookups/s", "ns", "steps", "bytes");
    for (i = 0; i < 2 && only != 1; i++) {
        bench_curve(24, 1, i);
        bench_curve(1000, 0, i);
        if (!quick)
            bench_curve(60000, 0, i);
    }
    if (only == 2)
        return 0;
    for (i = 0; i < 3; i++) {
        bench_cpg(5, 2, i);
        bench_cpg(10, 10, i);
        bench_cpg(40, 25, i);
        bench_cpg(100, 100, i);
        if (!quick)
            bench_cpg(400, 250, i);
    }
    if (only == 1)
        return 0;
    bench_pixels(16);
    bench_pixels(256);
    if (!quick)
        bench_pixels(4096);
    bench_quadtree(4);
    bench_quadtree(8);
    if (!quick)
        bench_quadtree(12);
    bench_tiling(PDS_TILE_SQUARE, "square");
    bench_tiling(PDS_TILE_BRICK, "brick");
    bench_tiling(PDS_TILE_HEX, "hex");
    bench_tiling(PDS_TILE_TRIANGLE, "triangle");
    bench_mosaic(16, 0);
    bench_mosaic(1024, 0);
    if (!quick) {
        bench_mosaic(65536, 0);
        bench_mosaic(65536, 1);
    }
    return 0;
}
