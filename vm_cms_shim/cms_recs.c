/* cms_recs — host forms of CMS files to records and back (see cms_recs.h). */
#include "vm_cms_shim/cms_recs.h"
#include "util/mem.h"
#include <stdint.h>
#include <string.h>
#include <strings.h>

/* Bytes below X'80' at the start of s[0..n), eight at a time while they
 * last: decks are nearly all ASCII. */
static size_t cms_recs_ascii_run(const unsigned char *s, size_t n)
{
    size_t i = 0;
    uint64_t w;
    for (; n - i >= sizeof w; i += sizeof w) {
        memcpy(&w, s + i, sizeof w);
        if (w & UINT64_C(0x8080808080808080))
            break;
    }
    while (i < n && s[i] < 0x80)
        i++;
    return i;
}

/* Characters (UTF-8 code points) in n bytes of host text: the column count
 * of a record, which is what LRECL limits. */
static size_t cms_recs_text_cols(const char *s, size_t n)
{
    size_t i = cms_recs_ascii_run((const unsigned char *)s, n), c = i;
    for (; i < n; i++)
        c += ((unsigned char)s[i] & 0xC0) != 0x80;
    return c;
}

static const char *const recs_form_names[] = {"auto", "text", "punch", "ebcdic", "vstream", "rdw"};

const char *cms_form_name(cms_form f)
{
    return (unsigned)f < sizeof recs_form_names / sizeof recs_form_names[0] ? recs_form_names[f] : "?";
}

