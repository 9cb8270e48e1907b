/* cli_idcheck — a render's identity map against the REAL(16) oracle's
 * (tests/oracle/ids_oracle.f90): writing the oracle's input from the scene
 * model, running it without a shell, reading its answer (regions by the
 * f64 PDS lookup at the oracle's (u,v)), and the comparison figures that
 * `maprt bench` and the tests report. See docs/idmap.md. */
#ifndef CLI_IDCHECK_H
#define CLI_IDCHECK_H
#include "render/render.h"

typedef struct cli_idcheck_stats {
    long pixels, flagged, compared;  /* compared = pixels - flagged */
    long mismatches;                 /* primitive, face or region differ */
    long hits;                       /* compared pixels both hit, same face */
    double err_median, err_max;      /* |t - t_oracle| over those, deck units */
} cli_idcheck_stats;

/* Traces sc's primary rays at w x h with the oracle executable at path
 * `oracle` into *out (idmap_free it). The oracle is run directly (execv),
 * its files are unpredictable temporary names, removed afterwards.
 * 0, DIAG_INPUT for a scene the oracle cannot take, DIAG_IO when it fails. */
int cli_idcheck_oracle(const char *oracle, const scene *sc, int w, int h, idmap *out, diag *err);

/* Compares a mode's map with the oracle's: pixels the oracle flags are
 * not counted. */
void cli_idcheck_compare(const idmap *mode, const idmap *oracle, cli_idcheck_stats *st);
#endif
