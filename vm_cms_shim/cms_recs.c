/* cms_recs — host forms of CMS files to records and back (see cms_recs.h). */
#include "vm_cms_shim/cms_recs.h"
#include "util/mem.h"
#include <string.h>
#include <strings.h>

/* Characters (UTF-8 code points) in n bytes of host text: the column count
 * of a record, which is what LRECL limits. */
static size_t text_cols(const char *s, size_t n)
{
    size_t i, c = 0;
    for (i = 0; i < n; i++)
        c += ((unsigned char)s[i] & 0xC0) != 0x80;
    return c;
}

static const char *const form_names[] = {"auto", "text", "punch", "ebcdic", "vstream", "rdw"};

const char *cms_form_name(cms_form f)
{
    return (unsigned)f < sizeof form_names / sizeof form_names[0] ? form_names[f] : "?";
}

int cms_form_parse(const char *s, cms_form *f)
{
    unsigned i;
    for (i = 0; i < sizeof form_names / sizeof form_names[0]; i++)
        if (!strcasecmp(s, form_names[i])) {
            *f = (cms_form)i;
            return 1;
        }
    return 0;
}

void cms_recs_free(cms_recs *r)
{
    mem_free(r->text);
    mem_free(r->rec);
    memset(r, 0, sizeof *r);
}

const char *cms_recs_at(const cms_recs *r, size_t i, size_t *len)
{
    *len = r->rec[i].len;
    return r->text ? r->text + r->rec[i].off : "";
}

int cms_recs_append(cms_recs *r, size_t *textcap, size_t *reccap,
                    const char *data, size_t len, diag *err)
{
    size_t used = r->count ? r->rec[r->count - 1].off + r->rec[r->count - 1].len : 0;
    if (mem_grow((void **)&r->rec, reccap, r->count + 1, sizeof *r->rec) ||
        (len && mem_grow((void **)&r->text, textcap, used + len, 1)))
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    if (len)
        memcpy(r->text + used, data, len);
    r->rec[r->count].off = used;
    r->rec[r->count].len = len;
    r->count++;
    return 0;
}

/* Growth state of a record set under construction. */
typedef struct recs_build {
    cms_recs r;
    size_t textcap, reccap;
    char *tmp;            /* scratch for one decoded record */
    size_t tmpcap;
} recs_build;

static void build_free(recs_build *b)
{
    cms_recs_free(&b->r);
    mem_free(b->tmp);
}

/* Hands the finished set to out (the only write to *out). */
static int build_done(recs_build *b, cms_recs *out)
{
    mem_free(b->tmp);
    *out = b->r;
    return 0;
}

static int build_tmp(recs_build *b, size_t need, diag *err)
{
    if (need && mem_grow((void **)&b->tmp, &b->tmpcap, need, 1))
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    return 0;
}

/* Decodes one EBCDIC record through cp and appends it. A bad byte is placed
 * by (recno, column) for cards (offset < 0), else by its byte offset in the
 * stream (offset = where the record's data starts). */
static int build_ebcdic(recs_build *b, const cms_cp *cp, const unsigned char *data, size_t len,
                        const char *name, long recno, long long offset, diag *err)
{
    size_t bad = 0, n;
    if (build_tmp(b, 2 * len, err))
        return DIAG_IO;
    n = cms_cp_decode(cp, data, len, b->tmp, &bad);
    if (n == (size_t)-1) {
        if (offset < 0)
            return diag_at(err, DIAG_INPUT, name, recno, (long)bad + 1,
                           "byte X'%02X' is not a character of code page %03d",
                           data[bad], (int)cp->id);
        return diag_offset(err, DIAG_INPUT, name, offset + (long long)bad,
                           "record %ld: byte X'%02X' is not a character of code page %03d",
                           recno, data[bad], (int)cp->id);
    }
    return cms_recs_append(&b->r, &b->textcap, &b->reccap, b->tmp, n, err);
}

