/* cms_aws — AWS and HET tape image reader and writer (see cms_aws.h). */
#include "vm_cms_shim/cms_aws.h"
#include "util/mem.h"
#if defined(CMS_HAVE_BZIP2)
#include <bzlib.h>
#endif
#include <limits.h>
#include <string.h>
#include <zlib.h>

#define AWS_HDR 6
#define AWS_SOR 0x80
#define AWS_MARK 0x40
#define AWS_EOR 0x20
#define AWS_COMP 0x03            /* flags1: HET compression method */
#define AWS_F2_BUSTECH 0x80      /* flags2: Bus-Tech zlib */

int cms_aws_detect(const unsigned char *buf, size_t n)
{
    size_t cur;
    if (n < AWS_HDR)
        return 0;
    cur = buf[0] | ((size_t)buf[1] << 8);
    if (buf[2] || buf[3])           /* previous length of the first block is 0 */
        return 0;
    if (buf[4] & AWS_MARK)
        return cur == 0;
    /* other flag bits are let through here so the reader can name them */
    return (buf[4] & AWS_SOR) && cur > 0 && cur <= n - AWS_HDR;
}

void cms_aws_init(cms_aws *a, const unsigned char *buf, size_t n, const char *name,
                  const cms_warn *warn)
{
    memset(a, 0, sizeof *a);
    a->buf = buf;
    a->n = n;
    a->name = name;
    a->warn = warn;
}

void cms_aws_free(cms_aws *a)
{
    mem_free(a->rec);
    mem_free(a->out);
    a->rec = a->out = NULL;
    a->cap = a->outcap = 0;
}

/* Inflates a HET record (method 1 zlib, 2 bzip2) into a->out. */
static int cms_aws_inflate(cms_aws *a, unsigned method, size_t have, long long start,
                       const unsigned char **rec, size_t *len, diag *err)
{
    if (!a->out && !(a->out = mem_alloc((size_t)CMS_AWS_MAX_RECORD)))
        return diag_offset(err, DIAG_IO, a->name, start, "out of memory");
    a->outcap = (size_t)CMS_AWS_MAX_RECORD;
    if (method == 1) {
        uLongf out = (uLongf)a->outcap;
        int zr = uncompress(a->out, &out, a->rec, (uLong)have);
        if (zr != Z_OK)
            return diag_offset(err, DIAG_INPUT, a->name, start,
                               "HET record: zlib data %s", zr == Z_BUF_ERROR
                               ? "inflates past the 2 MiB record limit, or is cut short"
                               : "is corrupt");
        *len = (size_t)out;
    } else if (method == 2) {
#if defined(CMS_HAVE_BZIP2)
        unsigned int out = (unsigned int)a->outcap;
        int br;
        if (have > UINT_MAX)
            return diag_offset(err, DIAG_INPUT, a->name, start, "HET record too long");
        br = BZ2_bzBuffToBuffDecompress((char *)a->out, &out, (char *)a->rec,
                                        (unsigned int)have, 0, 0);
        if (br != BZ_OK)
            return diag_offset(err, br == BZ_MEM_ERROR ? DIAG_IO : DIAG_INPUT, a->name, start,
                               "HET record: bzip2 data %s", br == BZ_OUTBUFF_FULL
                               ? "inflates past the 2 MiB record limit"
                               : br == BZ_MEM_ERROR ? "needs more memory than there is"
                               : "is corrupt or cut short");
        *len = (size_t)out;
#else
        return diag_offset(err, DIAG_INPUT, a->name, start, "HET record is compressed with bzip2, "
                           "and this maprt was built without libbz2 (apt-get install libbz2-dev, "
                           "then rebuild)");
#endif
    } else {
        return diag_offset(err, DIAG_INPUT, a->name, start,
                           "HET compression method %u is not zlib (1) or bzip2 (2)", method);
    }
    if (*len == 0)
        return diag_offset(err, DIAG_INPUT, a->name, start, "HET record inflates to nothing");
    *rec = a->out;
    return 0;
}

