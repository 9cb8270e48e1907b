/* cli_idcheck — the oracle run and the comparison (see cli_idcheck.h). */
#include "cli/cli_idcheck.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#define IDCHECK_REC 36

/* A length scale of the scene: the largest reach of a bounded primitive's
 * placement (translation plus its size through the matrix). */
static double cli_idcheck_scale(const scene *sc)
{
    double s = 0;
    size_t i;
    int r, c;
    for (i = 0; i < sc->nprims; i++) {
        const scene_prim *p = &sc->prims[i];
        const double *d = p->shape->dim;
        double t = 0, a = 0, dm = fabs(d[0]);
        if (p->shape->kind == PRIM_HALFSPACE)
            continue;
        for (r = 1; r < 3; r++)
            if (fabs(d[r]) > dm)
                dm = fabs(d[r]);
        for (r = 0; r < 3; r++) {
            t += p->world_from_object[4 * r + 3] * p->world_from_object[4 * r + 3];
            for (c = 0; c < 3; c++)
                a += p->world_from_object[4 * r + c] * p->world_from_object[4 * r + c];
        }
        if (sqrt(t) + sqrt(a) * dm > s)
            s = sqrt(t) + sqrt(a) * dm;
    }
    return s > 0 ? s : 1;
}

static int cli_idcheck_write_input(FILE *f, const scene *sc, int w, int h)
{
    const scene_view *v = &sc->view;
    size_t i;
    int k;
    fprintf(f, "%d %d %.17g\n", w, h, cli_idcheck_scale(sc));
    fprintf(f, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", v->eye[0], v->eye[1],
            v->eye[2], v->look[0], v->look[1], v->look[2], v->up[0], v->up[1], v->up[2], v->fov_deg);
    fprintf(f, "%lu %lu %lu\n", (unsigned long)sc->nprims, (unsigned long)sc->nnodes,
            (unsigned long)sc->nroots);
    for (i = 0; i < sc->nprims; i++) {
        const scene_prim *p = &sc->prims[i];
        const scene_shape *sh = p->shape;
        fprintf(f, "%d %.17g %.17g %.17g", (int)sh->kind, sh->dim[0], sh->dim[1], sh->dim[2]);
        for (k = 0; k < 12; k++)
            fprintf(f, " %.17g", p->world_from_object[k]);
        fputc('\n', f);
    }
    for (i = 0; i < sc->nnodes; i++)
        fprintf(f, "%d %d %d %d\n", (int)sc->nodes[i].op, sc->nodes[i].left, sc->nodes[i].right,
                sc->nodes[i].prim);
    for (i = 0; i < sc->nroots; i++)
        fprintf(f, "%d\n", sc->roots[i]);
    return ferror(f) ? -1 : 0;
}

