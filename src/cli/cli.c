/* cli — option helpers shared by the subcommands (see cli.h). */
#include "cli/cli.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int cli_usage_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "maprt %s: error: ", cmd);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n(see 'maprt %s --help')\n", cmd);
    return CLI_USAGE;
}

const char *cli_value(const char *cmd, int argc, char **argv, int *i)
{
    if (*i + 1 >= argc) {
        cli_usage_error(cmd, "option %s needs a value", argv[*i]);
        return NULL;
    }
    return argv[++*i];
}

int cli_long(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end || errno)
        return cli_usage_error(cmd, "%s: '%s' is not a whole number", opt, s);
    if (v < lo || v > hi)
        return cli_usage_error(cmd, "%s: %ld is outside %ld..%ld", opt, v, lo, hi);
    *out = v;
    return 0;
}

int cli_double(const char *cmd, const char *opt, const char *s, double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end || errno || !isfinite(v))
        return cli_usage_error(cmd, "%s: '%s' is not a finite number", opt, s);
    *out = v;
    return 0;
}

int cli_size(const char *cmd, const char *opt, const char *s, int max, int *w, int *h)
{
    const char *x = strchr(s, 'x');
    char buf[32];
    long lw = 0, lh = 0;
    size_t n;
    if (!x)
        x = strchr(s, 'X');
    n = x ? (size_t)(x - s) : 0;
    if (!x || n == 0 || n >= sizeof buf)
        return cli_usage_error(cmd, "%s: '%s' is not WIDTHxHEIGHT", opt, s);
    memcpy(buf, s, n);
    buf[n] = '\0';
    if (cli_long(cmd, opt, buf, 1, max, &lw) || cli_long(cmd, opt, x + 1, 1, max, &lh))
        return CLI_USAGE;
    *w = (int)lw;
    *h = (int)lh;
    return 0;
}

int cli_region(const char *cmd, const char *opt, const char *s, int max, int r[4])
{
    long v[4];
    char buf[64];
    const char *p = s;
    int k;
    for (k = 0; k < 4; k++) {
        const char *c = strchr(p, ',');
        size_t n = c && k < 3 ? (size_t)(c - p) : strlen(p);
        if ((k < 3 && !c) || n == 0 || n >= sizeof buf)
            return cli_usage_error(cmd, "%s: '%s' is not X0,Y0,X1,Y1", opt, s);
        memcpy(buf, p, n);
        buf[n] = '\0';
        if (cli_long(cmd, opt, buf, 0, max, &v[k]))
            return CLI_USAGE;
        p += n + 1;
    }
    if (v[0] >= v[2] || v[1] >= v[3])
        return cli_usage_error(cmd, "%s: '%s' is empty (it needs X0 < X1 and Y0 < Y1)", opt, s);
    for (k = 0; k < 4; k++)
        r[k] = (int)v[k];
    return 0;
}

int cli_wants_help(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; i++)
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help"))
            return 1;
    return 0;
}

int cli_is_tty(void) { return isatty(2); }
