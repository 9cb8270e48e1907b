/* scene_parse — scene deck (card images) to the scene model.
 * Data flow: recsrc records -> scene_lex statements -> a handler per
 * statement keyword (tables below; inside an open block such as PDS ... END
 * only the block's body table) -> definitions, lights, attributes, maps and
 * the view in a scene being built -> each OBJECT expanded at once into
 * primitive copies (with their FACE bindings) and binary CSG nodes (sizes
 * checked with saturating counts before any allocation) -> completeness
 * checks -> the finished scene. Attribute-mapping statements live in
 * scene_attrmap.c, scene_pds*.c and scene_face.c.
 * The language is documented in docs/scene-format.md. */
#include "util/dmath.h"
#include "scene/scene_parser.h"
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "scene/scene_xform.h"
#include "util/mem.h"
#include "util/suggest.h"

/* ---- shared helpers ------------------------------------------------------ */

scene_loc scene_parse_loc(const scene_lex_tok *t)
{
    scene_loc l;
    l.line = t->line;
    l.col = t->col;
    return l;
}

int scene_parse_oom(scene_parser *p, const scene_lex_tok *t)
{
    return diag_at(p->err, DIAG_IO, p->file, t ? t->line : 0, t ? t->col : 0,
                   "out of memory");
}

int scene_parse_find_solid(const scene_parser *p, const char *name)
{
    return scene_names_find(&p->names, SCENE_NAMES_SOLID, name);
}

int scene_parse_ref(scene_parser *p, scene_cur *c, int space, int *index)
{
    char name[SCENE_NAME_MAX + 1];
    const scene_lex_tok *t;
    int i;
    if (scene_cur_name(c, name, &t))
        return DIAG_INPUT;
    i = scene_names_find(&p->names, space, name);
    if (i < 0)
        return scene_cur_error(c, t, "%s is used before it is defined", t->text);
    *index = i;
    return 0;
}

int scene_parse_attr_ref(scene_parser *p, scene_cur *c, int *attr)
{
    return scene_parse_ref(p, c, SCENE_NAMES_ATTR, attr);
}

int scene_parse_can_read(scene_parser *p, const char *what, scene_loc at)
{
    if (p->loader && p->loader->image)
        return 0;
    return diag_at(p->err, DIAG_INPUT, p->file, at.line, at.col,
                   "%s: images cannot be read here", what);
}

int scene_parse_image(scene_parser *p, const char *what, scene_loc at, const char *name,
                      int channels, image *out)
{
    diag e;
    image img = { 0, 0, 0, NULL };
    int r;
    if (scene_parse_can_read(p, what, at))
        return DIAG_INPUT;
    diag_init(&e);
    r = p->loader->image(p->loader->ctx, name, channels, &img, &e);
    if (channels == IMAGE_INDEXED)
        channels = 1;
    if (r == 0 && (size_t)img.width * (size_t)img.height > SCENE_IMAGE_MAX_PIXELS) {
        snprintf(e.msg, sizeof e.msg, "image of %dx%d pixels is over the limit of %zu", img.width, img.height,
                 SCENE_IMAGE_MAX_PIXELS);
        r = DIAG_INPUT;
    }
    if (r == 0 && (img.channels != channels || img.width < 1 || img.height < 1 || !img.px)) {
        /* a loader that breaks its contract must not reach the builders */
        snprintf(e.msg, sizeof e.msg, "not a %d-channel image", channels);
        r = DIAG_INPUT;
    }
    if (r != 0) {
        image_free(&img);
        return diag_at(p->err, DIAG_INPUT, p->file, at.line, at.col, "%s: cannot read %s: %s",
                       what, name, e.msg[0] ? e.msg : "unknown error");
    }
    *out = img;
    return 0;
}

void scene_parse_close_block(scene_parser *p)
{
    if (p->block.release)
        p->block.release(p->block.state);
    memset(&p->block, 0, sizeof p->block);
}

int scene_parse_tail(scene_parser *p, scene_cur *c, double m[16], int *attr)
{
    for (;;) {
        const scene_lex_tok *t = scene_cur_peek(c);
        int r = scene_xform_parse(c, m);
        if (r > 0)
            return DIAG_INPUT;
        if (r == 0)
            continue;
        if (scene_cur_is(t, "ATTR")) {
            if (*attr >= 0)
                return scene_cur_error(c, t, "ATTR given twice");
            c->pos++;
            if (scene_parse_attr_ref(p, c, attr))
                return DIAG_INPUT;
        } else {
            return 0;
        }
    }
}

/* Reads a new solid's name and checks it is not yet defined. */
static int scene_parse_new_name(scene_parser *p, scene_cur *c, char name[SCENE_NAME_MAX + 1],
                                const scene_lex_tok **at)
{
    int i;
    if (scene_cur_name(c, name, at))
        return DIAG_INPUT;
    i = scene_parse_find_solid(p, name);
    if (i >= 0)
        return scene_cur_error(c, *at, "%s is already defined on record %ld",
                               (*at)->text, p->defs[i].loc.line);
    return 0;
}

/* Appends def (name already checked) to the definitions and the name table. */
static int scene_parse_add_def(scene_parser *p, scene_cur *c, const scene_lex_tok *at,
                               const scene_parse_def *def)
{
    if (p->ndefs >= SCENE_PARSE_MAX_DEFS)
        return scene_cur_error(c, at, "more than %d solids", SCENE_PARSE_MAX_DEFS);
    if (mem_grow((void **)&p->defs, &p->cap_defs, p->ndefs + 1, sizeof *p->defs) ||
        scene_names_add(&p->names, SCENE_NAMES_SOLID, def->name, (int)p->ndefs))
        return scene_parse_oom(p, at);
    p->defs[p->ndefs++] = *def;
    return 0;
}

