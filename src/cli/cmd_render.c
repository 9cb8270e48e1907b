/* cmd_render — `maprt render`: scene deck -> compiled scene for one numeric
 * mode -> tiled render -> PNG (and, later, a DL5080 display list). */
#include "image/image_out.h"
#include "cli/cli.h"
#include "cli/cli_sink.h"
#include "cli/cli_mpi.h"
#include "cli/cli_data.h"
#include "cli/cli_progress.h"
#include "cli/cli_scene.h"
#include "util/cpubind.h"
#include "render/render.h"
#include "render/render_part.h"
#include "util/outfile.h"
#include "display5080/dl_format.h"
#include "display5080/dl_image.h"
#include "util/mem.h"
#include "util/version.h"
#include "util/outfile.h"
#include <omp.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <unistd.h>

#define MAPRT_SHARE_HINT "PREFIX/share/maprt/scenes"

static void cmd_render_help(FILE *f)
{
    fprintf(f,
        "usage: maprt render SCENE [-o OUT.png|OUT.ppm|OUT.pam|-] [--dl OUT.dl5080]\n"
        "                    [--ids OUT.ids] [--part OUT.part [--part-ids] [--region X0,Y0,X1,Y1]]\n"
        "                    [options]\n"
        "       maprt render --list\n"
        "\n"
        "Ray-traces the scene deck SCENE (see docs/scene-format.md) and writes a\n"
        "true-colour PNG and/or a DL5080 display list, as the IBM 5081 would show it.\n"
        "SCENE and every output may be a host path or a CMS fileid ('FIG1 SCENE A');\n"
        "SCENE may also name a scene shipped with maprt ('fig1'; see --list), found\n"
        "in $MAPRT_SCENES, " MAPRT_SHARE_HINT " or the source tree.\n"
        "Outputs are written to a temporary name and renamed when complete (all or\n"
        "none); each is checked before the trace: its directory must be writable,\n"
        "and it must not be SCENE, an image SCENE names, or another output.\n"
        "\n"
        "options:\n"
        "  -o, --output OUT      write the picture: OUT.png a true-colour PNG, OUT.ppm\n"
        "                        a binary PPM (P6), OUT.pam a PAM (P7); '-' standard\n"
        "                        output (with --format). Other names are refused.\n"
        "                        PNGs carry tEXt provenance (maprt version, deck and\n"
        "                        its SHA-256, numeric mode, size, aa, date); PPM/PAM\n"
        "                        the same as '#' comments\n"
        "  --format png|ppm|pam  the format for -o - (a file's name decides its own)\n"
        "  --part OUT.part       write the rendered pixels as a region file for 'maprt\n"
        "                        merge' (docs/cluster.md)\n"
        "  --part-ids            put the identity map (as --ids) into the region file,\n"
        "                        for 'maprt merge --ids'\n"
        "  --region X0,Y0,X1,Y1  render only pixels [X0,X1) x [Y0,Y1) (with --part), e.g.\n"
        "                        one job of a batch array\n"
        "  --dl OUT.dl5080       write a DL5080 display list: the frame quantised to at\n"
        "                        most 256 colours in the DAC's colour space\n"
        "  --ids OUT.ids         write the identity map of the primary rays: per pixel\n"
        "                        the primitive, face, region (attribute) and distance\n"
        "                        of the hit (format in docs/idmap.md)\n"
        "  --dac 4|8             bits per gun of the 5081 colour table (default 4)\n"
        "  --dither              Floyd-Steinberg dithering when quantising (--dl)\n"
        "  --wireframe           add the outlines of the primitives as seen (--dl)\n"
        "  --numeric MODE        arithmetic of the geometry: q16 (Q16.16 fixed point, the\n"
        "                        default), q32 (Q32.32), f32 or f64 (IEEE binary32/64),\n"
        "                        hfp32 or hfp64 (System/370 short/long hexadecimal)\n"
        "  --isa auto|baseline   the tracer's machine code: auto (default) takes the\n"
        "                        x86-64-v3 build (AVX2, BMI2, FMA) where the binary\n"
        "                        holds it and the processor runs it, baseline the\n"
        "                        other; the pictures are the same\n"
        "  --size WxH            image size in pixels, 1..%d each (default: the\n"
        "                        deck's SIZE; at most %d with --dl)\n"
        "  --threads N           threads for the render and the PNG encoder, 1..%d\n"
        "                        (default: OpenMP's count, %d here); as many as the\n"
        "                        CPUs the process may use are kept on one CPU each,\n"
        "                        unless OMP_PROC_BIND or OMP_PLACES places them\n"
        "  --aa N                N x N samples per pixel, 1..%d (default 1)\n"
        , SCENE_MAX_SIDE, DL_MAX_SIDE, RENDER_MAX_THREADS, omp_get_max_threads(), RENDER_MAX_AA);
    fprintf(f,
        "  --stats               print key=value lines to stdout: numeric isa rays.primary\n"
        "                        rays.shadow rays.reflected rays.refracted pds.lookups\n"
        "                        fx.overflows tests.prim tests.bound csg.pruned\n"
        "                        skipped.uv (hits whose face needs no (u,v): no PDS,\n"
        "                        texture or bump) skipped.shadow (shadow rays not\n"
        "                        traced: no diffuse or specular term) objects\n"
        "                        instances.moved instances.turned (the deck's\n"
        "                        objects, and those of them traced through an\n"
        "                        earlier copy's compiled tree, translated or\n"
        "                        turned; none where copies are too few to gain:\n"
        "                        docs/numerics.md, \"Instances\")\n"
        "                        time.compile_s time.render_s range.cut (and\n"
        "                        dl.colours dl.bytes dl.psnr with --dl; rays.capped\n"
        "                        when the cap of %d reflected and refracted rays per\n"
        "                        sample was reached); any overflow or range.cut is\n"
        "                        also reported on stderr\n"
        "%s"
        "  --list                list the shipped scenes and exit\n"
        "  -h, --help            show this help\n"
        "\n"
        "  --progress            show progress on stderr even when it is not a terminal\n"
        "  --quiet               show neither progress nor the closing summary\n"
        "\n"
        "On a terminal (or with --progress) stderr shows the share done, elapsed\n"
        "time, ETA and rays/s, the share weighted by each tile's cost as measured\n"
        "before the render so that it runs linearly in time, and one closing line:\n"
        "time (wall and CPU), rays/s and the outputs written. Under 'mpirun -n N\n"
        "maprt-mpi render' the ranks share the image and rank 0 writes the outputs\n"
        "(--stats adds mpi.ranks and each rank's share).\n"
        "exit status: 0 ok, 1 bad scene, 2 usage, 3 I/O or internal failure\n",
        RENDER_MAX_RAYS_PER_SAMPLE, cli_files_help);
}