int cms_form_parse(const char *s, cms_form *f)
{
    unsigned i;
    for (i = 0; i < sizeof recs_form_names / sizeof recs_form_names[0]; i++)
        if (!strcasecmp(s, recs_form_names[i])) {
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

static void cms_recs_build_free(recs_build *b)
{
    cms_recs_free(&b->r);
    mem_free(b->tmp);
}

/* Hands the finished set to out (the only write to *out). */
static int cms_recs_build_done(recs_build *b, cms_recs *out)
{
    mem_free(b->tmp);
    *out = b->r;
    return 0;
}

static int cms_recs_build_tmp(recs_build *b, size_t need, diag *err)
{
    if (need && mem_grow((void **)&b->tmp, &b->tmpcap, need, 1))
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    return 0;
}

/* Decodes one EBCDIC record through cp and appends it. A bad byte is placed
 * by (recno, column) for cards (offset < 0), else by its byte offset in the
 * stream (offset = where the record's data starts). */
static int cms_recs_build_ebcdic(recs_build *b, const cms_cp *cp, const unsigned char *data, size_t len,
                        const char *name, long recno, long long offset, diag *err)
{
    size_t bad = 0, n;
    if (cms_recs_build_tmp(b, 2 * len, err))
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

/* A possible :READ card as record recno of a single-file decode, with
 * `prior` records already taken: 1 when it named the file (kept in b), 0 when
 * it is no :READ card, or a DIAG status (a bad fileid, or a second :READ
 * card, which only deck splitting accepts). */
static int cms_recs_take_header(recs_build *b, const char *s, size_t len, size_t prior,
                            const char *name, long recno, diag *err)
{
    cms_fileid id;
    int h = cms_recs_read_card(s, len, &id, name, recno, err);
    if (h <= 0)
        return h < 0 ? -1 : 0;
    if (b->r.has_header || prior) {
        diag_at(err, DIAG_INPUT, name, recno, 1,
                "a second :READ card: this deck holds several files "
                "(split it with 'maprt cms import')");
        return -1;
    }
    b->r.has_header = 1;
    b->r.header = id;
    return 1;
}

/* Room for all the records of text buf (one per line) and their bytes,
 * which a line's never exceed but where a card is padded to 80 columns:
 * grown a record at a time, 10,000 objects' deck was copied to fresh
 * pages as it doubled, about 260 page faults (docs/performance.md, run
 * AY). 0, or DIAG_IO when memory runs out. */
static int cms_recs_reserve(recs_build *b, const unsigned char *buf, size_t n, diag *err)
{
    size_t lines = 1;
    const unsigned char *at = buf, *end = buf + n, *nl;
    while (at < end && (nl = memchr(at, '\n', (size_t)(end - at))) != NULL) {
        lines++;
        at = nl + 1;
    }
    if (mem_grow((void **)&b->r.rec, &b->reccap, lines, sizeof *b->r.rec)
        || (n && mem_grow((void **)&b->r.text, &b->textcap, n, 1)))
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    return 0;
}

/* Text and punch decks: one line per record. */
static int cms_recs_decode_text(const unsigned char *buf, size_t n, cms_form form, int forced,
                       int raw, const char *name, cms_recs *out, diag *err)
{
    recs_build b;
    size_t pos = 0;
    long recno = 0, first_cols = 0;
    int same = 1;
    memset(&b, 0, sizeof b);
    if (cms_recs_reserve(&b, buf, n, err)) {
        cms_recs_build_free(&b);
        return DIAG_IO;
    }
    while (pos < n) {
        const unsigned char *s = buf + pos, *nl = memchr(s, '\n', n - pos);
        size_t len = nl ? (size_t)(nl - s) : n - pos;
        const unsigned char *z;
        pos += len + (nl ? 1 : 0);
        if (len && s[len - 1] == '\r')
            len--;
        recno++;
        if (len > CMS_LRECL_MAX) {
            cms_recs_build_free(&b);
            return diag_at(err, DIAG_INPUT, name, recno, CMS_LRECL_MAX + 1,
                           "record longer than %d bytes", CMS_LRECL_MAX);
        }
        if (!forced && (z = memchr(s, 0, len)) != NULL) {
            cms_recs_build_free(&b);
            return diag_at(err, DIAG_INPUT, name, recno, (long)(z - s) + 1,
                           "NUL byte: not a text file, nor a valid V or RDW stream "
                           "(choose the form with --read-as)");
        }
        if (!raw && (form == CMS_FORM_PUNCH || (!forced && recno == 1))) {
            int h = cms_recs_take_header(&b, (const char *)s, len, b.r.count, name, recno, err);
            if (h < 0) {
                cms_recs_build_free(&b);
                return err->status;
            }
            if (h) {
                form = CMS_FORM_PUNCH;
                continue;
            }
        }
        if (form == CMS_FORM_PUNCH) {
            size_t cols = cms_recs_text_cols((const char *)s, len);
            if (cols > CMS_CARD_COLS) {
                cms_recs_build_free(&b);
                return diag_at(err, DIAG_INPUT, name, recno, CMS_CARD_COLS + 1,
                               "card longer than %d columns", CMS_CARD_COLS);
            }
            if (cms_recs_build_tmp(&b, len + CMS_CARD_COLS - cols, err)) {
                cms_recs_build_free(&b);
                return DIAG_IO;
            }
            memcpy(b.tmp, s, len);
            memset(b.tmp + len, ' ', CMS_CARD_COLS - cols);
            len += CMS_CARD_COLS - cols;
            s = (const unsigned char *)b.tmp;
        }
        {
            long cols = (long)cms_recs_text_cols((const char *)s, len);
            if (b.r.count && cols != first_cols)
                same = 0;
            if (!b.r.count)
                first_cols = cols;
            if (cols > b.r.lrecl)
                b.r.lrecl = cols;
        }
        if (cms_recs_append(&b.r, &b.textcap, &b.reccap, (const char *)s, len, err)) {
            cms_recs_build_free(&b);
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
    return cms_recs_build_done(&b, out);
}

/* 1 if buf is valid UTF-8 (no overlong forms, no surrogates checked: a
 * single-byte code page's text fails on its first byte above X'7F' far more
 * often than it passes). */
static int cms_recs_utf8_valid(const unsigned char *b, size_t n)
{
    size_t i = 0;
    while ((i += cms_recs_ascii_run(b + i, n - i)) < n) {
        unsigned c = b[i];
        size_t k = (c & 0xE0) == 0xC0 ? 1 : (c & 0xF0) == 0xE0 ? 2 : (c & 0xF8) == 0xF0 ? 3 : 4;
        if (k == 4 || (k == 1 && c < 0xC2) || n - i - 1 < k)
            return 0;
        for (i++; k; k--, i++)
            if ((b[i] & 0xC0) != 0x80)
                return 0;
    }
    return 1;
}

/* Host lines: UTF-8, or else a single-byte code page, read as ISO 8859-1
 * (code page 819, the host side of Hercules' 819/037 and 819/1047 tables):
 * Hercules' ASCII punch writes one byte per column, so a cent or not sign
 * arrives as one byte, which is converted to UTF-8 here before the columns
 * are counted. */
static int cms_recs_decode_lines(const unsigned char *buf, size_t n, cms_form form, int forced,
                             int raw, const char *name, cms_recs *out, diag *err)
{
    unsigned char *u;
    size_t i, k = 0;
    int rc;
    if (cms_recs_utf8_valid(buf, n))
        return cms_recs_decode_text(buf, n, form, forced, raw, name, out, err);
    if (!(u = mem_alloc(2 * n)))
        return diag_at(err, DIAG_IO, name, 0, 0, "out of memory");
    for (i = 0; i < n; i++) {
        if (buf[i] < 0x80) {
            u[k++] = buf[i];
        } else {
            u[k++] = (unsigned char)(0xC0 | (buf[i] >> 6));
            u[k++] = (unsigned char)(0x80 | (buf[i] & 0x3F));
        }
    }
    rc = cms_recs_decode_text(u, k, form, forced, raw, name, out, err);
    mem_free(u);
    return rc;
}

/* Resolves the code page to use: the forced one, or the one the bytes
 * decide (1047 when they do not matter). */
static int cms_recs_pick_cp(cms_cp_id want, unsigned evidence, const char *name, const cms_cp **cp, diag *err)
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
static int cms_recs_decode_cards(const unsigned char *buf, size_t n, long lrecl, cms_cp_id want,
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
    if (cms_recs_pick_cp(want, cms_cp_scan(buf, n), name, &cp, err))
        return err->status;
    memset(&b, 0, sizeof b);
    ncards = n / L;
    for (i = 0; i < ncards; i++) {
        const unsigned char *c = buf + i * L;
        long recno = (long)i + 1;
        if (cms_recs_build_ebcdic(&b, cp, c, L, name, recno, -1, err)) {
            cms_recs_build_free(&b);
            return err->status;
        }
        if (!raw && memcmp(c, read_e, 5) == 0) {
            cms_rec *r = &b.r.rec[b.r.count - 1];
            int h = cms_recs_take_header(&b, b.r.text + r->off, r->len, b.r.count - 1, name, recno, err);
            if (h < 0) {
                cms_recs_build_free(&b);
                return err->status;
            }
            if (h)
                b.r.count--;
        }
    }
    b.r.form = CMS_FORM_EBCDIC;
    b.r.cp = cp->id;
    b.r.recfm = 'F';
    b.r.lrecl = lrecl;
    return cms_recs_build_done(&b, out);
}

/* Walks a V (rdw = 0) or RDW (rdw = 1) length chain. With b == NULL only
 * checks that the chain covers buf exactly with EBCDIC text records and
 * returns 1/0 without diagnostics, OR-ing code-page evidence into *ev. Otherwise decodes into b
 * and returns 0 or a status. */
static int cms_recs_walk_chain(const unsigned char *buf, size_t n, int rdw, unsigned *ev,
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
            if (cms_recs_build_ebcdic(b, cp, buf + pos + hdr, len, name, recno, (long long)(pos + hdr), err))
                return err->status;
            if ((long)len > b->r.lrecl)
                b->r.lrecl = (long)len;
        }
        pos += hdr + len;
    }
    return b ? 0 : recno > 0;
}

static int cms_recs_decode_chain(const unsigned char *buf, size_t n, int rdw, cms_cp_id want,
                        const char *name, cms_recs *out, diag *err)
{
    unsigned ev = 0;
    const cms_cp *cp;
    recs_build b;
    cms_recs_walk_chain(buf, n, rdw, &ev, NULL, NULL, name, err);
    if (cms_recs_pick_cp(want, ev, name, &cp, err))
        return err->status;
    memset(&b, 0, sizeof b);
    if (cms_recs_walk_chain(buf, n, rdw, &ev, &b, cp, name, err)) {
        cms_recs_build_free(&b);
        return err->status;
    }
    b.r.form = rdw ? CMS_FORM_RDW : CMS_FORM_VSTREAM;
    b.r.cp = cp->id;
    b.r.recfm = 'V';
    return cms_recs_build_done(&b, out);
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
            return cms_recs_decode_cards(buf, n, lrecl, cp, raw, name, out, err);
        v = cms_recs_walk_chain(buf, n, 0, &ev, NULL, NULL, name, err);
        rdw = cms_recs_walk_chain(buf, n, 1, &ev, NULL, NULL, name, err);
        if (v && rdw)
            return diag_at(err, DIAG_INPUT, name, 0, 0,
                           "the bytes read both as a CMS V stream and as an RDW stream "
                           "(choose with --read-as vstream or --read-as rdw)");
        if (v || rdw)
            return cms_recs_decode_chain(buf, n, rdw, cp, name, out, err);
        return cms_recs_decode_lines(buf, n, CMS_FORM_TEXT, 0, raw, name, out, err);
    }
    switch (form) {
    case CMS_FORM_TEXT:
    case CMS_FORM_PUNCH:
        return cms_recs_decode_lines(buf, n, form, 1, raw, name, out, err);
    case CMS_FORM_EBCDIC:
        return cms_recs_decode_cards(buf, n, lrecl, cp, raw, name, out, err);
    case CMS_FORM_VSTREAM:
    case CMS_FORM_RDW:
        return cms_recs_decode_chain(buf, n, form == CMS_FORM_RDW, cp, name, out, err);
    default:
        return diag_at(err, DIAG_USAGE, name, 0, 0, "unknown form %d", (int)form);
    }
}

/* Walks a CMS byte stream record by record: checks that count records
 * (count < 0: exactly the whole stream) fit, and calls visit for each
 * (visit may be NULL). Returns 0 or a status; visit's non-zero return stops
 * the walk and is returned. */
typedef int (*recs_visit)(void *ctx, long recno, const unsigned char *rec, size_t len,
                          size_t offset, diag *err);

static int cms_recs_walk_stream(const unsigned char *s, size_t n, char recfm, long lrecl, long count,
                            const char *name, recs_visit visit, void *ctx, long *nrecs, diag *err)
{
    size_t pos = 0;
    long i;
    int rc;
    if (lrecl < 1 || lrecl > CMS_LRECL_MAX)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "LRECL %ld is outside 1..%d", lrecl, CMS_LRECL_MAX);
    if (recfm != 'F' && recfm != 'V')
        return diag_at(err, DIAG_INPUT, name, 0, 0, "RECFM X'%02X' is neither F nor V",
                       (unsigned char)recfm);
    if (recfm == 'F') {
        if (count < 0) {
            if (n % (size_t)lrecl)
                return diag_offset(err, DIAG_INPUT, name, (long long)(n - n % (size_t)lrecl),
                                   "%zu bytes are no whole number of %ld-byte records", n, lrecl);
            count = (long)(n / (size_t)lrecl);
        } else if ((unsigned long long)lrecl * (unsigned long long)count > n) {
            return diag_at(err, DIAG_INPUT, name, 0, 0,
                           "%ld records of %ld bytes need %llu bytes, the data holds %zu",
                           count, lrecl, (unsigned long long)lrecl * (unsigned long long)count, n);
        }
    }
    for (i = 0; count < 0 ? pos < n : i < count; i++) {
        size_t len = (size_t)lrecl, hdr = 0;
        if (recfm == 'V') {
            if (n - pos < 2)
                return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                                   "record %ld: data ends before its length", i + 1);
            len = ((size_t)s[pos] << 8) | s[pos + 1];
            hdr = 2;
            if (len == 0 || (long)len > lrecl || len > n - pos - 2)
                return diag_offset(err, DIAG_INPUT, name, (long long)pos,
                                   "record %ld: bad length %zu (LRECL %ld, %zu bytes left)",
                                   i + 1, len, lrecl, n - pos - 2);
        }
        if (visit && (rc = visit(ctx, i + 1, s + pos + hdr, len, pos + hdr, err)))
            return rc;
        pos += hdr + len;
    }
    if (nrecs)
        *nrecs = i;
    return 0;
}