/* ---- view statements ----------------------------------------------------- */

/* Records that view statement slot appears here; fails on a repeat. */
static int scene_parse_once(scene_parser *p, scene_cur *c, int slot)
{
    const scene_lex_tok *kw = &c->st->tok[0];
    if (p->view_loc[slot].line)
        return diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col,
                       "%s given twice (first on record %ld)", c->what, p->view_loc[slot].line);
    p->view_loc[slot] = scene_parse_loc(kw);
    return 0;
}

static int scene_parse_color(scene_cur *c, double rgb[3])
{
    int i;
    for (i = 0; i < 3; i++)
        if (scene_cur_range(c, "a colour component", 0, 1, &rgb[i]))
            return DIAG_INPUT;
    return 0;
}

static int scene_parse_eye(scene_parser *p, scene_cur *c)
{
    double v[3];
    if (scene_parse_once(p, c, SCENE_PARSE_EYE) || scene_cur_numbers(c, v, 3) ||
        scene_cur_finish(c))
        return DIAG_INPUT;
    memcpy(p->s->view.eye, v, sizeof v);
    return 0;
}

static int scene_parse_look(scene_parser *p, scene_cur *c)
{
    double v[3];
    if (scene_parse_once(p, c, SCENE_PARSE_LOOK) || scene_cur_numbers(c, v, 3) ||
        scene_cur_finish(c))
        return DIAG_INPUT;
    memcpy(p->s->view.look, v, sizeof v);
    return 0;
}

static int scene_parse_up(scene_parser *p, scene_cur *c)
{
    double v[3];
    if (scene_parse_once(p, c, SCENE_PARSE_UP) || scene_cur_numbers(c, v, 3))
        return DIAG_INPUT;
    if (v[0] == 0 && v[1] == 0 && v[2] == 0)
        return scene_cur_error(c, &c->st->tok[1], "direction must not be zero");
    if (scene_cur_finish(c))
        return DIAG_INPUT;
    memcpy(p->s->view.up, v, sizeof v);
    return 0;
}

static int scene_parse_fov(scene_parser *p, scene_cur *c)
{
    const scene_lex_tok *t;
    double v;
    if (scene_parse_once(p, c, SCENE_PARSE_FOV) || scene_cur_number(c, &v, &t))
        return DIAG_INPUT;
    if (!(v > 0 && v < 180))
        return scene_cur_error(c, t, "angle must be above 0 and below 180 degrees");
    if (scene_cur_finish(c))
        return DIAG_INPUT;
    p->s->view.fov_deg = v;
    return 0;
}

static int scene_parse_size(scene_parser *p, scene_cur *c)
{
    long w, h;
    if (scene_parse_once(p, c, SCENE_PARSE_SIZE) ||
        scene_cur_int(c, "width", 1, SCENE_MAX_SIDE, &w) ||
        scene_cur_int(c, "height", 1, SCENE_MAX_SIDE, &h) || scene_cur_finish(c))
        return DIAG_INPUT;
    p->s->view.width = (int)w;
    p->s->view.height = (int)h;
    return 0;
}

static int scene_parse_ambient(scene_parser *p, scene_cur *c)
{
    double v[3];
    if (scene_parse_once(p, c, SCENE_PARSE_AMBIENT) || scene_parse_color(c, v) ||
        scene_cur_finish(c))
        return DIAG_INPUT;
    memcpy(p->s->ambient, v, sizeof v);
    return 0;
}

static int scene_parse_background(scene_parser *p, scene_cur *c)
{
    double v[3];
    if (scene_parse_once(p, c, SCENE_PARSE_BACKGROUND) || scene_parse_color(c, v) ||
        scene_cur_finish(c))
        return DIAG_INPUT;
    memcpy(p->s->background, v, sizeof v);
    return 0;
}

static int scene_parse_depth(scene_parser *p, scene_cur *c)
{
    long n;
    if (scene_parse_once(p, c, SCENE_PARSE_DEPTH) ||
        scene_cur_int(c, "depth", 0, 32, &n) || scene_cur_finish(c))
        return DIAG_INPUT;
    p->s->max_depth = (int)n;
    return 0;
}

/* ---- LIGHT and ATTR ------------------------------------------------------ */

int scene_parse_option(scene_cur *c, const char *kw, int *seen)
{
    const scene_lex_tok *t = scene_cur_peek(c);
    if (!scene_cur_is(t, kw))
        return 0;
    if (*seen) {
        scene_cur_error(c, t, "%s given twice", kw);
        return -1;
    }
    *seen = 1;
    c->pos++;
    return 1;
}

