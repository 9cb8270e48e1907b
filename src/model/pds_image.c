/* pds_image — raster to pixel-array PDS definition (see pds_image.h). */
#include "model/pds_image.h"
#include <stdlib.h>
#include "util/mem.h"

typedef struct colour_key { uint32_t rgb; int32_t attr; } colour_key;

static int pds_image_key_cmp(const void *a, const void *b)
{
    uint32_t x = ((const colour_key *)a)->rgb, y = ((const colour_key *)b)->rgb;
    return (x > y) - (x < y);
}

int pds_image_to_pixels(const image *img, const pds_image_map *map, pds_pixels *px,
                        const char *file, scene_loc loc, diag *err)
{
    size_t n = (size_t)img->width * (size_t)img->height, i;
    colour_key *keys = NULL;
    int32_t *cells;
    int rc = 0;
    if (img->width < 1 || img->height < 1 || img->width > PDS_MAX_SIDE || img->height > PDS_MAX_SIDE ||
        n > (size_t)PDS_MAX_CELLS)
        return diag_at(err, DIAG_INPUT, file, loc.line, loc.col,
                       "image of %d x %d pixels is too large for a pixel array (limit %ld cells)",
                       img->width, img->height, PDS_MAX_CELLS);
    if (img->channels == 3 && (!map || map->nrgb == 0))
        return diag_at(err, DIAG_INPUT, file, loc.line, loc.col, "a colour image needs a colour map");
    cells = mem_calloc(n, sizeof *cells);
    if (!cells)
        return diag_at(err, DIAG_IO, file, loc.line, loc.col, "out of memory reading a pixel array");
    if (img->channels == 3) {
        keys = mem_calloc(map->nrgb, sizeof *keys);
        if (!keys) {
            mem_free(cells);
            return diag_at(err, DIAG_IO, file, loc.line, loc.col, "out of memory reading a pixel array");
        }
        for (i = 0; i < map->nrgb; i++) {
            keys[i].rgb = (uint32_t)map->rgb[3 * i] << 16 | (uint32_t)map->rgb[3 * i + 1] << 8 | map->rgb[3 * i + 2];
            keys[i].attr = map->rgb_attr[i];
        }
        qsort(keys, map->nrgb, sizeof *keys, pds_image_key_cmp);
    }
    for (i = 0; i < n && !rc; i++) {
        if (img->channels == 1) {
            unsigned g = img->px[i];
            if (map && map->index_attr) {
                if (g >= map->nindex)
                    rc = diag_at(err, DIAG_INPUT, file, loc.line, loc.col,
                                 "pixel (%zu, %zu) has index %u but the index table has %zu entries",
                                 i % (size_t)img->width, i / (size_t)img->width, g, map->nindex);
                else
                    cells[i] = map->index_attr[g];
            } else
                cells[i] = (int32_t)g;
        } else {
            colour_key k, *hit;
            k.rgb = (uint32_t)img->px[3 * i] << 16 | (uint32_t)img->px[3 * i + 1] << 8 | img->px[3 * i + 2];
            hit = bsearch(&k, keys, map->nrgb, sizeof *keys, pds_image_key_cmp);
            if (!hit)
                rc = diag_at(err, DIAG_INPUT, file, loc.line, loc.col,
                             "pixel (%zu, %zu) has colour #%06lx, which the colour map does not list",
                             i % (size_t)img->width, i / (size_t)img->width, (unsigned long)k.rgb);
            else
                cells[i] = hit->attr;
        }
    }
    mem_free(keys);
    if (!rc) {
        mem_free(px->cells);
        px->cells = cells;
        px->ncells = px->cap_cells = n;
        px->width = img->width;
        px->height = img->height;
    } else
        mem_free(cells);
    return rc;
}
