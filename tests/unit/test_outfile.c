/* Tests of util/outfile: unpredictable temporary names created exclusively,
 * planted symlinks never followed, temporary files removed by SIGINT,
 * SIGTERM, SIGHUP and SIGXFSZ, all-or-none batches, bounded input reads. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include "util/mem.h"
#include "util/outfile.h"
#include "support.h"

static char dir[64];

static int setup(void **state)
{
    (void)state;
    strcpy(dir, "/tmp/maprt-test-outfile-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char p[384];
    (void)state;
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
            unlink(p);
        }
    if (d)
        closedir(d);
    return rmdir(dir);
}

static int entries(void) { return test_dir_entries(dir); }

/* Names are "<path>.tmp-" and 12 random characters, never repeated; the
 * file is new and private to the open. */
static void test_outfile_names_unpredictable(void **state)
{
    char path[128], seen[50][160];
    int i, j;
    (void)state;
    snprintf(path, sizeof path, "%s/out.png", dir);
    for (i = 0; i < 50; i++) {
        outfile of;
        struct stat st;
        diag err;
        diag_init(&err);
        assert_int_equal(outfile_open(&of, path, &err), 0);
        assert_int_equal(strncmp(of.tmp, path, strlen(path)), 0);
        assert_int_equal(strncmp(of.tmp + strlen(path), ".tmp-", 5), 0);
        assert_int_equal(strlen(of.tmp), strlen(path) + 5 + 12);
        assert_int_equal(lstat(of.tmp, &st), 0);
        assert_true(S_ISREG(st.st_mode));
        snprintf(seen[i], sizeof seen[i], "%s", of.tmp);
        for (j = 0; j < i; j++)
            assert_string_not_equal(seen[i], seen[j]);
        outfile_abort(&of);
    }
    assert_int_equal(entries(), 0);
}

/* A symlink planted at the target is replaced, its victim untouched. */
static void test_outfile_symlink_not_followed(void **state)
{
    char victim[128], path[128];
    char *data;
    size_t len;
    struct stat st;
    diag err;
    (void)state;
    snprintf(victim, sizeof victim, "%s/victim", dir);
    snprintf(path, sizeof path, "%s/out", dir);
    diag_init(&err);
    assert_int_equal(outfile_write_all(victim, "precious", 8, &err), 0);
    assert_int_equal(symlink(victim, path), 0);
    assert_int_equal(outfile_write_all(path, "new", 3, &err), 0);
    assert_int_equal(lstat(path, &st), 0);
    assert_true(S_ISREG(st.st_mode));
    assert_int_equal(infile_read_all(victim, 100, &data, &len, &err), 0);
    assert_int_equal(len, 8);
    assert_memory_equal(data, "precious", 8);
    mem_free(data);
    unlink(victim);
    unlink(path);
}

/* A child opens an output, writes, and is stopped by sig (SIGXFSZ: by
 * writing past RLIMIT_FSIZE); its temporary file must be gone. */
static void outfile_killed_by(int sig)
{
    char path[128];
    pid_t pid;
    int status;
    snprintf(path, sizeof path, "%s/sig.out", dir);
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        outfile of;
        diag err;
        static char block[65536];
        diag_init(&err);
        if (outfile_open(&of, path, &err))
            _exit(10);
        if (outfile_write(&of, "abc", 3, &err) || fflush(of.f))
            _exit(11);
        if (sig == SIGXFSZ) {
            struct rlimit rl = {4096, 4096};
            int i;
            setrlimit(RLIMIT_FSIZE, &rl);
            for (i = 0; i < 4; i++) {
                fwrite(block, 1, sizeof block, of.f);
                fflush(of.f);
            }
            _exit(12);   /* not reached: SIGXFSZ ends the process */
        }
        kill(getpid(), sig);
        _exit(13);
    }
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFSIGNALED(status));
    assert_int_equal(WTERMSIG(status), sig);
    assert_int_equal(entries(), 0);
}

static void test_outfile_signals_remove_temporaries(void **state)
{
    (void)state;
    outfile_killed_by(SIGINT);
    outfile_killed_by(SIGTERM);
    outfile_killed_by(SIGHUP);
    outfile_killed_by(SIGXFSZ);
}

