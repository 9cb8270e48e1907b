/* rsqrt_bound — fx_rsqrt_q30 against 2^46/sqrt(xs) in long double for every
 * one of its 3 * 2^30 inputs; prints the least and greatest error in units
 * of 2^-30 and fails when either lies beyond the 1.35 units fx.h states
 * (docs/numerics.md). `make check-rsqrt` builds and runs it: a few seconds
 * of two cores, too long for the unit tests, which sample the inputs. */
#include "num/fx.h"
#include <math.h>
#include <stdio.h>

int main(void)
{
    double lo = 0, hi = 0;
    long long i;
#if defined(_OPENMP)
#pragma omp parallel for reduction(min : lo) reduction(max : hi)
#endif
    for (i = 0; i < 3LL << 30; i++) {
        uint64_t xs = ((uint64_t)1 << 30) + (uint64_t)i;
        double e = (double)((long double)fx_rsqrt_q30(xs) - 70368744177664.0L / sqrtl((long double)xs));
        if (e < lo)
            lo = e;
        if (e > hi)
            hi = e;
    }
    printf("fx_rsqrt_q30 - 2^46/sqrt(xs), every xs in [2^30, 2^32): [%.4f, %.4f] units of 2^-30\n", lo, hi);
    return lo > -1.35 && hi < 1.35 ? 0 : 1;
}
