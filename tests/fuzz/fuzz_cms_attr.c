/* fuzz_cms_attr — the attribute sidecar parser (cms_attr_parse), and the
 * formatter on whatever it accepts (which must parse again to the same). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "vm_cms_shim/cms_attr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cms_attr a, b;
    char buf[256];
    size_t n;
    diag e;
    diag_init(&e);
    if (cms_attr_parse((const char *)data, size, "fuzz", &a, &e))
        return 0;
    n = cms_attr_format(&a, buf, sizeof buf);
    diag_init(&e);
    if (cms_attr_parse(buf, n, "again", &b, &e) || memcmp(&a, &b, sizeof a) != 0)
        abort();
    return 0;
}
