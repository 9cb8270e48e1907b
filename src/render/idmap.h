/* idmap — the identity map of a render's primary rays (`render --ids`): per
 * pixel the primitive, face and region (attribute) hit and the hit
 * distance, as maprt writes it and as the REAL(16) oracle
 * (tests/oracle/ids_oracle.f90) writes it for comparison. File format in
 * docs/idmap.md: "MAPRTID1", width and height, then one 24-byte record
 * per pixel, top row first, all little-endian. */
#ifndef RENDER_IDMAP_H
#define RENDER_IDMAP_H
#include <stddef.h>
#include <stdint.h>
#include "util/diag.h"

#define IDMAP_AMBIGUOUS 1     /* flags: a boundary within the error bound */

typedef struct idmap_px {
    int32_t prim;             /* primitive index, -1 for the background */
    int32_t face;             /* face number (model/prim_face.h), -1 none */
    int32_t region;           /* attribute index seen there, -1 none */
    int32_t flags;            /* IDMAP_AMBIGUOUS */
    double t;                 /* hit distance from the eye, deck units; -1 none */
} idmap_px;

typedef struct idmap {
    int width, height;
    idmap_px *px;
} idmap;

/* Allocates w x h background pixels. 0 or DIAG_IO. */
int idmap_alloc(idmap *m, int w, int h, diag *err);
void idmap_free(idmap *m);
/* Writes m to path (a temporary name renamed on success). 0 or DIAG_IO. */
int idmap_write(const char *path, const idmap *m, diag *err);
/* Reads path into *m. DIAG_INPUT, located by byte offset, for a bad magic,
 * size or length; DIAG_IO when it cannot be read. */
int idmap_read(const char *path, idmap *m, diag *err);
/* The same from len bytes at data; name is used in messages. */
int idmap_read_memory(const char *name, const void *data, size_t len, idmap *m, diag *err);
#endif
