/* cms_punch — READCARD-style splitting of punch decks (see cms_punch.h). */
#include "vm_cms_shim/cms_punch.h"
#include <string.h>

int cms_punch_split(const unsigned char *buf, size_t n, const cms_decode_opts *o,
                    const char *name,
                    int (*fn)(void *ctx, const cms_fileid *id, const cms_recs *recs, long card,
                              diag *err),
                    void *ctx, long *nfiles, diag *err)
{
    cms_decode_opts d;
    cms_recs all, part;
    cms_fileid id;
    size_t i, first;
    long files = 0;
    int rc = 0;
    memset(&d, 0, sizeof d);
    if (o)
        d = *o;
    d.raw_headers = 1;
    d.lrecl = CMS_CARD_COLS;
    if (d.form == CMS_FORM_AUTO)
        d.form = cms_recs_looks_ebcdic(buf, n, CMS_CARD_COLS) ? CMS_FORM_EBCDIC : CMS_FORM_PUNCH;
    else if (d.form == CMS_FORM_TEXT)
        d.form = CMS_FORM_PUNCH;
    if (d.form != CMS_FORM_PUNCH && d.form != CMS_FORM_EBCDIC)
        return diag_at(err, DIAG_USAGE, name, 0, 0, "a punch deck is ASCII lines or EBCDIC cards, not %s",
                       cms_form_name(d.form));
    if ((rc = cms_recs_decode(buf, n, &d, name, &all, err)))
        return rc;
    memset(&id, 0, sizeof id);
    strcpy(id.fn, "READCARD");
    strcpy(id.ft, "CMSUT1");
    id.mode = 'A';
    id.num = '1';
    first = 0;
    for (i = 0; i <= all.count && !rc; i++) {
        cms_fileid next;
        int h = 0;
        if (i < all.count) {
            size_t len;
            const char *rec = cms_recs_at(&all, i, &len);
            h = cms_recs_read_card(rec, len, &next, name, (long)i + 1, err);
            if (h < 0) {
                rc = DIAG_INPUT;
                break;
            }
        }
        if (!h && i < all.count)
            continue;
        /* cards first..i-1 form a file (skip an empty READCARD CMSUT1 part) */
        if (i > first || first > 0) {
            size_t k, textcap = 0, reccap = 0;
            if (files >= CMS_PUNCH_MAX_FILES) {
                rc = diag_at(err, DIAG_INPUT, name, (long)i + 1, 1, "more than %d files in the deck",
                             CMS_PUNCH_MAX_FILES);
                break;
            }
            memset(&part, 0, sizeof part);
            for (k = first; k < i && !rc; k++) {
                size_t len;
                const char *rec = cms_recs_at(&all, k, &len);
                rc = cms_recs_append(&part, &textcap, &reccap, rec, len, err);
            }
            part.recfm = 'F';
            part.lrecl = CMS_CARD_COLS;
            part.form = all.form;
            part.cp = all.cp;
            part.has_header = first > 0;
            part.header = id;
            if (!rc) {
                files++;
                rc = fn(ctx, &id, &part, first > 0 ? (long)first : 1L, err);
            }
            cms_recs_free(&part);
        }
        if (h) {
            id = next;
            first = i + 1;
        }
    }
    cms_recs_free(&all);
    if (!rc && nfiles)
        *nfiles = files;
    return rc;
}