/* Columns of a :READ card: 1 ':', 2-5 READ, 8-15 fn, 17-24 ft, 26-27 fm. */
int cms_recs_read_card(const char *s, size_t len, cms_fileid *id, const char *name,
                       long recno, diag *err)
{
    char card[CMS_CARD_COLS];
    size_t n = len < CMS_CARD_COLS ? len : CMS_CARD_COLS;
    diag sub;
    if (len < 5 || memcmp(s, ":READ", 5) != 0 || (len > 5 && s[5] != ' '))
        return 0;
    memset(card, ' ', sizeof card);
    memcpy(card, s, n);
    diag_init(&sub);
    if (cms_fileid_from_fields(card + 7, card + 16, card + 25, id, &sub)) {
        diag_at(err, DIAG_INPUT, name, recno, 8, ":READ card: %.480s", sub.msg);
        err->rc = sub.rc;
        return -1;
    }
    return 1;
}

/* cms_recs_read_card with errors as negative statuses. */
static int punch_header(const char *s, size_t len, cms_fileid *id, const char *name,
                        long recno, diag *err)
{
    int h = cms_recs_read_card(s, len, id, name, recno, err);
    return h < 0 ? -DIAG_INPUT : h;
}

/* Text and punch decks: one line per record. */
static int decode_text(const unsigned char *buf, size_t n, cms_form form, int forced,
                       int raw, const char *name, cms_recs *out, diag *err)
{
    recs_build b;
    size_t pos = 0;
    long recno = 0, first_cols = 0;
    int same = 1;
    memset(&b, 0, sizeof b);
    while (pos < n) {
        const unsigned char *s = buf + pos, *nl = memchr(s, '\n', n - pos);
        size_t len = nl ? (size_t)(nl - s) : n - pos;
        const unsigned char *z;
        int h;
        pos += len + (nl ? 1 : 0);
        if (len && s[len - 1] == '\r')
            len--;
        recno++;
        if (len > CMS_LRECL_MAX) {
            build_free(&b);
            return diag_at(err, DIAG_INPUT, name, recno, CMS_LRECL_MAX + 1,
                           "record longer than %d bytes", CMS_LRECL_MAX);
        }
        if (!forced && (z = memchr(s, 0, len)) != NULL) {
            build_free(&b);
            return diag_at(err, DIAG_INPUT, name, recno, (long)(z - s) + 1,
                           "NUL byte: not a text file, nor a valid V or RDW stream "
                           "(choose the form with --read-as)");
        }
        if (!raw && (form == CMS_FORM_PUNCH || (!forced && recno == 1))) {
            cms_fileid id;
            h = punch_header((const char *)s, len, &id, name, recno, err);
            if (h < 0) {
                build_free(&b);
                return -h;
            }
            if (h && (b.r.has_header || b.r.count)) {
                build_free(&b);
                return diag_at(err, DIAG_INPUT, name, recno, 1,
                               "a second :READ card: this deck holds several files "
                               "(split it with 'maprt cms import')");
            }
            if (h) {
                b.r.has_header = 1;
                b.r.header = id;
                form = CMS_FORM_PUNCH;
                continue;
            }
        }
        if (form == CMS_FORM_PUNCH) {
            size_t cols = text_cols((const char *)s, len);
            if (cols > CMS_CARD_COLS) {
                build_free(&b);
                return diag_at(err, DIAG_INPUT, name, recno, CMS_CARD_COLS + 1,
                               "card longer than %d columns", CMS_CARD_COLS);
            }
            if (build_tmp(&b, len + CMS_CARD_COLS - cols, err)) {
                build_free(&b);
                return DIAG_IO;
            }
            memcpy(b.tmp, s, len);
            memset(b.tmp + len, ' ', CMS_CARD_COLS - cols);
            len += CMS_CARD_COLS - cols;
            s = (const unsigned char *)b.tmp;
        }
        {
            long cols = (long)text_cols((const char *)s, len);
            if (b.r.count && cols != first_cols)
                same = 0;
            if (!b.r.count)
                first_cols = cols;
            if (cols > b.r.lrecl)
                b.r.lrecl = cols;
        }
        if (cms_recs_append(&b.r, &b.textcap, &b.reccap, (const char *)s, len, err)) {
            build_free(&b);
            return DIAG_IO;
        }
    }
    b.r.form = form;
    b.r.cp = CMS_CP_AUTO;
    b.r.recfm = (same && b.r.count) ? 'F' : 'V';
    if (form == CMS_FORM_PUNCH) {
        b.r.recfm = 'F';
        b.r.lrecl = CMS_CARD_COLS;
    }
    return build_done(&b, out);
}