/* LIGHT x y z [COLOR r g b] [INTENSITY i]: appends a point light. */
static int scene_parse_light(scene_parser *p, scene_cur *c)
{
    scene_light l;
    int seen_color = 0, seen_int = 0, r;
    const scene_lex_tok *kw = &c->st->tok[0];
    if (p->s->nlights >= SCENE_MAX_LIGHTS)
        return scene_cur_error(c, kw, "more than %d lights", SCENE_MAX_LIGHTS);
    if (scene_cur_numbers(c, l.pos, 3))
        return DIAG_INPUT;
    l.color[0] = l.color[1] = l.color[2] = 1;
    l.intensity = 1;
    l.loc = scene_parse_loc(kw);
    while (!scene_cur_at_end(c)) {
        const scene_lex_tok *t = scene_cur_peek(c);
        if ((r = scene_parse_option(c, "COLOR", &seen_color)) != 0) {
            if (r < 0 || scene_parse_color(c, l.color))
                return DIAG_INPUT;
        } else if ((r = scene_parse_option(c, "INTENSITY", &seen_int)) != 0) {
            const scene_lex_tok *at;
            if (r < 0 || scene_cur_number(c, &l.intensity, &at))
                return DIAG_INPUT;
            if (l.intensity < 0)
                return scene_cur_error(c, at, "INTENSITY must not be negative");
        } else {
            return scene_cur_error(c, t, "expected COLOR or INTENSITY, found %s", t->text);
        }
    }
    if (mem_grow((void **)&p->s->lights, &p->cap_lights, p->s->nlights + 1, sizeof l))
        return scene_parse_oom(p, kw);
    p->s->lights[p->s->nlights++] = l;
    return 0;
}

/* Default coefficients of an attribute (docs/scene-format.md). */
static void scene_parse_attr_defaults(scene_attr *a)
{
    memset(a, 0, sizeof *a);
    a->color[0] = a->color[1] = a->color[2] = 0.8;
    a->ambient = 1;
    a->diffuse = 0.8;
    a->specular = 0;
    a->exponent = 20;
    a->mirror = 0;
    a->transmit = 0;
    a->ior = 1;
    a->texture = -1;
    a->bump = -1;
}

static int scene_parse_add_attr(scene_parser *p, const scene_attr *a, const scene_lex_tok *at)
{
    if (mem_grow((void **)&p->s->attrs, &p->cap_attrs, p->s->nattrs + 1, sizeof *a) ||
        scene_names_add(&p->names, SCENE_NAMES_ATTR, a->name, (int)p->s->nattrs))
        return scene_parse_oom(p, at);
    p->s->attrs[p->s->nattrs++] = *a;
    return 0;
}

/* Passes a warning at token t to the loader's warn(). */
static void scene_parse_warn(scene_parser *p, const scene_lex_tok *t, const char *msg)
{
    diag w;
    if (!p->loader || !p->loader->warn)
        return;
    diag_init(&w);
    diag_at(&w, DIAG_INPUT, p->file, t->line, t->col, "%s", msg);
    p->loader->warn(p->loader->ctx, &w);
}

/* Energy conservation: a surface cannot send on more light than reaches
 * it, DIFFUSE + MIRROR + TRANSMIT <= 1. It also bounds the ray tree: the
 * weights of the rays of one depth then sum to at most 1, so the weight cut
 * (trace.c) leaves at most 1/TRACE_MIN_WEIGHT rays per depth. A DIFFUSE the
 * deck did not write becomes what MIRROR and TRANSMIT leave of 1 (if less
 * than its default); coefficients the deck wrote that sum over 1 are scaled
 * to sum 1, with a warning at the attribute's name. */
static void scene_parse_energy(scene_parser *p, scene_attr *a, int diffuse_written, const scene_lex_tok *at)
{
    double sum, k;
    char msg[256];
    if (!diffuse_written && a->diffuse + a->mirror + a->transmit > 1)
        a->diffuse = a->mirror + a->transmit < 1 ? 1 - a->mirror - a->transmit : 0;
    sum = a->diffuse + a->mirror + a->transmit;
    if (sum <= 1 + 1e-9)
        return;
    k = 1 / sum;
    snprintf(msg, sizeof msg,
             "ATTR %s: DIFFUSE %g + MIRROR %g + TRANSMIT %g = %g sends on more light than arrives; scaled by "
             "%.4g to DIFFUSE %.4g, MIRROR %.4g, TRANSMIT %.4g",
             a->name, a->diffuse, a->mirror, a->transmit, sum, k, a->diffuse * k, a->mirror * k,
             a->transmit * k);
    a->diffuse *= k;
    a->mirror *= k;
    a->transmit *= k;
    scene_parse_warn(p, at, msg);
}

/* ATTR name COLOR r g b {option value} [TEXTURE t] [BUMP b]: appends an
 * attribute; the option table gives each coefficient's keyword, range and
 * field; TEXTURE and BUMP name a texture or bump defined earlier. */
