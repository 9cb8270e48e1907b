/* cms_cp — EBCDIC 037/1047 tables from iconv (see cms_cp.h). */
#include "vm_cms_shim/cms_cp.h"
#include <iconv.h>
#include <string.h>

static cms_cp cp_037 = {CMS_CP_037, {0}, {0}};
static cms_cp cp_1047 = {CMS_CP_1047, {0}, {0}};
static int cp_ready037, cp_ready1047;

/* Fills cp's tables by converting each byte with iconv. */
static int cms_cp_build(cms_cp *cp, const char *name, diag *err)
{
    unsigned char seen[256];
    iconv_t h = iconv_open("ISO-8859-1", name);
    int b;
    if (h == (iconv_t)-1)
        return diag_at(err, DIAG_IO, "", 0, 0, "iconv does not know code page %s", name);
    memset(seen, 0, sizeof seen);
    for (b = 0; b < 256; b++) {
        char in = (char)b, out[4];
        char *ip = &in, *op = out;
        size_t il = 1, ol = sizeof out;
        if (iconv(h, &ip, &il, &op, &ol) == (size_t)-1 || ol != sizeof out - 1 ||
            seen[(unsigned char)out[0]]) {
            iconv_close(h);
            return diag_at(err, DIAG_IO, "", 0, 0,
                           "iconv table %s is not a permutation of ISO 8859-1 (byte 0x%02X)", name, b);
        }
        seen[(unsigned char)out[0]] = 1;
        cp->to_latin1[b] = (unsigned char)out[0];
        cp->from_latin1[(unsigned char)out[0]] = (unsigned char)b;
    }
    iconv_close(h);
    return 0;
}

int cms_cp_get(cms_cp_id id, const cms_cp **cp, diag *err)
{
    if (id == CMS_CP_037) {
        if (!cp_ready037 && cms_cp_build(&cp_037, "IBM037", err))
            return DIAG_IO;
        cp_ready037 = 1;
        *cp = &cp_037;
        return 0;
    }
    if (id == CMS_CP_1047) {
        if (!cp_ready1047 && cms_cp_build(&cp_1047, "IBM1047", err))
            return DIAG_IO;
        cp_ready1047 = 1;
        *cp = &cp_1047;
        return 0;
    }
    return diag_at(err, DIAG_USAGE, "", 0, 0, "unknown code page %d (use 037 or 1047)", (int)id);
}

unsigned cms_cp_scan(const unsigned char *b, size_t n)
{
    unsigned ev = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        switch (b[i]) {
        case 0xAD: case 0xBD: case 0x5F: ev |= 1; break;
        case 0xBA: case 0xBB: case 0xB0: ev |= 2; break;
        default: break;
        }
    }
    return ev;
}

cms_cp_id cms_cp_choose(unsigned ev, cms_cp_id fallback)
{
    if (ev == 3)
        return CMS_CP_AUTO;
    if (ev == 1)
        return CMS_CP_1047;
    if (ev == 2)
        return CMS_CP_037;
    return fallback;
}

cms_cp_id cms_cp_detect(const unsigned char *b, size_t n, cms_cp_id fallback)
{
    return cms_cp_choose(cms_cp_scan(b, n), fallback);
}

size_t cms_cp_decode(const cms_cp *cp, const unsigned char *in, size_t n, char *out, size_t *bad)
{
    size_t i, o = 0;
    for (i = 0; i < n; i++) {
        unsigned c;
        if (in[i] < 0x40 || in[i] == 0xFF) {
            *bad = i;
            return (size_t)-1;
        }
        c = cp->to_latin1[in[i]];
        if (c < 0x80) {
            out[o++] = (char)c;
        } else {
            out[o++] = (char)(0xC0 | (c >> 6));
            out[o++] = (char)(0x80 | (c & 0x3F));
        }
    }
    return o;
}

size_t cms_cp_encode(const cms_cp *cp, const char *in, size_t n, unsigned char *out, size_t *bad)
{
    size_t i = 0, o = 0;
    while (i < n) {
        unsigned c = (unsigned char)in[i];
        size_t at = i;
        if (c >= 0xC2 && c <= 0xC3 && i + 1 < n && ((unsigned char)in[i + 1] & 0xC0) == 0x80) {
            c = ((c & 0x1F) << 6) | ((unsigned char)in[i + 1] & 0x3F);
            i += 2;
        } else if (c >= 0x80) {
            *bad = at;
            return (size_t)-1;
        } else {
            i++;
        }
        if (c < 0x20 || (c >= 0x7F && c < 0xA0)) {
            *bad = at;
            return (size_t)-1;
        }
        if (out)
            out[o] = cp->from_latin1[c];
        o++;
    }
    return o;
}

int cms_cp_parse(const char *s, cms_cp_id *id)
{
    if (!strcmp(s, "037") || !strcmp(s, "37"))
        *id = CMS_CP_037;
    else if (!strcmp(s, "1047"))
        *id = CMS_CP_1047;
    else
        return 0;
    return 1;
}
