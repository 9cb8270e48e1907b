/* pds_curve — closed curves of the PDS definitions, in double precision:
 * flattening of uniform cubic closed B-splines to polylines, and the
 * simplicity test shared by CPG polygons and curve-bounded regions.
 * Used by pds_def_check (validation) and by the per-mode compilers, which
 * round the flattened polyline into their number type. */
#ifndef PDS_CURVE_H
#define PDS_CURVE_H
#include <stddef.h>

/* Flattens the closed uniform cubic B-spline with control points ctl[2*n]
 * (u,v pairs, n >= 3) so that the polyline deviates from the curve by at most
 * `tol`: segment i (control points i-1..i+2, indices mod n) is sampled at k
 * equal parameter steps with k = ceil(sqrt(M / (8 tol))), M the larger norm
 * of its two second differences (the bound |C''| <= M gives a chord error of
 * at most M/(8 k^2)); k is clamped to 1..max_per_seg. On success *out (mem_*
 * owned, caller frees) holds *nout points and 0 is returned; -1: the result
 * would exceed max_total points; -2: out of memory. */
int pds_curve_flatten(const double *ctl, size_t n, double tol, size_t max_per_seg,
                      size_t max_total, double **out, size_t *nout);

/* Checks that the closed polyline pts[2*n] is simple: no two non-adjacent
 * edges touch and no two adjacent edges overlap. Returns 1 if simple, 0 if
 * not (then *ea < *eb are two offending edge indices; edge i runs from
 * vertex i to vertex i+1 mod n), -2 if out of memory, -3 if it would need
 * more than PDS_CURVE_PAIR_BUDGET edge-pair tests. Sweep over edges sorted
 * by their smallest u, so typical curves cost O(n log n); the budget bounds
 * the time taken by contrived ones (e.g. combs whose edges all span the
 * same u range). */
#define PDS_CURVE_PAIR_BUDGET 10000000UL
int pds_curve_simple(const double *pts, size_t n, size_t *ea, size_t *eb);

/* Twice the signed area of the closed polyline (positive: counter-clockwise). */
double pds_curve_area2(const double *pts, size_t n);
#endif
