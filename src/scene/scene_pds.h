/* scene_pds — the PDS blocks of the scene language (PDS name kind ... END),
 * for the statement files that read them: scene_pds.c opens and closes a
 * block and reads region attribute items; one file per group of kinds
 * reads the rest of the PDS statement and the body statements:
 *   scene_pds_cpg.c     CPG                 RECT ELLIPSE CIRCLE POLYGON
 *                                           UNION INTER DIFF NEST ROOT
 *   scene_pds_raster.c  PIXELS, QUADTREE    KEY ROW INDEX CODE
 *   scene_pds_cells.c   TILING, MOSAIC      TILES SEED SCATTER
 *   scene_pds_curves.c  CURVES              BSPLINE POLYLINE
 * The block's definition is built with the pds_def builders and checked by
 * pds_def_check at END. Grammar: docs/scene-format.md, "Attribute mapping". */
#ifndef SCENE_PDS_H
#define SCENE_PDS_H
#include <stddef.h>
#include <stdint.h>
#include "model/scene_map.h"
#include "scene/scene_parser.h"

/* The block being defined (scene_parse_block.state). */
typedef struct scene_pds_block {
    scene_map *map;                 /* owned until END hands it to the scene */
    scene_names names;              /* CPG node names, KEY colours */
    long root;                      /* CPG: ROOT's node, -1 = none */
    long root_rec;
    /* PIXELS, QUADTREE: KEY characters and ROW lines, or CODE lines */
    int width, height, rows;        /* width 0: no KEY/ROW form */
    int32_t key[128];               /* KEY character -> region id */
    long key_rec[128];              /* its record, 0 = not a key */
    int32_t *vals; size_t nvals, cap_vals;   /* cells, or the quadtree code */
    /* PIXELS, QUADTREE from an image: KEY colours or an INDEX line */
    char file[SCENE_LEX_COLUMNS + 1];        /* "" = not from an image */
    scene_loc file_loc;
    uint8_t *rgb; size_t cap_rgb;
    int32_t *rgb_attr; size_t nrgb, cap_rgb_attr;
    long rgb_rec;                   /* record of the first KEY colour */
    int32_t index[256]; size_t nindex;
    long index_rec;                 /* record of INDEX, 0 = none */
    long tiles_rec;                 /* TILING: record of TILES, 0 = none */
} scene_pds_block;

/* What one PDS kind adds to the PDS statement and to END. */
typedef struct scene_pds_kind {
    /* Reads the rest of the PDS statement (the cursor is past the kind)
     * and opens the block's body: sets p->block.body and p->block.kind. */
    int (*open)(scene_parser *p, scene_cur *c, scene_pds_block *b);
    /* At END, before pds_def_check: completes the definition (NULL: none). */
    int (*finish)(scene_parser *p, scene_pds_block *b);
} scene_pds_kind;

extern const scene_pds_kind scene_pds_cpg, scene_pds_raster, scene_pds_tiling,
    scene_pds_mosaic, scene_pds_curves;
extern const scene_parse_stmt scene_pds_cpg_body[], scene_pds_keyed_body[],
    scene_pds_image_body[], scene_pds_code_body[], scene_pds_tiling_body[],
    scene_pds_mosaic_body[], scene_pds_curves_body[];

/* The open block (body statements run only while one is open). */
scene_pds_block *scene_pds_current(scene_parser *p);
/* END: completes and checks the definition and adds it to the scene. */
int scene_pds_end(scene_parser *p, scene_cur *c);
/* Reads a region attribute item: an ATTR name, or NONE (PDS_NONE). */
int scene_pds_region(scene_parser *p, scene_cur *c, int32_t *id);
/* Reads the rest of the statement, at least one item, as region attribute
 * items into ids[SCENE_LEX_MAX_ITEMS] (*n of them); with split, SPLIT
 * reads as PDS_QT_SPLIT. */
int scene_pds_regions(scene_parser *p, scene_cur *c, int split, int32_t *ids, size_t *n);
#endif
