/* pds_image — pixel-array PDS definitions from a raster (src/image), e.g. a
 * PNG named by the deck. The parser reads the PNG (image_read_png) and maps
 * its pixels to region attribute ids here:
 *   index image (1 channel, read with IMAGE_INDEXED: a palette PNG's
 *     palette indices, or another PNG's grey values): g is an index; with an
 *     index table the id is index_attr[g], otherwise g itself;
 *   RGB image (3 channels): each colour must appear in the colour map
 *     (rgb[3k..3k+2] -> rgb_attr[k]); an unlisted colour is an error.
 * Image rows run top to bottom, which is the order pds_pixels expects. */
#ifndef PDS_IMAGE_H
#define PDS_IMAGE_H
#include <stddef.h>
#include <stdint.h>
#include "image/image.h"
#include "model/pds_def.h"

typedef struct pds_image_map {
    const int32_t *index_attr; size_t nindex;  /* grey: optional table */
    const uint8_t *rgb; const int32_t *rgb_attr; size_t nrgb;  /* RGB */
} pds_image_map;

/* Fills px (replacing its cells) from img. Returns 0; DIAG_INPUT with the
 * first unmappable pixel (at loc in file); DIAG_IO when memory runs out. */
int pds_image_to_pixels(const image *img, const pds_image_map *map, pds_pixels *px,
                        const char *file, scene_loc loc, diag *err);
#endif