static int cms_recs_visit_scan(void *ctx, long recno, const unsigned char *rec, size_t len,
                           size_t offset, diag *err)
{
    (void)recno;
    (void)offset;
    (void)err;
    *(unsigned *)ctx |= cms_cp_scan(rec, len);
    return 0;
}

typedef struct recs_stream_ctx {
    recs_build *b;
    const cms_cp *cp;      /* NULL: keep bytes */
    const char *name;
} recs_stream_ctx;

static int cms_recs_visit_build(void *ctx, long recno, const unsigned char *rec, size_t len,
                            size_t offset, diag *err)
{
    recs_stream_ctx *c = ctx;
    if (!c->cp)
        return cms_recs_append(&c->b->r, &c->b->textcap, &c->b->reccap, (const char *)rec, len, err);
    return cms_recs_build_ebcdic(c->b, c->cp, rec, len, c->name, recno, (long long)offset, err) ?
           err->status : 0;
}

int cms_recs_from_stream(const unsigned char *s, size_t n, char recfm, long lrecl,
                         long count, cms_cp_id want, int binary, const char *name,
                         cms_recs *out, diag *err)
{
    recs_stream_ctx c;
    recs_build b;
    unsigned ev = 0;
    int rc;
    memset(&c, 0, sizeof c);
    if (!binary) {
        if ((rc = cms_recs_walk_stream(s, n, recfm, lrecl, count, name, cms_recs_visit_scan, &ev, NULL, err)))
            return rc;
        if (cms_recs_pick_cp(want, ev, name, &c.cp, err))
            return err->status;
    }
    memset(&b, 0, sizeof b);
    c.b = &b;
    c.name = name;
    if ((rc = cms_recs_walk_stream(s, n, recfm, lrecl, count, name, cms_recs_visit_build, &c, NULL, err))) {
        cms_recs_build_free(&b);
        return rc;
    }
    b.r.form = recfm == 'V' ? CMS_FORM_VSTREAM : CMS_FORM_EBCDIC;
    b.r.cp = c.cp ? c.cp->id : CMS_CP_AUTO;
    b.r.recfm = recfm;
    b.r.lrecl = lrecl;
    b.r.binary = binary != 0;
    return cms_recs_build_done(&b, out);
}

