/* scene_attrmap — the attributes an ATTR can map over a face besides its
 * PDS regions (ATTR name ... TEXTURE t BUMP b):
 *   TEXTURE name IMAGE file [REPEAT nu nv] [LOCAL]
 *   BUMP name WAVES|BUMPS|DIMPLES|NOISE|GROOVES|IMAGE file AMPLITUDE a
 *        [FREQUENCY fu fv] [SEED n] [WIDTH w] [LOCAL]
 * Each has a name space of its own. The image is read through the parse's
 * loader once the statement is known to be well formed. */
#include <string.h>
#include "scene/scene_parser.h"
#include "util/mem.h"

/* Reads the new name of a texture or bump (name space `space`, `count` of
 * them defined so far, at most `limit`). */
static int scene_attrmap_new_name(scene_parser *p, scene_cur *c, int space, size_t count, int limit,
                            const char *what, char name[SCENE_NAME_MAX + 1], const scene_lex_tok **at)
{
    int i;
    if (scene_cur_name(c, name, at))
        return DIAG_INPUT;
    i = scene_names_find(&p->names, space, name);
    if (i >= 0)
        return scene_cur_error(c, *at, "%s is already defined on record %ld", (*at)->text,
                               space == SCENE_NAMES_TEXTURE ? p->s->textures[i].loc.line
                                                            : p->s->bumps[i].loc.line);
    if (count >= (size_t)limit)
        return scene_cur_error(c, *at, "more than %d %s", limit, what);
    return 0;
}

/* TEXTURE name IMAGE file [REPEAT nu nv]: an RGB image over the face. */
static int scene_attrmap_texture(scene_parser *p, scene_cur *c)
{
    scene *s = p->s;
    const scene_lex_tok *kw = &c->st->tok[0], *at, *ft;
    scene_texture t;
    long rep[2] = { 1, 1 };
    memset(&t, 0, sizeof t);
    if (scene_attrmap_new_name(p, c, SCENE_NAMES_TEXTURE, s->ntextures, SCENE_PARSE_MAX_TEXTURES,
                         "textures", t.name, &at))
        return DIAG_INPUT;
    if (!scene_cur_accept(c, "IMAGE")) {
        ft = scene_cur_peek(c);
        return ft ? scene_cur_error(c, ft, "expected IMAGE, found %s", ft->text)
                  : scene_cur_error(c, NULL, "missing IMAGE");
    }
    if (!(ft = scene_cur_peek(c)))
        return scene_cur_error(c, NULL, "missing file name");
    if (scene_parse_can_read(p, "TEXTURE", scene_parse_loc(ft)))
        return DIAG_INPUT;
    c->pos++;
    if (scene_cur_accept(c, "REPEAT") &&
        (scene_cur_int(c, "REPEAT", 1, 1024, &rep[0]) || scene_cur_int(c, "REPEAT", 1, 1024, &rep[1])))
        return DIAG_INPUT;
    t.local = scene_cur_accept(c, "LOCAL");
    if (scene_cur_finish(c))
        return DIAG_INPUT;
    if (mem_grow((void **)&s->textures, &p->cap_textures, s->ntextures + 1, sizeof t))
        return scene_parse_oom(p, kw);
    if (scene_parse_image(p, "TEXTURE", scene_parse_loc(ft), ft->text, 3, &t.img))
        return DIAG_INPUT;
    if (scene_names_add(&p->names, SCENE_NAMES_TEXTURE, t.name, (int)s->ntextures)) {
        image_free(&t.img);
        return scene_parse_oom(p, kw);
    }
    t.repeat[0] = (double)rep[0];
    t.repeat[1] = (double)rep[1];
    t.loc = scene_parse_loc(kw);
    s->textures[s->ntextures++] = t;
    return 0;
}

/* One FREQUENCY component: 0 (constant along that parameter, e.g. WAVES
 * ridges parallel to it) or 0.001..4096. */
static int scene_attrmap_freq(scene_cur *c, double *f, const scene_lex_tok **at)
{
    if (scene_cur_number(c, f, at))
        return DIAG_INPUT;
    if (!(*f == 0 || (*f >= 0.001 && *f <= 4096)))
        return scene_cur_error(c, *at, "FREQUENCY must be 0 or between 0.001 and 4096");
    return 0;
}

/* BUMP name pattern AMPLITUDE a [FREQUENCY fu fv] [SEED n]; options in
 * any order, each at most once. */
