/* cms_fileid — parsing and formatting of "fn ft fm" (see cms_fileid.h). */
#include "vm_cms_shim/cms_fileid.h"
#include <stdio.h>
#include <string.h>

int cms_fileid_char_ok(int c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
           (c != 0 && strchr("$#@+-:_", c) != NULL);
}

static char cms_fileid_upper(char c) { return (c >= 'a' && c <= 'z') ? (char)(c - 'a' + 'A') : c; }

/* Copies one name token (n bytes at s) into out, fileid_upper-cased, after checking
 * length and characters. what is "filename" or "filetype" for messages. */
static int cms_fileid_name(const char *s, size_t n, char *out, const char *what,
                       const char *text, diag *err)
{
    size_t i;
    if (n == 0 || n > CMS_NAME_MAX) {
        diag_at(err, DIAG_INPUT, text, 0, 0,
                "invalid character in fileid (RC 20): %s '%.*s' must be 1-8 characters",
                what, (int)(n > 40 ? 40 : n), s);
        err->rc = CMS_RC_BADCHAR;
        return CMS_RC_BADCHAR;
    }
    for (i = 0; i < n; i++) {
        if (!cms_fileid_char_ok((unsigned char)s[i])) {
            if ((unsigned char)s[i] >= 0x21 && (unsigned char)s[i] < 0x7f)
                diag_at(err, DIAG_INPUT, text, 0, 0,
                        "invalid character in fileid (RC 20): '%c' in %s '%.*s'",
                        s[i], what, (int)n, s);
            else
                diag_at(err, DIAG_INPUT, text, 0, 0,
                        "invalid character in fileid (RC 20): byte 0x%02X in %s",
                        (unsigned char)s[i], what);
            err->rc = CMS_RC_BADCHAR;
            return CMS_RC_BADCHAR;
        }
        out[i] = cms_fileid_upper(s[i]);
    }
    out[n] = '\0';
    return 0;
}

/* Parses a filemode token: "*", a letter, or a letter and a digit 0-6. */
static int cms_fileid_mode(const char *s, size_t n, cms_fileid *id, const char *text, diag *err)
{
    char l = n ? cms_fileid_upper(s[0]) : 0;
    if (n == 1 && s[0] == '*') {
        id->mode = '*';
        id->num = '1';
        return 0;
    }
    if ((n == 1 || n == 2) && l >= 'A' && l <= 'Z' && (n == 1 || (s[1] >= '0' && s[1] <= '6'))) {
        id->mode = l;
        id->num = n == 2 ? s[1] : '1';
        return 0;
    }
    diag_at(err, DIAG_INPUT, text, 0, 0,
            "invalid filemode (RC 24): '%.*s' is not a letter A-Z with an optional number 0-6",
            (int)(n > 40 ? 40 : n), s);
    err->rc = CMS_RC_BADMODE;
    return CMS_RC_BADMODE;
}

int cms_fileid_parse(const char *text, cms_fileid *id, diag *err)
{
    const char *tok[4];
    size_t len[4];
    int ntok = 0, rc;
    const char *p = text;
    cms_fileid r;
    memset(&r, 0, sizeof r);
    while (*p) {
        while (*p == ' ' || *p == '\t')
            p++;
        if (!*p)
            break;
        if (ntok == 4)
            break;
        tok[ntok] = p;
        while (*p && *p != ' ' && *p != '\t')
            p++;
        len[ntok] = (size_t)(p - tok[ntok]);
        ntok++;
    }
    if (ntok < 2 || ntok > 3) {
        diag_at(err, DIAG_INPUT, text, 0, 0,
                "invalid character in fileid (RC 20): expected 'fn ft [fm]', got %d word%s",
                ntok, ntok == 1 ? "" : "s");
        err->rc = CMS_RC_BADCHAR;
        return CMS_RC_BADCHAR;
    }
    if ((rc = cms_fileid_name(tok[0], len[0], r.fn, "filename", text, err)) ||
        (rc = cms_fileid_name(tok[1], len[1], r.ft, "filetype", text, err)))
        return rc;
    if (ntok == 3) {
        if ((rc = cms_fileid_mode(tok[2], len[2], &r, text, err)))
            return rc;
    } else {
        r.mode = 'A';
        r.num = '1';
    }
    *id = r;
    return 0;
}

/* Length of a blank-padded field of at most max bytes. */
static size_t cms_fileid_field_len(const char *s, size_t max)
{
    size_t n = 0;
    while (n < max && s[n] && s[n] != ' ')
        n++;
    return n;
}

int cms_fileid_from_fields(const char *fn8, const char *ft8, const char *fm2,
                           cms_fileid *id, diag *err)
{
    char text[40];
    cms_fileid r;
    int rc;
    size_t nfn = cms_fileid_field_len(fn8, 8), nft = cms_fileid_field_len(ft8, 8), nfm = cms_fileid_field_len(fm2, 2);
    memset(&r, 0, sizeof r);
    snprintf(text, sizeof text, "%.8s %.8s %.2s", fn8, ft8, fm2);
    if ((rc = cms_fileid_name(fn8, nfn, r.fn, "filename", text, err)) ||
        (rc = cms_fileid_name(ft8, nft, r.ft, "filetype", text, err)))
        return rc;
    if (nfm == 0) {
        r.mode = 'A';
        r.num = '1';
    } else if ((rc = cms_fileid_mode(fm2, nfm, &r, text, err)) != 0) {
        return rc;
    } else if (r.mode == '*') {
        diag_at(err, DIAG_INPUT, text, 0, 0, "invalid filemode (RC 24): '*' in a stored fileid");
        err->rc = CMS_RC_BADMODE;
        return CMS_RC_BADMODE;
    }
    *id = r;
    return 0;
}

int cms_fileid_is_fileid(const char *arg)
{
    cms_fileid id;
    diag d;
    diag_init(&d);
    if (strchr(arg, '/'))
        return 0;
    return cms_fileid_parse(arg, &id, &d) == 0;
}

char *cms_fileid_format(const cms_fileid *id, char *buf, size_t size)
{
    if (id->mode == '*')
        snprintf(buf, size, "%s %s *", id->fn, id->ft);
    else
        snprintf(buf, size, "%s %s %c%c", id->fn, id->ft, id->mode, id->num);
    return buf;
}
