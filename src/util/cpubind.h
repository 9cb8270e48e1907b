/* cpubind — the threads of a process's OpenMP regions kept on one CPU each.
 *
 * OpenMP's default wait policy has an idle thread spin for some
 * milliseconds before it sleeps: at the end of a region, and in the pool
 * while the initial thread goes on alone. Where the scheduler has put that
 * thread on the CPU of a thread with work, the two share the CPU in time
 * slices of some milliseconds, and the one with work waits: small renders
 * on two threads took twice as long as with threads that sleep
 * (docs/performance.md, run AJ). Kept apart, a spinning thread takes no
 * time from another. */
#ifndef UTIL_CPUBIND_H
#define UTIL_CPUBIND_H

/* Where the process may run on exactly nthreads (>= 2) CPUs and neither
 * OMP_PROC_BIND, OMP_PLACES nor GOMP_CPU_AFFINITY chooses a placement,
 * starts the team whose first nthreads threads later regions of that size
 * reuse, and keeps its thread k (0: the calling one) on the k-th of those
 * CPUs for the rest of the process: 1. Else changes nothing: 0 (every
 * system but Linux). The team is started one thread larger, so that its
 * start does not wait on a spinning thread (cpubind.c says why). */
int cpubind_threads(int nthreads);
#endif
