/* scene_pds_cpg — the body of a CPG block (constructive planar geometry,
 * docs/pds.md): one node per statement, named in the block's own name
 * table (constant-time lookup, so blocks of many thousands of nodes parse
 * in linear time):
 *   RECT | ELLIPSE | CIRCLE | POLYGON node numbers [ATTR a] [placement]
 *   UNION | INTER | DIFF node operand... [ATTR a] [placement]
 *   NEST node pdsname [placement]       ROOT node
 * placement: TRANSLATE du dv | ROTATE deg | SCALE su [sv] | SHEAR hu hv,
 * composed in the order written. Geometry is validated by pds_def_check
 * at END, at each node's statement. */
#include "scene/scene_pds.h"

enum { CPG_RECT, CPG_ELLIPSE, CPG_CIRCLE, CPG_POLYGON };

/* 1 if t starts the items after a node's own operands. */
static int scene_pds_cpg_tail_starts(const scene_lex_tok *t)
{
    return scene_cur_is(t, "ATTR") || scene_cur_is(t, "TRANSLATE") || scene_cur_is(t, "ROTATE") ||
           scene_cur_is(t, "SCALE") || scene_cur_is(t, "SHEAR");
}

/* Reads the rest of a node statement: placements, composed onto node in
 * the order written, and (with_attr) at most one ATTR region item. */
static int scene_pds_cpg_tail(scene_parser *p, scene_cur *c, pds_def *d, size_t node, int with_attr)
{
    int seen = 0, r;
    double a[2];
    while (!scene_cur_at_end(c)) {
        if (scene_cur_accept(c, "TRANSLATE")) {
            if (scene_cur_numbers(c, a, 2))
                return DIAG_INPUT;
            pds_cpg_translate(d, node, a[0], a[1]);
        } else if (scene_cur_accept(c, "ROTATE")) {
            if (scene_cur_number(c, &a[0], NULL))
                return DIAG_INPUT;
            pds_cpg_rotate(d, node, a[0]);
        } else if (scene_cur_accept(c, "SCALE")) {
            /* one factor scales both axes, as SCALE s does in 3-D */
            if (scene_cur_number(c, &a[0], NULL))
                return DIAG_INPUT;
            a[1] = a[0];
            if (scene_cur_numeric(scene_cur_peek(c)) && scene_cur_number(c, &a[1], NULL))
                return DIAG_INPUT;
            pds_cpg_scale(d, node, a[0], a[1]);
        } else if (scene_cur_accept(c, "SHEAR")) {
            if (scene_cur_numbers(c, a, 2))
                return DIAG_INPUT;
            pds_cpg_shear(d, node, a[0], a[1]);
        } else if (with_attr && (r = scene_parse_option(c, "ATTR", &seen)) != 0) {
            int32_t id;
            if (r < 0 || scene_pds_region(p, c, &id))
                return DIAG_INPUT;
            d->cpg.nodes[node].attr = id;
        } else {
            return scene_cur_finish(c);
        }
    }
    return 0;
}

/* Reads a node name not yet defined in this block. */
static int scene_pds_cpg_new_name(scene_pds_block *b, scene_cur *c, char name[SCENE_NAME_MAX + 1],
                        const scene_lex_tok **at)
{
    const pds_cpg *g = &b->map->def.cpg;
    int i;
    if (scene_cur_name(c, name, at))
        return DIAG_INPUT;
    i = scene_names_find(&b->names, SCENE_NAMES_NODE, name);
    if (i >= 0)
        return scene_cur_error(c, *at, "%s is already defined on record %ld", (*at)->text,
                               g->nodes[i].loc.line);
    /* the check at END has the same limit; here it also bounds the table */
    if (g->nnodes >= PDS_MAX_NODES)
        return scene_cur_error(c, *at, "CPG has more than %d nodes", PDS_MAX_NODES);
    return 0;
}

/* Names node i, just returned by a builder (-1: out of memory). */
static int scene_pds_cpg_add(scene_parser *p, scene_pds_block *b, long i, const char *name,
                   const scene_lex_tok *at)
{
    if (i < 0 || scene_names_add(&b->names, SCENE_NAMES_NODE, name, (int)i))
        return scene_parse_oom(p, at);
    return 0;
}

