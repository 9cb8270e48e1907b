/* dl_encode — builds DL5080 byte streams in memory: the header, then elements
 * appended one by one with the length patched in when each element closes.
 * Used by the image writer (dl_image), by tests and by anyone who wants to
 * emit a display list. Errors (out of memory, an element over 65534 bytes, a
 * coordinate outside 16 bits) are sticky: the first one is kept and reported
 * by dl_encode_finish, so a caller can append without checking every call. */
#ifndef DL_ENCODE_H
#define DL_ENCODE_H
#include <stddef.h>
#include <stdint.h>
#include "display5080/dl_format.h"
#include "util/diag.h"

typedef struct dl_encoder {
    uint8_t *buf;
    size_t len, cap;
    size_t open;        /* offset of the element being built; (size_t)-1 if none */
    int status;         /* first error (diag status), 0 if none */
    char msg[128];
} dl_encoder;

/* Starts a stream with its header (version DL_VERSION). flags: DL_FLAG_DAC8 or 0. Never fails
 * itself: a failure shows at dl_encode_finish. */
void dl_encode_init(dl_encoder *enc, int width, int height, unsigned flags);
/* Frees the buffer (after an error or when the caller did not take it). */
void dl_encode_free(dl_encoder *enc);

/* Low level: open an element, append words/bytes, close it (pads to even). */
void dl_encode_begin(dl_encoder *enc, unsigned code);
void dl_encode_u16(dl_encoder *enc, unsigned v);
void dl_encode_s16(dl_encoder *enc, long v);     /* sticky error outside -32768..32767 */
void dl_encode_u32(dl_encoder *enc, uint32_t v);
void dl_encode_bytes(dl_encoder *enc, const void *p, size_t n);
void dl_encode_end(dl_encoder *enc);

/* Whole elements. Points are (x,y) pairs of device coordinates. */
void dl_encode_simple(dl_encoder *enc, unsigned code);             /* no payload */
void dl_encode_word(dl_encoder *enc, unsigned code, unsigned v);   /* one u16 */
void dl_encode_points(dl_encoder *enc, unsigned code, const int *xy, size_t n);
void dl_encode_rect(dl_encoder *enc, unsigned code, int x0, int y0, int x1, int y1);
void dl_encode_circle(dl_encoder *enc, unsigned code, int cx, int cy, unsigned r);
void dl_encode_text(dl_encoder *enc, int x, int y, const uint8_t *ebcdic, size_t n);
void dl_encode_colours(dl_encoder *enc, unsigned start, const uint32_t *rgb, size_t n);
/* rows: h rows of w index bytes, bottom row first, row i at rows + i*stride;
 * written as IBM's driver sends them: top row first, packed. */
void dl_encode_blt(dl_encoder *enc, int x0, int y0, int w, int h, unsigned op,
                   const uint8_t *rows, size_t stride);
/* The plane mask letting the planes in `writable` (bit k = plane k) be
 * written, as the driver sends it: (~writable & 0xFF) << 8. */
void dl_encode_plane_mask(dl_encoder *enc, unsigned writable);
/* runs: n (count, index) pairs. */
void dl_encode_run_row(dl_encoder *enc, int y, int x0, const unsigned *runs, size_t n);

/* Bytes one element of each kind would take (for choosing encodings). */
size_t dl_encode_run_row_size(size_t runs);
size_t dl_encode_blt_size(int w, int h);

/* Ends the stream: returns 0 and hands over the buffer (*out, *len; mem_free
 * it), or the first error (DIAG_INPUT or DIAG_IO) in err, buffer freed. name
 * labels the diagnostic. Does not append the end element itself. */
int dl_encode_finish(dl_encoder *enc, const char *name, uint8_t **out, size_t *len, diag *err);
#endif
