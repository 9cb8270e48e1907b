/* cms_aws — the Hercules tape containers AWS and HET: blocks (chunks) with a
 * 6-byte header (current length u16 LE, previous length u16 LE, flags1,
 * flags2; flags1 X'80' start of record, X'20' end of record, X'40' tape mark,
 * X'03' the HET compression of the record: 1 zlib, 2 bzip2; flags2 X'80'
 * Bus-Tech zlib). A record may span several chunks; HET compresses the whole
 * record, then chunks it. Yields whole tape records (reassembled, inflated)
 * and tape marks to the CMS tape decoders (cms_tape), and writes records
 * the same way (cms_aws_put). */
#ifndef CMS_AWS_H
#define CMS_AWS_H
#include <stddef.h>
#include "util/diag.h"
#include "vm_cms_shim/cms_warn.h"

#define CMS_AWS_MAX_RECORD 2097152L   /* longest record, as Hercules' HETMAX_BLOCKSIZE */
#define CMS_AWS_MAX_CHUNK 65535L      /* a chunk length is a halfword */

enum { CMS_AWS_END = 0, CMS_AWS_RECORD = 1, CMS_AWS_MARK = 2 };

typedef struct cms_aws {
    const unsigned char *buf;
    size_t n, pos;
    size_t prev;              /* length of the previous chunk */
    unsigned char *rec;       /* reassembly buffer (owned) */
    unsigned char *out;       /* inflated record (owned) */
    size_t cap, outcap;
    const char *name;
    const cms_warn *warn;     /* may be NULL */
    long chain_breaks;        /* previous-length mismatches seen */
    int compressed;           /* the image holds compressed (HET) chunks */
} cms_aws;

/* 1 if buf starts like an AWS or HET image (first header plausible). */
int cms_aws_detect(const unsigned char *buf, size_t n);

void cms_aws_init(cms_aws *a, const unsigned char *buf, size_t n, const char *name,
                  const cms_warn *warn);
void cms_aws_free(cms_aws *a);

/* Next item: CMS_AWS_RECORD with *rec and *len (valid until the next call) and
 * *offset (of the record's first header), CMS_AWS_MARK, CMS_AWS_END, or -1
 * after recording an error with the byte offset (DIAG_INPUT, or DIAG_IO when
 * out of memory). A previous-length field that does not match the chunk
 * before is reported once through the warning hook and otherwise ignored, as
 * Hercules' tapemap and hetlib ignore it. */
int cms_aws_next(cms_aws *a, const unsigned char **rec, size_t *len, long long *offset,
                 diag *err);

/* ---- writing ------------------------------------------------------------ */

typedef enum cms_aws_comp { CMS_AWS_PLAIN = 0, CMS_AWS_ZLIB = 1, CMS_AWS_BZIP2 = 2 } cms_aws_comp;

typedef void (*cms_aws_sink)(void *ctx, const void *data, size_t len);

typedef struct cms_aws_writer {
    cms_aws_sink sink;
    void *ctx;
    cms_aws_comp comp;        /* HET: compress each record (kept raw if not smaller) */
    size_t chunk;             /* longest chunk written (<= CMS_AWS_MAX_CHUNK) */
    size_t prev;
    unsigned char *tmp;       /* compression buffer (owned) */
    size_t tmpcap;
} cms_aws_writer;

/* chunk 0 means CMS_AWS_MAX_CHUNK (Hercules' default). */
/* 1 when this build has libbz2 (HET bzip2 blocks read and written). */
int cms_aws_have_bzip2(void);

void cms_aws_writer_init(cms_aws_writer *w, cms_aws_sink sink, void *ctx, cms_aws_comp comp,
                         size_t chunk);
void cms_aws_writer_free(cms_aws_writer *w);
/* Writes one record of 1..CMS_AWS_MAX_RECORD bytes. 0, DIAG_USAGE for a bad
 * length, DIAG_IO when compression fails or memory runs out. */
int cms_aws_put(cms_aws_writer *w, const void *rec, size_t len, diag *err);
void cms_aws_put_mark(cms_aws_writer *w);
#endif
