/* scene_pds_cells — cell decompositions (docs/pds.md): TILING and MOSAIC
 * blocks.
 *   PDS name TILING shape w [h] [OFFSET f] [MORTAR width attr]
 *                   [CYCLE s1 s2 s3 | HASH seed]          then TILES a b ...
 *   PDS name MOSAIC [MORTAR width attr]    then SEED u v attr and
 *                                          SCATTER n seed a b ... lines
 * Sizes, widths and seed positions are validated by pds_def_check at END. */
#include "scene/scene_pds.h"
#include <string.h>

/* MORTAR width attr, after the keyword. */
static int scene_pds_cells_mortar(scene_parser *p, scene_cur *c, double *width, int32_t *attr)
{
    return scene_cur_number(c, width, NULL) || scene_pds_region(p, c, attr) ? DIAG_INPUT : 0;
}

/* The tiling's options: each at most once, CYCLE and HASH not both. */
static int scene_pds_cells_tiling_options(scene_parser *p, scene_cur *c, pds_tiling *t)
{
    int seen_off = 0, seen_mortar = 0, seen_cycle = 0, seen_hash = 0, r, i;
    while (!scene_cur_at_end(c)) {
        const scene_lex_tok *at = scene_cur_peek(c);
        long v;
        if ((r = scene_parse_option(c, "OFFSET", &seen_off)) != 0) {
            if (r < 0)
                return DIAG_INPUT;
            if (t->shape != PDS_TILE_BRICK)
                return scene_cur_error(c, at, "OFFSET is for BRICK tilings only");
            if (scene_cur_number(c, &t->offset, NULL))
                return DIAG_INPUT;
        } else if ((r = scene_parse_option(c, "MORTAR", &seen_mortar)) != 0) {
            if (r < 0 || scene_pds_cells_mortar(p, c, &t->mortar, &t->mortar_attr))
                return DIAG_INPUT;
        } else if ((r = scene_parse_option(c, "CYCLE", &seen_cycle)) != 0) {
            if (r < 0)
                return DIAG_INPUT;
            if (seen_hash)
                return scene_cur_error(c, at, "CYCLE and HASH exclude each other");
            t->rule = PDS_RULE_CYCLE;
            for (i = 0; i < 3; i++)
                if (scene_cur_int(c, "step", -1000000, 1000000, &t->step[i]))
                    return DIAG_INPUT;
        } else if ((r = scene_parse_option(c, "HASH", &seen_hash)) != 0) {
            if (r < 0)
                return DIAG_INPUT;
            if (seen_cycle)
                return scene_cur_error(c, at, "CYCLE and HASH exclude each other");
            if (scene_cur_int(c, "seed", 0, SCENE_PARSE_MAX_SEED, &v))
                return DIAG_INPUT;
            t->rule = PDS_RULE_HASH;
            t->seed = (uint32_t)v;
        } else {
            return scene_cur_error(c, at, "expected OFFSET, MORTAR, CYCLE or HASH, found %s",
                                   at->text);
        }
    }
    return 0;
}

/* PDS name TILING shape w [h] options: shapes in pds_tile_shape order;
 * SQUARE and BRICK take a height (default: the width). */
static int scene_pds_cells_tiling_open(scene_parser *p, scene_cur *c, scene_pds_block *b)
{
    static const char *const shapes[] = { "SQUARE", "BRICK", "HEX", "TRIANGLE", NULL };
    pds_tiling *t = &b->map->def.tiling;
    int s;
    if (scene_cur_choice(c, shapes, &s) || scene_cur_number(c, &t->size[0], NULL))
        return DIAG_INPUT;
    t->shape = (pds_tile_shape)s;
    t->size[1] = t->size[0];
    if ((t->shape == PDS_TILE_SQUARE || t->shape == PDS_TILE_BRICK) &&
        scene_cur_numeric(scene_cur_peek(c)) && scene_cur_number(c, &t->size[1], NULL))
        return DIAG_INPUT;
    if (scene_pds_cells_tiling_options(p, c, t))
        return DIAG_INPUT;
    p->block.body = scene_pds_tiling_body;
    p->block.kind = "TILING";
    return 0;
}

/* TILES a b ...: the tile attributes the rule chooses from (once). */
static int scene_pds_cells_tiling_tiles(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    const scene_lex_tok *kw = &c->st->tok[0];
    int32_t ids[SCENE_LEX_MAX_ITEMS];
    size_t n;
    if (b->tiles_rec)
        return diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col,
                       "TILES given twice (first on record %ld)", b->tiles_rec);
    if (scene_pds_regions(p, c, 0, ids, &n))
        return DIAG_INPUT;
    if (pds_tiling_attrs(&b->map->def, ids, n))
        return scene_parse_oom(p, kw);
    b->tiles_rec = kw->line;
    return 0;
}

