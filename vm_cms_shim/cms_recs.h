/* cms_recs — a CMS file's records decoded into host text (UTF-8, no line
 * ends), from any host form a file can arrive in: ASCII lines (optionally a
 * Hercules punch deck with a :READ header card), EBCDIC fixed-length card
 * images, CMS V streams (2-byte length not counting itself), z/OS RDW streams,
 * or a CMS byte stream with a known RECFM/LRECL/count (from a tape). The
 * record reader (cms_file) and the importers build on it; the encoders for
 * the write side live here too so every form is written and read in one
 * place. */
#ifndef CMS_RECS_H
#define CMS_RECS_H
#include <stddef.h>
#include "util/diag.h"
#include "vm_cms_shim/cms_cp.h"
#include "vm_cms_shim/cms_fileid.h"

#define CMS_LRECL_MAX 65535                 /* V length prefix is a halfword */
#define CMS_FILE_MAX_BYTES (64L << 20)      /* largest host file read */
#define CMS_CARD_COLS 80

typedef enum cms_form {
    CMS_FORM_AUTO = 0,
    CMS_FORM_TEXT,      /* ASCII/UTF-8 lines, LF or CRLF */
    CMS_FORM_PUNCH,     /* text lines led by a :READ card, F 80 restored */
    CMS_FORM_EBCDIC,    /* EBCDIC fixed-length cards, no line ends */
    CMS_FORM_VSTREAM,   /* CMS V stream: u16 BE length (excl. itself) + EBCDIC */
    CMS_FORM_RDW        /* z/OS RDW: u16 BE length (incl. 4) + 00 00 + EBCDIC */
} cms_form;

const char *cms_form_name(cms_form f);
/* Parses "text", "punch", "ebcdic", "vstream", "rdw" or "auto"; 0 if unknown. */
int cms_form_parse(const char *s, cms_form *f);

typedef struct cms_decode_opts {
    cms_form form;        /* CMS_FORM_AUTO: detect from the content */
    cms_cp_id cp;         /* CMS_CP_AUTO: detect, defaulting to 1047 */
    long lrecl;           /* card length for CMS_FORM_EBCDIC; 0 = 80 */
    int raw_headers;      /* keep :READ cards as records (deck splitting) */
} cms_decode_opts;

typedef struct cms_rec {
    size_t off, len;      /* into cms_recs.text */
} cms_rec;

typedef struct cms_recs {
    char *text;           /* owned */
    cms_rec *rec;         /* owned */
    size_t count;
    char recfm;           /* 'F' or 'V' */
    long lrecl;
    cms_form form;        /* the form the bytes were in */
    cms_cp_id cp;         /* page used for EBCDIC forms, else CMS_CP_AUTO */
    int has_header;       /* a :READ card named the file */
    cms_fileid header;
    int binary;           /* records are raw bytes (EBCDIC or binary), not host text */
} cms_recs;

/* Decodes a whole host file (buf, n bytes) into *out; name labels the
 * diagnostics (fileid or path; the line is the record number, binary forms
 * give byte offsets). Auto-detection: EBCDIC cards when n is a multiple of
 * the card length and every byte is at least X'40' with some above X'7F';
 * else an RDW or V stream when the length chain covers the buffer exactly
 * with EBCDIC text records (both at once is an error asking for --read-as);
 * else text. RECFM of text is F when every line has the same length, else
 * V; LRECL the longest (in characters). A punch
 * deck is F 80; a second :READ card is an error (import splits decks).
 * Returns 0 or DIAG_INPUT / DIAG_IO; *out is written only on success. */
int cms_recs_decode(const unsigned char *buf, size_t n, const cms_decode_opts *o,
                    const char *name, cms_recs *out, diag *err);

/* Decodes a CMS byte stream as stored on disk/tape: F = count records of
 * lrecl bytes (bytes beyond are block padding), V = count records with
 * 2-byte lengths. count < 0: the stream holds whole records exactly (a
 * binary host file). Text records are EBCDIC through cp; binary != 0 keeps
 * the bytes as they are (r->binary set). Errors name `name` with byte
 * offsets. */
int cms_recs_from_stream(const unsigned char *s, size_t n, char recfm, long lrecl,
                         long count, cms_cp_id cp, int binary, const char *name,
                         cms_recs *out, diag *err);

/* The first byte of a valid CMS byte stream (as cms_recs_from_stream
 * accepts it) that no text record may hold (below X'40', or X'FF'): 1 with
 * its record number, column (1-based) and value, or 0 if every record is
 * text. */
int cms_recs_stream_control(const unsigned char *s, size_t n, char recfm, long lrecl,
                            long count, long *recno, long *col, unsigned char *byte);

void cms_recs_free(cms_recs *r);

/* Record i (0-based, < r->count) and its length; never a null pointer, also
 * when every record is empty and no text was stored. */
const char *cms_recs_at(const cms_recs *r, size_t i, size_t *len);

/* 1 if buf looks like EBCDIC cards of card_len bytes (the auto-detection
 * rule of cms_recs_decode), else 0. */
int cms_recs_looks_ebcdic(const unsigned char *buf, size_t n, size_t card_len);

/* Reads a :READ control card from host text s (len bytes): returns 1 and
 * fills *id, 0 when s is not a :READ card, or -1 after a DIAG_INPUT error at
 * (name, recno, column 8) for a card with a bad fileid. */
int cms_recs_read_card(const char *s, size_t len, cms_fileid *id, const char *name,
                       long recno, diag *err);

/* Appends one record (host text) to a growing record set; used by decoders
 * and the punch splitter. Returns 0 or DIAG_IO. */
int cms_recs_append(cms_recs *r, size_t *textcap, size_t *reccap,
                    const char *data, size_t len, diag *err);

/* Output forms (cms_recs_encode): text lines, EBCDIC cards (each record padded
 * to LRECL), CMS V stream, or an ASCII punch deck (:READ card, records padded
 * to 80 then trailing blanks stripped, as Hercules' ascii punch writes). */
typedef void (*cms_sink)(void *ctx, const void *data, size_t len);

/* Writes one record in form f (text/ebcdic/vstream/punch) through sink.
 * recfm/lrecl: F pads with blanks to lrecl, V writes an empty record as one
 * blank; a record longer than lrecl is an error (DIAG_INPUT, line recno).
 * cp is needed for EBCDIC forms. */
int cms_recs_encode_record(cms_form f, char recfm, long lrecl, const cms_cp *cp,
                           const char *rec, size_t len, cms_sink sink, void *ctx,
                           const char *name, long recno, diag *err);

/* Writes one binary record (raw bytes) in form f: ebcdic (the bytes, F
 * padded with X'00' to lrecl) or vstream (2-byte length + bytes). Text and
 * punch forms refuse binary records (DIAG_USAGE). */
int cms_recs_encode_binary(cms_form f, char recfm, long lrecl, const char *rec, size_t len,
                           cms_sink sink, void *ctx, const char *name, long recno, diag *err);

/* The :READ card for id (80 columns, ASCII, trailing blanks stripped) + "\n". */
void cms_recs_punch_header(const cms_fileid *id, cms_sink sink, void *ctx);
#endif