static int scene_parse_attr(scene_parser *p, scene_cur *c)
{
    static const struct { const char *kw; double lo, hi; size_t off; } opt[] = {
        { "AMBIENT", 0, 1, offsetof(scene_attr, ambient) },
        { "DIFFUSE", 0, 1, offsetof(scene_attr, diffuse) },
        { "SPECULAR", 0, 1, offsetof(scene_attr, specular) },
        { "EXPONENT", 1, 10000, offsetof(scene_attr, exponent) },
        { "MIRROR", 0, 1, offsetof(scene_attr, mirror) },
        { "TRANSMIT", 0, 1, offsetof(scene_attr, transmit) },
        { "IOR", 1, 10, offsetof(scene_attr, ior) },
    };
    enum { NOPT = sizeof opt / sizeof opt[0] };
    /* MODEL names, in shade_model order */
    static const char *const models[] = { "PHONG", "LAMBERT", "BLINN", "MIRROR", "TRANSPARENT", NULL };
    int seen[NOPT + 1] = { 0 }, seen_tex = 0, seen_bump = 0, seen_model = 0, i, r;
    const scene_lex_tok *kw = &c->st->tok[0], *at;
    scene_attr a;
    scene_parse_attr_defaults(&a);
    if (scene_cur_name(c, a.name, &at))
        return DIAG_INPUT;
    i = scene_names_find(&p->names, SCENE_NAMES_ATTR, a.name);
    if (i >= 0) {
        if (p->s->attrs[i].loc.line == 0)
            return scene_cur_error(c, at, "%s is built in and cannot be redefined", at->text);
        return scene_cur_error(c, at, "%s is already defined on record %ld", at->text,
                               p->s->attrs[i].loc.line);
    }
    if (p->s->nattrs >= SCENE_PARSE_MAX_ATTRS)
        return scene_cur_error(c, at, "more than %d attributes", SCENE_PARSE_MAX_ATTRS);
    a.loc = scene_parse_loc(kw);
    while (!scene_cur_at_end(c)) {
        const scene_lex_tok *t = scene_cur_peek(c);
        if ((r = scene_parse_option(c, "COLOR", &seen[NOPT])) != 0) {
            if (r < 0 || scene_parse_color(c, a.color))
                return DIAG_INPUT;
            continue;
        }
        if ((r = scene_parse_option(c, "TEXTURE", &seen_tex)) != 0) {
            if (r < 0 || scene_parse_ref(p, c, SCENE_NAMES_TEXTURE, &a.texture))
                return DIAG_INPUT;
            continue;
        }
        if ((r = scene_parse_option(c, "BUMP", &seen_bump)) != 0) {
            if (r < 0 || scene_parse_ref(p, c, SCENE_NAMES_BUMP, &a.bump))
                return DIAG_INPUT;
            continue;
        }
        if ((r = scene_parse_option(c, "MODEL", &seen_model)) != 0) {
            int m;
            if (r < 0 || scene_cur_choice(c, models, &m))
                return DIAG_INPUT;
            a.model = (shade_model)m;
            continue;
        }
        for (i = 0; i < NOPT; i++)
            if ((r = scene_parse_option(c, opt[i].kw, &seen[i])) != 0)
                break;
        if (i == NOPT)
            return scene_cur_error(c, t, "expected COLOR, AMBIENT, DIFFUSE, SPECULAR, "
                                   "EXPONENT, MIRROR, TRANSMIT, IOR, TEXTURE, BUMP or MODEL, "
                                   "found %s", t->text);
        if (r < 0 || scene_cur_range(c, opt[i].kw, opt[i].lo, opt[i].hi,
                                     (double *)(void *)((char *)&a + opt[i].off)))
            return DIAG_INPUT;
    }
    if (!seen[NOPT])
        return scene_cur_error(c, NULL, "COLOR is required");
    /* A mirror reflects, a transparent attribute transmits, unless told how
     * much: all the light the other written coefficient leaves (the energy
     * rule below then holds). */
    if (a.model == SHADE_MIRROR && !seen[4])
        a.mirror = seen[5] ? 1 - a.transmit : 1;
    if (a.model == SHADE_TRANSPARENT && !seen[5])
        a.transmit = seen[4] ? 1 - a.mirror : 1;
    if (a.model == SHADE_TRANSPARENT && !seen[6])
        a.ior = 1.5;
    scene_parse_energy(p, &a, seen[1], at);
    return scene_parse_add_attr(p, &a, kw);
}

/* ---- solids -------------------------------------------------------------- */

/* A definition made by the statement at kw: no ATTR, no own transform, no
 * FACE bindings, not placed yet. */
static void scene_parse_def_init(scene_parse_def *d, csg_op op, const scene_lex_tok *kw)
{
    int i;
    memset(d, 0, sizeof *d);
    d->loc = scene_parse_loc(kw);
    d->op = op;
    d->attr = -1;
    for (i = 0; i < SCENE_MAX_FACES; i++)
        d->face_map[i] = -1;
    scene_xform_identity(d->m);
}

/* Reads a dimension that must be positive (or, if zero_ok, not negative). */
static int scene_parse_dim(scene_cur *c, const char *label, int zero_ok, double *v)
{
    const scene_lex_tok *t;
    if (scene_cur_number(c, v, &t))
        return DIAG_INPUT;
    if (zero_ok ? *v < 0 : *v <= 0)
        return scene_cur_error(c, t, "%s must be %s", label, zero_ok ? "0 or more" : "positive");
    return 0;
}

/* SPHERE | CYLINDER | BLOCK | CONE | HALFSPACE name dims tail: defines a
 * primitive solid (dimensions as in scene.h's canonical frames). */
