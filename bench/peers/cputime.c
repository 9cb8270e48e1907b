/* cputime — runs a command and appends "cpu wall user system" (seconds,
 * microsecond resolution) to a file: user + system time of the command
 * (wait4's rusage, the child alone), its wall time, and the user and
 * system times apart. /usr/bin/time prints CPU in
 * 10 ms steps, a sixth of a 0.06 s render; the bench/peers scripts time
 * each run through this instead (built by make bench-peers).
 *   usage: cputime OUT CMD [ARG...]; exit: the command's status, 127 when
 *   it could not be started, 2 on a usage or output error. The command's
 *   standard output and error go to /dev/null. */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE
#include <fcntl.h>
#include <stdio.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    struct timespec t0, t1;
    struct rusage ru;
    int status, fd;
    pid_t pid;
    FILE *out;
    if (argc < 3) {
        fprintf(stderr, "usage: cputime OUT CMD [ARG...]\n");
        return 2;
    }
    clock_gettime(CLOCK_MONOTONIC, &t0);
    pid = fork();
    if (pid < 0) {
        perror("cputime: fork");
        return 2;
    }
    if (pid == 0) {
        if ((fd = open("/dev/null", O_WRONLY)) >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        execvp(argv[2], argv + 2);
        _exit(127);
    }
    if (wait4(pid, &status, 0, &ru) != pid) {
        perror("cputime: wait4");
        return 2;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if (!(out = fopen(argv[1], "a"))) {
        perror(argv[1]);
        return 2;
    }
    {
        double user = ru.ru_utime.tv_sec + ru.ru_utime.tv_usec / 1e6;
        double sys = ru.ru_stime.tv_sec + ru.ru_stime.tv_usec / 1e6;
        fprintf(out, "%.6f %.6f %.6f %.6f\n", user + sys,
                (t1.tv_sec - t0.tv_sec) + (t1.tv_nsec - t0.tv_nsec) / 1e9, user, sys);
    }
    if (fclose(out)) {
        perror(argv[1]);
        return 2;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
