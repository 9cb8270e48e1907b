/* diag — the first error of an operation, with its location.
 * Parsers and decoders fill one diag and stop; the CLI prints it as
 *   maprt: FILE:LINE:COL: error: TEXT     (text and record formats)
 *   maprt: FILE: offset N: error: TEXT    (binary formats)
 *   maprt: FILE: error: TEXT              (no position)
 * and maps its status to the exit code (DIAG_INPUT 1, DIAG_USAGE 2, DIAG_IO 3). */
#ifndef DIAG_H
#define DIAG_H
#include <stdio.h>

enum diag_status { DIAG_OK = 0, DIAG_INPUT = 1, DIAG_USAGE = 2, DIAG_IO = 3 };

typedef struct diag {
    int status;         /* enum diag_status; 0 = no error recorded */
    int rc;             /* optional host return code (CMS RC), 0 if none */
    char file[256];     /* file name or CMS fileid; "" if none */
    long line, col;     /* 1-based; 0 = unknown */
    long long offset;   /* byte offset for binary formats; -1 = not used */
    char msg[512];
} diag;

void diag_init(diag *d);
/* Records an error unless one is already recorded (the first error wins).
 * Returns status, so callers can write `return diag_at(...)`. */
int diag_at(diag *d, int status, const char *file, long line, long col,
            const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;
int diag_offset(diag *d, int status, const char *file, long long offset,
                const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;
/* Formats the diagnostic (without the "maprt: " prefix) into buf. */
void diag_format(const diag *d, char *buf, size_t size);
/* Prints "maprt: <formatted>\n" to f. */
void diag_print(FILE *f, const diag *d);
/* The same for a warning: "FILE:LINE:COL: warning: TEXT". */
void diag_format_warning(const diag *d, char *buf, size_t size);
/* The same with "warning:" in place of "error:" (for a diag that reports a
 * warning, whatever its status). */
void diag_print_warning(FILE *f, const diag *d);
#endif
