/* dl_work — the drawing budget of one display list, in pixel steps. The
 * rasteriser (dl_cover) charges each step it takes (a line's Bresenham steps,
 * a disc's rows, a polygon's edge tests per row) and the interpreter
 * (dl_interp) charges each device operation before it is issued (a clear or a
 * fill its pixels, a shape's merged runs their pixels, a block its pixels),
 * so every backend (png, osmesa, egl) spends the same budget on the same list
 * and refuses it at the same element. */
#ifndef DL_WORK_H
#define DL_WORK_H

#define DL_WORK_LIMIT (1ull << 30)

typedef struct dl_work {
    unsigned long long used, limit;   /* used <= limit always */
    int over;                         /* sticky: a charge did not fit */
} dl_work;

/* limit 0 = DL_WORK_LIMIT. */
void dl_work_init(dl_work *w, unsigned long long limit);
/* Charges n steps: 1 if they fit, else 0 (and from then on always 0). */
int dl_work_charge(dl_work *w, unsigned long long n);
#endif
