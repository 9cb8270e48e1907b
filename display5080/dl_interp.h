/* dl_interp — the 5081 display model as a dl_decode visitor. It keeps the
 * display state the elements set (colour table; polyline, interior, text and
 * edge colours; logic op; plane mask; line type, user style and width;
 * character height, up vector and code page; scissor; viewport; the polygon
 * being built), rasterises each shape once (dl_cover, dl_font), clips it, and
 * hands the pixels to a dl_device, so every backend writes the same pixels.
 * Every device operation is charged to the list's drawing budget (dl_work)
 * before it is issued, so every backend refuses the same lists for their work.
 * Data flow: dl_decode -> dl_interp -> dl_cover -> dl_device (dl_raster | dl_gl). */
#ifndef DL_INTERP_H
#define DL_INTERP_H
#include <stdint.h>
#include "display5080/dl_cover.h"
#include "display5080/dl_decode.h"
#include "display5080/dl_device.h"

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
    unsigned version;              /* the list's; 0 for a raw stream */
    int dac;                       /* 4 or 8; from the header unless forced */
    int force_dac;                 /* 0 = use the header */
    uint32_t lut[256];             /* colour table as loaded, 0x00RRGGBB */
    unsigned line_colour, interior_colour, text_colour, edge_colour;
    unsigned op, mask;             /* logic op 1..16; planes that may be written */
    unsigned line_type, style_mask, style_factor, line_width;
    unsigned long long style_pos;  /* pattern position carried by line type 150 */
    unsigned char_height, code_page;
    int up_x, up_y;
    unsigned edge_flag;
    int sx0, sy0, sx1, sy1;        /* scissor as set */
    int vx0, vy0, vx1, vy1;        /* viewport as set (no effect on device coordinates) */
    int *pts;                      /* scratch points and the pending polygon */
    size_t pts_cap;
    int *poly;
    size_t poly_n, poly_cap;
    dl_work work;                  /* drawing budget: dl_cover's steps and the device writes */
    dl_cover cover;
    unsigned long src_blts;        /* 0x5012 elements left undrawn (adapter memory) */
    long long src_blt_offset;      /* the first of them */
} dl_interp;

extern const dl_visitor dl_interp_visitor;

/* Prepares an interpreter; force_dac 0, 4 or 8; work_limit the drawing
 * budget in pixel steps (0 = DL_WORK_LIMIT). */
void dl_interp_init(dl_interp *in, const char *name, int force_dac, unsigned long long work_limit,
                    dl_interp_open_fn open, void *octx);
/* Frees scratch memory (not the device: its creator owns it). */
void dl_interp_free(dl_interp *in);
/* The colour table as the DAC shows it: 256 RGB triples. A 4-bit DAC keeps
 * the high nibble of each gun and shows it times 17. */
void dl_interp_palette(const dl_interp *in, uint8_t rgb[768]);
/* One gun value as a DAC of dac bits shows it. */
static inline uint8_t dl_interp_gun(unsigned v, int dac) { return (uint8_t)(dac == 4 ? (v >> 4) * 17u : v); }
#endif