/* Resolves the code page to use: the forced one, or the one the bytes
 * decide (1047 when they do not matter). */
static int pick_cp(cms_cp_id want, unsigned evidence, const char *name, const cms_cp **cp, diag *err)
{
    cms_cp_id id = want != CMS_CP_AUTO ? want : cms_cp_choose(evidence, CMS_CP_1047);
    if (id == CMS_CP_AUTO)
        return diag_at(err, DIAG_INPUT, name, 0, 0,
                       "the code page cannot be told from the bytes: both 037 and 1047 "
                       "bracket or caret codes occur (choose one with --cp 037 or --cp 1047)");
    return cms_cp_get(id, cp, err);
}

/* EBCDIC cards of lrecl bytes, no line ends; a leading :READ card names the
 * file. */
static int decode_cards(const unsigned char *buf, size_t n, long lrecl, cms_cp_id want,
                        int raw, const char *name, cms_recs *out, diag *err)
{
    static const unsigned char read_e[5] = {0x7A, 0xD9, 0xC5, 0xC1, 0xC4};
    const cms_cp *cp;
    recs_build b;
    size_t L = (size_t)lrecl, i, ncards;
    if (n % L != 0)
        return diag_offset(err, DIAG_INPUT, name, (long long)(n - n % L),
                           "the deck ends with a partial card of %zu bytes (cards are %zu bytes)",
                           n % L, L);
    if (pick_cp(want, cms_cp_scan(buf, n), name, &cp, err))
        return err->status;
    memset(&b, 0, sizeof b);
    ncards = n / L;
    for (i = 0; i < ncards; i++) {
        const unsigned char *c = buf + i * L;
        long recno = (long)i + 1;
        if (build_ebcdic(&b, cp, c, L, name, recno, -1, err)) {
            build_free(&b);
            return err->status;
        }
        if (!raw && memcmp(c, read_e, 5) == 0) {
            cms_fileid id;
            cms_rec *r = &b.r.rec[b.r.count - 1];
            int h = punch_header(b.r.text + r->off, r->len, &id, name, recno, err);
            if (h < 0) {
                build_free(&b);
                return -h;
            }
            if (h && (b.r.has_header || b.r.count > 1)) {
                build_free(&b);
                return diag_at(err, DIAG_INPUT, name, recno, 1,
                               "a second :READ card: this deck holds several files "
                               "(split it with 'maprt cms import')");
            }
            if (h) {
                b.r.has_header = 1;
                b.r.header = id;
                b.r.count--;
            }
        }
    }
    b.r.form = CMS_FORM_EBCDIC;
    b.r.cp = cp->id;
    b.r.recfm = 'F';
    b.r.lrecl = lrecl;
    return build_done(&b, out);
}

/* Walks a V (rdw = 0) or RDW (rdw = 1) length chain. With b == NULL only
 * checks that the chain covers buf exactly with EBCDIC text records and
 * returns 1/0 without diagnostics, OR-ing code-page evidence into *ev. Otherwise decodes into b
 * and returns 0 or a status. */
