/* cms_deck — scene decks through the shim as recsrc (see cms_deck.h). */
#include "vm_cms_shim/cms_deck.h"
#include "util/mem.h"

struct cms_deck {
    cms_file *file;
    cms_file_info info;
};

static int cms_deck_next(void *ctx, const char **rec, size_t *len, diag *err)
{
    cms_deck *dk = ctx;
    (void)err;   /* records are decoded at open; reading cannot fail */
    return cms_file_read(dk->file, 0, rec, len) == 0 ? 1 : 0;
}

int cms_deck_open(cms_deck **deck, recsrc *src, const cms_disks *d, const char *name,
                  const cms_decode_opts *o, diag *err)
{
    cms_deck *dk = mem_calloc(1, sizeof *dk);
    int rc;
    if (!dk)
        return diag_at(err, DIAG_IO, name, 0, 0, "out of memory");
    if ((rc = cms_file_open_read(&dk->file, d, name, o, err))) {
        mem_free(dk);
        return rc;
    }
    cms_file_state(dk->file, &dk->info);
    src->next = cms_deck_next;
    src->ctx = dk;
    src->name = dk->info.label;
    src->records = dk->info.records > 0 ? (size_t)dk->info.records : 0;
    *deck = dk;
    return 0;
}

void cms_deck_state(const cms_deck *deck, cms_file_info *info) { *info = deck->info; }

void cms_deck_close(cms_deck *deck)
{
    if (!deck)
        return;
    cms_file_abort(deck->file);
    mem_free(deck);
}
