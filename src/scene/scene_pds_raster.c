/* scene_pds_raster — PIXELS and QUADTREE blocks, which share their forms:
 *   PDS name PIXELS|QUADTREE w h       KEY c attr lines, then h ROW lines
 *                                      (top row first) of w KEY characters
 *   PDS name PIXELS|QUADTREE IMAGE f   KEY #RRGGBB attr lines (colour image)
 *                                      or one INDEX a0 a1 ... line (palette
 *                                      index or grey value g -> a_g), the
 *                                      image read at END
 *   PDS name QUADTREE                  CODE lines: ids, NONE or SPLIT in
 *                                      preorder (children SW SE NW NE)
 * Cells and code gather in the block and reach the definition at END. */
#include "scene/scene_pds.h"
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "model/pds_image.h"
#include "util/mem.h"

static pds_pixels *scene_pds_raster_pixels(pds_def *d)
{
    return d->kind == PDS_PIXELS ? &d->pixels : &d->quad.pixels;
}

/* The rest of the PDS statement: w h, IMAGE file, or (QUADTREE) nothing. */
static int scene_pds_raster_open(scene_parser *p, scene_cur *c, scene_pds_block *b)
{
    int quad = b->map->def.kind == PDS_QUADTREE;
    const scene_lex_tok *t;
    long w, h;
    if (scene_cur_accept(c, "IMAGE")) {
        if (!(t = scene_cur_peek(c)))
            return scene_cur_error(c, NULL, "missing file name");
        b->file_loc = scene_parse_loc(t);
        if (scene_parse_can_read(p, "PDS", b->file_loc))
            return DIAG_INPUT;
        memcpy(b->file, t->text, t->len + 1);
        c->pos++;
        p->block.body = scene_pds_image_body;
        p->block.kind = quad ? "QUADTREE IMAGE" : "PIXELS IMAGE";
        return 0;
    }
    if (quad && scene_cur_at_end(c)) {
        p->block.body = scene_pds_code_body;
        p->block.kind = "QUADTREE CODE";
        return 0;
    }
    if (scene_cur_int(c, "width", 1, PDS_MAX_SIDE, &w))
        return DIAG_INPUT;
    t = scene_cur_peek(c);
    if (scene_cur_int(c, "height", 1, PDS_MAX_SIDE, &h))
        return DIAG_INPUT;
    /* refused here, before ROW lines could gather that many cells */
    if (w * h > PDS_MAX_CELLS)
        return scene_cur_error(c, t, "%ld x %ld is more than %ld cells", w, h, PDS_MAX_CELLS);
    b->width = (int)w;
    b->height = (int)h;
    p->block.body = scene_pds_keyed_body;
    p->block.kind = quad ? "QUADTREE" : "PIXELS";
    return 0;
}

/* KEY #RRGGBB attr, for a colour image. */
static int scene_pds_raster_colour_key(scene_parser *p, scene_cur *c, scene_pds_block *b,
                             const scene_lex_tok *t)
{
    const scene_lex_tok *kw = &c->st->tok[0];
    char up[8];
    unsigned long rgb;
    int32_t id;
    int i;
    if (b->index_rec)
        return scene_cur_error(c, kw, "the image already has an INDEX line (record %ld)",
                               b->index_rec);
    if (t->len != 7 || t->text[0] != '#' || strspn(t->text + 1, "0123456789abcdefABCDEF") != 6)
        return scene_cur_error(c, t, "expected a colour #RRGGBB, found %s", t->text);
    for (i = 0; i < 8; i++)
        up[i] = (char)toupper((unsigned char)t->text[i]);
    /* the colour table maps each colour to the record that keyed it */
    i = scene_names_find(&b->names, SCENE_NAMES_COLOUR, up);
    if (i >= 0)
        return scene_cur_error(c, t, "%s is already a key on record %d", t->text, i);
    c->pos++;
    if (scene_pds_region(p, c, &id) || scene_cur_finish(c))
        return DIAG_INPUT;
    if (mem_grow((void **)&b->rgb, &b->cap_rgb, 3 * (b->nrgb + 1), 1) ||
        mem_grow((void **)&b->rgb_attr, &b->cap_rgb_attr, b->nrgb + 1, sizeof *b->rgb_attr) ||
        scene_names_add(&b->names, SCENE_NAMES_COLOUR, up, (int)kw->line))
        return scene_parse_oom(p, kw);
    rgb = strtoul(up + 1, NULL, 16);
    b->rgb[3 * b->nrgb] = (uint8_t)(rgb >> 16);
    b->rgb[3 * b->nrgb + 1] = (uint8_t)(rgb >> 8);
    b->rgb[3 * b->nrgb + 2] = (uint8_t)rgb;
    b->rgb_attr[b->nrgb] = id;
    if (b->nrgb++ == 0)
        b->rgb_rec = kw->line;
    return 0;
}

/* KEY c attr (rows of characters) or KEY #RRGGBB attr (a colour image). */
static int scene_pds_raster_key(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    const scene_lex_tok *t = scene_cur_peek(c);
    unsigned char ch;
    int32_t id;
    if (!t)
        return scene_cur_error(c, NULL, "missing key");
    if (b->file[0])
        return scene_pds_raster_colour_key(p, c, b, t);
    ch = (unsigned char)t->text[0];
    if (t->len != 1 || ch >= 128)
        return scene_cur_error(c, t, "a key is one character, found %s", t->text);
    if (b->key_rec[ch])
        return scene_cur_error(c, t, "%s is already a key on record %ld", t->text, b->key_rec[ch]);
    c->pos++;
    if (scene_pds_region(p, c, &id) || scene_cur_finish(c))
        return DIAG_INPUT;
    b->key[ch] = id;
    b->key_rec[ch] = c->st->tok[0].line;
    return 0;
}

