/* dl_quant — colour quantisation for the 5081: at most 256 colours chosen in
 * the DAC's space (4 bits per gun by default, so 4096 possible colours, or 8),
 * by median cut over the image's colour histogram (a near-grey colour is
 * first put on the DAC colour around it with the least hue and brightness
 * error, not each gun rounded on its own), then each pixel mapped to
 * its nearest colour table entry, optionally with Floyd-Steinberg dithering.
 * Colours the caller must have exactly (wireframe colours) are reserved
 * first. Used by dl_image on the way from an RGB frame to a display list. */
#ifndef DL_QUANT_H
#define DL_QUANT_H
#include <stdint.h>
#include "image/image.h"

typedef struct dl_quant_opts {
    int dac;                   /* 4 or 8 */
    int dither;                /* Floyd-Steinberg error diffusion */
    const uint32_t *fixed;     /* colours (0x00RRGGBB) that must be in the table */
    int nfixed;                /* 0..255 */
} dl_quant_opts;

typedef struct dl_quant {
    int ncolours;              /* table entries used, 1..256 */
    uint32_t table[256];       /* 0x00RRGGBB as the DAC shows them (4-bit guns x17) */
    int fixed_index[256];      /* table index of each fixed colour */
    uint8_t *index;            /* width*height indices, top row first (mem_free) */
} dl_quant;

/* Quantises rgb (3 channels). Returns 0, DIAG_INPUT for bad options, DIAG_IO
 * when memory runs out. */
int dl_quant_image(const image *rgb, const dl_quant_opts *opts, dl_quant *q, diag *err);
void dl_quant_free(dl_quant *q);
/* A gun value snapped to what a DAC of dac bits can show (nearest level). */
uint8_t dl_quant_gun(unsigned v, int dac);
#endif