int cms_aws_next(cms_aws *a, const unsigned char **rec, size_t *len, long long *offset,
                 diag *err)
{
    size_t have = 0;
    long long start = (long long)a->pos;
    int in_record = 0;
    unsigned method = 0;
    for (;;) {
        const unsigned char *h = a->buf + a->pos;
        size_t cur, prev;
        unsigned f1, m;
        if (a->pos == a->n) {
            if (in_record) {
                diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                            "tape ends inside a record (no end-of-record block)");
                return -1;
            }
            return CMS_AWS_END;
        }
        if (a->n - a->pos < AWS_HDR) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "truncated AWS block header (%zu bytes)", a->n - a->pos);
            return -1;
        }
        cur = h[0] | ((size_t)h[1] << 8);
        prev = h[2] | ((size_t)h[3] << 8);
        f1 = h[4];
        m = (f1 & AWS_COMP) ? (f1 & AWS_COMP) : (h[5] & AWS_F2_BUSTECH) ? 1u : 0u;
        if (f1 & 0x1C) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "AWS block flags X'%02X': bits X'1C' are neither AWS nor HET flags", f1);
            return -1;
        }
        if ((f1 & AWS_COMP) && (h[5] & AWS_F2_BUSTECH)) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "HET block names two compressions (flags %02X %02X)", f1, h[5]);
            return -1;
        }
        if (prev != a->prev) {
            if (a->chain_breaks++ == 0)
                cms_warn_emit(a->warn, a->name, (long long)a->pos,
                              "AWS header: previous length %zu, but the block before held %zu "
                              "bytes; the previous-length chain is ignored (as Hercules' tapemap "
                              "does), further mismatches are not reported", prev, a->prev);
        }
        if (cur > a->n - a->pos - AWS_HDR) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "AWS block of %zu bytes runs past the end of the image", cur);
            return -1;
        }
        if (f1 & AWS_MARK) {
            if (in_record || cur) {
                diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                            in_record ? "tape mark inside a record" : "tape mark with data");
                return -1;
            }
            a->pos += AWS_HDR;
            a->prev = 0;
            return CMS_AWS_MARK;
        }
        if (!in_record && !(f1 & AWS_SOR)) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "AWS block continues a record that never started (flags %02X)", f1);
            return -1;
        }
        if (in_record && (f1 & AWS_SOR)) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "AWS block starts a record before the previous one ended");
            return -1;
        }
        if (in_record && m != method) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "HET chunk compression differs from the record's first chunk");
            return -1;
        }
        if (have + cur > (size_t)CMS_AWS_MAX_RECORD) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "tape record longer than %ld bytes", CMS_AWS_MAX_RECORD);
            return -1;
        }
        if (!in_record)
            method = m;
        in_record = 1;
        if (cur && mem_grow((void **)&a->rec, &a->cap, have + cur, 1)) {
            diag_offset(err, DIAG_IO, a->name, (long long)a->pos, "out of memory");
            return -1;
        }
        if (cur)
            memcpy(a->rec + have, h + AWS_HDR, cur);
        have += cur;
        a->pos += AWS_HDR + cur;
        a->prev = cur;
        if (f1 & AWS_EOR) {
            if (have == 0) {
                diag_offset(err, DIAG_INPUT, a->name, start, "empty tape record");
                return -1;
            }
            *offset = start;
            if (method) {
                a->compressed = 1;
                return cms_aws_inflate(a, method, have, start, rec, len, err) ? -1 : CMS_AWS_RECORD;
            }
            *rec = a->rec;
            *len = have;
            return CMS_AWS_RECORD;
        }
    }
}

/* ---- writing ------------------------------------------------------------ */

