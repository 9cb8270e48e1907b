/* scene_parse — the scene deck language's entry point: records of a deck
 * (host text, EBCDIC cards or a CMS V stream, through recsrc) in, the
 * double-precision scene model (model/scene.h) out. The statements are
 * documented in docs/scene-format.md; the parser's own state, shared by the
 * statement files, is in scene_parser.h. */
#ifndef SCENE_PARSE_H
#define SCENE_PARSE_H
#include "image/image.h"
#include "model/scene.h"
#include "util/diag.h"
#include "util/recsrc.h"

/* Reads files a deck names (TEXTURE and PIXELS images). image() reads the
 * image `name` as written in the deck into *out with `channels` (1 or 3)
 * channels, or IMAGE_INDEXED for one channel of palette indices (see
 * image_read_png), or returns a diag status with err saying why; the parser
 * adds the record and column. warn(), if not NULL, receives each warning
 * (a diag with status 0: location and text), e.g. an item that ends in
 * column 72 against a sequence number, or an attribute that sends on more
 * light than arrives. */
#define SCENE_IMAGE_MAX_PIXELS ((size_t)1 << 24)   /* an image a deck names (16 Mpixels) */
/* A loader must refuse an image over SCENE_IMAGE_MAX_PIXELS from its header,
 * before decoding it; the parser refuses one that gets through. */
typedef struct scene_loader {
    int (*image)(void *ctx, const char *name, int channels, image *out, diag *err);
    void *ctx;
    void (*warn)(void *ctx, const diag *w);
} scene_loader;

/* Parses a scene deck. On success *out owns a new scene and 0 is returned;
 * otherwise err holds the first error (file:record:column) and *out is
 * untouched. Never crashes, hangs or allocates without bound. */
int scene_parse(const recsrc *src, scene **out, diag *err);
/* The same, reading the files the deck names through ld (NULL: a deck that
 * names an image is refused). */
int scene_parse_with(const recsrc *src, const scene_loader *ld, scene **out, diag *err);
#endif