static int scene_parse_prim(scene_parser *p, scene_cur *c, prim_kind kind)
{
    scene_parse_def d;
    const scene_lex_tok *at;
    scene_parse_def_init(&d, CSG_LEAF, &c->st->tok[0]);
    if (scene_parse_new_name(p, c, d.name, &at))
        return DIAG_INPUT;
    d.kind = kind;
    d.leaves = 1;
    d.depth = 1;
    switch (kind) {
    case PRIM_SPHERE:
        if (scene_parse_dim(c, "radius", 0, &d.dim[0]))
            return DIAG_INPUT;
        break;
    case PRIM_CYLINDER:
        if (scene_parse_dim(c, "radius", 0, &d.dim[0]) ||
            scene_parse_dim(c, "height", 0, &d.dim[1]))
            return DIAG_INPUT;
        break;
    case PRIM_BLOCK:
        if (scene_parse_dim(c, "size", 0, &d.dim[0]) || scene_parse_dim(c, "size", 0, &d.dim[1]) ||
            scene_parse_dim(c, "size", 0, &d.dim[2]))
            return DIAG_INPUT;
        break;
    case PRIM_CONE:
        if (scene_parse_dim(c, "radius", 1, &d.dim[0]) ||
            scene_parse_dim(c, "radius", 1, &d.dim[1]))
            return DIAG_INPUT;
        if (d.dim[0] == 0 && d.dim[1] == 0)
            return scene_cur_error(c, &c->st->tok[c->pos - 1], "radii must not both be zero");
        if (scene_parse_dim(c, "height", 0, &d.dim[2]))
            return DIAG_INPUT;
        break;
    default:  /* PRIM_HALFSPACE: no dimensions */
        break;
    }
    if (scene_parse_tail(p, c, d.m, &d.attr) || scene_cur_finish(c))
        return DIAG_INPUT;
    return scene_parse_add_def(p, c, at, &d);
}

static int scene_parse_sphere(scene_parser *p, scene_cur *c) { return scene_parse_prim(p, c, PRIM_SPHERE); }
static int scene_parse_cylinder(scene_parser *p, scene_cur *c) { return scene_parse_prim(p, c, PRIM_CYLINDER); }
static int scene_parse_box(scene_parser *p, scene_cur *c) { return scene_parse_prim(p, c, PRIM_BLOCK); }
static int scene_parse_cone(scene_parser *p, scene_cur *c) { return scene_parse_prim(p, c, PRIM_CONE); }
static int scene_parse_halfspace(scene_parser *p, scene_cur *c) { return scene_parse_prim(p, c, PRIM_HALFSPACE); }

/* Reads one use of a solid: its name (defined earlier) and its tail. */
static int scene_parse_use_at(scene_parser *p, scene_cur *c, scene_parse_use *u,
                              const scene_lex_tok **at)
{
    char name[SCENE_NAME_MAX + 1];
    if (scene_cur_name(c, name, at))
        return DIAG_INPUT;
    u->def = scene_parse_find_solid(p, name);
    if (u->def < 0)
        return scene_cur_error(c, *at, "%s is used before it is defined", (*at)->text);
    u->loc = scene_parse_loc(*at);
    u->attr = -1;
    scene_xform_identity(u->m);
    return scene_parse_tail(p, c, u->m, &u->attr);
}

/* a + b, saturated just above the primitive limit. */
static size_t scene_parse_sat_add(size_t a, size_t b)
{
    size_t cap = (size_t)SCENE_PARSE_MAX_PRIMS + 1;
    return (a >= cap || b >= cap || a + b >= cap) ? cap : a + b;
}

/* UNION | INTER | DIFF name operand operand {operand}: defines a CSG solid.
 * Its leaf count (saturated) and nesting depth are derived from the
 * operands here, so OBJECT can check sizes before expanding. On error the
 * operands already appended are dropped again. */
static int scene_parse_csg(scene_parser *p, scene_cur *c, csg_op op)
{
    scene_parse_def d;
    const scene_lex_tok *at, *ot;
    size_t first = p->noperands;
    scene_parse_def_init(&d, op, &c->st->tok[0]);
    if (scene_parse_new_name(p, c, d.name, &at))
        return DIAG_INPUT;
    d.first = first;
    while (!scene_cur_at_end(c)) {
        scene_parse_use u;
        const scene_parse_def *od;
        if (scene_parse_use_at(p, c, &u, &ot))
            goto fail;
        od = &p->defs[u.def];
        if (od->depth >= SCENE_PARSE_MAX_NEST) {
            scene_cur_error(c, ot, "%s would nest solids more than %d deep", ot->text,
                            SCENE_PARSE_MAX_NEST);
            goto fail;
        }
        if (od->depth + 1 > d.depth)
            d.depth = od->depth + 1;
        d.leaves = scene_parse_sat_add(d.leaves, od->leaves);
        if (p->noperands >= SCENE_PARSE_MAX_OPERANDS) {
            scene_cur_error(c, ot, "more than %d operands in all", SCENE_PARSE_MAX_OPERANDS);
            goto fail;
        }
        if (mem_grow((void **)&p->operands, &p->cap_operands, p->noperands + 1, sizeof u)) {
            scene_parse_oom(p, ot);
            goto fail;
        }
        p->operands[p->noperands++] = u;
    }
    d.count = p->noperands - first;
    if (d.count < 2) {
        scene_cur_error(c, NULL, "needs at least two operands");
        goto fail;
    }
    if (scene_parse_add_def(p, c, at, &d) == 0)
        return 0;
fail:
    p->noperands = first;
    return DIAG_INPUT;
}

static int scene_parse_union(scene_parser *p, scene_cur *c) { return scene_parse_csg(p, c, CSG_UNION); }
static int scene_parse_inter(scene_parser *p, scene_cur *c) { return scene_parse_csg(p, c, CSG_INTER); }
static int scene_parse_diff(scene_parser *p, scene_cur *c) { return scene_parse_csg(p, c, CSG_DIFF); }

/* ---- OBJECT: expansion --------------------------------------------------- */

/* The shape of leaf definition d (its kind, dimensions, FACE bindings,
 * name and place), added to the scene; NULL when memory runs out. Made at
 * d's first placement: FACE must come before it, so the shape is final. */