/* ROW item...: the items' characters, concatenated, are one row of exactly
 * width KEY characters; errors point at the offending character. */
static int scene_pds_raster_row(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    size_t w = (size_t)b->width, n = 0, i, k;
    if (b->rows >= b->height)
        return scene_cur_error(c, &c->st->tok[0], "more rows than the height of %d", b->height);
    if (mem_grow((void **)&b->vals, &b->cap_vals, b->nvals + w, sizeof *b->vals))
        return scene_parse_oom(p, &c->st->tok[0]);
    for (i = c->pos; i < c->st->ntok; i++) {
        const scene_lex_tok *t = &c->st->tok[i];
        for (k = 0; k < t->len; k++) {
            unsigned char ch = (unsigned char)t->text[k];
            if (n == w || ch >= 128 || !b->key_rec[ch]) {
                scene_lex_tok at = *t;
                at.col += (long)k;
                if (n == w)
                    return scene_cur_error(c, &at, "row is longer than %zu characters", w);
                return scene_cur_error(c, &at, "%c is not a KEY character", ch);
            }
            b->vals[b->nvals + n++] = b->key[ch];
        }
    }
    c->pos = c->st->ntok;
    if (n < w)
        return scene_cur_error(c, NULL, "row has %zu characters but the array is %zu wide", n, w);
    b->nvals += w;
    b->rows++;
    return 0;
}

/* INDEX a0 a1 ...: palette index (palette PNG) or grey value g of the
 * image is region a_g (at most 256). */
static int scene_pds_raster_index(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    const scene_lex_tok *kw = &c->st->tok[0];
    int32_t ids[SCENE_LEX_MAX_ITEMS];
    size_t n;
    if (b->index_rec)
        return diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col,
                       "INDEX given twice (first on record %ld)", b->index_rec);
    if (b->nrgb)
        return scene_cur_error(c, kw, "the image already has KEY colours (record %ld)", b->rgb_rec);
    if (scene_pds_regions(p, c, 0, ids, &n))
        return DIAG_INPUT;
    if (n > 256)
        return scene_cur_error(c, &c->st->tok[1 + 256], "more than 256 entries (grey values 0..255)");
    memcpy(b->index, ids, n * sizeof *ids);
    b->nindex = n;
    b->index_rec = kw->line;
    return 0;
}

/* CODE item...: appends to the explicit quadtree code. */
static int scene_pds_raster_code(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    const scene_lex_tok *kw = &c->st->tok[0];
    int32_t ids[SCENE_LEX_MAX_ITEMS];
    size_t n;
    if (scene_pds_regions(p, c, 1, ids, &n))
        return DIAG_INPUT;
    if (b->nvals + n > (size_t)PDS_MAX_CELLS)
        return scene_cur_error(c, kw, "quadtree code of more than %ld values", PDS_MAX_CELLS);
    if (mem_grow((void **)&b->vals, &b->cap_vals, b->nvals + n, sizeof *b->vals))
        return scene_parse_oom(p, kw);
    memcpy(b->vals + b->nvals, ids, n * sizeof *ids);
    b->nvals += n;
    return 0;
}

/* Hands the cells or code to the definition; reads and maps the image. */
static int scene_pds_raster_finish(scene_parser *p, scene_pds_block *b)
{
    pds_def *d = &b->map->def;
    pds_pixels *px = scene_pds_raster_pixels(d);
    const scene_lex_tok *kw = &p->st.tok[0];
    pds_image_map m;
    image img;
    int r;
    if (d->kind == PDS_QUADTREE && !b->width && !b->file[0])
        return pds_quadtree_code(d, b->vals, b->nvals) ? scene_parse_oom(p, kw) : 0;
    d->quad.from_pixels = d->kind == PDS_QUADTREE;
    if (!b->file[0])
        return pds_pixels_set(px, b->width, b->height, b->vals, b->nvals) ? scene_parse_oom(p, kw) : 0;
    if (!b->nrgb && !b->index_rec)
        return diag_at(p->err, DIAG_INPUT, p->file, d->loc.line, d->loc.col,
                       "%s: IMAGE needs KEY #RRGGBB lines or an INDEX line", p->block.title);
    if (scene_parse_image(p, "PDS", b->file_loc, b->file, b->nrgb ? 3 : IMAGE_INDEXED, &img))
        return DIAG_INPUT;
    memset(&m, 0, sizeof m);
    m.index_attr = b->index;
    m.nindex = b->nindex;
    m.rgb = b->rgb;
    m.rgb_attr = b->rgb_attr;
    m.nrgb = b->nrgb;
    r = pds_image_to_pixels(&img, &m, px, p->file, d->loc, p->err);
    image_free(&img);
    return r;
}

const scene_pds_kind scene_pds_raster = { scene_pds_raster_open, scene_pds_raster_finish };

const scene_parse_stmt scene_pds_keyed_body[] = {
    { "KEY", "KEY", scene_pds_raster_key },
    { "ROW", "ROW", scene_pds_raster_row },
    { "END", "END", scene_pds_end },
    { NULL, NULL, NULL }
};

const scene_parse_stmt scene_pds_image_body[] = {
    { "KEY", "KEY", scene_pds_raster_key },
    { "INDEX", "INDEX", scene_pds_raster_index },
    { "END", "END", scene_pds_end },
    { NULL, NULL, NULL }
};

const scene_parse_stmt scene_pds_code_body[] = {
    { "CODE", "CODE", scene_pds_raster_code },
    { "END", "END", scene_pds_end },
    { NULL, NULL, NULL }
};