static int scene_attrmap_bump(scene_parser *p, scene_cur *c)
{
    static const char *const patterns[] = { "WAVES", "BUMPS", "DIMPLES", "NOISE", "GROOVES", "IMAGE", NULL };
    scene *s = p->s;
    const scene_lex_tok *kw = &c->st->tok[0], *at;
    const scene_lex_tok *ft = NULL;
    int seen_amp = 0, seen_freq = 0, seen_seed = 0, seen_width = 0, seen_local = 0, pat, r;
    scene_bump b;
    memset(&b, 0, sizeof b);
    if (scene_attrmap_new_name(p, c, SCENE_NAMES_BUMP, s->nbumps, SCENE_PARSE_MAX_BUMPS, "bumps",
                         b.name, &at) ||
        scene_cur_choice(c, patterns, &pat))
        return DIAG_INPUT;
    b.pattern = (bump_pattern)pat;
    b.freq[0] = b.freq[1] = b.pattern == BUMP_IMAGE ? 1 : 8;
    b.seed = 1;
    if (b.pattern == BUMP_IMAGE) {
        if (!(ft = scene_cur_peek(c)))
            return scene_cur_error(c, NULL, "missing file name");
        if (scene_parse_can_read(p, "BUMP", scene_parse_loc(ft)))
            return DIAG_INPUT;
        c->pos++;
    }
    while (!scene_cur_at_end(c)) {
        const scene_lex_tok *t = scene_cur_peek(c);
        if ((r = scene_parse_option(c, "AMPLITUDE", &seen_amp)) != 0) {
            if (r < 0 || scene_cur_number(c, &b.amplitude, &at))
                return DIAG_INPUT;
            if (b.amplitude == 0)
                return scene_cur_error(c, at, "AMPLITUDE must not be zero");
        } else if ((r = scene_parse_option(c, "FREQUENCY", &seen_freq)) != 0) {
            if (r < 0 || scene_attrmap_freq(c, &b.freq[0], &at) || scene_attrmap_freq(c, &b.freq[1], &at))
                return DIAG_INPUT;
            if (b.freq[0] == 0 && b.freq[1] == 0)
                return scene_cur_error(c, at, "FREQUENCY 0 0 leaves the surface flat");
        } else if ((r = scene_parse_option(c, "SEED", &seen_seed)) != 0) {
            long v;
            if (r < 0 || scene_cur_int(c, "SEED", 0, SCENE_PARSE_MAX_SEED, &v))
                return DIAG_INPUT;
            b.seed = (unsigned)v;
        } else if ((r = scene_parse_option(c, "WIDTH", &seen_width)) != 0) {
            if (r < 0 || scene_cur_number(c, &b.width, &at))
                return DIAG_INPUT;
            if (!(b.width > 0 && b.width <= 0.5))
                return scene_cur_error(c, at, "WIDTH must be above 0 and at most 0.5");
        } else if ((r = scene_parse_option(c, "LOCAL", &seen_local)) != 0) {
            if (r < 0)
                return DIAG_INPUT;
            b.local = 1;
        } else {
            return scene_cur_error(c, t, "expected AMPLITUDE, FREQUENCY, SEED, WIDTH or LOCAL, found %s",
                                   t->text);
        }
    }
    if (!seen_amp)
        return scene_cur_error(c, NULL, "AMPLITUDE is required");
    if (b.pattern == BUMP_GROOVES && !seen_width)
        return scene_cur_error(c, NULL, "GROOVES needs WIDTH");
    if (b.pattern != BUMP_GROOVES && seen_width)
        return scene_cur_error(c, NULL, "WIDTH applies to GROOVES only");
    if (mem_grow((void **)&s->bumps, &p->cap_bumps, s->nbumps + 1, sizeof b))
        return scene_parse_oom(p, kw);
    if (ft && scene_parse_image(p, "BUMP", scene_parse_loc(ft), ft->text, 3, &b.img))
        return DIAG_INPUT;
    if (scene_names_add(&p->names, SCENE_NAMES_BUMP, b.name, (int)s->nbumps)) {
        image_free(&b.img);
        return scene_parse_oom(p, kw);
    }
    b.loc = scene_parse_loc(kw);
    s->bumps[s->nbumps++] = b;
    return 0;
}

const scene_parse_stmt scene_attrmap_stmts[] = {
    { "TEXTURE", "TEXTURE", scene_attrmap_texture },
    { "BUMP", "BUMP", scene_attrmap_bump },
    { NULL, NULL, NULL }
};