static const scene_shape *scene_parse_shape(scene_parser *p, const scene_parse_def *d)
{
    scene *s = p->s;
    scene_shape *sh;
    if (mem_grow((void **)&s->shapes, &p->cap_shapes, s->nshapes + 1, sizeof *s->shapes) ||
        !(sh = mem_alloc(sizeof *sh)))
        return NULL;
    sh->kind = d->kind;
    memcpy(sh->dim, d->dim, sizeof sh->dim);
    memcpy(sh->face_map, d->face_map, sizeof sh->face_map);
    memcpy(sh->name, d->name, sizeof sh->name);
    sh->loc = d->loc;
    s->shapes[s->nshapes++] = sh;
    return sh;
}

/* Expands definition di under transform m and inherited attribute attr into
 * prims and nodes (capacity reserved by the caller) for the OBJECT on record
 * rec; returns the node index, -1 when a composed transform is unusable
 * (*bad names the primitive) or -2 when memory runs out. Each primitive
 * points at its definition's shape, and the definition remembers the first
 * OBJECT that placed it. m and every transform of the parser come from scene_xform_identity
 * or scene_xform_mul, so a product with a transform that is the identity
 * would be m again and is not formed; m_ok is 1 when m itself passed
 * scene_xform_ok (an OBJECT's transforms did), which a primitive placed by
 * m alone need not ask again. Recursion depth is bounded by
 * SCENE_PARSE_MAX_NEST (checked at definition). */
static int scene_parse_expand(scene_parser *p, int di, const double m[16], int m_ok, int attr,
                              long rec, const scene_parse_def **bad)
{
    scene_parse_def *d = &p->defs[di];
    scene *s = p->s;
    scene_node *n;
    size_t i;
    int left = -1;
    if (d->op == CSG_LEAF) {
        scene_prim *pr = &s->prims[s->nprims];
        double t[16];
        const double *w = m;
        if (!scene_xform_is_identity(d->m)) {
            scene_xform_mul(t, m, d->m);
            w = t;
            m_ok = 0;
        }
        if (!m_ok && !scene_xform_ok(w)) {
            *bad = d;
            return -1;
        }
        if (!d->shape && !(d->shape = scene_parse_shape(p, d)))
            return -2;
        if (!d->placed)
            d->placed = rec;
        memcpy(pr->world_from_object, w, sizeof pr->world_from_object);
        pr->shape = d->shape;
        pr->attr = d->attr >= 0 ? d->attr : attr;
        n = &s->nodes[s->nnodes];
        n->op = CSG_LEAF;
        n->left = n->right = -1;
        n->prim = (int)s->nprims++;
        return (int)s->nnodes++;
    }
    for (i = 0; i < d->count; i++) {
        const scene_parse_use *u = &p->operands[d->first + i];
        const double *um = m;
        double prod[16];
        int r, um_ok = m_ok;
        if (!scene_xform_is_identity(u->m)) {
            scene_xform_mul(prod, m, u->m);
            um = prod;
            um_ok = 0;
        }
        r = scene_parse_expand(p, u->def, um, um_ok, u->attr >= 0 ? u->attr : attr, rec, bad);
        if (r < 0)
            return r;
        if (left < 0) {
            left = r;
            continue;
        }
        n = &s->nodes[s->nnodes];
        n->op = d->op;
        n->left = left;
        n->right = r;
        n->prim = -1;
        left = (int)s->nnodes++;
    }
    return left;
}

/* The room to ask for when an array of the expansion must grow to hold
 * need entries, `adds` of them this statement's (at most limit): where
 * the source knows its records in all, room for the rest of the deck as
 * statements like this one (as many records each, adding as many
 * entries), else need (mem_grow then doubles). Each growth copies the
 * array to pages never touched before: 10,000 objects' primitives and
 * nodes doubled thirteen and fourteen times, about 690 of the load's
 * 2,860 page faults, where each now grows once (docs/performance.md,
 * run AY). A deck that is not all such statements is given room it
 * does not touch, at most limit entries. */
static size_t scene_parse_room(const scene_parser *p, size_t need, size_t adds, size_t limit)
{
    size_t total = p->lex.src->records, read = p->lex.recno > 0 ? (size_t)p->lex.recno : 0;
    size_t first = p->st.tok[0].line > 0 ? (size_t)p->st.tok[0].line : read;
    double guess;
    if (!total || read >= total || first > read || need >= limit)
        return need;
    guess = (double)need + (double)adds * (double)(total - read) / (double)(read - first + 1);
    return guess >= (double)limit ? limit : (size_t)guess;
}

/* OBJECT name tail: checks the expansion against the scene limits, makes
 * room for it (scene_parse_room), expands it and adds its root. On error
 * the scene is left as before the statement. */
