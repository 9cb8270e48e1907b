/* cli_data — the shipped scenes (see cli_data.h). */
#include "cli/cli_data.h"
#include "cli/cli.h"
#include "util/mem.h"
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef MAPRT_DATADIR
#define MAPRT_DATADIR "/usr/local/share/maprt"
#endif
#ifndef MAPRT_SRCDIR
#define MAPRT_SRCDIR "."
#endif

/* The search directories, in order, into dirs (pointers into env or
 * static strings); returns their count. */
static int cli_data_dirs(char *env, const char **dirs, int cap)
{
    int n = 0;
    char *p = env, *save = NULL, *tok;
    for (tok = p ? strtok_r(p, ":", &save) : NULL; tok && n < cap - 2; tok = strtok_r(NULL, ":", &save))
        if (*tok)
            dirs[n++] = tok;
    dirs[n++] = MAPRT_DATADIR "/scenes";
    dirs[n++] = MAPRT_SRCDIR "/scenes";
    return n;
}

/* A plain scene name: letters, digits, '-' and '_' (plus ".scene"). */
static int cli_data_plain(const char *name, size_t *len)
{
    size_t i, n = strlen(name);
    if (n > 6 && !strcmp(name + n - 6, ".scene"))
        n -= 6;
    if (n == 0 || n > 64)
        return 0;
    for (i = 0; i < n; i++) {
        char c = name[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'))
            return 0;
    }
    *len = n;
    return 1;
}

int cli_data_scene(const char *name, char **path)
{
    const char *dirs[16];
    char *env = getenv("MAPRT_SCENES") ? mem_strdup(getenv("MAPRT_SCENES")) : NULL;
    size_t n;
    int i, nd, found = 0;
    if (!cli_data_plain(name, &n) || access(name, F_OK) == 0) {
        mem_free(env);
        return 0;
    }
    nd = cli_data_dirs(env, dirs, 16);
    for (i = 0; i < nd && !found; i++) {
        size_t k = strlen(dirs[i]) + n + 8;
        char *p = mem_alloc(k);
        if (!p)
            break;
        snprintf(p, k, "%s/%.*s.scene", dirs[i], (int)n, name);
        if (access(p, R_OK) == 0) {
            *path = p;
            found = 1;
        } else {
            mem_free(p);
        }
    }
    mem_free(env);
    return found;
}

int cli_data_list(FILE *f)
{
    const char *dirs[16];
    char *env = getenv("MAPRT_SCENES") ? mem_strdup(getenv("MAPRT_SCENES")) : NULL;
    int i, nd = cli_data_dirs(env, dirs, 16), listed = 0;
    for (i = 0; i < nd; i++) {
        DIR *d = opendir(dirs[i]);
        struct dirent *e;
        char seen[64][65];
        int ns = 0, j, k;
        if (!d)
            continue;
        while ((e = readdir(d)) != NULL && ns < 64) {
            size_t n;
            if (cli_data_plain(e->d_name, &n) && strlen(e->d_name) == n + 6)
                snprintf(seen[ns++], sizeof seen[0], "%.*s", (int)n, e->d_name);
        }
        closedir(d);
        if (!ns)
            continue;
        /* sorted, for a stable listing */
        for (j = 1; j < ns; j++)
            for (k = j; k > 0 && strcmp(seen[k - 1], seen[k]) > 0; k--) {
                char t[65];
                memcpy(t, seen[k], sizeof t);
                memcpy(seen[k], seen[k - 1], sizeof t);
                memcpy(seen[k - 1], t, sizeof t);
            }
        fprintf(f, "scenes in %s:\n", dirs[i]);
        for (j = 0; j < ns; j++) {
            char path[4200], line[128] = "";
            FILE *in;
            snprintf(path, sizeof path, "%s/%s.scene", dirs[i], seen[j]);
            if ((in = fopen(path, "r")) != NULL) {
                if (fgets(line, sizeof line, in) && line[0] == '*') {
                    char *t = line + 1, *end;
                    line[72 < sizeof line ? 72 : sizeof line - 1] = '\0';
                    while (*t == ' ')
                        t++;
                    /* the title: what follows "NAME SCENE:" up to the card's end */
                    if ((end = strstr(t, "SCENE: ")) != NULL)
                        t = end + 7;
                    if ((end = strstr(t, ". ")) != NULL)   /* its first sentence */
                        end[1] = '\0';
                    for (end = t + strlen(t); end > t && (end[-1] == ' ' || end[-1] == '\n'); end--)
                        ;
                    *end = '\0';
                    memmove(line, t, strlen(t) + 1);
                } else {
                    line[0] = '\0';
                }
                fclose(in);
            }
            fprintf(f, "  %-14s %s\n", seen[j], line);
        }
        listed++;
    }
    mem_free(env);
    if (!listed)
        fprintf(f, "no scenes found (looked in $MAPRT_SCENES, %s/scenes, %s/scenes)\n", MAPRT_DATADIR, MAPRT_SRCDIR);
    return ferror(f) ? CLI_IO : 0;
}
