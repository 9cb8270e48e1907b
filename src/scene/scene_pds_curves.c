/* scene_pds_curves — CURVES blocks (curve-bounded regions, docs/pds.md):
 *   PDS name CURVES [TOLERANCE t] [STRIPS [WIDTH w]]
 *   BSPLINE attr u v u v ...    closed uniform cubic B-spline control points
 *   POLYLINE attr u v u v ...   closed polyline vertices
 * in priority order (the first curve containing a point wins). Shapes and
 * the tolerance are validated by pds_def_check at END. STRIPS answers
 * membership with Ballard's strip trees (pds_strip.h) built to width w. */
#include "scene/scene_pds.h"

static int scene_pds_curves_open(scene_parser *p, scene_cur *c, scene_pds_block *b)
{
    pds_curves *cv = &b->map->def.curves;
    const scene_lex_tok *t = scene_cur_peek(c), *at;
    if (scene_cur_accept(c, "TOLERANCE") && scene_cur_number(c, &cv->tolerance, NULL))
        return DIAG_INPUT;
    if (scene_cur_accept(c, "STRIPS")) {
        cv->strips = 1;
        if (scene_cur_accept(c, "WIDTH")) {
            if (scene_cur_number(c, &cv->strip_width, &at))
                return DIAG_INPUT;
            if (!(cv->strip_width >= 0 && cv->strip_width <= 1))
                return scene_cur_error(c, at, "strip WIDTH must be between 0 and 1");
        }
    }
    if ((t = scene_cur_peek(c)) != NULL)
        return scene_cur_error(c, t, "expected TOLERANCE or STRIPS, found %s", t->text);
    p->block.body = scene_pds_curves_body;
    p->block.kind = "CURVES";
    return 0;
}

/* attr, then (u,v) pairs to the end of the statement. */
static int scene_pds_curves_add(scene_parser *p, scene_cur *c, int bspline)
{
    pds_def *d = &scene_pds_current(p)->map->def;
    const scene_lex_tok *kw = &c->st->tok[0];
    double uv[SCENE_LEX_MAX_ITEMS];
    size_t n = 0;
    int32_t id;
    if (scene_pds_region(p, c, &id))
        return DIAG_INPUT;
    for (; !scene_cur_at_end(c); n += 2)
        if (scene_cur_numbers(c, uv + n, 2))
            return DIAG_INPUT;
    if (pds_curve_add(d, bspline, uv, n / 2, id, scene_parse_loc(kw)) < 0)
        return scene_parse_oom(p, kw);
    return 0;
}

static int scene_pds_curves_bspline(scene_parser *p, scene_cur *c) { return scene_pds_curves_add(p, c, 1); }
static int scene_pds_curves_polyline(scene_parser *p, scene_cur *c) { return scene_pds_curves_add(p, c, 0); }

const scene_pds_kind scene_pds_curves = { scene_pds_curves_open, NULL };

const scene_parse_stmt scene_pds_curves_body[] = {
    { "BSPLINE", "BSPLINE", scene_pds_curves_bspline },
    { "POLYLINE", "POLYLINE", scene_pds_curves_polyline },
    { "END", "END", scene_pds_end },
    { NULL, NULL, NULL }
};
