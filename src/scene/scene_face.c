/* scene_face — FACE solid face pdsname: binds a PDS closed earlier to one
 * face of a primitive definition (face names from prim_face_name). The
 * binding is kept with the definition and goes into the shape its
 * placements share (scene_shape.face_map), made at the first OBJECT that
 * places it: so FACE must come before that OBJECT. */
#include <stdio.h>
#include "model/prim_face.h"
#include "scene/scene_parser.h"

/* Statement keywords of the primitive kinds, in prim_kind order. */
static const char *const face_kind_names[PRIM_KIND_COUNT] = {
    "SPHERE", "CYLINDER", "BLOCK", "CONE", "HALFSPACE"
};

/* Reads the face name of a `kind` primitive into *face. */
static int scene_face_name(scene_cur *c, int kind, int *face)
{
    const scene_lex_tok *t = scene_cur_peek(c);
    char list[80] = "";
    size_t len = 0;
    int f, n = prim_face_count(kind);
    if (!t)
        return scene_cur_error(c, NULL, "missing face name");
    for (f = 0; f < n; f++)
        if (scene_cur_is(t, prim_face_name(kind, f))) {
            *face = f;
            c->pos++;
            return 0;
        }
    for (f = 0; f < n && len < sizeof list; f++)
        len += (size_t)snprintf(list + len, sizeof list - len, "%s%s", f ? ", " : "",
                                prim_face_name(kind, f));
    return scene_cur_error(c, t, "a %s has no face %s (it has %s)", face_kind_names[kind], t->text,
                           list);
}

static int scene_face_statement(scene_parser *p, scene_cur *c)
{
    char name[SCENE_NAME_MAX + 1];
    const scene_lex_tok *st, *ft;
    scene_parse_def *d;
    int di, f = 0, m;
    if (scene_cur_name(c, name, &st))
        return DIAG_INPUT;
    di = scene_parse_find_solid(p, name);
    if (di < 0)
        return scene_cur_error(c, st, "%s is used before it is defined", st->text);
    d = &p->defs[di];
    if (d->op != CSG_LEAF)
        return scene_cur_error(c, st, "%s is a CSG solid; faces belong to primitives", st->text);
    if (d->placed)
        return scene_cur_error(c, st, "%s is already placed by OBJECT on record %ld; "
                               "bind its faces before", st->text, d->placed);
    ft = scene_cur_peek(c);
    if (scene_face_name(c, d->kind, &f))
        return DIAG_INPUT;
    if (d->face_map[f] >= 0)
        return scene_cur_error(c, ft, "%s of %s is already bound on record %ld",
                               prim_face_name(d->kind, f), st->text, d->face_rec[f]);
    if (scene_parse_ref(p, c, SCENE_NAMES_PDS, &m) || scene_cur_finish(c))
        return DIAG_INPUT;
    d->face_map[f] = m;
    d->face_rec[f] = c->st->tok[0].line;
    return 0;
}

const scene_parse_stmt scene_face_stmts[] = {
    { "FACE", "FACE", scene_face_statement },
    { NULL, NULL, NULL }
};