/* PDS name MOSAIC [MORTAR width attr]. */
static int scene_pds_cells_mosaic_open(scene_parser *p, scene_cur *c, scene_pds_block *b)
{
    pds_mosaic *m = &b->map->def.mosaic;
    const scene_lex_tok *t = scene_cur_peek(c);
    if (t && !scene_cur_accept(c, "MORTAR"))
        return scene_cur_error(c, t, "expected MORTAR, found %s", t->text);
    if (t && scene_pds_cells_mortar(p, c, &m->mortar, &m->mortar_attr))
        return DIAG_INPUT;
    p->block.body = scene_pds_mosaic_body;
    p->block.kind = "MOSAIC";
    return 0;
}

/* Refuses n more seeds beyond the mosaic limit (checked before any is
 * added, so SCATTER cannot make the deck's size grow without bound). */
static int scene_pds_cells_mosaic_room(scene_cur *c, const pds_mosaic *m, long n, const scene_lex_tok *at)
{
    if ((size_t)n > (size_t)PDS_MAX_SEEDS - m->nseeds)
        return scene_cur_error(c, at, "the mosaic would have more than %ld seeds", PDS_MAX_SEEDS);
    return 0;
}

/* SEED u v attr. */
static int scene_pds_cells_mosaic_seed(scene_parser *p, scene_cur *c)
{
    pds_def *d = &scene_pds_current(p)->map->def;
    const scene_lex_tok *kw = &c->st->tok[0];
    double uv[2];
    int32_t id;
    if (scene_pds_cells_mosaic_room(c, &d->mosaic, 1, kw) || scene_cur_numbers(c, uv, 2) ||
        scene_pds_region(p, c, &id) || scene_cur_finish(c))
        return DIAG_INPUT;
    return pds_mosaic_seed(d, uv[0], uv[1], id) < 0 ? scene_parse_oom(p, kw) : 0;
}

/* splitmix64 (Steele, Lea and Flood 2014): the same stream on every
 * platform, unlike rand(). */
static uint64_t scene_pds_cells_mosaic_next(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* SCATTER n seed a b ...: n seeds uniform in [0,1) x [0,1) (53-bit
 * coordinates from the stream of `seed`), attributes cycling a, b, .... */
static int scene_pds_cells_mosaic_scatter(scene_parser *p, scene_cur *c)
{
    pds_def *d = &scene_pds_current(p)->map->def;
    const scene_lex_tok *kw = &c->st->tok[0], *nt = scene_cur_peek(c);
    int32_t ids[SCENE_LEX_MAX_ITEMS];
    size_t nids, i;
    long n, seed;
    uint64_t x;
    if (scene_cur_int(c, "count", 1, 65536, &n) || scene_pds_cells_mosaic_room(c, &d->mosaic, n, nt) ||
        scene_cur_int(c, "seed", 0, SCENE_PARSE_MAX_SEED, &seed) ||
        scene_pds_regions(p, c, 0, ids, &nids))
        return DIAG_INPUT;
    x = (uint64_t)seed;
    for (i = 0; i < (size_t)n; i++) {
        double u = (double)(scene_pds_cells_mosaic_next(&x) >> 11) * 0x1p-53;
        double v = (double)(scene_pds_cells_mosaic_next(&x) >> 11) * 0x1p-53;
        if (pds_mosaic_seed(d, u, v, ids[i % nids]) < 0)
            return scene_parse_oom(p, kw);
    }
    return 0;
}

const scene_pds_kind scene_pds_tiling = { scene_pds_cells_tiling_open, NULL };
const scene_pds_kind scene_pds_mosaic = { scene_pds_cells_mosaic_open, NULL };

const scene_parse_stmt scene_pds_tiling_body[] = {
    { "TILES", "TILES", scene_pds_cells_tiling_tiles },
    { "END", "END", scene_pds_end },
    { NULL, NULL, NULL }
};

const scene_parse_stmt scene_pds_mosaic_body[] = {
    { "SEED", "SEED", scene_pds_cells_mosaic_seed },
    { "SCATTER", "SCATTER", scene_pds_cells_mosaic_scatter },
    { "END", "END", scene_pds_end },
    { NULL, NULL, NULL }
};
