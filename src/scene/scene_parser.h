/* scene_parser — the parser's state and statement dispatch, for files that
 * add statements to the scene language (e.g. attribute mapping). A statement
 * file provides a table of scene_parse_stmt entries ending with a NULL
 * keyword; scene_parse.c lists the tables it consults (scene_parse_tables).
 * Handlers read their operands with scene_cur, resolve names through
 * scene_parse_attr_ref / scene_parse_find_solid and build into p->s.
 * New keywords must also be added to the reserved words (scene_cur.c) so
 * that they cannot be names, and documented in docs/scene-format.md
 * (tests/cli/scene_keywords.sh checks both). scene_parse() itself is declared in scene_parse.h. */
#ifndef SCENE_PARSER_H
#define SCENE_PARSER_H
#include <stddef.h>
#include "scene/scene_parse.h"
#include "scene/scene_cur.h"
#include "scene/scene_lex.h"
#include "scene/scene_names.h"

/* Documented limits (docs/scene-format.md). */
#define SCENE_PARSE_MAX_ATTRS    4096
#define SCENE_PARSE_MAX_DEFS     65536     /* named solids */
#define SCENE_PARSE_MAX_OPERANDS 100000    /* operands of all CSG statements */
#define SCENE_PARSE_MAX_NEST     64        /* CSG definitions inside each other */
#define SCENE_PARSE_MAX_PRIMS    100000    /* primitives after expansion */
#define SCENE_PARSE_MAX_NODES    400000    /* CSG nodes after expansion */
#define SCENE_PARSE_MAX_MAPS     4096      /* PDS definitions */
#define SCENE_PARSE_MAX_TEXTURES 4096
#define SCENE_PARSE_MAX_BUMPS    4096
#define SCENE_PARSE_MAX_SEED     2147483647L /* BUMP, HASH and SCATTER seeds */

/* A named solid: a primitive (op CSG_LEAF) or a CSG combination of
 * operands[first .. first+count-1]. */
typedef struct scene_parse_def {
    char name[SCENE_NAME_MAX + 1];
    scene_loc loc;
    csg_op op;
    prim_kind kind;           /* leaf: primitive kind, dimensions, */
    double dim[3];
    double m[16];             /* its own transforms, */
    int attr;                 /* and its ATTR (-1 none) */
    size_t first, count;      /* CSG: operands */
    size_t leaves;            /* primitives in one expansion (saturated) */
    int depth;                /* nesting: 1 for a primitive */
    int face_map[SCENE_MAX_FACES];  /* leaf: PDS bound by FACE (index into
                                       maps), -1 none */
    long face_rec[SCENE_MAX_FACES]; /* record of that FACE statement */
    long placed;              /* record of the first OBJECT that expanded it
                                 (0: none yet; FACE must come before) */
    const scene_shape *shape; /* leaf: what its placements point at, made
                                 at the first (scene.shapes) */
} scene_parse_def;

/* One use of a solid: as a CSG operand or by OBJECT. */
typedef struct scene_parse_use {
    int def;
    double m[16];             /* transforms written at the use */
    int attr;                 /* ATTR written at the use, -1 none */
    scene_loc loc;
} scene_parse_use;

typedef struct scene_parser scene_parser;
typedef int (*scene_parse_fn)(scene_parser *p, scene_cur *c);

typedef struct scene_parse_stmt {
    const char *keyword;      /* upper case; NULL ends a table */
    const char *canon;        /* name used in messages (for aliases) */
    scene_parse_fn fn;
} scene_parse_stmt;

/* An open block (PDS ... END). While body is set only its statements are
 * accepted, END among them; everything else is refused with a message
 * naming the block. The statement file that opened it owns state and frees
 * it through release, also when the parse stops inside the block. */
typedef struct scene_parse_block {
    const scene_parse_stmt *body;   /* NULL: no block is open */
    char title[8 + SCENE_NAME_MAX]; /* "PDS NAME", for messages */
    const char *kind;               /* "CPG", ...: what its body describes */
    scene_loc loc;                  /* the opening statement */
    void *state;
    void (*release)(void *state);
} scene_parse_block;

enum { SCENE_PARSE_EYE, SCENE_PARSE_LOOK, SCENE_PARSE_UP, SCENE_PARSE_FOV,
       SCENE_PARSE_SIZE, SCENE_PARSE_AMBIENT, SCENE_PARSE_BACKGROUND,
       SCENE_PARSE_DEPTH, SCENE_PARSE_VIEW_COUNT };

struct scene_parser {
    scene *s;
    const char *file;
    diag *err;
    const scene_loader *loader;   /* NULL: images cannot be read */
    scene_lex lex;
    scene_lex_stmt st;
    scene_names names;
    scene_parse_def *defs;     size_t ndefs, cap_defs;
    scene_parse_use *operands; size_t noperands, cap_operands;
    size_t cap_attrs, cap_lights, cap_prims, cap_nodes, cap_roots;
    size_t cap_maps, cap_textures, cap_bumps, cap_shapes;
    scene_loc view_loc[SCENE_PARSE_VIEW_COUNT];  /* each view statement; line 0 = none */
    scene_parse_block block;
    /* The entry the last statement found, and the body it was looked up
     * in (NULL: the statement tables); a deck repeats its keywords. */
    const scene_parse_stmt *last;
    const scene_parse_stmt *last_body;
};

/* Statement tables of the statement files, consulted by scene_parse.c. */
extern const scene_parse_stmt scene_attrmap_stmts[];       /* TEXTURE BUMP */
extern const scene_parse_stmt scene_pds_stmts[];           /* PDS */
extern const scene_parse_stmt scene_face_stmts[];          /* FACE */
extern const scene_parse_stmt *const scene_pds_bodies[];   /* PDS block bodies,
                                                              NULL-terminated */

scene_loc scene_parse_loc(const scene_lex_tok *t);
/* Records "out of memory" (DIAG_IO) at t (NULL: no position). */
int scene_parse_oom(scene_parser *p, const scene_lex_tok *t);
/* Accepts option keyword kw once; *seen tracks it. Returns 1 if consumed,
 * 0 if the next item is something else, -1 after an error (given twice). */
int scene_parse_option(scene_cur *c, const char *kw, int *seen);
/* Reads a name at the cursor and resolves it in name space `space`
 * (scene_names.h) to *index ("<name> is used before it is defined"). */
int scene_parse_ref(scene_parser *p, scene_cur *c, int space, int *index);

/* Reads "ATTR name"'s name at the cursor and resolves it to an attribute
 * index in *attr ("<name> is used before it is defined"). */
int scene_parse_attr_ref(scene_parser *p, scene_cur *c, int *attr);
/* Index of the named solid, or -1. */
int scene_parse_find_solid(const scene_parser *p, const char *name);
/* Refuses (at `at`, "<what>: images cannot be read here") a deck that names
 * an image when the parse has no loader; 0 when it has one. */
int scene_parse_can_read(scene_parser *p, const char *what, scene_loc at);
/* Reads image `name` (as written at `at`) with `channels` channels through
 * the loader into *out: "<what>: cannot read NAME: <reason>". */
int scene_parse_image(scene_parser *p, const char *what, scene_loc at, const char *name,
                      int channels, image *out);
/* Ends the open block: releases its state and accepts every statement again. */
void scene_parse_close_block(scene_parser *p);
/* Reads the items after a solid's name at a use or definition: any mix of
 * transforms (composed after m) and at most one "ATTR name" (into *attr,
 * which the caller sets to -1). Stops at the first other item. */
int scene_parse_tail(scene_parser *p, scene_cur *c, double m[16], int *attr);
#endif
