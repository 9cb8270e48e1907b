/* cms_fileid — CMS file identifiers ("fn ft fm"): parsing, validation and
 * formatting. First stage of the shim: every name a user gives (command line,
 * :READ card, tape trailer) becomes a cms_fileid here before a disk is looked
 * up. Errors carry the CMS return codes of FSSTATE. */
#ifndef CMS_FILEID_H
#define CMS_FILEID_H
#include "util/diag.h"

/* CMS return codes used by the shim (FSSTATE / FSREAD meanings). */
enum cms_rc {
    CMS_RC_OK = 0,
    CMS_RC_EOF = 12,          /* FSREAD: end of file / record number past end */
    CMS_RC_BADCHAR = 20,      /* invalid character in fileid */
    CMS_RC_BADMODE = 24,      /* invalid filemode */
    CMS_RC_NOTFOUND = 28,     /* file not found */
    CMS_RC_NOTACCESSED = 36   /* disk not accessed */
};

#define CMS_NAME_MAX 8

typedef struct cms_fileid {
    char fn[CMS_NAME_MAX + 1];    /* 1-8 characters, NUL-terminated */
    char ft[CMS_NAME_MAX + 1];
    char mode;                    /* 'A'..'Z', or '*' = search A..Z */
    char num;                     /* '0'..'6' */
} cms_fileid;

/* 1 if c may appear in a filename or filetype (A-Z a-z 0-9 $ # @ + - : _). */
int cms_fileid_char_ok(int c);

/* Parses a command-style fileid "fn ft [fm]" (blank-separated; the string is
 * upper-cased). A missing fm means A1, a letter alone means number 1, and "*"
 * means every accessed disk in A..Z order. Returns 0 and fills *id, or the CMS
 * return code (CMS_RC_BADCHAR, CMS_RC_BADMODE) after recording a DIAG_INPUT
 * error in err (err->rc set) naming the text. */
int cms_fileid_parse(const char *text, cms_fileid *id, diag *err);

/* Builds a fileid from fixed fields as stored in directory entries and cards
 * (fn and ft blank-padded, fm two characters; already in ASCII). Same return
 * codes as cms_fileid_parse; names are upper-cased. */
int cms_fileid_from_fields(const char *fn8, const char *ft8, const char *fm2,
                           cms_fileid *id, diag *err);

/* 1 when arg reads as a CMS fileid rather than a host path: two or three
 * blank-separated tokens that parse as a valid fileid, and no '/'. */
int cms_fileid_is_fileid(const char *arg);

/* Formats "FN FT FM" (e.g. "FIG1 SCENE A1", or "FIG1 SCENE *") into buf,
 * which should hold CMS_FILEID_TEXT_MAX bytes. Returns buf. */
#define CMS_FILEID_TEXT_MAX 24
char *cms_fileid_format(const cms_fileid *id, char *buf, size_t size);
#endif
