/* cms_cp — EBCDIC code pages 037 and 1047, translated through glibc iconv.
 * Both pages are permutations of ISO 8859-1, so each is held as a pair of
 * 256-byte tables built once from iconv. Host text is UTF-8: EBCDIC bytes whose
 * Latin-1 character is outside ASCII become two-byte UTF-8 sequences.
 * Used by the record decoders (EBCDIC -> host) and the exporters (host ->
 * EBCDIC). */
#ifndef CMS_CP_H
#define CMS_CP_H
#include <stddef.h>
#include "util/diag.h"

typedef enum cms_cp_id {
    CMS_CP_AUTO = 0,     /* decide from the bytes (cms_cp_detect) */
    CMS_CP_037 = 37,
    CMS_CP_1047 = 1047
} cms_cp_id;

typedef struct cms_cp {
    cms_cp_id id;
    unsigned char to_latin1[256];     /* EBCDIC byte -> ISO 8859-1 code */
    unsigned char from_latin1[256];   /* inverse */
} cms_cp;

/* Parses "037" (or "37") and "1047"; 1 and *id on success, else 0. */
int cms_cp_parse(const char *s, cms_cp_id *id);

/* The tables for page id (037 or 1047), built through iconv on first use.
 * Returns 0 and sets *cp (static storage), or DIAG_IO if iconv lacks the page
 * or does not give a permutation of Latin-1. Not thread-safe on first call. */
int cms_cp_get(cms_cp_id id, const cms_cp **cp, diag *err);

/* Chooses the page for EBCDIC text from the six code points where 037 and
 * 1047 differ: X'AD' X'BD' X'5F' are [ ] ^ in 1047 but Y-acute, diaeresis,
 * not-sign in 037; X'BA' X'BB' X'B0' are [ ] ^ in 037. Returns CMS_CP_1047
 * or CMS_CP_037 when only one group occurs, `fallback` when neither does (both
 * pages then give the same text), and CMS_CP_AUTO when both occur (the bytes
 * do not decide; the caller must ask for --cp). */
cms_cp_id cms_cp_detect(const unsigned char *b, size_t n, cms_cp_id fallback);
/* The same decision in two steps, for text spread over several buffers:
 * cms_cp_scan returns evidence bits (1 = a 1047 code, 2 = a 037 code), to be
 * OR-ed over all buffers and passed to cms_cp_choose. */
unsigned cms_cp_scan(const unsigned char *b, size_t n);
cms_cp_id cms_cp_choose(unsigned evidence, cms_cp_id fallback);

/* Appends the UTF-8 form of EBCDIC bytes to out (room for 2*n bytes needed).
 * Returns the number of bytes written, or (size_t)-1 with *bad set to the
 * index of the first control character (below X'40' or X'FF'), which no text
 * record may hold. */
size_t cms_cp_decode(const cms_cp *cp, const unsigned char *in, size_t n, char *out, size_t *bad);

/* Encodes UTF-8 host text to EBCDIC (out has room for n bytes, or is NULL to
 * only count). Returns the
 * number of bytes written, or (size_t)-1 with *bad set to the byte index of the
 * first character outside Latin-1, control character or malformed sequence. */
size_t cms_cp_encode(const cms_cp *cp, const char *in, size_t n, unsigned char *out, size_t *bad);
#endif
