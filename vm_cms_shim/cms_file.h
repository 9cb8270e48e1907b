/* cms_file — record-level file access in the manner of the CMS file-system
 * macros: open, read by record number or sequentially (RC 12 at end of file,
 * as FSREAD), write, state, close, erase. Files are named by fileid or host
 * path (cms_name); reading accepts every host form cms_recs decodes, writing
 * produces text lines (default), EBCDIC cards, a CMS V stream or an ASCII
 * punch deck, committed on close through util/outfile. */
#ifndef CMS_FILE_H
#define CMS_FILE_H
#include <stddef.h>
#include "util/diag.h"
#include "vm_cms_shim/cms_name.h"
#include "vm_cms_shim/cms_recs.h"

typedef struct cms_file cms_file;

typedef struct cms_file_info {
    char label[CMS_NAME_LABEL_MAX];   /* fileid ("FIG1 SCENE A1") or host path */
    int is_fileid;
    cms_fileid id;                    /* when is_fileid */
    char recfm;                       /* 'F' or 'V' */
    long lrecl;
    long records;
    cms_form form;                    /* host form read / written */
    cms_cp_id cp;                     /* EBCDIC page, CMS_CP_AUTO for text */
    int has_header;                   /* a :READ card led the deck */
    cms_fileid header;
    int binary;                       /* raw records (a binary file, see cms_attr) */
    char date[20];                    /* date last written from the sidecar, or "" */
    char sha256[65];                  /* SHA-256 of the host file's bytes as
                                         read (cms_file_open_read), 64 hex
                                         digits; "" for a file written */
} cms_file_info;

/* Opens an existing file for reading and decodes it whole (at most
 * CMS_FILE_MAX_BYTES). o may be NULL (auto-detect everything). An attribute
 * sidecar (cms_attr) beside the host file gives the mode number and date,
 * marks a binary file (its bytes are then the CMS record stream, records
 * returned raw), and gives a text file its RECFM and LRECL when the records
 * fit them. Errors: CMS
 * RCs for fileids (err->rc), DIAG_IO when the host file cannot be read,
 * DIAG_INPUT for undecodable content (located in the file). */
int cms_file_open_read(cms_file **f, const cms_disks *d, const char *arg,
                       const cms_decode_opts *o, diag *err);

/* Reads record recno (1-based; 0 = the next one, as FSREAD's RECNO=0).
 * Returns 0 with *rec and *len (host text, valid until close), or CMS_RC_EOF
 * (12) past the last record; no diagnostic for end of file. */
int cms_file_read(cms_file *f, long recno, const char **rec, size_t *len);

/* Number of the record the last successful read returned (0 before any). */
long cms_file_recno(const cms_file *f);

void cms_file_state(const cms_file *f, cms_file_info *info);

typedef struct cms_write_opts {
    cms_form form;                /* CMS_FORM_AUTO/TEXT = text lines */
    cms_cp_id cp;                 /* for EBCDIC forms; AUTO = 1047 */
    const cms_fileid *header;     /* punch form: the :READ card's fileid;
                                     NULL = the output fileid, if it is one */
    int binary;                   /* records are raw bytes (ebcdic/vstream forms) */
    const char *date;             /* for the sidecar; NULL = none */
    char num;                     /* mode number for the sidecar; 0 = none */
} cms_write_opts;

/* Creates (or replaces, on close) a file. recfm 'F' or 'V', 1 <= lrecl <=
 * 65535; the punch form needs records of at most 80 columns. o may be NULL.
 * Nothing appears under the real name before cms_file_close succeeds. */
int cms_file_open_write(cms_file **f, const cms_disks *d, const char *arg, char recfm,
                        long lrecl, const cms_write_opts *o, diag *err);

/* Appends a record (host text). F records shorter than LRECL are padded with
 * blanks; an empty V record is written as one blank (CMS has no empty
 * records); a longer record is a DIAG_INPUT error naming the record. */
int cms_file_write(cms_file *f, const char *rec, size_t len, diag *err);

/* Writes bytes as they are ahead of the records (control cards such as the
 * CP ID card of a reader deck). */
void cms_file_put_raw(cms_file *f, const void *data, size_t len);

/* Closes: a written file is committed (renamed into place) unless a write
 * failed; a read file is released. f is freed in every case. A binary file,
 * or one with a mode number other than 1, gets an attribute sidecar; a stale
 * sidecar of the replaced file is removed. */
int cms_file_close(cms_file *f, diag *err);

/* Releases without committing (written data is discarded). NULL is fine. */
void cms_file_abort(cms_file *f);

/* The CMS record stream of a file opened for reading, as a CMS disk or tape
 * holds it: F = the records padded to LRECL, V = each record led by its
 * 2-byte length; text records in EBCDIC page cp, binary records as they
 * are. *data (mem_free it) and *len on success; DIAG_INPUT names the record
 * that does not fit or has no EBCDIC code. */
int cms_file_stream(const cms_file *f, cms_cp_id cp, unsigned char **data, size_t *len,
                    diag *err);

/* STATE: information about an existing file (decodes it). */
int cms_file_stat(const cms_disks *d, const char *arg, const cms_decode_opts *o,
                  cms_file_info *info, diag *err);

/* ERASE: removes an existing file. Errors: RC 28 when it does not exist,
 * DIAG_IO when the host refuses. */
int cms_file_erase(const cms_disks *d, const char *arg, diag *err);
#endif