/* Runs path IN OUT without a shell; 0 when it exits with status 0. */
static int cli_idcheck_run(const char *path, const char *in, const char *out)
{
    pid_t pid = fork();
    int status;
    if (pid < 0)
        return -1;
    if (pid == 0) {
        char *argv[4];
        argv[0] = (char *)path;
        argv[1] = (char *)in;
        argv[2] = (char *)out;
        argv[3] = NULL;
        execv(path, argv);
        _exit(127);
    }
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

static int32_t cli_idcheck_i32(const unsigned char *b)
{
    return (int32_t)((uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24);
}

static double cli_idcheck_f64(const unsigned char *b)
{
    uint64_t bits = 0;
    double d;
    int j;
    for (j = 7; j >= 0; j--)
        bits = bits << 8 | b[j];
    memcpy(&d, &bits, sizeof d);
    return d;
}

int cli_idcheck_oracle(const char *oracle, const scene *sc, int w, int h, idmap *out, diag *err)
{
    char in[64], outp[64], *data = NULL;
    const char *tmpdir = getenv("TMPDIR");
    size_t len, i, n = (size_t)w * (size_t)h;
    void *cs = NULL, *tc = NULL;
    idmap m;
    FILE *f;
    int fd, st = 0;
    memset(&m, 0, sizeof m);
    if (!tmpdir || !*tmpdir || strlen(tmpdir) > 40)
        tmpdir = "/tmp";
    snprintf(in, sizeof in, "%s/maprt-ids-in-XXXXXX", tmpdir);
    snprintf(outp, sizeof outp, "%s/maprt-ids-out-XXXXXX", tmpdir);
    if ((fd = mkstemp(in)) < 0)
        return diag_at(err, DIAG_IO, "ids oracle", 0, 0, "cannot create a temporary file");
    if (!(f = fdopen(fd, "w"))) {
        close(fd);
        remove(in);
        return diag_at(err, DIAG_IO, "ids oracle", 0, 0, "cannot create a temporary file");
    }
    if (cli_idcheck_write_input(f, sc, w, h) | fclose(f)) {
        remove(in);
        return diag_at(err, DIAG_IO, "ids oracle", 0, 0, "cannot write the oracle's input");
    }
    if ((fd = mkstemp(outp)) < 0) {
        remove(in);
        return diag_at(err, DIAG_IO, "ids oracle", 0, 0, "cannot create a temporary file");
    }
    close(fd);
    if (cli_idcheck_run(oracle, in, outp)) {
        st = diag_at(err, DIAG_IO, oracle, 0, 0, "the REAL(16) oracle failed or is not installed");
        goto done;
    }
    if ((st = infile_read_all(outp, (size_t)IDCHECK_REC * n, &data, &len, err)))
        goto done;
    if (len != (size_t)IDCHECK_REC * n) {
        st = diag_offset(err, DIAG_IO, oracle, (long long)len, "the oracle wrote %lu bytes, not %lu",
                         (unsigned long)len, (unsigned long)(IDCHECK_REC * n));
        goto done;
    }
    if ((st = idmap_alloc(&m, w, h, err)) || (st = f64_render_ops.compile(sc, &cs, err)))
        goto done;
    if (f64_render_ops.thread_new(cs, &tc)) {
        st = diag_at(err, DIAG_IO, "ids oracle", 0, 0, "out of memory");
        goto done;
    }
    for (i = 0; i < n; i++) {
        const unsigned char *r = (const unsigned char *)data + IDCHECK_REC * i;
        idmap_px *p = &m.px[i];
        p->prim = cli_idcheck_i32(r);
        p->face = cli_idcheck_i32(r + 4);
        p->flags = cli_idcheck_i32(r + 8);
        p->t = cli_idcheck_f64(r + 12);
        if (p->prim >= (int32_t)sc->nprims) {
            st = diag_offset(err, DIAG_IO, oracle, (long long)(IDCHECK_REC * i), "primitive out of range");
            goto done;
        }
        if (p->prim >= 0)
            p->region = f64_render_ops.region(cs, tc, p->prim, p->face, cli_idcheck_f64(r + 20),
                                              cli_idcheck_f64(r + 28));
    }
    *out = m;
    m.px = NULL;
done:
    if (tc)
        f64_render_ops.thread_free(tc);
    if (cs)
        f64_render_ops.free(cs);
    idmap_free(&m);
    mem_free(data);
    remove(in);
    remove(outp);
    return st;
}

static int cli_idcheck_dcmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

void cli_idcheck_compare(const idmap *mode, const idmap *oracle, cli_idcheck_stats *st)
{
    size_t i, n = (size_t)mode->width * (size_t)mode->height;
    double *e = mem_calloc(n ? n : 1, sizeof *e);
    memset(st, 0, sizeof *st);
    st->pixels = (long)n;
    for (i = 0; i < n; i++) {
        const idmap_px *a = &mode->px[i], *b = &oracle->px[i];
        if (b->flags & IDMAP_AMBIGUOUS) {
            st->flagged++;
            continue;
        }
        st->compared++;
        if (a->prim != b->prim || (b->prim >= 0 && (a->face != b->face || a->region != b->region))) {
            st->mismatches++;
            continue;
        }
        if (a->prim >= 0 && e)
            e[st->hits++] = fabs(a->t - b->t);
    }
    if (st->hits && e) {
        qsort(e, (size_t)st->hits, sizeof *e, cli_idcheck_dcmp);
        st->err_median = e[st->hits / 2];
        st->err_max = e[st->hits - 1];
    }
    mem_free(e);
}