void cms_aws_writer_init(cms_aws_writer *w, cms_aws_sink sink, void *ctx, cms_aws_comp comp,
                         size_t chunk)
{
    memset(w, 0, sizeof *w);
    w->sink = sink;
    w->ctx = ctx;
    w->comp = comp;
    w->chunk = chunk && chunk <= (size_t)CMS_AWS_MAX_CHUNK ? chunk : (size_t)CMS_AWS_MAX_CHUNK;
}

void cms_aws_writer_free(cms_aws_writer *w)
{
    mem_free(w->tmp);
    w->tmp = NULL;
    w->tmpcap = 0;
}

static void cms_aws_header(cms_aws_writer *w, size_t cur, unsigned f1)
{
    unsigned char h[AWS_HDR];
    h[0] = (unsigned char)(cur & 0xFF);
    h[1] = (unsigned char)(cur >> 8);
    h[2] = (unsigned char)(w->prev & 0xFF);
    h[3] = (unsigned char)(w->prev >> 8);
    h[4] = (unsigned char)f1;
    h[5] = 0;
    w->sink(w->ctx, h, AWS_HDR);
    w->prev = cur;
}

/* Compresses rec into w->tmp; 1 when the result is smaller (then *out and *olen
 * are the compressed bytes), 0 to keep the record raw, -1 on failure. */
static int cms_aws_deflate(cms_aws_writer *w, const unsigned char *rec, size_t len,
                       const unsigned char **out, size_t *olen)
{
    size_t need = len + len / 100 + 600;   /* bzip2's documented worst case, zlib's is less */
    if (need > w->tmpcap) {
        unsigned char *t = mem_realloc(w->tmp, need);
        if (!t)
            return -1;
        w->tmp = t;
        w->tmpcap = need;
    }
    if (w->comp == CMS_AWS_ZLIB) {
        uLongf n = (uLongf)w->tmpcap;
        if (compress2(w->tmp, &n, rec, (uLong)len, 4) != Z_OK)   /* level 4, hetlib's default */
            return -1;
        *olen = (size_t)n;
    } else {
#if defined(CMS_HAVE_BZIP2)
        unsigned int n = (unsigned int)w->tmpcap;
        if (BZ2_bzBuffToBuffCompress((char *)w->tmp, &n, (char *)rec, (unsigned int)len, 4, 0, 0)
            != BZ_OK)
            return -1;
        *olen = (size_t)n;
#else
        return -1;                /* refused before: cms_aws_have_bzip2 */
#endif
    }
    *out = w->tmp;
    return *olen < len;
}

int cms_aws_put(cms_aws_writer *w, const void *rec, size_t len, diag *err)
{
    const unsigned char *p = rec;
    unsigned flags = AWS_SOR;
    if (len == 0 || len > (size_t)CMS_AWS_MAX_RECORD)
        return diag_at(err, DIAG_USAGE, "", 0, 0, "tape record of %zu bytes (1..%ld)", len,
                       CMS_AWS_MAX_RECORD);
    if (w->comp != CMS_AWS_PLAIN) {
        const unsigned char *c;
        size_t clen;
        int k = cms_aws_deflate(w, p, len, &c, &clen);
        if (k < 0)
            return diag_at(err, DIAG_IO, "", 0, 0, "%s compression failed",
                           w->comp == CMS_AWS_ZLIB ? "zlib" : "bzip2");
        if (k) {
            p = c;
            len = clen;
            flags |= (unsigned)w->comp;
        }
    }
    do {
        size_t n = len < w->chunk ? len : w->chunk;
        if (n == len)
            flags |= AWS_EOR;
        cms_aws_header(w, n, flags);
        w->sink(w->ctx, p, n);
        p += n;
        len -= n;
        flags &= ~(unsigned)AWS_SOR;
    } while (len);
    return 0;
}

void cms_aws_put_mark(cms_aws_writer *w)
{
    cms_aws_header(w, 0, AWS_MARK);
    w->prev = 0;
}

int cms_aws_have_bzip2(void)
{
#if defined(CMS_HAVE_BZIP2)
    return 1;
#else
    return 0;
#endif
}
