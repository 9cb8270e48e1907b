/* outfile — outputs committed on close, bounded whole-file reads, and the
 * input/output identity rule (see outfile.h). */
#include "util/outfile.h"
#include "util/mem.h"
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define OUTFILE_LIVE_MAX 32      /* temporary files open at once */
#define OUTFILE_RAND 12          /* random characters in a temporary name */

/* ---- signal cleanup ------------------------------------------------------ */

/* Temporary names the handler removes. A slot is published only once its
 * string is complete and cleared before the string is freed. */
static char *volatile outfile_live[OUTFILE_LIVE_MAX];
static int outfile_handlers_set;
static const int outfile_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};

void outfile_remove_temporaries(void)
{
    int i;
    for (i = 0; i < OUTFILE_LIVE_MAX; i++) {
        char *t = outfile_live[i];
        if (t)
            unlink(t);
    }
}

static void outfile_on_signal(int sig)
{
    outfile_remove_temporaries();
    signal(sig, SIG_DFL);
    raise(sig);
}

/* Installs the handler for each signal not ignored by whoever started us
 * (nohup's SIGHUP stays ignored). */
static void outfile_handlers(void)
{
    size_t i;
    if (outfile_handlers_set)
        return;
    outfile_handlers_set = 1;
    for (i = 0; i < sizeof outfile_signals / sizeof outfile_signals[0]; i++) {
        struct sigaction old, sa;
        if (sigaction(outfile_signals[i], NULL, &old) != 0 || old.sa_handler == SIG_IGN)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = outfile_on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(outfile_signals[i], &sa, NULL);
    }
}

static int outfile_live_add(char *tmp)
{
    int i;
    outfile_handlers();
    for (i = 0; i < OUTFILE_LIVE_MAX; i++)
        if (!outfile_live[i]) {
            outfile_live[i] = tmp;
            return i;
        }
    return -1;
}

static void outfile_live_drop(int slot)
{
    if (slot >= 0 && slot < OUTFILE_LIVE_MAX)
        outfile_live[slot] = NULL;
}

/* ---- inputs read ----------------------------------------------------------- */

typedef struct outfile_id {
    dev_t dev;
    ino_t ino;
} outfile_id;

static outfile_id *outfile_inputs;
static size_t outfile_ninputs, outfile_inputs_cap;
static int outfile_tracking;

void outfile_track_inputs(void) { outfile_tracking = 1; }

static void outfile_note_input(const struct stat *st)
{
    size_t i;
    if (!outfile_tracking)
        return;
    for (i = 0; i < outfile_ninputs; i++)
        if (outfile_inputs[i].dev == st->st_dev && outfile_inputs[i].ino == st->st_ino)
            return;
    if (mem_grow((void **)&outfile_inputs, &outfile_inputs_cap, outfile_ninputs + 1,
                 sizeof *outfile_inputs))
        return;   /* the rename would still not touch the open input's data */
    outfile_inputs[outfile_ninputs].dev = st->st_dev;
    outfile_inputs[outfile_ninputs].ino = st->st_ino;
    outfile_ninputs++;
}

static int outfile_is_input(const struct stat *st)
{
    size_t i;
    for (i = 0; i < outfile_ninputs; i++)
        if (outfile_inputs[i].dev == st->st_dev && outfile_inputs[i].ino == st->st_ino)
            return 1;
    return 0;
}

/* ---- outputs --------------------------------------------------------------- */

/* The directory part of path ("." for a bare name) into a new string. */
static char *outfile_dir(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    char *d;
    if (!slash)
        return mem_strdup(".");
    if (n == 0)
        n = 1;   /* "/name" */
    if (!(d = mem_alloc(n + 1)))
        return NULL;
    memcpy(d, path, n);
    d[n] = '\0';
    return d;
}

