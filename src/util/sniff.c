/* sniff — file kinds by magic number (see sniff.h). */
#include "util/sniff.h"
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const struct sniff_info {
    const char *name, *reader;
} sniff_info[SNIFF_NKINDS] = {
    [SNIFF_UNKNOWN] = {"a file of unknown kind", NULL},
    [SNIFF_TEXT] = {"a text file", "maprt render"},
    [SNIFF_PNG] = {"a PNG image", "maprt compare"},
    [SNIFF_JPEG] = {"a JPEG image", "maprt compare"},
    [SNIFF_TIFF] = {"a TIFF image", "maprt compare"},
    [SNIFF_PNM] = {"a Netpbm image", "maprt compare"},
    [SNIFF_GIF] = {"a GIF image", NULL},
    [SNIFF_DL5080] = {"a DL5080 display list", "maprt dl2png"},
    [SNIFF_AWS] = {"a Hercules AWS tape image", "maprt cms import --tape"},
    [SNIFF_GZIP] = {"a gzip-compressed file", NULL},
    [SNIFF_ZIP] = {"a zip archive", NULL},
    [SNIFF_PDF] = {"a PDF document", NULL},
    [SNIFF_ELF] = {"an executable (ELF)", NULL},
};

sniff_kind sniff_data(const void *data, size_t len)
{
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char dl[6] = {0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0};
    const unsigned char *p = data;
    size_t i, n = len < SNIFF_BYTES ? len : SNIFF_BYTES;
    if (len >= 8 && !memcmp(p, png, 8))
        return SNIFF_PNG;
    if (len >= 3 && p[0] == 0xFF && p[1] == 0xD8 && p[2] == 0xFF)
        return SNIFF_JPEG;
    if (len >= 4 && ((!memcmp(p, "II", 2) && p[2] == 42 && p[3] == 0) || (!memcmp(p, "MM", 2) && p[2] == 0 && p[3] == 42)))
        return SNIFF_TIFF;
    if (len >= 3 && p[0] == 'P' && p[1] >= '1' && p[1] <= '7' && (p[2] == '\n' || p[2] == ' ' || p[2] == '\r' || p[2] == '\t'))
        return SNIFF_PNM;
    if (len >= 6 && (!memcmp(p, "GIF87a", 6) || !memcmp(p, "GIF89a", 6)))
        return SNIFF_GIF;
    if (len >= 6 && !memcmp(p, dl, 6))
        return SNIFF_DL5080;
    if (len >= 2 && p[0] == 0x1F && p[1] == 0x8B)
        return SNIFF_GZIP;
    if (len >= 4 && !memcmp(p, "PK\3\4", 4))
        return SNIFF_ZIP;
    if (len >= 5 && !memcmp(p, "%PDF-", 5))
        return SNIFF_PDF;
    if (len >= 4 && !memcmp(p, "\177ELF", 4))
        return SNIFF_ELF;
    /* AWS: a first block header with no previous block, a record start
     * flag (X'A0' a whole record, X'80' its first part), a second flag
     * byte of 0, and a length the file holds */
    if (len >= 6 && !p[2] && !p[3] && (p[4] == 0xA0 || p[4] == 0x80) && !p[5]
        && (size_t)(p[0] | p[1] << 8) > 0 && (size_t)(p[0] | p[1] << 8) <= len - 6)
        return SNIFF_AWS;
    for (i = 0; i < n; i++)
        if (!(p[i] >= 0x20 && p[i] < 0x7f) && p[i] != '\n' && p[i] != '\r' && p[i] != '\t')
            return SNIFF_UNKNOWN;
    return n ? SNIFF_TEXT : SNIFF_UNKNOWN;
}

/* The first SNIFF_BYTES of a regular file; -1 for anything else (a FIFO,
 * a device, a directory, a file that cannot be opened), which is left to
 * the reader to report. Opened without blocking: a FIFO with no writer
 * must not hang the sniff. */
static long sniff_head(const char *path, unsigned char *buf)
{
    struct stat st;
    ssize_t n;
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0)
        return -1;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return -1;
    }
    n = read(fd, buf, SNIFF_BYTES);
    close(fd);
    return n < 0 ? -1 : (long)n;
}

sniff_kind sniff_file(const char *path)
{
    unsigned char buf[SNIFF_BYTES];
    long n = sniff_head(path, buf);
    return n < 0 ? SNIFF_UNKNOWN : sniff_data(buf, (size_t)n);
}


const char *sniff_name(sniff_kind k) { return sniff_info[k < SNIFF_NKINDS ? k : 0].name; }

const char *sniff_reader(sniff_kind k) { return sniff_info[k < SNIFF_NKINDS ? k : 0].reader; }

int sniff_refuse_data(const void *data, size_t len, const char *label, unsigned accepted,
                      const char *wanted, diag *err)
{
    sniff_kind k = sniff_data(data, len);
    const char *reader = sniff_reader(k);
    if (k == SNIFF_UNKNOWN || (accepted & (1u << k)))
        return 0;
    if (reader)
        return diag_at(err, DIAG_INPUT, label, 0, 0, "this is %s, not %s; did you mean `%s`?",
                       sniff_name(k), wanted, reader);
    return diag_at(err, DIAG_INPUT, label, 0, 0, "this is %s, not %s", sniff_name(k), wanted);
}

int sniff_refuse(const char *path, const char *label, unsigned accepted, const char *wanted, diag *err)
{
    unsigned char buf[SNIFF_BYTES];
    long n = sniff_head(path, buf);
    if (n < 0)
        return 0;      /* the reader reports what is wrong with it */
    return sniff_refuse_data(buf, (size_t)n, label, accepted, wanted, err);
}
