/* cms_aws — AWS tape image reader (see cms_aws.h). */
#include "vm_cms_shim/cms_aws.h"
#include "util/mem.h"
#include <string.h>

#define AWS_HDR 6
#define AWS_SOR 0x80
#define AWS_EOR 0x20
#define AWS_MARK 0x40

int cms_aws_detect(const unsigned char *buf, size_t n)
{
    size_t cur;
    if (n < AWS_HDR)
        return 0;
    cur = buf[0] | ((size_t)buf[1] << 8);
    if (buf[2] || buf[3])           /* previous length of the first block is 0 */
        return 0;
    if (buf[4] == AWS_MARK)
        return cur == 0;
    /* other flag bits are let through here so the reader can name them */
    return (buf[4] & AWS_SOR) && !(buf[4] & AWS_MARK) && cur > 0 && cur <= n - AWS_HDR;
}

void cms_aws_init(cms_aws *a, const unsigned char *buf, size_t n, const char *name)
{
    memset(a, 0, sizeof *a);
    a->buf = buf;
    a->n = n;
    a->name = name;
}

void cms_aws_free(cms_aws *a)
{
    mem_free(a->rec);
    a->rec = NULL;
    a->cap = 0;
}

int cms_aws_next(cms_aws *a, const unsigned char **rec, size_t *len, long long *offset,
                 diag *err)
{
    size_t have = 0;
    long long start = (long long)a->pos;
    int in_record = 0;
    for (;;) {
        const unsigned char *h = a->buf + a->pos;
        size_t cur, prev;
        unsigned f1;
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
        if (f1 & ~(unsigned)(AWS_SOR | AWS_EOR | AWS_MARK)) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "AWS block flags X'%02X' are not plain AWS (compressed HET images are "
                        "not read: copy the tape to an uncompressed AWS image first)", f1);
            return -1;
        }
        if (prev != a->prev) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "AWS header: previous length %zu, but the previous block held %zu bytes "
                        "(not an AWS image, or damaged)", prev, a->prev);
            return -1;
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
        if (have + cur > (size_t)CMS_AWS_MAX_RECORD) {
            diag_offset(err, DIAG_INPUT, a->name, (long long)a->pos,
                        "tape record longer than %ld bytes", CMS_AWS_MAX_RECORD);
            return -1;
        }
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
            *rec = a->rec;
            *len = have;
            *offset = start;
            return CMS_AWS_RECORD;
        }
    }
}