static int walk_chain(const unsigned char *buf, size_t n, int rdw, unsigned *ev,
                      recs_build *b, const cms_cp *cp, const char *name, diag *err)
{
    size_t pos = 0, hdr = rdw ? 4 : 2;
    long recno = 0;
    while (pos < n) {
        size_t len;
        recno++;
        if (n - pos < hdr) {
            if (!b)
                return 0;
            return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                               "record %ld: truncated %s", recno, rdw ? "RDW" : "length prefix");
        }
        len = ((size_t)buf[pos] << 8) | buf[pos + 1];
        if (rdw) {
            if (len < 5 || buf[pos + 2] || buf[pos + 3]) {
                if (!b)
                    return 0;
                return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                                   "record %ld: invalid RDW (length %zu, flags %02X%02X)",
                                   recno, len, buf[pos + 2], buf[pos + 3]);
            }
            len -= 4;
        } else if (len == 0) {
            if (!b)
                return 0;
            return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                               "record %ld: zero-length record (CMS V files have none)", recno);
        }
        if (len > n - pos - hdr) {
            if (!b)
                return 0;
            return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                               "record %ld: length %zu runs past the end of the file (%zu bytes left)",
                               recno, len, n - pos - hdr);
        }
        if (!b) {
            /* detection also wants EBCDIC text: a text file's line ends fail here */
            size_t i;
            for (i = 0; i < len; i++)
                if (buf[pos + hdr + i] < 0x40 || buf[pos + hdr + i] == 0xFF)
                    return 0;
            *ev |= cms_cp_scan(buf + pos + hdr, len);
        } else {
            if (build_ebcdic(b, cp, buf + pos + hdr, len, name, recno, (long long)(pos + hdr), err))
                return err->status;
            if ((long)len > b->r.lrecl)
                b->r.lrecl = (long)len;
        }
        pos += hdr + len;
    }
    return b ? 0 : recno > 0;
}

static int decode_chain(const unsigned char *buf, size_t n, int rdw, cms_cp_id want,
                        const char *name, cms_recs *out, diag *err)
{
    unsigned ev = 0;
    const cms_cp *cp;
    recs_build b;
    walk_chain(buf, n, rdw, &ev, NULL, NULL, name, err);
    if (pick_cp(want, ev, name, &cp, err))
        return err->status;
    memset(&b, 0, sizeof b);
    if (walk_chain(buf, n, rdw, &ev, &b, cp, name, err)) {
        build_free(&b);
        return err->status;
    }
    b.r.form = rdw ? CMS_FORM_RDW : CMS_FORM_VSTREAM;
    b.r.cp = cp->id;
    b.r.recfm = 'V';
    return build_done(&b, out);
}

/* Content test for EBCDIC cards: every byte a graphic EBCDIC code (X'40' or
 * above), and some byte above X'7F' (letters and digits are), which ASCII
 * text never satisfies (it has blanks X'20' and line ends). */
int cms_recs_looks_ebcdic(const unsigned char *buf, size_t n, size_t L)
{
    size_t i;
    int high = 0;
    if (n == 0 || n % L)
        return 0;
    for (i = 0; i < n; i++) {
        if (buf[i] < 0x40)
            return 0;
        if (buf[i] >= 0x80)
            high = 1;
    }
    return high;
}