int outfile_check(const char *path, diag *err)
{
    struct stat st;
    char *dir;
    int rc = 0;
    if (!path[0])
        return diag_at(err, DIAG_USAGE, path, 0, 0, "empty output name");
    if (stat(path, &st) == 0) {
        if (outfile_is_input(&st))
            return diag_at(err, DIAG_USAGE, path, 0, 0,
                           "is an input of this command; refusing to overwrite it");
        /* The rename would replace a device, FIFO or directory entry (e.g.
         * /dev/null) with a plain file. */
        if (!S_ISREG(st.st_mode))
            return diag_at(err, DIAG_IO, path, 0, 0, "%s; refusing to replace it",
                           S_ISDIR(st.st_mode) ? "is a directory" : "not a regular file");
    }
    if (!(dir = outfile_dir(path)))
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    if (stat(dir, &st) != 0)
        rc = diag_at(err, DIAG_IO, path, 0, 0, "cannot create: directory %s: %s", dir, strerror(errno));
    else if (!S_ISDIR(st.st_mode))
        rc = diag_at(err, DIAG_IO, path, 0, 0, "cannot create: %s is not a directory", dir);
    else if (access(dir, W_OK | X_OK) != 0)
        rc = diag_at(err, DIAG_IO, path, 0, 0, "cannot create: directory %s: %s", dir, strerror(errno));
    mem_free(dir);
    return rc;
}

/* 1 when paths a and b name the same directory entry (same directory by
 * device and inode, same last component). */
static int outfile_same_entry(const char *a, const char *b)
{
    const char *ba = strrchr(a, '/'), *bb = strrchr(b, '/');
    char *da, *db;
    struct stat sa, sb;
    int same = 0;
    if (strcmp(ba ? ba + 1 : a, bb ? bb + 1 : b))
        return 0;
    da = outfile_dir(a);
    db = outfile_dir(b);
    if (da && db && stat(da, &sa) == 0 && stat(db, &sb) == 0)
        same = sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    mem_free(da);
    mem_free(db);
    return same;
}

int outfile_check_set(const char *const *paths, size_t n, diag *err)
{
    size_t i, j;
    struct stat si, sj;
    for (i = 0; i < n; i++) {
        if (!paths[i])
            continue;
        if (outfile_check(paths[i], err))
            return err->status;
        for (j = 0; j < i; j++)
            if (paths[j] && (outfile_same_entry(paths[i], paths[j]) ||
                             (stat(paths[i], &si) == 0 && stat(paths[j], &sj) == 0 &&
                              si.st_dev == sj.st_dev && si.st_ino == sj.st_ino)))
                return diag_at(err, DIAG_USAGE, paths[i], 0, 0, "is also the output %s", paths[j]);
    }
    return 0;
}

/* Fills out[0..OUTFILE_RAND-1] with unpredictable name characters: from
 * /dev/urandom, else (no such device) from the clock, pid and a counter;
 * O_EXCL keeps even a guessed name safe, it then merely fails. */