static int scene_parse_object(scene_parser *p, scene_cur *c)
{
    scene *s = p->s;
    scene_parse_use u;
    const scene_lex_tok *at;
    const scene_parse_def *d, *bad = NULL;
    size_t np0 = s->nprims, nn0 = s->nnodes, leaves;
    int root;
    if (scene_parse_use_at(p, c, &u, &at) || scene_cur_finish(c))
        return DIAG_INPUT;
    d = &p->defs[u.def];
    leaves = d->leaves;
    if (leaves > SCENE_PARSE_MAX_PRIMS - s->nprims)
        return scene_cur_error(c, at, "%s brings the scene to more than %d primitives",
                               at->text, SCENE_PARSE_MAX_PRIMS);
    if (2 * leaves - 1 > SCENE_PARSE_MAX_NODES - s->nnodes)
        return scene_cur_error(c, at, "%s brings the scene to more than %d CSG nodes",
                               at->text, SCENE_PARSE_MAX_NODES);
    if ((s->nprims + leaves > p->cap_prims
         && mem_grow((void **)&s->prims, &p->cap_prims,
                     scene_parse_room(p, s->nprims + leaves, leaves, SCENE_PARSE_MAX_PRIMS), sizeof *s->prims))
        || (s->nnodes + 2 * leaves - 1 > p->cap_nodes
            && mem_grow((void **)&s->nodes, &p->cap_nodes,
                        scene_parse_room(p, s->nnodes + 2 * leaves - 1, 2 * leaves - 1, SCENE_PARSE_MAX_NODES),
                        sizeof *s->nodes))
        || (s->nroots + 1 > p->cap_roots
            && mem_grow((void **)&s->roots, &p->cap_roots, scene_parse_room(p, s->nroots + 1, 1, SCENE_PARSE_MAX_NODES),
                        sizeof *s->roots)))
        return scene_parse_oom(p, at);
    root = scene_parse_expand(p, u.def, u.m, 1, u.attr >= 0 ? u.attr : 0, c->st->tok[0].line, &bad);
    if (root < 0) {
        s->nprims = np0;
        s->nnodes = nn0;
        if (root == -2)
            return scene_parse_oom(p, at);
        return scene_cur_error(c, at, "transforms make primitive %s degenerate or out of range",
                               bad->name);
    }
    s->roots[s->nroots++] = root;
    return 0;
}

/* ---- dispatch ------------------------------------------------------------ */

static const scene_parse_stmt scene_parse_core[] = {
    { "EYE", "EYE", scene_parse_eye },
    { "LOOKAT", "LOOKAT", scene_parse_look },
    { "LOOK", "LOOKAT", scene_parse_look },
    { "UP", "UP", scene_parse_up },
    { "FOV", "FOV", scene_parse_fov },
    { "SIZE", "SIZE", scene_parse_size },
    { "AMBIENT", "AMBIENT", scene_parse_ambient },
    { "BACKGROUND", "BACKGROUND", scene_parse_background },
    { "DEPTH", "DEPTH", scene_parse_depth },
    { "LIGHT", "LIGHT", scene_parse_light },
    { "ATTR", "ATTR", scene_parse_attr },
    { "SPHERE", "SPHERE", scene_parse_sphere },
    { "CYLINDER", "CYLINDER", scene_parse_cylinder },
    { "BLOCK", "BLOCK", scene_parse_box },
    { "CONE", "CONE", scene_parse_cone },
    { "HALFSPACE", "HALFSPACE", scene_parse_halfspace },
    { "UNION", "UNION", scene_parse_union },
    { "INTER", "INTER", scene_parse_inter },
    { "INTERSECT", "INTER", scene_parse_inter },
    { "INTERSECTION", "INTER", scene_parse_inter },
    { "DIFF", "DIFF", scene_parse_diff },
    { "DIFFERENCE", "DIFF", scene_parse_diff },
    { "OBJECT", "OBJECT", scene_parse_object },
    { NULL, NULL, NULL }
};

/* Statement tables consulted in order; a statement file adds its table here. */
static const scene_parse_stmt *const scene_parse_tables[] = {
    scene_parse_core,
    scene_attrmap_stmts,
    scene_pds_stmts,
    scene_face_stmts,
    NULL
};

/* The entry for keyword kw in the NULL-terminated list of tables, or NULL.
 * Only keywords with kw's first letter are compared in full. */
static const scene_parse_stmt *scene_parse_find(const scene_parse_stmt *const *tables,
                                                const scene_lex_tok *kw)
{
    const char first = (char)toupper((unsigned char)kw->text[0]);
    size_t t, i;
    for (t = 0; tables[t]; t++)
        for (i = 0; tables[t][i].keyword; i++)
            if (tables[t][i].keyword[0] == first && scene_cur_is(kw, tables[t][i].keyword))
                return &tables[t][i];
    return NULL;
}

/* The keyword nearest to a mistyped one: of the open block's body if there
 * is one, else of the statement tables; NULL if none is close. */
static const char *scene_parse_nearest(const scene_parse_stmt *body, const char *word)
{
    const scene_parse_stmt *const inside[] = { body, NULL };
    const scene_parse_stmt *const *tables = body ? inside : scene_parse_tables;
    suggest sg;
    size_t t, i;
    suggest_init(&sg, word);
    for (t = 0; tables[t]; t++)
        for (i = 0; tables[t][i].keyword; i++)
            suggest_try(&sg, tables[t][i].canon, 0);
    return suggest_best(&sg);
}

/* The handler for statement kw: inside an open block only the block's body
 * statements, elsewhere the statement tables. NULL with the error recorded
 * for anything else (a keyword known in another place is named as such). */
