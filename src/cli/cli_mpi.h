/* cli_mpi — maprt across the ranks of an MPI job (Open MPI), in maprt-mpi
 * (mk/mpi.mk: MAPRT_MPI). Under `mpirun -n N build/maprt-mpi render ...`
 * every rank reads the deck and compiles the scene; rank 0 hands out bands of
 * tile rows, renders bands itself, gathers the others' bands (as render_part
 * encodings, with the identity map when asked) and writes the outputs,
 * which are exactly the bytes a single process writes. `bench` hands out
 * its (scene, mode) cells through the same farm. Without MPI, or when the
 * program was not started by an MPI launcher, everything here is a
 * single-rank no-op; maprt built without MPI refuses to start as one of
 * several ranks. */
#ifndef CLI_MPI_H
#define CLI_MPI_H
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "render/render.h"
#include "util/diag.h"

#define CLI_MPI_MAX_RANKS 4096

/* What one rank contributed to a distributed render. */
typedef struct cli_mpi_share {
    long bands;                   /* bands of tile rows it rendered */
    unsigned long long rays;      /* all its rays */
} cli_mpi_share;

/* Starts MPI when the process was launched by mpirun (Open MPI or PMIx
 * environment); call first thing in main. 0, or -1 when MPI failed to start
 * or this build has no MPI and is one of several ranks (a message is
 * printed). */
int cli_mpi_start(int *argc, char ***argv);
/* Ends MPI (if started); call before returning from main. */
void cli_mpi_stop(void);
/* This process's rank and the number of ranks (0 and 1 without MPI). */
int cli_mpi_rank(void);
int cli_mpi_size(void);
/* Ends the whole job after a failure on this rank: prints d (with the rank)
 * and aborts every rank with `status` as the exit code. Single rank: no-op. */
void cli_mpi_fail(const diag *d, int status);

/* Collective: every rank passes its own status and gets the largest, so
 * that all ranks stop together when any of them failed (e.g. to read the
 * deck); *root (may be NULL) receives rank 0's own status, so that a failure
 * every rank shares is reported once, by rank 0. Single rank: status. */
int cli_mpi_agree(int status, int *root);

/* A job cut into cells 0..cells-1 that ranks run in any order and rank 0
 * takes in any order: rank 0 hands them out on demand, two in flight per
 * rank, and runs cells itself one at a time on a second thread while its
 * main thread keeps answering. run (on the rank the cell went to; on rank 0
 * on that thread, so it must not call MPI) returns its result as bytes
 * (*out, mem_alloc'd, may be NULL when *len is 0); take (on rank 0's main
 * thread) receives them with the rank that ran it. */
typedef struct cli_mpi_farm {
    int cells;
    int (*run)(void *ctx, int cell, uint8_t **out, size_t *len, diag *err);
    int (*take)(void *ctx, int cell, int rank, const uint8_t *buf, size_t len, diag *err);
    void *ctx;
} cli_mpi_farm;

/* Runs the farm on every rank (collective). A cell that fails (run or take)
 * stops the handing out; the cells in flight are still received (and taken
 * when they succeeded) and rank 0 returns the first failure's status, with
 * its diag (and the rank that failed, when not 0) in *err; the other ranks
 * return 0. With one rank the cells run in order, each taken as it is done,
 * up to the first failure. */
int cli_mpi_farm_run(const cli_mpi_farm *f, diag *err);

/* Renders sc like render_scene, with the bands spread over the ranks. On rank
 * 0 *fb and *st receive the whole frame and the counters summed over ranks
 * (time.render_s is the job's wall time) and share[r] (for r < size, when
 * share is not NULL) what rank r did; on other ranks *fb is left empty
 * (width 0) and *st holds that rank's own counters. With one rank it is
 * render_scene. 0 or the diag status (the same on every rank for problems
 * every rank finds, such as an option out of range). */
int cli_mpi_render(const scene *sc, const render_ops *ops, const render_opts *o, render_fb *fb,
                   render_stats *st, cli_mpi_share *share, diag *err);
/* Prints mpi.ranks=N and each rank's share as --stats lines. */
void cli_mpi_print_shares(FILE *f, const cli_mpi_share *share, int n);
#endif
