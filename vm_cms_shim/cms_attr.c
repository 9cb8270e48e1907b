/* cms_attr — attribute sidecars of host files (see cms_attr.h). */
#include "vm_cms_shim/cms_attr.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define ATTR_MAGIC "maprt-cms-attributes 1"
#define ATTR_MAX_BYTES 4096

char *cms_attr_path(const char *path)
{
    size_t n = strlen(path);
    char *p = mem_alloc(n + sizeof CMS_ATTR_SUFFIX);
    if (p) {
        memcpy(p, path, n);
        memcpy(p + n, CMS_ATTR_SUFFIX, sizeof CMS_ATTR_SUFFIX);
    }
    return p;
}

size_t cms_attr_format(const cms_attr *a, char *buf, size_t size)
{
    int n = snprintf(buf, size, ATTR_MAGIC "\nform %s\n", a->binary ? "binary" : "text");
    if (a->recfm && n >= 0 && (size_t)n < size)
        n += snprintf(buf + n, size - (size_t)n, "recfm %c\n", a->recfm);
    if (a->lrecl && n >= 0 && (size_t)n < size)
        n += snprintf(buf + n, size - (size_t)n, "lrecl %ld\n", a->lrecl);
    if (a->num && n >= 0 && (size_t)n < size)
        n += snprintf(buf + n, size - (size_t)n, "mode %c\n", a->num);
    if (a->date[0] && n >= 0 && (size_t)n < size)
        n += snprintf(buf + n, size - (size_t)n, "date %s\n", a->date);
    return n < 0 ? 0 : (size_t)n < size ? (size_t)n : size - 1;
}

int cms_attr_write(const char *path, const cms_attr *a, diag *err)
{
    char buf[256], *p = cms_attr_path(path);
    size_t n = cms_attr_format(a, buf, sizeof buf);
    int rc;
    if (!p)
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    rc = outfile_write_all(p, buf, n, err);
    mem_free(p);
    return rc;
}

/* One "key value" line (s, len bytes, no line end) into *a. */
static int cms_attr_line(cms_attr *a, const char *s, size_t len, const char *name, long line,
                     diag *err)
{
    char key[16], val[32];
    const char *sp = memchr(s, ' ', len);
    size_t k = sp ? (size_t)(sp - s) : len, v = sp ? len - k - 1 : 0;
    char *end;
    size_t i;
    for (i = 0; i < len; i++)
        if ((unsigned char)s[i] < 0x20 || (unsigned char)s[i] > 0x7E)
            return diag_at(err, DIAG_INPUT, name, line, (long)i + 1,
                           "byte X'%02X' in an attribute file (printable ASCII only)",
                           (unsigned char)s[i]);
    if (!sp || k >= sizeof key || v == 0 || v >= sizeof val)
        return diag_at(err, DIAG_INPUT, name, line, 1, "expected 'key value'");
    memcpy(key, s, k);
    key[k] = '\0';
    memcpy(val, sp + 1, v);
    val[v] = '\0';
    if (!strcmp(key, "form")) {
        if (strcmp(val, "binary") && strcmp(val, "text"))
            return diag_at(err, DIAG_INPUT, name, line, (long)k + 2, "form must be binary or text");
        a->binary = !strcmp(val, "binary");
    } else if (!strcmp(key, "recfm")) {
        if ((val[0] != 'F' && val[0] != 'V') || val[1])
            return diag_at(err, DIAG_INPUT, name, line, (long)k + 2, "recfm must be F or V");
        a->recfm = val[0];
    } else if (!strcmp(key, "lrecl")) {
        long l = strtol(val, &end, 10);
        if (*end || l < 1 || l > 65535)
            return diag_at(err, DIAG_INPUT, name, line, (long)k + 2, "lrecl must be 1..65535");
        a->lrecl = l;
    } else if (!strcmp(key, "mode")) {
        if (val[0] < '0' || val[0] > '6' || val[1])
            return diag_at(err, DIAG_INPUT, name, line, (long)k + 2, "mode number must be 0..6");
        a->num = val[0];
    } else if (!strcmp(key, "date")) {
        static const char shape[] = "dddd-dd-dd dd:dd:dd";
        size_t j;
        int ok = v == 16 || v == 19;
        for (j = 0; ok && j < v; j++)
            ok = shape[j] == 'd' ? val[j] >= '0' && val[j] <= '9' : val[j] == shape[j];
        if (!ok)
            return diag_at(err, DIAG_INPUT, name, line, (long)k + 2,
                           "date must read YYYY-MM-DD HH:MM[:SS]");
        memset(a->date, 0, sizeof a->date);
        memcpy(a->date, val, v + 1);
    } else {
        return diag_at(err, DIAG_INPUT, name, line, 1, "unknown attribute '%s'", key);
    }
    return 0;
}

int cms_attr_parse(const char *data, size_t len, const char *name, cms_attr *a, diag *err)
{
    cms_attr r;
    size_t pos = 0;
    long line = 0;
    int rc = 0;
    memset(&r, 0, sizeof r);
    r.present = 1;
    while (pos < len && !rc) {
        const char *s = data + pos, *nl = memchr(s, '\n', len - pos);
        size_t n = nl ? (size_t)(nl - s) : len - pos;
        pos += n + (nl ? 1 : 0);
        line++;
        if (line == 1) {
            if (n != strlen(ATTR_MAGIC) || memcmp(s, ATTR_MAGIC, n) != 0)
                rc = diag_at(err, DIAG_INPUT, name, 1, 1, "not a maprt attribute file "
                             "(first line must be '" ATTR_MAGIC "')");
            continue;
        }
        if (n)
            rc = cms_attr_line(&r, s, n, name, line, err);
    }
    if (!rc && line == 0)
        rc = diag_at(err, DIAG_INPUT, name, 0, 0, "empty attribute file");
    if (!rc)
        *a = r;
    return rc;
}

int cms_attr_read(const char *path, cms_attr *a, diag *err)
{
    char *p = cms_attr_path(path), *data = NULL;
    size_t len = 0;
    int rc;
    if (!p)
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    if (access(p, F_OK) != 0) {
        mem_free(p);
        memset(a, 0, sizeof *a);
        return 0;
    }
    if (!(rc = infile_read_all(p, ATTR_MAX_BYTES, &data, &len, err)))
        rc = cms_attr_parse(data, len, p, a, err);
    mem_free(data);
    mem_free(p);
    return rc;
}