int cms_recs_decode(const unsigned char *buf, size_t n, const cms_decode_opts *o,
                    const char *name, cms_recs *out, diag *err)
{
    long lrecl = o && o->lrecl ? o->lrecl : CMS_CARD_COLS;
    cms_form form = o ? o->form : CMS_FORM_AUTO;
    cms_cp_id cp = o ? o->cp : CMS_CP_AUTO;
    int raw = o ? o->raw_headers : 0;
    if (lrecl < 1 || lrecl > CMS_LRECL_MAX)
        return diag_at(err, DIAG_USAGE, name, 0, 0, "LRECL %ld is outside 1..%d", lrecl, CMS_LRECL_MAX);
    if (n > (size_t)CMS_FILE_MAX_BYTES)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "file larger than %ld bytes", CMS_FILE_MAX_BYTES);
    if (form != CMS_FORM_VSTREAM && form != CMS_FORM_RDW) {
        static const unsigned char cms_card[4] = {0x02, 0xC3, 0xD4, 0xE2};
        static const unsigned char netdata[7] = {0xE0, 0xC9, 0xD5, 0xD4, 0xD9, 0xF0, 0xF1};
        if (n >= 4 && memcmp(buf, cms_card, 4) == 0)
            return diag_offset(err, DIAG_INPUT, name, 0,
                               "cards starting X'02' CMS: a DISK DUMP deck or raw CMS tape blocks; "
                               "DISK DUMP decks are not read (their card layout is unconfirmed): "
                               "restore it on CMS with DISK LOAD and send the file by PUNCH or TAPE DUMP");
        if (n >= 8 && memcmp(buf + 1, netdata, 7) == 0)
            return diag_offset(err, DIAG_INPUT, name, 0,
                               "a NETDATA deck (SENDFILE/TRANSMIT): not read; RECEIVE it on CMS "
                               "and send the file by PUNCH or TAPE DUMP");
    }
    if (form == CMS_FORM_AUTO) {
        unsigned ev = 0;
        int v, rdw;
        if (cms_recs_looks_ebcdic(buf, n, (size_t)lrecl))
            return decode_cards(buf, n, lrecl, cp, raw, name, out, err);
        v = walk_chain(buf, n, 0, &ev, NULL, NULL, name, err);
        rdw = walk_chain(buf, n, 1, &ev, NULL, NULL, name, err);
        if (v && rdw)
            return diag_at(err, DIAG_INPUT, name, 0, 0,
                           "the bytes read both as a CMS V stream and as an RDW stream "
                           "(choose with --read-as vstream or --read-as rdw)");
        if (v || rdw)
            return decode_chain(buf, n, rdw, cp, name, out, err);
        return decode_text(buf, n, CMS_FORM_TEXT, 0, raw, name, out, err);
    }
    switch (form) {
    case CMS_FORM_TEXT:
    case CMS_FORM_PUNCH:
        return decode_text(buf, n, form, 1, raw, name, out, err);
    case CMS_FORM_EBCDIC:
        return decode_cards(buf, n, lrecl, cp, raw, name, out, err);
    case CMS_FORM_VSTREAM:
    case CMS_FORM_RDW:
        return decode_chain(buf, n, form == CMS_FORM_RDW, cp, name, out, err);
    default:
        return diag_at(err, DIAG_USAGE, name, 0, 0, "unknown form %d", (int)form);
    }
}

int cms_recs_from_stream(const unsigned char *s, size_t n, char recfm, long lrecl,
                         long count, cms_cp_id want, const char *name, cms_recs *out,
                         diag *err)
{
    const cms_cp *cp;
    recs_build b;
    unsigned ev = 0;
    size_t pos = 0;
    long i;
    if (lrecl < 1 || lrecl > CMS_LRECL_MAX)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "LRECL %ld is outside 1..%d", lrecl, CMS_LRECL_MAX);
    if (count < 0)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "negative record count");
    if (recfm == 'F') {
        if ((unsigned long long)lrecl * (unsigned long long)count > n)
            return diag_at(err, DIAG_INPUT, name, 0, 0,
                           "%ld records of %ld bytes need %llu bytes, the data holds %zu",
                           count, lrecl, (unsigned long long)lrecl * (unsigned long long)count, n);
        ev = cms_cp_scan(s, (size_t)lrecl * (size_t)count);
    } else if (recfm == 'V') {
        for (i = 0; i < count; i++) {
            size_t len;
            if (n - pos < 2)
                return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                                   "record %ld of %ld: data ends before its length", i + 1, count);
            len = ((size_t)s[pos] << 8) | s[pos + 1];
            if (len == 0 || (long)len > lrecl || len > n - pos - 2)
                return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                                   "record %ld of %ld: bad length %zu (LRECL %ld, %zu bytes left)",
                                   i + 1, count, len, lrecl, n - pos - 2);
            ev |= cms_cp_scan(s + pos + 2, len);
            pos += 2 + len;
        }
    } else {
        return diag_at(err, DIAG_INPUT, name, 0, 0, "RECFM X'%02X' is neither F nor V",
                       (unsigned char)recfm);
    }
    if (pick_cp(want, ev, name, &cp, err))
        return err->status;
    memset(&b, 0, sizeof b);
    for (i = 0, pos = 0; i < count; i++) {
        size_t len = (size_t)lrecl, hdr = 0;
        if (recfm == 'V') {
            len = ((size_t)s[pos] << 8) | s[pos + 1];
            hdr = 2;
        }
        if (build_ebcdic(&b, cp, s + pos + hdr, len, name, i + 1, (long long)(pos + hdr), err)) {
            build_free(&b);
            return err->status;
        }
        pos += hdr + len;
    }
    b.r.form = recfm == 'V' ? CMS_FORM_VSTREAM : CMS_FORM_EBCDIC;
    b.r.cp = cp->id;
    b.r.recfm = recfm;
    b.r.lrecl = lrecl;
    return build_done(&b, out);
}

