/* fuzz_cms_tape — the AWS container, CMS TAPE DUMP and VMFPLC2 decoders
 * (cms_tape_read), with every file's byte stream decoded into records. */
#include <stddef.h>
#include <stdint.h>
#include "vm_cms_shim/cms_recs.h"
#include "vm_cms_shim/cms_tape.h"

static int on_file(void *ctx, const cms_tape_file *f, diag *err)
{
    cms_recs r;
    (void)ctx;
    if (cms_recs_from_stream(f->data, f->len, f->recfm, f->lrecl, f->count, CMS_CP_AUTO, 0,
                             "fuzz", &r, err) == 0)
        cms_recs_free(&r);
    diag_init(err);   /* keep scanning the tape */
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    diag e;
    long n;
    diag_init(&e);
    cms_tape_read(data, size, "fuzz", NULL, on_file, NULL, &n, &e);
    return 0;
}
