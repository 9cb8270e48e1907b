/* dl_backend — the drawing backends behind one table: png (software raster),
 * osmesa (OpenGL into an OSMesa buffer) and egl (OpenGL on a surfaceless EGL
 * context). Each backend creates a device for a width x height screen, draws
 * through the dl_device operations and reads the 8-bit indices back.
 * dl_render drives them; the CLI picks one by name. */
#ifndef DL_BACKEND_H
#define DL_BACKEND_H
#include <stdint.h>
#include "display5080/dl_device.h"

typedef struct dl_backend {
    const char *name;
    const char *summary;
    /* Creates a device with every index 0; DIAG_IO (with the reason) when
     * the backend cannot start here. */
    int (*open)(int width, int height, void **dev, diag *err);
    const dl_device *ops;
    /* Copies width*height indices, bottom row first, into px. */
    int (*read)(void *dev, uint8_t *px, diag *err);
    void (*close)(void *dev);
} dl_backend;

extern const dl_backend dl_backend_png;
extern const dl_backend dl_backend_osmesa;   /* says why when libOSMesa is missing */
extern const dl_backend dl_backend_egl;

/* The backend called name, or NULL. */
const dl_backend *dl_backend_find(const char *name);
#endif
