/* image_out — writing a picture in the format its name asks for: .png PNG,
 * .ppm binary PPM (P6; PGM for grey), .pam PAM (P7); "-" is standard output,
 * whose format must be given. Names with any other ending are refused, so a
 * caller can check them before the work. Provenance (image_meta) goes into
 * PNG tEXt chunks and Netpbm comment lines. Files are committed on close
 * (util/outfile.h). */
#ifndef IMAGE_OUT_H
#define IMAGE_OUT_H
#include "image/image.h"
#include "image/image_meta.h"
#include "util/diag.h"

typedef enum image_out_format { IMAGE_OUT_NONE = 0, IMAGE_OUT_PNG, IMAGE_OUT_PPM, IMAGE_OUT_PAM } image_out_format;

/* "png", "ppm" or "pam" in any case; IMAGE_OUT_NONE otherwise. */
image_out_format image_out_parse(const char *s);
/* The format for output name (a host path or "-") and the --format value
 * given (IMAGE_OUT_NONE if none): the name's ending decides, "-" needs the
 * value, and a value that contradicts the ending is refused. 0 and *out, or
 * DIAG_USAGE with err saying why (naming the formats known). */
int image_out_choose(const char *name, image_out_format given, image_out_format *out, diag *err);
/* Writes img to path ("-": standard output) in format f with meta m (NULL
 * for none). 0, or DIAG_IO. */
int image_out_write(const char *path, image_out_format f, const image *img, const image_meta *m,
                    diag *err);
#endif