static const scene_parse_stmt *scene_parse_lookup(scene_parser *p, const scene_lex_tok *kw)
{
    const scene_parse_block *b = &p->block;
    const scene_parse_stmt *e;
    /* the tables searched depend on the body only, and a keyword that is
     * the last entry's is found there first again */
    if (p->last && p->last_body == b->body && scene_cur_is(kw, p->last->keyword))
        return p->last;
    if (b->body) {
        const scene_parse_stmt *const body[] = { b->body, NULL };
        if ((e = scene_parse_find(body, kw)) != NULL) {
            p->last = e;
            p->last_body = b->body;
            return e;
        }
        if ((e = scene_parse_find(scene_parse_tables, kw)) != NULL)
            diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col,
                    "%s: not allowed inside %s (END missing?)", e->canon, b->title);
        else if ((e = scene_parse_find(scene_pds_bodies, kw)) != NULL)
            diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col,
                    "%s: not allowed in %s, a %s block", e->canon, b->title, b->kind);
    } else {
        if ((e = scene_parse_find(scene_parse_tables, kw)) != NULL) {
            p->last = e;
            p->last_body = NULL;
            return e;
        }
        if ((e = scene_parse_find(scene_pds_bodies, kw)) != NULL)
            diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col,
                    "%s: allowed only inside a PDS block", e->canon);
    }
    if (!e) {
        const char *near = scene_parse_nearest(b->body, kw->text);
        diag_at(p->err, DIAG_INPUT, p->file, kw->line, kw->col, "unknown statement %s%s%s%s",
                kw->text, near ? " (did you mean " : "", near ? near : "", near ? "?)" : "");
    }
    return NULL;
}

/* Checks that the deck is complete and its view usable. */
static int scene_parse_finish(scene_parser *p)
{
    scene *s = p->s;
    scene_view *v = &s->view;
    static const char *const need[] = { "EYE", "LOOKAT" };
    double d[3], x[3];
    int i;
    for (i = 0; i < 2; i++)
        if (!p->view_loc[i].line)
            return diag_at(p->err, DIAG_INPUT, p->file, 0, 0, "scene has no %s statement",
                           need[i]);
    if (s->nlights == 0)
        return diag_at(p->err, DIAG_INPUT, p->file, 0, 0, "scene has no LIGHT statement");
    if (s->nroots == 0)
        return diag_at(p->err, DIAG_INPUT, p->file, 0, 0, "scene has no OBJECT statement");
    for (i = 0; i < 3; i++)
        d[i] = v->look[i] - v->eye[i];
    if (d[0] == 0 && d[1] == 0 && d[2] == 0)
        return diag_at(p->err, DIAG_INPUT, p->file, p->view_loc[SCENE_PARSE_LOOK].line,
                       p->view_loc[SCENE_PARSE_LOOK].col, "LOOKAT: point is the EYE point");
    dmath_cross3(d, v->up, x);
    if (dmath_len3(x) <= 1e-9 * dmath_len3(d) * dmath_len3(v->up)) {
        const scene_loc *at = p->view_loc[SCENE_PARSE_UP].line ? &p->view_loc[SCENE_PARSE_UP]
                                                              : &p->view_loc[SCENE_PARSE_LOOK];
        return diag_at(p->err, DIAG_INPUT, p->file, at->line, at->col,
                       "UP is parallel to the line of sight");
    }
    return 0;
}

/* Defaults of the view and lighting statements (docs/scene-format.md). */
static void scene_parse_defaults(scene *s)
{
    s->view.up[2] = 1;
    s->view.fov_deg = 40;
    s->view.width = s->view.height = 512;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.1;
    s->max_depth = 5;
}

int scene_parse(const recsrc *src, scene **out, diag *err)
{
    return scene_parse_with(src, NULL, out, err);
}

/* See scene.h. The built-in DEFAULT attribute is attrs[0]; statements are
 * dispatched through scene_parse_tables; the parser state (with its large
 * statement buffer) lives on the heap. */
int scene_parse_with(const recsrc *src, const scene_loader *ld, scene **out, diag *err)
{
    scene_parser *p = mem_calloc(1, sizeof *p);
    const char *file = src->name ? src->name : "";
    scene_attr def;
    int r;
    if (!p)
        return diag_at(err, DIAG_IO, file, 0, 0, "out of memory");
    p->file = file;
    p->err = err;
    p->loader = ld;
    scene_names_init(&p->names);
    scene_lex_init(&p->lex, src);
    if (ld) {
        p->lex.warn = ld->warn;
        p->lex.warn_ctx = ld->ctx;
    }
    p->s = mem_calloc(1, sizeof *p->s);
    if (!p->s || !(p->s->source = mem_strdup(file))) {
        r = diag_at(err, DIAG_IO, file, 0, 0, "out of memory");
        goto done;
    }
    scene_parse_defaults(p->s);
    scene_parse_attr_defaults(&def);
    strcpy(def.name, "DEFAULT");
    if (scene_parse_add_attr(p, &def, NULL) != 0) {
        r = err->status;
        goto done;
    }
    while ((r = scene_lex_next(&p->lex, &p->st, err)) == 1) {
        const scene_parse_stmt *e = scene_parse_lookup(p, &p->st.tok[0]);
        scene_cur c;
        if (!e) {
            r = err->status;
            goto done;
        }
        scene_cur_init(&c, &p->st, file, e->canon, err);
        if (e->fn(p, &c)) {
            r = err->status ? err->status : DIAG_INPUT;
            goto done;
        }
    }
    if (r < 0)
        r = err->status;
    else if (p->block.body)
        r = diag_at(err, DIAG_INPUT, file, p->block.loc.line, p->block.loc.col, "%s has no END",
                    p->block.title);
    else
        r = scene_parse_finish(p);
done:
    if (r == 0) {
        *out = p->s;
        p->s = NULL;
    }
    scene_parse_close_block(p);
    scene_free(p->s);
    scene_names_free(&p->names);
    mem_free(p->defs);
    mem_free(p->operands);
    mem_free(p);
    return r;
}
