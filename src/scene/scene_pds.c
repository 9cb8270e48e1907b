/* scene_pds — PDS name kind [options] ... END: opens a block whose body
 * statements (the kind's table) build one pds_def; END completes it, runs
 * pds_def_check and appends it to scene.maps under its name (a name space
 * of its own). Each definition is allocated on its own, so that a NEST
 * that points at it stays valid while maps grows. */
#include "scene/scene_pds.h"
#include <stdio.h>
#include <string.h>
#include "util/mem.h"

/* The kinds in pds_kind order. */
static const char *const pds_kind_words[] = {
    "CPG", "PIXELS", "TILING", "MOSAIC", "QUADTREE", "CURVES", NULL
};
static const scene_pds_kind *const pds_kinds[PDS_KIND_COUNT] = {
    &scene_pds_cpg, &scene_pds_raster, &scene_pds_tiling, &scene_pds_mosaic,
    &scene_pds_raster, &scene_pds_curves
};

const scene_parse_stmt *const scene_pds_bodies[] = {
    scene_pds_cpg_body, scene_pds_keyed_body, scene_pds_image_body, scene_pds_code_body,
    scene_pds_tiling_body, scene_pds_mosaic_body, scene_pds_curves_body, NULL
};

scene_pds_block *scene_pds_current(scene_parser *p)
{
    return p->block.state;
}

int scene_pds_region(scene_parser *p, scene_cur *c, int32_t *id)
{
    int a;
    if (scene_cur_accept(c, "NONE")) {
        *id = PDS_NONE;
        return 0;
    }
    if (scene_parse_attr_ref(p, c, &a))
        return DIAG_INPUT;
    *id = a;
    return 0;
}

int scene_pds_regions(scene_parser *p, scene_cur *c, int split, int32_t *ids, size_t *n)
{
    *n = 0;
    do {
        if (split && scene_cur_accept(c, "SPLIT"))
            ids[*n] = PDS_QT_SPLIT;
        else if (scene_pds_region(p, c, &ids[*n]))
            return DIAG_INPUT;
        ++*n;
    } while (!scene_cur_at_end(c));
    return 0;
}

static void scene_pds_release(void *state)
{
    scene_pds_block *b = state;
    if (!b)
        return;
    if (b->map) {
        pds_def_free(&b->map->def);
        mem_free(b->map);
    }
    scene_names_free(&b->names);
    mem_free(b->vals);
    mem_free(b->rgb);
    mem_free(b->rgb_attr);
    mem_free(b);
}

/* PDS name kind [options]: a new name (PDS name space), then the kind's
 * own items; the block stays open until END. */
static int scene_pds_statement(scene_parser *p, scene_cur *c)
{
    const scene_lex_tok *kw = &c->st->tok[0], *at;
    char name[SCENE_NAME_MAX + 1];
    scene_pds_block *b;
    int i, k;
    if (scene_cur_name(c, name, &at))
        return DIAG_INPUT;
    i = scene_names_find(&p->names, SCENE_NAMES_PDS, name);
    if (i >= 0)
        return scene_cur_error(c, at, "%s is already defined on record %ld", at->text,
                               p->s->maps[i]->loc.line);
    if (p->s->nmaps >= SCENE_PARSE_MAX_MAPS)
        return scene_cur_error(c, at, "more than %d PDS", SCENE_PARSE_MAX_MAPS);
    if (scene_cur_choice(c, pds_kind_words, &k))
        return DIAG_INPUT;
    b = mem_calloc(1, sizeof *b);
    if (!b || !(b->map = mem_calloc(1, sizeof *b->map))) {
        mem_free(b);
        return scene_parse_oom(p, kw);
    }
    /* Owned by the parser from here: released on any later error. */
    p->block.state = b;
    p->block.release = scene_pds_release;
    p->block.loc = scene_parse_loc(kw);
    snprintf(p->block.title, sizeof p->block.title, "PDS %.*s", SCENE_NAME_MAX, at->text);
    memcpy(b->map->name, name, sizeof name);
    b->map->loc = p->block.loc;
    pds_def_init(&b->map->def, (pds_kind)k, b->map->loc);
    scene_names_init(&b->names);
    b->root = -1;
    if (pds_kinds[k]->open(p, c, b))
        return DIAG_INPUT;
    return scene_cur_finish(c);
}

int scene_pds_end(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    const scene_pds_kind *k = pds_kinds[b->map->def.kind];
    scene *s = p->s;
    if (scene_cur_finish(c))
        return DIAG_INPUT;
    if (k->finish && k->finish(p, b))
        return p->err->status;
    if (pds_def_check(&b->map->def, p->file, p->err))
        return p->err->status;
    if (mem_grow((void **)&s->maps, &p->cap_maps, s->nmaps + 1, sizeof *s->maps) ||
        scene_names_add(&p->names, SCENE_NAMES_PDS, b->map->name, (int)s->nmaps))
        return scene_parse_oom(p, &c->st->tok[0]);
    s->maps[s->nmaps++] = b->map;
    b->map = NULL;
    scene_parse_close_block(p);
    return 0;
}

const scene_parse_stmt scene_pds_stmts[] = {
    { "PDS", "PDS", scene_pds_statement },
    { NULL, NULL, NULL }
};