static void outfile_random(char *out)
{
    static const char set[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-";
    static unsigned long serial;
    unsigned char b[OUTFILE_RAND];
    int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC), i;
    if (fd < 0 || read(fd, b, sizeof b) != (ssize_t)sizeof b) {
        struct timespec ts;
        uint64_t x;
        clock_gettime(CLOCK_REALTIME, &ts);
        x = (uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^ ((uint64_t)getpid() << 17) ^ ++serial;
        for (i = 0; i < OUTFILE_RAND; i++) {
            x = x * 6364136223846793005ull + 1442695040888963407ull;   /* LCG step */
            b[i] = (unsigned char)(x >> 56);
        }
    }
    if (fd >= 0)
        close(fd);
    for (i = 0; i < OUTFILE_RAND; i++)
        out[i] = set[b[i] & 63];
}

int outfile_open(outfile *of, const char *path, diag *err)
{
    size_t n = strlen(path);
    int fd = -1, tries, e = 0;
    memset(of, 0, sizeof *of);
    of->slot = -1;
    if (outfile_check(path, err))
        return err->status;
    of->path = mem_strdup(path);
    of->tmp = mem_alloc(n + 6 + OUTFILE_RAND);
    if (!of->path || !of->tmp) {
        outfile_abort(of);
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    }
    for (tries = 0; tries < 100 && fd < 0; tries++) {
        memcpy(of->tmp, path, n);
        memcpy(of->tmp + n, ".tmp-", 5);
        outfile_random(of->tmp + n + 5);
        of->tmp[n + 5 + OUTFILE_RAND] = '\0';
        fd = open(of->tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        e = errno;
        if (fd < 0 && e != EEXIST)
            break;
    }
    if (fd < 0) {
        mem_free(of->tmp);
        of->tmp = NULL;   /* not ours: never remove it */
        outfile_abort(of);
        return diag_at(err, DIAG_IO, path, 0, 0, "cannot create: %s", strerror(e));
    }
    of->slot = outfile_live_add(of->tmp);
    if (!(of->f = fdopen(fd, "wb"))) {
        e = errno;
        close(fd);
        outfile_abort(of);
        return diag_at(err, DIAG_IO, path, 0, 0, "cannot create: %s", strerror(e));
    }
    return 0;
}

int outfile_write(outfile *of, const void *data, size_t len, diag *err)
{
    if (of->failed || !of->f || (len && fwrite(data, 1, len, of->f) != len)) {
        of->failed = 1;
        return diag_at(err, DIAG_IO, of->path, 0, 0, "write failed: %s", strerror(errno));
    }
    return 0;
}

void outfile_sink(void *ctx, const void *data, size_t len)
{
    outfile *of = ctx;
    if (!of->failed && (!of->f || fwrite(data, 1, len, of->f) != len))
        of->failed = 1;
}

/* The batch of outputs written but not yet renamed. */
static struct {
    int active;
    size_t n;
    outfile of[OUTFILE_BATCH_MAX];
} outfile_batch;

static int outfile_rename(outfile *of, diag *err)
{
    if (rename(of->tmp, of->path) != 0) {
        int e = errno;
        diag_at(err, DIAG_IO, of->path, 0, 0, "cannot rename into place: %s", strerror(e));
        outfile_abort(of);
        return DIAG_IO;
    }
    outfile_live_drop(of->slot);
    mem_free(of->tmp);
    mem_free(of->path);
    memset(of, 0, sizeof *of);
    of->slot = -1;
    return 0;
}

int outfile_commit(outfile *of, diag *err)
{
    int bad = of->failed || !of->f, e = 0;
    if (of->f) {
        if (fflush(of->f) != 0) {
            e = errno;
            bad = 1;
        }
        if (fclose(of->f) != 0) {
            e = e ? e : errno;
            bad = 1;
        }
        of->f = NULL;
    }
    if (bad) {
        diag_at(err, DIAG_IO, of->path, 0, 0, "write failed%s%s", e ? ": " : "", e ? strerror(e) : "");
        outfile_abort(of);
        return DIAG_IO;
    }
    if (outfile_batch.active) {
        if (outfile_batch.n == OUTFILE_BATCH_MAX) {
            diag_at(err, DIAG_IO, of->path, 0, 0, "more than %d outputs in one command", OUTFILE_BATCH_MAX);
            outfile_abort(of);
            return DIAG_IO;
        }
        outfile_batch.of[outfile_batch.n++] = *of;
        memset(of, 0, sizeof *of);
        of->slot = -1;
        return 0;
    }
    return outfile_rename(of, err);
}

void outfile_abort(outfile *of)
{
    if (of->f)
        fclose(of->f);
    if (of->tmp)
        unlink(of->tmp);
    outfile_live_drop(of->slot);
    mem_free(of->tmp);
    mem_free(of->path);
    memset(of, 0, sizeof *of);
    of->slot = -1;
}

void outfile_batch_begin(void)
{
    outfile_batch_abort();
    outfile_batch.active = 1;
}

int outfile_batch_commit(diag *err)
{
    size_t i;
    int rc = 0;
    /* Every output is complete and closed: only the renames remain, which
     * within one directory each are atomic. */
    for (i = 0; i < outfile_batch.n; i++)
        if (!rc)
            rc = outfile_rename(&outfile_batch.of[i], err);
        else
            outfile_abort(&outfile_batch.of[i]);
    outfile_batch.n = 0;
    outfile_batch.active = 0;
    return rc;
}

void outfile_batch_abort(void)
{
    size_t i;
    for (i = 0; i < outfile_batch.n; i++)
        outfile_abort(&outfile_batch.of[i]);
    outfile_batch.n = 0;
    outfile_batch.active = 0;
}

int outfile_write_all(const char *path, const void *data, size_t len, diag *err)
{
    outfile of;
    if (outfile_open(&of, path, err))
        return err->status;
    if (outfile_write(&of, data, len, err)) {
        outfile_abort(&of);
        return DIAG_IO;
    }
    return outfile_commit(&of, err);
}

int outfile_close_stdout(diag *err)
{
    int bad = fflush(stdout) != 0 || ferror(stdout), e = errno;
    if (fclose(stdout) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    if (bad)
        return diag_at(err, DIAG_IO, "<stdout>", 0, 0, "write failed: %s", strerror(e));
    return 0;
}

/* ---- inputs ---------------------------------------------------------------- */

int infile_read_all(const char *path, size_t max, char **data, size_t *len, diag *err)
{
    struct stat st;
    char *buf;
    size_t n = 0, cap;
    /* O_NONBLOCK: opening a FIFO with no writer must not wait for one; only
     * regular files are read, so the flag changes nothing else. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC), e = errno;
    if (fd < 0) /* a name that does not exist is bad input; anything else is I/O */
        return diag_at(err, e == ENOENT || e == ENOTDIR || e == ENXIO ? DIAG_INPUT : DIAG_IO, path, 0,
                       0, "cannot open: %s", strerror(e));
    if (fstat(fd, &st) != 0) {
        e = errno;
        close(fd);
        return diag_at(err, DIAG_IO, path, 0, 0, "cannot stat: %s", strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return diag_at(err, DIAG_INPUT, path, 0, 0, "%s, not a regular file",
                       S_ISDIR(st.st_mode) ? "is a directory"
                       : S_ISFIFO(st.st_mode) ? "is a FIFO" : S_ISSOCK(st.st_mode) ? "is a socket"
                                                                                    : "is a device");
    }
    if (st.st_size < 0 || (uintmax_t)st.st_size > (uintmax_t)max) {
        close(fd);
        return diag_at(err, DIAG_INPUT, path, 0, 0, "file larger than %zu bytes", max);
    }
    /* One byte more than the size, to see a file that grows past it. */
    cap = (size_t)st.st_size + 1;
    if (!(buf = mem_alloc(cap))) {
        close(fd);
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    }
    for (;;) {
        ssize_t got = read(fd, buf + n, cap - n);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            e = errno;
            mem_free(buf);
            close(fd);
            return diag_at(err, e == EISDIR ? DIAG_INPUT : DIAG_IO, path, 0, 0, "read error: %s", strerror(e));
        }
        if (got == 0)
            break;
        n += (size_t)got;
        if (n > max) {   /* it grew while being read */
            mem_free(buf);
            close(fd);
            return diag_at(err, DIAG_INPUT, path, 0, 0, "file larger than %zu bytes", max);
        }
        if (n == cap) {
            if (mem_grow((void **)&buf, &cap, n + 65536, 1)) {
                mem_free(buf);
                close(fd);
                return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
            }
        }
    }
    close(fd);
    outfile_note_input(&st);
    *data = buf;
    *len = n;
    return 0;
}