/* A batch renames nothing until its commit; an abort removes everything. */
static void test_outfile_batch_all_or_none(void **state)
{
    char a[128], b[128];
    struct stat st;
    diag err;
    (void)state;
    snprintf(a, sizeof a, "%s/a", dir);
    snprintf(b, sizeof b, "%s/b", dir);
    diag_init(&err);
    outfile_batch_begin();
    assert_int_equal(outfile_write_all(a, "1", 1, &err), 0);
    assert_int_equal(stat(a, &st), -1);
    outfile_batch_abort();
    assert_int_equal(entries(), 0);
    outfile_batch_begin();
    assert_int_equal(outfile_write_all(a, "1", 1, &err), 0);
    assert_int_equal(outfile_write_all(b, "2", 1, &err), 0);
    assert_int_equal(stat(a, &st), -1);
    assert_int_equal(outfile_batch_commit(&err), 0);
    assert_int_equal(stat(a, &st), 0);
    assert_int_equal(stat(b, &st), 0);
    assert_int_equal(entries(), 2);
    unlink(a);
    unlink(b);
}

/* Inputs: limits from the size, non-regular files refused at once. */
static void test_outfile_input_kinds(void **state)
{
    char path[128], buf[512];
    char *data;
    size_t len;
    diag err;
    (void)state;
    snprintf(path, sizeof path, "%s/in", dir);
    diag_init(&err);
    assert_int_equal(outfile_write_all(path, "0123456789", 10, &err), 0);
    assert_int_equal(infile_read_all(path, 9, &data, &len, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_non_null(strstr(buf, "file larger than 9 bytes"));
    diag_init(&err);
    assert_int_equal(infile_read_all(path, 10, &data, &len, &err), 0);
    assert_int_equal(len, 10);
    mem_free(data);
    diag_init(&err);
    assert_int_equal(infile_read_all(dir, 10, &data, &len, &err), DIAG_INPUT);
    diag_init(&err);
    assert_int_equal(infile_read_all("/dev/zero", 10, &data, &len, &err), DIAG_INPUT);
    unlink(path);
    snprintf(path, sizeof path, "%s/fifo", dir);
    assert_int_equal(mkfifo(path, 0600), 0);
    diag_init(&err);
    assert_int_equal(infile_read_all(path, 10, &data, &len, &err), DIAG_INPUT);   /* no writer: no wait */
    diag_format(&err, buf, sizeof buf);
    assert_non_null(strstr(buf, "is a FIFO"));
    unlink(path);
}

/* With tracking on, an output that is an input is refused. */
static void test_outfile_input_is_not_output(void **state)
{
    char path[128], link[128];
    char *data;
    size_t len;
    diag err;
    (void)state;
    snprintf(path, sizeof path, "%s/in", dir);
    snprintf(link, sizeof link, "%s/link", dir);
    diag_init(&err);
    assert_int_equal(outfile_write_all(path, "x", 1, &err), 0);
    outfile_track_inputs();
    assert_int_equal(infile_read_all(path, 10, &data, &len, &err), 0);
    mem_free(data);
    assert_int_equal(symlink(path, link), 0);
    assert_int_equal(outfile_write_all(path, "y", 1, &err), DIAG_USAGE);
    diag_init(&err);
    assert_int_equal(outfile_write_all(link, "y", 1, &err), DIAG_USAGE);
    unlink(link);
    unlink(path);
}

int main(void)
{
    /* a launcher may have left a signal ignored (nohup: SIGHUP), which
     * outfile rightly keeps ignored: the signal tests need the defaults */
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    signal(SIGXFSZ, SIG_DFL);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_outfile_names_unpredictable),
        cmocka_unit_test(test_outfile_symlink_not_followed),
        cmocka_unit_test(test_outfile_signals_remove_temporaries),
        cmocka_unit_test(test_outfile_batch_all_or_none),
        cmocka_unit_test(test_outfile_input_kinds),
        cmocka_unit_test(test_outfile_input_is_not_output),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
