/* outline — edge segments from a surface-id buffer (see outline.h). */
#include "render/outline.h"
#include "util/mem.h"
#include <string.h>

typedef struct outline_list {
    outline_seg *v;
    size_t n, cap;
} outline_list;

static int outline_push(outline_list *l, int x0, int y0, int x1, int y1)
{
    if (mem_grow((void **)&l->v, &l->cap, l->n + 1, sizeof *l->v))
        return -1;
    l->v[l->n].x0 = x0;
    l->v[l->n].y0 = y0;
    l->v[l->n].x1 = x1;
    l->v[l->n].y1 = y1;
    l->n++;
    return 0;
}

int outline_trace(const int32_t *id, int width, int height, outline_seg **segs,
                  size_t *nsegs, diag *err)
{
    size_t npx = (size_t)width * (size_t)height, i;
    uint8_t *edge = mem_calloc(npx ? npx : 1, 1);
    outline_list l = {NULL, 0, 0};
    int x, y;
    if (!edge)
        return diag_at(err, DIAG_IO, "outline", 0, 0, "out of memory");
    for (y = 0; y < height; y++)
        for (x = 0; x < width; x++) {
            i = (size_t)y * width + x;
            edge[i] = (x + 1 < width && id[i] != id[i + 1]) ||
                      (y + 1 < height && id[i] != id[i + width]);
        }
    /* vertical runs of two or more pixels; consumed pixels are cleared */
    for (x = 0; x < width; x++)
        for (y = 0; y < height; y++) {
            int y1 = y;
            if (!edge[(size_t)y * width + x])
                continue;
            while (y1 + 1 < height && edge[(size_t)(y1 + 1) * width + x])
                y1++;
            if (y1 > y) {
                int k;
                if (outline_push(&l, x, y, x, y1))
                    goto oom;
                for (k = y; k <= y1; k++)
                    edge[(size_t)k * width + x] = 0;
            }
            y = y1;
        }
    /* horizontal runs (including single pixels) of what is left */
    for (y = 0; y < height; y++)
        for (x = 0; x < width; x++) {
            int x1 = x;
            if (!edge[(size_t)y * width + x])
                continue;
            while (x1 + 1 < width && edge[(size_t)y * width + x1 + 1])
                x1++;
            if (outline_push(&l, x, y, x1, y))
                goto oom;
            x = x1;
        }
    mem_free(edge);
    *segs = l.v;
    *nsegs = l.n;
    return 0;
oom:
    mem_free(edge);
    mem_free(l.v);
    return diag_at(err, DIAG_IO, "outline", 0, 0, "out of memory");
}
