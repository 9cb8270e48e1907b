/* cms_aws — the Hercules AWS tape container: blocks with a 6-byte header
 * (current length u16 LE, previous length u16 LE, flags1, flags2; flags1
 * X'80' start of record, X'20' end of record, X'40' tape mark). Yields whole
 * tape records (reassembled across blocks) and tape marks to the CMS tape
 * decoders (cms_tape). */
#ifndef CMS_AWS_H
#define CMS_AWS_H
#include <stddef.h>
#include "util/diag.h"

#define CMS_AWS_MAX_RECORD 65536L     /* longest reassembled tape record */

enum { CMS_AWS_END = 0, CMS_AWS_RECORD = 1, CMS_AWS_MARK = 2 };

typedef struct cms_aws {
    const unsigned char *buf;
    size_t n, pos;
    size_t prev;              /* length of the previous block */
    unsigned char *rec;       /* reassembly buffer (owned) */
    size_t cap;
    const char *name;
} cms_aws;

/* 1 if buf starts like an AWS image (first header plausible). */
int cms_aws_detect(const unsigned char *buf, size_t n);

void cms_aws_init(cms_aws *a, const unsigned char *buf, size_t n, const char *name);
void cms_aws_free(cms_aws *a);

/* Next item: CMS_AWS_RECORD with *rec and *len (valid until the next call) and
 * *offset (of the record's first header), CMS_AWS_MARK, CMS_AWS_END, or -1
 * after recording a DIAG_INPUT error with the byte offset. */
int cms_aws_next(cms_aws *a, const unsigned char **rec, size_t *len, long long *offset,
                 diag *err);
#endif
