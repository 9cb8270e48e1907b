/* fuzz_cms_recs — every host form decoder of the CMS shim (cms_recs_decode)
 * on arbitrary bytes: auto-detection, then each form forced, then the first
 * result re-encoded through every writer form. The first byte picks the
 * code page and card length so those paths are explored too. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "vm_cms_shim/cms_recs.h"

static void sink_null(void *ctx, const void *data, size_t len)
{
    (void)data;
    *(size_t *)ctx += len;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const cms_form forms[] = {CMS_FORM_AUTO, CMS_FORM_TEXT, CMS_FORM_PUNCH,
                                     CMS_FORM_EBCDIC, CMS_FORM_VSTREAM, CMS_FORM_RDW};
    static const cms_cp_id cps[] = {CMS_CP_AUTO, CMS_CP_037, CMS_CP_1047};
    cms_decode_opts o;
    size_t f;
    unsigned sel = size ? data[0] : 0;
    memset(&o, 0, sizeof o);
    o.cp = cps[sel % 3];
    o.lrecl = (sel & 4) ? 80 : 1 + (long)(sel >> 3);
    o.raw_headers = (sel >> 7) & 1;
    for (f = 0; f < sizeof forms / sizeof forms[0]; f++) {
        cms_recs r;
        diag e;
        o.form = forms[f];
        diag_init(&e);
        if (cms_recs_decode(data, size, &o, "fuzz", &r, &e) == 0) {
            const cms_cp *cp;
            size_t i, out = 0;
            int w;
            if (f == 0 && cms_cp_get(CMS_CP_1047, &cp, &e) == 0)
                for (w = 0; w < 4; w++)
                    for (i = 0; i < r.count; i++) {
                        size_t len;
                        const char *rec = cms_recs_at(&r, i, &len);
                        cms_recs_encode_record((cms_form)(CMS_FORM_TEXT + w), r.recfm,
                                               r.lrecl > 0 ? r.lrecl : 1, cp, rec, len,
                                               sink_null, &out, "fuzz", (long)i + 1, &e);
                    }
            cms_recs_free(&r);
        }
    }
    return 0;
}