/* The closing line: what was rendered, the time it took, the rate, and
 * the outputs written. */
static void cmd_render_summary(const char *deck, const render_opts *o, const render_fb *fb,
                           const render_ops *ops, const render_stats *st, clock_t cpu0,
                           const char *png, const char *dl)
{
    char wall[24], cpu[24], rate[32];
    double secs = st->time_compile_s + st->time_render_s;
    unsigned long long rays = st->rays_primary + st->rays_shadow + st->rays_reflected + st->rays_refracted;
    cli_progress_time(secs, wall, sizeof wall);
    cli_progress_time((double)(clock() - cpu0) / CLOCKS_PER_SEC, cpu, sizeof cpu);
    cli_progress_rate(st->time_render_s > 0 ? (double)rays / st->time_render_s : 0, rate, sizeof rate);
    fprintf(stderr, "maprt: %s: %dx%d, aa %d, %s: %s (CPU %s), %.3g Mrays, %s; wrote %s%s%s\n", deck,
            fb->img.width, fb->img.height, o->aa, ops->name, wall, cpu, (double)rays / 1e6, rate,
            png ? (strcmp(png, "-") ? png : "standard output") : "", png && dl ? ", " : "", dl ? dl : "");
}

/* Writes the rendered region (the whole image without --region) as a
 * region file for 'maprt merge'. */