/* The node a name in this block stands for. */
static int scene_pds_cpg_ref(scene_pds_block *b, scene_cur *c, size_t *node)
{
    char name[SCENE_NAME_MAX + 1];
    const scene_lex_tok *t;
    int i;
    if (scene_cur_name(c, name, &t))
        return DIAG_INPUT;
    i = scene_names_find(&b->names, SCENE_NAMES_NODE, name);
    if (i < 0)
        return scene_cur_error(c, t, "%s is used before it is defined", t->text);
    *node = (size_t)i;
    return 0;
}

/* RECT u0 v0 u1 v1, ELLIPSE cu cv ru rv, CIRCLE cu cv r, POLYGON u v ...:
 * a leaf, region NONE unless ATTR says otherwise. */
static int scene_pds_cpg_leaf(scene_parser *p, scene_cur *c, int shape)
{
    scene_pds_block *b = scene_pds_current(p);
    pds_def *d = &b->map->def;
    scene_loc loc = scene_parse_loc(&c->st->tok[0]);
    char name[SCENE_NAME_MAX + 1];
    const scene_lex_tok *at;
    double v[SCENE_LEX_MAX_ITEMS];
    size_t n = 0;
    long i;
    if (scene_pds_cpg_new_name(b, c, name, &at))
        return DIAG_INPUT;
    switch (shape) {
    case CPG_RECT:
        if (scene_cur_numbers(c, v, 4))
            return DIAG_INPUT;
        i = pds_cpg_rect(d, v[0], v[1], v[2], v[3], PDS_NONE, loc);
        break;
    case CPG_ELLIPSE:
        if (scene_cur_numbers(c, v, 4))
            return DIAG_INPUT;
        i = pds_cpg_ellipse(d, v[0], v[1], v[2], v[3], PDS_NONE, loc);
        break;
    case CPG_CIRCLE:
        if (scene_cur_numbers(c, v, 3))
            return DIAG_INPUT;
        i = pds_cpg_ellipse(d, v[0], v[1], v[2], v[2], PDS_NONE, loc);
        break;
    default:   /* POLYGON: (u,v) pairs up to the first other item */
        for (; scene_cur_numeric(scene_cur_peek(c)); n += 2)
            if (scene_cur_numbers(c, v + n, 2))
                return DIAG_INPUT;
        i = pds_cpg_polygon(d, v, n / 2, PDS_NONE, loc);
    }
    if (scene_pds_cpg_add(p, b, i, name, at))
        return DIAG_INPUT;
    return scene_pds_cpg_tail(p, c, d, (size_t)i, 1);
}

static int scene_pds_cpg_rect(scene_parser *p, scene_cur *c) { return scene_pds_cpg_leaf(p, c, CPG_RECT); }
static int scene_pds_cpg_ellipse(scene_parser *p, scene_cur *c) { return scene_pds_cpg_leaf(p, c, CPG_ELLIPSE); }
static int scene_pds_cpg_circle(scene_parser *p, scene_cur *c) { return scene_pds_cpg_leaf(p, c, CPG_CIRCLE); }
static int scene_pds_cpg_polygon(scene_parser *p, scene_cur *c) { return scene_pds_cpg_leaf(p, c, CPG_POLYGON); }

/* UNION | INTER | DIFF node operand...: the operands are nodes of this
 * block, in priority order; the region comes from them unless ATTR
 * overrides it. */
static int scene_pds_cpg_operator(scene_parser *p, scene_cur *c, pds_cpg_op op)
{
    scene_pds_block *b = scene_pds_current(p);
    pds_def *d = &b->map->def;
    char name[SCENE_NAME_MAX + 1];
    const scene_lex_tok *at;
    size_t ops[SCENE_LEX_MAX_ITEMS], n = 0;
    long i;
    if (scene_pds_cpg_new_name(b, c, name, &at))
        return DIAG_INPUT;
    while (!scene_cur_at_end(c) && !scene_pds_cpg_tail_starts(scene_cur_peek(c)))
        if (scene_pds_cpg_ref(b, c, &ops[n++]))
            return DIAG_INPUT;
    i = pds_cpg_op_node(d, op, ops, n, PDS_INHERIT, scene_parse_loc(&c->st->tok[0]));
    if (scene_pds_cpg_add(p, b, i, name, at))
        return DIAG_INPUT;
    return scene_pds_cpg_tail(p, c, d, (size_t)i, 1);
}