typedef struct recs_control_ctx {
    long recno, col;
    unsigned char byte;
} recs_control_ctx;

static int cms_recs_visit_control(void *ctx, long recno, const unsigned char *rec, size_t len,
                              size_t offset, diag *err)
{
    recs_control_ctx *c = ctx;
    size_t i;
    (void)offset;
    (void)err;
    for (i = 0; i < len; i++)
        if (rec[i] < 0x40 || rec[i] == 0xFF) {
            c->recno = recno;
            c->col = (long)i + 1;
            c->byte = rec[i];
            return 1;
        }
    return 0;
}

int cms_recs_stream_control(const unsigned char *s, size_t n, char recfm, long lrecl,
                            long count, long *recno, long *col, unsigned char *byte)
{
    recs_control_ctx c;
    diag d;
    diag_init(&d);
    memset(&c, 0, sizeof c);
    if (cms_recs_walk_stream(s, n, recfm, lrecl, count, "", cms_recs_visit_control, &c, NULL, &d) != 1)
        return 0;
    *recno = c.recno;
    *col = c.col;
    *byte = c.byte;
    return 1;
}

/* ---- encoders ---------------------------------------------------------- */

static const char recs_blanks[64] = "                                                                ";

static void cms_recs_put_pad(cms_sink sink, void *ctx, unsigned char c, size_t n)
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
static void cms_recs_put_ebcdic(const cms_cp *cp, const char *rec, size_t len, cms_sink sink, void *ctx)
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
    size_t bad = 0, elen = cms_recs_text_cols(rec, len);
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
            cms_recs_put_pad(sink, ctx, ' ', (size_t)lrecl - elen);
        else if (len == 0)
            sink(ctx, recs_blanks, 1);
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
        cms_recs_put_ebcdic(cp, rec, len, sink, ctx);
        cms_recs_put_pad(sink, ctx, 0x40, (size_t)lrecl - elen);
        return 0;
    case CMS_FORM_VSTREAM: {
        size_t out = recfm == 'F' ? (size_t)lrecl : (elen ? elen : 1);
        unsigned char hw[2];
        hw[0] = (unsigned char)(out >> 8);
        hw[1] = (unsigned char)(out & 0xFF);
        sink(ctx, hw, 2);
        cms_recs_put_ebcdic(cp, rec, len, sink, ctx);
        cms_recs_put_pad(sink, ctx, 0x40, out - elen);
        return 0;
    }
    default:
        return diag_at(err, DIAG_USAGE, name, 0, 0, "cannot write form '%s'", cms_form_name(f));
    }
}

