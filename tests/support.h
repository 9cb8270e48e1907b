/* support — helpers shared by the cmocka test binaries. */
#ifndef TEST_SUPPORT_H
#define TEST_SUPPORT_H
#include <stddef.h>
#include <stdint.h>

/* Seed for property tests: MAPRT_SEED from the environment, else a fixed
 * default; printed once so a failure can be replayed. */
uint64_t test_seed(const char *test_name);
/* xorshift64* generator; state must be non-zero. */
uint64_t test_rand(uint64_t *state);
/* Uniform double in [lo, hi). */
double test_uniform(uint64_t *state, double lo, double hi);
/* Reads a whole file into a new buffer (mem_free it); NULL on failure. */
char *test_read_file(const char *path, size_t *len);
/* Number of entries other than . and .. in directory path; -1 if it
 * cannot be opened. */
int test_dir_entries(const char *path);
/* 1 when long double arithmetic really carries 64 bits, as references
 * computed in it need: LDBL_MANT_DIG says so on x86-64, but valgrind runs
 * x87 code with 53. */
int test_long_double_ok(void);
#endif