static int cmd_render_write_part(const char *path, const render_fb *fb, const render_opts *o,
                             int ids, const render_ops *ops, const render_stats *st, diag *err)
{
    render_part_info info;
    uint8_t *buf;
    size_t len;
    int rc;
    memset(&info, 0, sizeof info);
    info.width = fb->img.width;
    info.height = fb->img.height;
    memcpy(info.region, o->region, sizeof info.region);
    if (!info.region[2]) {
        info.region[2] = info.width;
        info.region[3] = info.height;
    }
    info.aa = o->aa;
    info.ids = ids;
    strncpy(info.mode, ops->name, sizeof info.mode - 1);
    info.stats = *st;
    if ((rc = render_part_encode(fb, &info, &buf, &len, err)) != 0)
        return rc;
    rc = outfile_write_all(path, buf, len, err);
    mem_free(buf);
    return rc;
}

int cmd_render(int argc, char **argv)
{
    const char *scene_name = NULL, *out_png = NULL, *out_dl = NULL, *out_part = NULL;
    char deck_sum[65] = "";
    const char *out_ids = NULL, *mode = "q16", *v;
    const char *format = NULL;
    image_out_format pic_format = IMAGE_OUT_NONE;
    char *png_path = NULL, *dl_path = NULL, *part_path = NULL, *ids_path = NULL, *shipped = NULL;
    const char *outs[4];
    cli_mpi_share share[CLI_MPI_MAX_RANKS];
    const render_ops *ops = NULL;
    render_isa isa = RENDER_ISA_AUTO;
    render_opts o;
    render_stats st;
    render_fb fb;
    dl_image_opts dlo;
    dl_image_stats dls;
    cli_files files;
    scene *sc = NULL;
    diag err;
    long n;
    int i, stats = 0, wireframe = 0, status = 0, rendered = 0, quiet = 0, root_status = 0;
    int progress = -1, part_ids = 0;
    cli_progress bar;
    clock_t cpu0 = clock();

    if (cli_wants_help(argc, argv)) {
        cmd_render_help(stdout);
        return CLI_OK;
    }
    for (i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--list"))
            return cli_data_list(stdout);
    diag_init(&err);
    if (cli_files_init(&files, &err)) {
        diag_print(stderr, &err);
        cli_files_free(&files);
        return CLI_USAGE;
    }
    memset(&o, 0, sizeof o);
    memset(&dlo, 0, sizeof dlo);
    o.threads = omp_get_max_threads();
    if (o.threads > RENDER_MAX_THREADS)
        o.threads = RENDER_MAX_THREADS;
    o.aa = 1;
    dlo.dac = 4;
    for (i = 1; i < argc && !status; i++) {
        const char *a = argv[i];
        if (cli_files_option(&files, "render", argc, argv, &i, &status))
            continue;
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (!(out_png = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--format")) {
            if (!(format = cli_value("render", argc, argv, &i)))
                status = CLI_USAGE;
            else if (!image_out_parse(format))
                status = cli_usage_error("render", "--format: '%s' is not png, ppm or pam", format);
        } else if (!strcmp(a, "--dl")) {
            if (!(out_dl = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--part")) {
            if (!(out_part = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--part-ids")) {
            part_ids = 1;
        } else if (!strcmp(a, "--region")) {
            if (!(v = cli_value("render", argc, argv, &i)) || cli_region("render", a, v, SCENE_MAX_SIDE, o.region))
                status = CLI_USAGE;
        } else if (!strcmp(a, "--ids")) {
            if (!(out_ids = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (cli_sink_dl_option("render", argc, argv, &i, &dlo, &wireframe, &status)) {
            continue;
        } else if (!strcmp(a, "--numeric")) {
            if (!(mode = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--isa")) {
            if (!(v = cli_value("render", argc, argv, &i)))
                status = CLI_USAGE;
            else if (!strcasecmp(v, "auto"))
                isa = RENDER_ISA_AUTO;
            else if (!strcasecmp(v, "baseline"))
                isa = RENDER_ISA_BASELINE;
            else
                status = cli_usage_error("render", "--isa: '%s' is not auto or baseline", v);
        } else if (!strcmp(a, "--size")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_size("render", a, v, SCENE_MAX_SIDE, &o.width, &o.height))
                status = CLI_USAGE;
        } else if (!strcmp(a, "--threads")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_long("render", a, v, 1, RENDER_MAX_THREADS, &n))
                status = CLI_USAGE;
            else
                o.threads = (int)n;
        } else if (!strcmp(a, "--aa")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_long("render", a, v, 1, RENDER_MAX_AA, &n))
                status = CLI_USAGE;
            else
                o.aa = (int)n;
        } else if (!strcmp(a, "--stats")) {
            stats = 1;
        } else if (!strcmp(a, "--progress") || !strcmp(a, "--quiet")) {
            progress = a[2] == 'p';
        } else if (a[0] == '-' && a[1]) {
            status = cli_unknown_option("render", a, cmd_render_help);
        } else if (scene_name) {
            status = cli_usage_error("render", "more than one SCENE ('%s', '%s')", scene_name, a);
        } else {
            scene_name = a;
        }
    }
    if (!status && !scene_name)
        status = cli_usage_error("render", "no SCENE given");
    if (!status && !out_png && !out_dl && !out_part && !out_ids)
        status = cli_usage_error("render", "no output: give -o OUT.png, --dl OUT.dl5080, --ids "
                                 "OUT.ids or --part OUT.part");
    if (!status && o.region[2] && (out_png || out_dl || out_ids))
        status = cli_usage_error("render", "--region renders part of the image: write it with "
                                 "--part and assemble the parts with 'maprt merge'");
    if (!status && part_ids && !out_part)
        status = cli_usage_error("render", "--part-ids needs --part");
    if (!status && format && !out_png)
        status = cli_usage_error("render", "--format applies to -o");
    if (!status && out_png && !strcmp(out_png, "-") && stats)
        status = cli_usage_error("render", "--stats writes to standard output, so it cannot go with -o -");
    if (!status && out_png && !strcmp(out_png, "-") && isatty(1))
        status = cli_usage_error("render", "-o -: standard output is a terminal; redirect it to a file or a pipe");
    if (!status && !(ops = render_ops_find(mode, isa)))
        status = cli_usage_error("render", "--numeric: '%s' is not q16, q32, f32, f64, hfp32 or hfp64", mode);
    if (!status && !out_dl && (dlo.dither || wireframe || dlo.dac != 4))
        status = cli_usage_error("render", "--dac, --dither and --wireframe need --dl");
    if (status) {
        cli_files_free(&files);
        return status;
    }
    /* every parallel region after the render too (the PNG encoder) */
    omp_set_num_threads(o.threads);
    cpubind_threads(o.threads);

    /* Resolve and check every name before the long work: a bad fileid, a
     * missing or read-only directory, two outputs on one file or an output
     * that is an input (the deck or an image it names) fails fast. */
    if (cli_data_scene(scene_name, &shipped))
        scene_name = shipped;
    if ((out_png && strcmp(out_png, "-") && cli_output_path(&files, out_png, &png_path, &err))
        || (out_png && image_out_choose(png_path ? png_path : "-", format ? image_out_parse(format)
                                                                          : IMAGE_OUT_NONE,
                                        &pic_format, &err))
        || (out_dl && cli_output_path(&files, out_dl, &dl_path, &err))
        || (out_part && cli_output_path(&files, out_part, &part_path, &err))
        || (out_ids && cli_output_path(&files, out_ids, &ids_path, &err))
        || (outs[0] = png_path, outs[1] = dl_path, outs[2] = part_path, outs[3] = ids_path,
            outfile_check_set(outs, 4, &err))
        || cli_scene_load_sum(&files, scene_name, &sc, deck_sum, &err) || outfile_check_set(outs, 4, &err)) {
        cli_mpi_agree(err.status, &root_status);
        quiet = cli_mpi_rank() != 0 && root_status;   /* rank 0 says it */
        goto done;
    }
    /* Under mpirun every rank has read the deck; all go on, or none. */
    if (cli_mpi_agree(0, NULL)) {
        diag_at(&err, DIAG_INPUT, scene_name, 0, 0, "another MPI rank could not read the deck");
        quiet = cli_mpi_rank() != 0;
        goto done;
    }
    if (out_dl && ((o.width ? o.width : sc->view.width) > DL_MAX_SIDE
                   || (o.height ? o.height : sc->view.height) > DL_MAX_SIDE)) {
        diag_at(&err, DIAG_USAGE, out_dl, 0, 0, "a display list holds at most %dx%d pixels",
                DL_MAX_SIDE, DL_MAX_SIDE);
        goto done;
    }
    if (progress < 0)
        progress = cli_is_tty();
    if (progress && cli_mpi_rank() == 0) {
        cli_progress_init(&bar);
        o.progress = cli_progress_update;
        o.progress_ctx = &bar;
    }
    o.ids = out_ids || part_ids;
    o.skip_pid = !dl_path && !part_path;   /* only those two read PIDs */
    if (cli_mpi_render(sc, ops, &o, &fb, &st, share, &err)) {
        quiet = cli_mpi_rank() != 0;  /* the ranks agreed; rank 0 says why */
        goto done;
    }
    rendered = 1;
    if (cli_mpi_rank() != 0)
        goto done;                    /* rank 0 writes and reports */
    /* a precision event is never silent, --stats or not */
    if (st.fx_overflows || st.range_cut)
        fprintf(stderr, "maprt: %s: warning: %s: %llu fixed-point overflows, %llu primary rays "
                        "beyond the mode's range shown as background (docs/numerics.md); %s\n",
                scene_name, ops->name, st.fx_overflows, st.range_cut,
                strcmp(ops->name, "q16") ? "the picture may be wrong there"
                                         : "try --numeric q32 or f64");
    /* every output or none */
    outfile_batch_begin();
    {
        image_meta meta;
        if (out_png)
            cli_sink_provenance(scene_name, deck_sum, ops->name, o.aa, &fb, &meta);
        if ((part_path && cmd_render_write_part(part_path, &fb, &o, part_ids, ops, &st, &err))
            || (out_png && image_out_write(png_path ? png_path : "-", pic_format, &fb.img, &meta, &err))
            || (dl_path && cli_sink_dl(dl_path, &fb, &dlo, wireframe, &dls, &err))
            || (ids_path && idmap_write(ids_path, &fb.ids, &err))
            || outfile_batch_commit(&err)) {
            outfile_batch_abort();
            goto done;
        }
    }
    if (progress)
        cmd_render_summary(scene_name, &o, &fb, ops, &st, cpu0, out_png, out_dl);
    if (stats) {
        printf("numeric=%s\nisa=%s\n", ops->name, ops->isa);
        render_stats_print(stdout, &st);
        if (cli_mpi_size() > 1)
            cli_mpi_print_shares(stdout, share, cli_mpi_size());
        if (dl_path)
            printf("dl.colours=%d\ndl.bytes=%lu\ndl.psnr=%.2f\n", dls.colours,
                   (unsigned long)dls.bytes, dls.psnr);
    }
done:
    if (rendered)
        render_fb_free(&fb);
    scene_free(sc);
    mem_free(png_path);
    mem_free(dl_path);
    mem_free(part_path);
    mem_free(ids_path);
    mem_free(shipped);
    cli_files_free(&files);
    if (err.status) {
        if (!quiet)
            diag_print(stderr, &err);
        return err.status;
    }
    return CLI_OK;
}
