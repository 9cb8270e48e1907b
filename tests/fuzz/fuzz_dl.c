/* fuzz_dl — libFuzzer target for the DL5080 parser and everything behind it:
 * validation, the disassembler and the software 5081 interpreter (with a
 * small work budget so slow inputs end as errors, not timeouts), on DL5080
 * lists of either version and on raw MegaPel streams. */
#include <stddef.h>
#include <stdint.h>
#include "display5080/dl_dump.h"
#include "display5080/dl_render.h"
#include "display5080/dl_validate.h"

static void fuzz_dl_sink(void *ctx, const void *data, size_t len)
{
    (void)ctx;
    (void)data;
    (void)len;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    dl_validate_summary s;
    dl_render_opts ro = {.work_limit = 1u << 22};
    dl_frame f;
    diag err;
    diag_init(&err);
    dl_decode_opts d;
    /* The first byte picks a DL5080 list or a raw MegaPel stream, so both
     * decoder paths (and version 1 conversion) are explored. */
    if (size < 1)
        return 0;
    ro.raw = data[0] & 1;
    d = dl_render_decode_opts(&ro);
    data++;
    size--;
    if (dl_validate(data, size, "fuzz", &d, &s, &err) != 0)
        return 0;
    diag_init(&err);
    dl_dump(data, size, "fuzz", &d, fuzz_dl_sink, NULL, &err);
    diag_init(&err);
    if (ro.raw)
        ro.width = ro.height = 64;   /* keep raw frames small */
    if (dl_render(data, size, "fuzz", &dl_backend_png, &ro, &f, &err) == 0)
        dl_frame_free(&f);
    return 0;
}
