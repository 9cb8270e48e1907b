/* test_cms_lib — helpers shared by the CMS shim tests: an EBCDIC encoder
 * written out by hand from the code page charts (independent of the shim's
 * iconv tables), a growable byte buffer, AWS/tape block builders, and scratch
 * directories. Header-only (static functions) so each test binary stays one
 * .c file. */
#ifndef TEST_CMS_LIB_H
#define TEST_CMS_LIB_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <dirent.h>
#include <sys/stat.h>

#if defined(__GNUC__)
#define T_UNUSED __attribute__((unused))
#else
#define T_UNUSED
#endif

/* EBCDIC for the characters the test decks use; cp is 37 or 1047. Returns
 * -1 for a character not in the chart below. */
T_UNUSED static int t_ebcdic(int c, int cp)
{
    static const char *const rows[] = {"ABCDEFGHI", "JKLMNOPQR", "STUVWXYZ",
                                       "abcdefghi", "jklmnopqr", "stuvwxyz", "0123456789"};
    static const int base[] = {0xC1, 0xD1, 0xE2, 0x81, 0x91, 0xA2, 0xF0};
    static const struct { char c; int e; } punct[] = {
        {' ', 0x40}, {'.', 0x4B}, {'<', 0x4C}, {'(', 0x4D}, {'+', 0x4E}, {'|', 0x4F},
        {'&', 0x50}, {'!', 0x5A}, {'$', 0x5B}, {'*', 0x5C}, {')', 0x5D}, {';', 0x5E},
        {'-', 0x60}, {'/', 0x61}, {',', 0x6B}, {'%', 0x6C}, {'_', 0x6D}, {'>', 0x6E},
        {'?', 0x6F}, {':', 0x7A}, {'#', 0x7B}, {'@', 0x7C}, {'\'', 0x7D}, {'=', 0x7E},
        {'"', 0x7F}, {'{', 0xC0}, {'}', 0xD0}, {'\\', 0xE0}};
    size_t r, k;
    for (r = 0; r < 7; r++) {
        const char *p = strchr(rows[r], c);
        if (c && p)
            return base[r] + (int)(p - rows[r]);
    }
    for (k = 0; k < sizeof punct / sizeof punct[0]; k++)
        if (punct[k].c == c)
            return punct[k].e;
    if (c == '[') return cp == 37 ? 0xBA : 0xAD;
    if (c == ']') return cp == 37 ? 0xBB : 0xBD;
    if (c == '^') return cp == 37 ? 0xB0 : 0x5F;
    return -1;
}

typedef struct tbuf {
    unsigned char *p;
    size_t n, cap;
} tbuf;

T_UNUSED static void tb_put(tbuf *b, const void *d, size_t n)
{
    if (b->n + n > b->cap) {
        b->cap = (b->n + n) * 2 + 64;
        b->p = realloc(b->p, b->cap);
        if (!b->p)
            abort();
    }
    if (n)
        memcpy(b->p + b->n, d, n);
    b->n += n;
}

T_UNUSED static void tb_byte(tbuf *b, int c)
{
    unsigned char x = (unsigned char)c;
    tb_put(b, &x, 1);
}

T_UNUSED static void tb_fill(tbuf *b, int c, size_t n)
{
    while (n--)
        tb_byte(b, c);
}

/* Text s as EBCDIC in page cp, padded with X'40' to width (0 = no pad). */
T_UNUSED static void tb_ebcdic(tbuf *b, const char *s, int cp, size_t width)
{
    size_t n = 0;
    for (; *s; s++, n++) {
        int e = t_ebcdic(*s, cp);
        if (e < 0)
            abort();
        tb_byte(b, e);
    }
    while (n++ < width)
        tb_byte(b, 0x40);
}

T_UNUSED static void tb_free(tbuf *b)
{
    free(b->p);
    memset(b, 0, sizeof *b);
}

/* AWS: one block holding a whole record (flags X'A0'), or a tape mark. */
static size_t t_aws_prev;
T_UNUSED static void tb_aws_record(tbuf *b, const unsigned char *d, size_t n)
{
    unsigned char h[6];
    h[0] = (unsigned char)(n & 0xFF);
    h[1] = (unsigned char)(n >> 8);
    h[2] = (unsigned char)(t_aws_prev & 0xFF);
    h[3] = (unsigned char)(t_aws_prev >> 8);
    h[4] = 0xA0;
    h[5] = 0;
    tb_put(b, h, 6);
    tb_put(b, d, n);
    t_aws_prev = n;
}

T_UNUSED static void tb_aws_mark(tbuf *b)
{
    unsigned char h[6] = {0, 0, 0, 0, 0x40, 0};
    h[2] = (unsigned char)(t_aws_prev & 0xFF);
    h[3] = (unsigned char)(t_aws_prev >> 8);
    tb_put(b, h, 6);
    t_aws_prev = 0;
}

T_UNUSED static void tb_be(tbuf *b, unsigned long v, int n)
{
    while (n--)
        tb_byte(b, (int)((v >> (8 * n)) & 0xFF));
}

/* A scratch directory under /tmp; returns a static path. */
static char *t_mkdtemp(void)
{
    static char dir[64];
    strcpy(dir, "/tmp/maprt-cms-XXXXXX");
    if (!mkdtemp(dir))
        abort();
    return dir;
}

/* Removes a scratch directory and the files in it. */
T_UNUSED static void t_rmdir(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char p[512];
    if (!d)
        return;
    while ((e = readdir(d)) != NULL) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        remove(p);
    }
    closedir(d);
    rmdir(dir);
}

T_UNUSED static void t_write(const char *dir, const char *name, const void *d, size_t n)
{
    char p[512];
    FILE *f;
    snprintf(p, sizeof p, "%s/%s", dir, name);
    f = fopen(p, "wb");
    if (!f || fwrite(d, 1, n, f) != n)
        abort();
    fclose(f);
}

/* Number of directory entries other than . and .. */
T_UNUSED static int t_count_files(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (!d)
        return -1;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            n++;
    closedir(d);
    return n;
}
#endif
