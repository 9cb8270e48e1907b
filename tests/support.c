/* support — helpers shared by the cmocka test binaries (see support.h). */
#include "support.h"
#include "util/mem.h"
#include <dirent.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint64_t test_seed(const char *test_name)
{
    const char *env = getenv("MAPRT_SEED");
    uint64_t seed = env ? strtoull(env, NULL, 0) : 0x9E3779B97F4A7C15ull;
    if (seed == 0)
        seed = 1;
    printf("# %s: seed %llu (set MAPRT_SEED to replay)\n", test_name, (unsigned long long)seed);
    return seed;
}

uint64_t test_rand(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 2685821657736338717ull;
}

double test_uniform(uint64_t *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(test_rand(s) >> 11) / 9007199254740992.0;
}

char *test_read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    long n;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        buf = mem_alloc((size_t)n + 1);
        if (buf && fread(buf, 1, (size_t)n, f) == (size_t)n) {
            buf[n] = '\0';
            *len = (size_t)n;
        } else {
            mem_free(buf);
            buf = NULL;
        }
    }
    fclose(f);
    return buf;
}

int test_dir_entries(const char *path)
{
    DIR *d = opendir(path);
    struct dirent *e;
    int n = 0;
    if (!d)
        return -1;
    while ((e = readdir(d)))
        n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    closedir(d);
    return n;
}

int test_long_double_ok(void)
{
    volatile long double one = 1.0L, tiny = ldexpl(1.0L, -63);
    return LDBL_MANT_DIG >= 64 && one + tiny != one;
}