int cms_recs_encode_binary(cms_form f, char recfm, long lrecl, const char *rec, size_t len,
                           cms_sink sink, void *ctx, const char *name, long recno, diag *err)
{
    unsigned char hw[2];
    if (f != CMS_FORM_EBCDIC && f != CMS_FORM_VSTREAM)
        return diag_at(err, DIAG_USAGE, name, 0, 0,
                       "a binary file is written as ebcdic, vstream or a tape, not as %s",
                       cms_form_name(f));
    if ((long)len > lrecl)
        return diag_at(err, DIAG_INPUT, name, recno, lrecl + 1,
                       "record of %zu bytes is longer than LRECL %ld", len, lrecl);
    if (len == 0 && recfm == 'V')
        return diag_at(err, DIAG_INPUT, name, recno, 1, "empty record (CMS V files have none)");
    if (f == CMS_FORM_VSTREAM) {
        size_t out = recfm == 'F' ? (size_t)lrecl : len;
        hw[0] = (unsigned char)(out >> 8);
        hw[1] = (unsigned char)(out & 0xFF);
        sink(ctx, hw, 2);
    }
    sink(ctx, rec, len);
    if (recfm == 'F')
        cms_recs_put_pad(sink, ctx, 0x00, (size_t)lrecl - len);
    return 0;
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
