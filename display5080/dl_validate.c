/* dl_validate — check-only visitor (see dl_validate.h). */
#include "display5080/dl_validate.h"
#include <string.h>

static int dl_validate_element(void *ctx, const dl_element *e, diag *err)
{
    dl_validate_summary *s = ctx;
    (void)err;
    s->elements++;
    s->count[dl_format_slot(e->code)]++;   /* the decoder passes known codes only */
    return 0;
}

int dl_validate(const uint8_t *buf, size_t len, const char *name, const dl_decode_opts *opts,
                dl_validate_summary *s, diag *err)
{
    static const dl_visitor v = {.header = NULL, .element = dl_validate_element};
    dl_validate_summary t;
    memset(&t, 0, sizeof t);
    if (dl_decode(buf, len, name, opts, &v, &t, &t.header, err))
        return err->status;
    *s = t;
    return 0;
}
