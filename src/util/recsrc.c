/* recsrc — memory line reader (see recsrc.h). */
#include "util/recsrc.h"
#include <string.h>

static int recsrc_mem_next(void *ctx, const char **rec, size_t *len, diag *err)
{
    recsrc_mem *m = ctx;
    const char *start, *nl;
    size_t n;
    (void)err;
    if (m->pos >= m->len)
        return 0;
    start = m->buf + m->pos;
    nl = memchr(start, '\n', m->len - m->pos);
    n = nl ? (size_t)(nl - start) : m->len - m->pos;
    m->pos += n + (nl ? 1 : 0);
    if (n > 0 && start[n - 1] == '\r')
        n--;
    *rec = start;
    *len = n;
    return 1;
}

void recsrc_from_memory(recsrc *src, recsrc_mem *state, const char *name,
                        const char *buf, size_t len)
{
    state->buf = buf;
    state->len = len;
    state->pos = 0;
    src->next = recsrc_mem_next;
    src->ctx = state;
    src->name = name;
    src->records = 0;
}
