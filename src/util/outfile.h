/* outfile — outputs committed on close, inputs read with a bound, and the
 * rule that an output never replaces an input.
 *
 * Outputs: bytes go to a new temporary file beside the target,
 * "<path>.tmp-XXXXXXXXXXXX" (twelve random characters), created with
 * O_CREAT|O_EXCL|O_NOFOLLOW so that nothing planted under that name (a
 * symlink, a file) is followed or reused. outfile_commit renames it over the
 * target, outfile_abort removes it, so a failed run never leaves a
 * half-written file under the real name. Temporary files still open when
 * SIGINT, SIGTERM, SIGHUP or SIGXFSZ arrives are removed by the signal
 * handler (unlink only: async-signal-safe) before the signal takes its
 * default course.
 *
 * Inputs: infile_read_all reads regular files only (a FIFO, device or
 * directory is refused without blocking) and, once outfile_track_inputs was
 * called (the command line does so: one process, one command), remembers the
 * device and inode of every file it read; an output that is the same file as one of them
 * (through hard or symbolic links too) is refused by outfile_check and by
 * outfile_open.
 *
 * Several outputs of one command commit all or none: between
 * outfile_batch_begin and outfile_batch_commit, outfile_commit only writes
 * and closes; the renames happen together in outfile_batch_commit once every
 * output was written, and outfile_batch_abort removes them all.
 * Host paths only: the CMS shim resolves fileids to host paths first. */
#ifndef OUTFILE_H
#define OUTFILE_H
#include <stddef.h>
#include <stdio.h>
#include "util/diag.h"

typedef struct outfile {
    FILE *f;
    char *path;      /* final name */
    char *tmp;       /* temporary name */
    int failed;      /* a write failed: commit will refuse */
    int slot;        /* index in the signal-cleanup table, -1 if none */
} outfile;

/* From now on, files read by infile_read_all are inputs no output may
 * replace. */
void outfile_track_inputs(void);
/* Checks an output path before the work that produces it: DIAG_USAGE when
 * it is the same file as an input read so far; DIAG_IO when it exists but is
 * not a regular file, or its directory is missing or not writable. */
int outfile_check(const char *path, diag *err);
/* outfile_check on each non-NULL path, and DIAG_USAGE when two of them
 * name the same file. */
int outfile_check_set(const char *const *paths, size_t n, diag *err);
int outfile_open(outfile *of, const char *path, diag *err);   /* outfile_check, then create */
int outfile_write(outfile *of, const void *data, size_t len, diag *err);
int outfile_commit(outfile *of, diag *err);   /* flush, close, rename; 0 or DIAG_IO */
void outfile_abort(outfile *of);              /* close and remove; safe to repeat */
/* Unlinks every temporary file still open (async-signal-safe): for the
 * signal handler, and for an exit that a library takes behind our back. */
void outfile_remove_temporaries(void);
/* Writes a whole buffer to path through open/write/commit. */
int outfile_write_all(const char *path, const void *data, size_t len, diag *err);
/* A writer callback (stb style) that appends to an outfile: ctx is the outfile;
 * errors are remembered and reported by outfile_commit. */
void outfile_sink(void *ctx, const void *data, size_t len);

/* All-or-none commits of the outputs of one command (at most
 * OUTFILE_BATCH_MAX; one batch at a time). */
#define OUTFILE_BATCH_MAX 8
void outfile_batch_begin(void);
int outfile_batch_commit(diag *err);          /* renames every output; 0 or DIAG_IO */
void outfile_batch_abort(void);               /* removes every output written */

/* Reads a whole host file, refusing files larger than max bytes (from its
 * size, before reading) and anything but a regular file.
 * On success *data (mem_free it) and *len are set; else err names the file:
 * DIAG_INPUT when it does not exist, is a directory, FIFO or device, or is
 * too large; DIAG_IO otherwise. */
int infile_read_all(const char *path, size_t max, char **data, size_t *len, diag *err);

/* Closes stdout and reports a write error that was buffered (e.g. a full
 * disk or /dev/full): 0 or DIAG_IO. */
int outfile_close_stdout(diag *err);
#endif
