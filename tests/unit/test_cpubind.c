/* test_cpubind — the threads of an OpenMP team kept on one CPU each
 * (src/util/cpubind). */
#define _GNU_SOURCE 1         /* sched_getaffinity, cpu_set_t */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "util/cpubind.h"
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#if defined(__linux__)
#include <sched.h>
#endif

#if defined(__linux__)
/* Where the process may run on n >= 2 CPUs: a team of n threads is kept
 * on them in order, one each, and the answer is 0 (nothing changed) for
 * one thread, for a count that is not the CPUs', where the environment
 * chooses OpenMP's placement, and where the team would be smaller. Every
 * thread's mask is put back at the end. */
static void test_cpubind_one_cpu_each(void **state)
{
    cpu_set_t all, mine;
    int cpu[CPU_SETSIZE], n = 0, c, wrong = 0, inner = -1, kept = -1;
    (void)state;
    unsetenv("OMP_PROC_BIND");
    unsetenv("OMP_PLACES");
    unsetenv("GOMP_CPU_AFFINITY");
    assert_int_equal(sched_getaffinity(0, sizeof all, &all), 0);
    for (c = 0; c < CPU_SETSIZE; c++)
        if (CPU_ISSET(c, &all))
            cpu[n++] = c;
    assert_int_equal(cpubind_threads(1), 0);
    assert_int_equal(cpubind_threads(n + 1), 0);
    if (n < 2) {
        print_message("# one CPU here: nothing to keep apart\n");
        return;
    }
    assert_int_equal(setenv("OMP_PROC_BIND", "close", 1), 0);
    assert_int_equal(cpubind_threads(n), 0);
    unsetenv("OMP_PROC_BIND");
    /* inside an active region the team is of one thread: none is kept */
    omp_set_max_active_levels(1);
#pragma omp parallel num_threads(2)
#pragma omp single
    {
        inner = cpubind_threads(n);
        kept = sched_getaffinity(0, sizeof mine, &mine) || !CPU_EQUAL(&mine, &all);
    }
    assert_int_equal(inner, 0);
    assert_int_equal(kept, 0);
    assert_int_equal(cpubind_threads(n), 1);
#pragma omp parallel num_threads(n) reduction(+ : wrong)
    {
        cpu_set_t mine;
        int me = omp_get_thread_num();
        wrong += sched_getaffinity(0, sizeof mine, &mine) || CPU_COUNT(&mine) != 1 || !CPU_ISSET(cpu[me], &mine);
    }
    print_message("# %d threads on %d CPUs, %d not on their own\n", n, n, wrong);
    assert_int_equal(wrong, 0);
#pragma omp parallel num_threads(n)
    (void)sched_setaffinity(0, sizeof all, &all);
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
#if defined(__linux__)
        cmocka_unit_test(test_cpubind_one_cpu_each),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