static int scene_pds_cpg_union(scene_parser *p, scene_cur *c) { return scene_pds_cpg_operator(p, c, PDS_CPG_UNION); }
static int scene_pds_cpg_inter(scene_parser *p, scene_cur *c) { return scene_pds_cpg_operator(p, c, PDS_CPG_INTER); }
static int scene_pds_cpg_diff(scene_parser *p, scene_cur *c) { return scene_pds_cpg_operator(p, c, PDS_CPG_DIFF); }

/* NEST node pdsname: a PDS closed earlier over the node's unit square. */
static int scene_pds_cpg_nest(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    pds_def *d = &b->map->def;
    char name[SCENE_NAME_MAX + 1];
    const scene_lex_tok *at;
    int m;
    long i;
    if (scene_pds_cpg_new_name(b, c, name, &at) || scene_parse_ref(p, c, SCENE_NAMES_PDS, &m))
        return DIAG_INPUT;
    i = pds_cpg_nested(d, &p->s->maps[m]->def, scene_parse_loc(&c->st->tok[0]));
    if (scene_pds_cpg_add(p, b, i, name, at))
        return DIAG_INPUT;
    return scene_pds_cpg_tail(p, c, d, (size_t)i, 0);
}

/* ROOT node: the node the CPG is (default: the last one). */
static int scene_pds_cpg_root(scene_parser *p, scene_cur *c)
{
    scene_pds_block *b = scene_pds_current(p);
    const scene_lex_tok *kw = &c->st->tok[0];
    size_t node = 0;
    if (b->root >= 0)
        return diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col,
                       "ROOT given twice (first on record %ld)", b->root_rec);
    if (scene_pds_cpg_ref(b, c, &node) || scene_cur_finish(c))
        return DIAG_INPUT;
    b->root = (long)node;
    b->root_rec = kw->line;
    return 0;
}

/* A ROOT applies at END, as later nodes would otherwise become the root. */
static int scene_pds_cpg_finish(scene_parser *p, scene_pds_block *b)
{
    (void)p;
    if (b->root >= 0)
        b->map->def.cpg.root = (size_t)b->root;
    return 0;
}

/* PDS name CPG: no options. */
static int scene_pds_cpg_open(scene_parser *p, scene_cur *c, scene_pds_block *b)
{
    (void)c;
    (void)b;
    p->block.body = scene_pds_cpg_body;
    p->block.kind = "CPG";
    return 0;
}

const scene_pds_kind scene_pds_cpg = { scene_pds_cpg_open, scene_pds_cpg_finish };

const scene_parse_stmt scene_pds_cpg_body[] = {
    { "RECT", "RECT", scene_pds_cpg_rect },
    { "ELLIPSE", "ELLIPSE", scene_pds_cpg_ellipse },
    { "CIRCLE", "CIRCLE", scene_pds_cpg_circle },
    { "POLYGON", "POLYGON", scene_pds_cpg_polygon },
    { "UNION", "UNION", scene_pds_cpg_union },
    { "INTER", "INTER", scene_pds_cpg_inter },
    { "INTERSECT", "INTER", scene_pds_cpg_inter },
    { "INTERSECTION", "INTER", scene_pds_cpg_inter },
    { "DIFF", "DIFF", scene_pds_cpg_diff },
    { "DIFFERENCE", "DIFF", scene_pds_cpg_diff },
    { "NEST", "NEST", scene_pds_cpg_nest },
    { "ROOT", "ROOT", scene_pds_cpg_root },
    { "END", "END", scene_pds_end },
    { NULL, NULL, NULL }
};
