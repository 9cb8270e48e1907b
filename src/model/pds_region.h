/* pds_region — where a point lies within its region, for attributes placed
 * in the region's own frame (TEXTURE/BUMP ... LOCAL) and for bumps made from
 * region boundaries (BUMP ... GROOVES). Evaluated in double on the
 * definition (mode-independent; only attributes that ask for it pay for it):
 *   CPG       the first leaf that wins by the priority rules (docs/pds.md);
 *             frame: the point in the leaf's own coordinates, scaled so that
 *             the leaf's bounding box there is [0,1]^2 (a rectangle's own
 *             square, an ellipse's box, a polygon's box); edge: distance to
 *             the leaf's outline in face units (exact for rectangles and
 *             polygons under any placement; for ellipses the radial gap
 *             times the smaller semi-axis; nested PDSs scale theirs by the
 *             placement's smaller singular value)
 *   TILING    the cell: its box for squares and bricks, the distance to
 *             the cell's nearest side; hexagons and triangles: distance to
 *             the nearest side, frame = the point in tile-size units
 *   PIXELS    the pixel cell and the distance to its sides
 *   others    frame = (u,v), no edge (PDS_REGION_FAR)
 * A point in no region gets frame (u,v) and PDS_REGION_FAR. */
#ifndef PDS_REGION_H
#define PDS_REGION_H
#include "model/pds_def.h"

#define PDS_REGION_FAR 1e30

typedef struct pds_region {
    double frame[2];     /* 0..1 over the region's box in its own frame */
    double edge;         /* distance to the region's boundary, face (u,v) units */
} pds_region;

/* Fills *r for point (u,v) of definition d (checked). Returns 1 if (u,v)
 * lies in a region, else 0. */
int pds_region_at(const pds_def *d, double u, double v, pds_region *r);
#endif
