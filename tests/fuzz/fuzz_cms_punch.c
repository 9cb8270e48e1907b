/* fuzz_cms_punch — READCARD-style splitting of punch decks (ASCII and
 * EBCDIC) at :READ cards, and the fileid parser on the same bytes. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "vm_cms_shim/cms_punch.h"

static int on_file(void *ctx, const cms_fileid *id, const cms_recs *r, long card, diag *err)
{
    (void)ctx;
    (void)err;
    (void)card;
    return (id->fn[0] == 0 || r->lrecl != CMS_CARD_COLS) ? DIAG_INPUT : 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char text[64];
    cms_fileid id;
    diag e;
    long n;
    size_t k = size < sizeof text - 1 ? size : sizeof text - 1;
    diag_init(&e);
    cms_punch_split(data, size, NULL, "fuzz", on_file, NULL, &n, &e);
    memcpy(text, data, k);
    text[k] = '\0';
    diag_init(&e);
    cms_fileid_parse(text, &id, &e);
    cms_fileid_is_fileid(text);
    return 0;
}
