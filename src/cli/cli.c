/* cli — option helpers shared by the subcommands (see cli.h). */
#include "cli/cli.h"
#include "util/mem.h"
#include "util/suggest.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
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

int cli_png_name(const char *cmd, const char *opt, const char *name)
{
    size_t n = strlen(name);
    if (n > 4 && !strcasecmp(name + n - 4, ".png"))
        return 0;
    return cli_usage_error(cmd, "%s '%s': this output is a PNG, so its name must end in .png", opt, name);
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

/* Offers every option the help text names ("-o", "--size", ...) to sg, and
 * notes in *prefix the one that opt abbreviates if exactly one does. */
static void cli_offer_options(suggest *sg, const char *text, const char *opt, const char **prefix,
                              size_t *prefix_len)
{
    const char *p = text;
    size_t lo = strlen(opt);
    int nprefix = 0;
    while ((p = strchr(p, '-')) != NULL) {
        const char *q = p;
        size_t n;
        if (p > text && !strchr(" \t\n,[(|", p[-1])) {
            p++;
            continue;
        }
        q += p[1] == '-' ? 2 : 1;
        while ((*q >= 'a' && *q <= 'z') || (*q >= 'A' && *q <= 'Z') || (*q >= '0' && *q <= '9')
               || (*q == '-' && q[1] != '-' && q > p + 2))
            q++;
        n = (size_t)(q - p);
        if (n >= 2 && p[n - 1] != '-') {
            suggest_try(sg, p, n);
            if (lo > 2 && n > lo && !strncmp(p, opt, lo) && !(*prefix && *prefix_len == n
                                                              && !strncmp(*prefix, p, n))) {
                *prefix = p;
                *prefix_len = n;
                nprefix++;
            }
        }
        p = q;
    }
    if (nprefix != 1)
        *prefix = NULL;
}

int cli_unknown_option(const char *cmd, const char *opt, void (*help)(FILE *f))
{
    char *text = NULL, *near = NULL;
    size_t size = 0, near_len = 0;
    const char *prefix = NULL;
    FILE *f = help ? open_memstream(&text, &size) : NULL;
    suggest sg;
    suggest_init(&sg, opt);
    if (f) {
        help(f);
        if (fclose(f) == 0 && text) {
            size_t plen = 0;
            cli_offer_options(&sg, text, opt, &prefix, &plen);
            if (prefix) {
                near = (char *)prefix;
                near_len = plen;
            } else if (suggest_best(&sg)) {
                near = (char *)sg.best;
                near_len = sg.best_len;
            }
        }
    }
    if (near)
        cli_usage_error(cmd, "unknown option '%s' (did you mean %.*s?)", opt, (int)near_len, near);
    else
        cli_usage_error(cmd, "unknown option '%s'", opt);
    free(text);
    return CLI_USAGE;
}

/* The rewritten argv and the strings made for it (freed by
 * cli_conventions_free). */
static char **cli_argv, **cli_owned;
static int cli_nowned;

/* A new string of the first n bytes of a, prefixed by prefix, recorded in
 * cli_owned; NULL when out of memory. */
static char *cli_own(const char *prefix, const char *a, size_t n)
{
    size_t k = strlen(prefix);
    char *p = mem_alloc(k + n + 1);
    if (!p)
        return NULL;
    memcpy(p, prefix, k);
    memcpy(p + k, a, n);
    p[k + n] = '\0';
    cli_owned[cli_nowned++] = p;
    return p;
}

int cli_conventions(int *argc, char ***argv)
{
    int i, n = 0, ended = 0, version = 0;
    char **in = *argv;
    cli_argv = mem_calloc((size_t)*argc * 2 + 1, sizeof *cli_argv);
    cli_owned = mem_calloc((size_t)*argc + 1, sizeof *cli_owned);
    if (!cli_argv || !cli_owned) {
        cli_conventions_free();
        *argv = NULL;
        return 0;
    }
    for (i = 0; i < *argc; i++) {
        char *a = in[i], *eq;
        if (i == 0 || (ended && !(a[0] == '-' && a[1]))) {
            cli_argv[n++] = a;
        } else if (ended) {
            if (!(cli_argv[n++] = cli_own("./", a, strlen(a))))
                goto oom;
        } else if (!strcmp(a, "--")) {
            ended = 1;
        } else if (!strcmp(a, "--version")) {
            version = 1;
        } else if (a[0] == '-' && a[1] == '-' && a[2] && (eq = strchr(a, '=')) != NULL && eq > a + 2) {
            if (!(cli_argv[n++] = cli_own("", a, (size_t)(eq - a))))
                goto oom;
            cli_argv[n++] = eq + 1;
        } else {
            cli_argv[n++] = a;
        }
    }
    cli_argv[n] = NULL;
    *argc = n;
    *argv = cli_argv;
    return version;
oom:
    cli_conventions_free();
    *argv = NULL;
    return 0;
}

void cli_conventions_free(void)
{
    int i;
    for (i = 0; i < cli_nowned; i++)
        mem_free(cli_owned[i]);
    mem_free(cli_owned);
    mem_free(cli_argv);
    cli_owned = cli_argv = NULL;
    cli_nowned = 0;
}
