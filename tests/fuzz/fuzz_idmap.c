/* fuzz_idmap — the MAPRTID1 identity map reader on arbitrary bytes: it
 * must return a status, never crash, leak or allocate more than the input
 * describes (the length is checked against the header before allocating). */
#include <stddef.h>
#include <stdint.h>
#include "render/idmap.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    idmap m;
    diag err;
    diag_init(&err);
    if (idmap_read_memory("fuzz", data, size, &m, &err) == 0)
        idmap_free(&m);
    return 0;
}
