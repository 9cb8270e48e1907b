/* cpubind — one CPU per thread of a process's OpenMP team (see cpubind.h). */
#define _GNU_SOURCE 1         /* sched_getaffinity, cpu_set_t */
#include "util/cpubind.h"
#include <omp.h>
#include <stdlib.h>
#if defined(__linux__)
#include <sched.h>
#endif

int cpubind_threads(int nthreads)
{
#if defined(__linux__)
    cpu_set_t set;
    int cpu[CPU_SETSIZE], n = 0, c, pinned = 0;
    if (nthreads < 2 || getenv("OMP_PROC_BIND") || getenv("OMP_PLACES") || getenv("GOMP_CPU_AFFINITY")
        || sched_getaffinity(0, sizeof set, &set))
        return 0;
    for (c = 0; c < CPU_SETSIZE; c++)
        if (CPU_ISSET(c, &set))
            cpu[n++] = c;
    if (n != nthreads)
        return 0;
    /* One thread more than the CPUs. A new thread starts on the CPU of
     * the one that creates it, and that one waits for it at libgomp's dock:
     * spinning 300,000 times, the new thread queued behind it for a
     * scheduler tick; with more threads than CPUs it spins 100 times and
     * sleeps (libgomp manual, GOMP_SPINCOUNT). The extra thread ends when
     * the next region, of nthreads, starts. A smaller team (OMP_DYNAMIC,
     * OMP_THREAD_LIMIT) keeps none: a later region's threads, pinned or
     * not, would not match. */
#pragma omp parallel num_threads(nthreads + 1) reduction(+ : pinned)
    {
        cpu_set_t one;
        int me = omp_get_thread_num();
        if (me < nthreads && omp_get_num_threads() >= nthreads) {
            CPU_ZERO(&one);
            CPU_SET(cpu[me], &one);
            pinned += !sched_setaffinity(0, sizeof one, &one);
        }
    }
    return pinned == nthreads;
#else
    (void)nthreads;
    return 0;
#endif
}