/* ---- encoders ---------------------------------------------------------- */

static const char blanks[64] = "                                                                ";

static void put_pad(cms_sink sink, void *ctx, unsigned char c, size_t n)
{
    unsigned char buf[64];
    memset(buf, c, sizeof buf);
    while (n) {
        size_t k = n < sizeof buf ? n : sizeof buf;
        sink(ctx, buf, k);
        n -= k;
    }
}

/* Encodes rec to EBCDIC through the sink in chunks (no allocation). The
 * record was checked by a counting pass, so encoding cannot fail here. */
static void put_ebcdic(const cms_cp *cp, const char *rec, size_t len, cms_sink sink, void *ctx)
{
    unsigned char buf[256];
    size_t i = 0, bad;
    while (i < len) {
        size_t k = len - i < 128 ? len - i : 128;
        /* do not split a two-byte sequence */
        if (i + k < len && ((unsigned char)rec[i + k] & 0xC0) == 0x80)
            k--;
        k = k ? k : 1;
        sink(ctx, buf, cms_cp_encode(cp, rec + i, k, buf, &bad));
        i += k;
    }
}

int cms_recs_encode_record(cms_form f, char recfm, long lrecl, const cms_cp *cp,
                           const char *rec, size_t len, cms_sink sink, void *ctx,
                           const char *name, long recno, diag *err)
{
    size_t bad = 0, elen = text_cols(rec, len);
    if (f == CMS_FORM_EBCDIC || f == CMS_FORM_VSTREAM) {
        elen = cms_cp_encode(cp, rec, len, NULL, &bad);
        if (elen == (size_t)-1)
            return diag_at(err, DIAG_INPUT, name, recno, (long)bad + 1,
                           "character has no code in EBCDIC code page %03d", (int)cp->id);
    }
    if ((long)elen > lrecl)
        return diag_at(err, DIAG_INPUT, name, recno, lrecl + 1,
                       "record of %zu bytes is longer than LRECL %ld", elen, lrecl);
    switch (f) {
    case CMS_FORM_TEXT:
        sink(ctx, rec, len);
        if (recfm == 'F')
            put_pad(sink, ctx, ' ', (size_t)lrecl - elen);
        else if (len == 0)
            sink(ctx, blanks, 1);
        sink(ctx, "\n", 1);
        return 0;
    case CMS_FORM_PUNCH:
        if (elen > CMS_CARD_COLS)
            return diag_at(err, DIAG_INPUT, name, recno, CMS_CARD_COLS + 1,
                           "record longer than the %d columns of a card", CMS_CARD_COLS);
        while (len && rec[len - 1] == ' ')
            len--;
        sink(ctx, rec, len);
        sink(ctx, "\n", 1);
        return 0;
    case CMS_FORM_EBCDIC:
        put_ebcdic(cp, rec, len, sink, ctx);
        put_pad(sink, ctx, 0x40, (size_t)lrecl - elen);
        return 0;
    case CMS_FORM_VSTREAM: {
        size_t out = recfm == 'F' ? (size_t)lrecl : (elen ? elen : 1);
        unsigned char hw[2];
        hw[0] = (unsigned char)(out >> 8);
        hw[1] = (unsigned char)(out & 0xFF);
        sink(ctx, hw, 2);
        put_ebcdic(cp, rec, len, sink, ctx);
        put_pad(sink, ctx, 0x40, out - elen);
        return 0;
    }
    default:
        return diag_at(err, DIAG_USAGE, name, 0, 0, "cannot write form '%s'", cms_form_name(f));
    }
}

void cms_recs_punch_header(const cms_fileid *id, cms_sink sink, void *ctx)
{
    char card[CMS_CARD_COLS + 2];
    size_t n;
    snprintf(card, sizeof card, ":READ  %-8s %-8s %c%c", id->fn, id->ft, id->mode, id->num);
    n = strlen(card);
    while (n && card[n - 1] == ' ')
        n--;
    card[n++] = '\n';
    sink(ctx, card, n);
}
