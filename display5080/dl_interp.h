/* dl_interp — the 5081 display model as a dl_decode visitor. It keeps the
 * display state the format defines (colour table, polyline and interior
 * colours, logic op, plane mask, scissor, viewport, the polygon being built)
 * and turns each element into dl_device calls, so the software raster and the
 * GL backends share one interpretation of the list.
 * Data flow: dl_decode -> dl_interp -> dl_device (dl_raster | dl_gl). */
#ifndef DL_INTERP_H
#define DL_INTERP_H
#include <stdint.h>
#include "display5080/dl_decode.h"
#include "display5080/dl_device.h"
#include "display5080/dl_work.h"

/* Called once the header is known: creates the drawing device. */
typedef int (*dl_interp_open_fn)(void *octx, int width, int height, const dl_device **ops,
                                  void **dev, diag *err);

typedef struct dl_interp {
    dl_interp_open_fn open;
    void *octx;
    const char *name;
    const dl_device *ops;
    void *dev;
    int width, height;
    int dac;                       /* 4 or 8; from the header unless forced */
    int force_dac;                 /* 0 = use the header */
    uint32_t lut[256];             /* colour table as loaded, 0x00RRGGBB */
    unsigned line_colour, interior_colour, op, mask;
    int sx0, sy0, sx1, sy1;        /* scissor as set */
    int vx0, vy0, vx1, vy1;        /* viewport as set (no effect on device coordinates) */
    int *pts;                      /* scratch points and the pending polygon */
    size_t pts_cap;
    int *poly;
    size_t poly_n, poly_cap;
    dl_work work;                  /* drawing budget, the same for every backend */
} dl_interp;

extern const dl_visitor dl_interp_visitor;

/* Prepares an interpreter; force_dac 0, 4 or 8. The budget is
 * DL_WORK_LIMIT; set in->work.limit to change it. */
void dl_interp_init(dl_interp *in, const char *name, int force_dac, dl_interp_open_fn open,
                    void *octx);
/* Frees scratch memory (not the device: its creator owns it). */
void dl_interp_free(dl_interp *in);
/* The colour table as the DAC shows it: 256 RGB triples. A 4-bit DAC keeps
 * the high nibble of each gun and shows it times 17. */
void dl_interp_palette(const dl_interp *in, uint8_t rgb[768]);
/* One gun value as a DAC of dac bits shows it. */
static inline uint8_t dl_interp_gun(unsigned v, int dac) { return (uint8_t)(dac == 4 ? (v >> 4) * 17u : v); }
#endif
