/* cmd_merge — `maprt merge PART... -o OUT.png [--dl OUT.dl5080] [--ids OUT.ids]`: assembles
 * the region files of `render --region X0,Y0,X1,Y1 --part FILE` (one per job
 * of a batch array, docs/cluster.md) into the whole frame and writes the
 * outputs a single `maprt render` would have written, byte for byte. */
#include "cli/cli.h"
#include "cli/cli_sink.h"
#include "cli/cli_scene.h"
#include "image/image_out.h"
#include "image/image_png.h"
#include "render/render_part.h"
#include "util/cpubind.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <omp.h>
#include <string.h>

static void cmd_merge_help(FILE *f)
{
    fprintf(f,
        "usage: maprt merge PART... [-o OUT.png|OUT.ppm|OUT.pam] [--deck SCENE]\n"
        "                   [--dl OUT.dl5080 [--dac 4|8] [--dither] [--wireframe]]\n"
        "                   [--ids OUT.ids] [--stats]\n"
        "\n"
        "Assembles region files written by 'maprt render SCENE --region X0,Y0,X1,Y1\n"
        "--part FILE' into the whole image and writes it as 'maprt render' would: the\n"
        "same PNG, DL5080 and identity map bytes. The parts must come from one scene,\n"
        "size, --aa and --numeric, and cover every pixel exactly once. The outputs\n"
        "are written all or none. The PNG is encoded on OMP_NUM_THREADS threads\n"
        "(default: one per CPU).\n"
        "\n"
        "  -o OUT         write the picture (.png, .ppm or .pam, as render does)\n"
        "  --deck SCENE   the deck the parts were rendered from: its name and SHA-256\n"
        "                 go into the picture's provenance, as render writes them\n"
        "                 (without it they are left out, and the PNG differs from\n"
        "                 render's in those chunks only)\n"
        "  --dl OUT       write a DL5080 display list (--dac, --dither, --wireframe as\n"
        "                 for render)\n"
        "  --ids OUT      write the identity map (docs/idmap.md); the parts must have\n"
        "                 been rendered with --part-ids\n"
        "  --stats        print the counters summed over the parts (objects and\n"
        "                 instances.*: the scene's, once; time.render_s: the\n"
        "                 slowest part's)\n"
        "  -h, --help     show this help\n"
        "\n"
        "exit status: 0 ok, 1 bad or incomplete parts, 2 usage, 3 I/O failure\n");
}

/* Reads one part file, checks it against the first (*first, filled from the
 * first part) and places it into *fb (allocated at the first part). */
static int cmd_merge_one(const char *path, render_part_info *first, render_fb *fb, uint8_t **covered,
                     render_stats *total, diag *err)
{
    render_part_info info;
    char *data = NULL;
    size_t len = 0, max = RENDER_PART_HEADER + (size_t)(RENDER_PART_PX + RENDER_PART_ID_PX) *
                                                   SCENE_MAX_SIDE * SCENE_MAX_SIDE;
    int rc;
    if ((rc = infile_read_all(path, max, &data, &len, err)) != 0)
        return rc;
    if ((rc = render_part_decode(path, (const uint8_t *)data, len, &info, err)) != 0)
        goto done;
    if (!fb->img.px) {
        *first = info;
        if ((rc = image_alloc(&fb->img, info.width, info.height, 3, path, err)) != 0
            || (info.ids && (rc = idmap_alloc(&fb->ids, info.width, info.height, err)) != 0))
            goto done;
        fb->pid = mem_calloc((size_t)info.width * (size_t)info.height, sizeof *fb->pid);
        *covered = mem_calloc((size_t)info.width * (size_t)info.height, 1);
        if (!fb->pid || !*covered) {
            rc = diag_at(err, DIAG_IO, path, 0, 0, "out of memory for a %dx%d image",
                         info.width, info.height);
            goto done;
        }
    } else if (info.width != first->width || info.height != first->height ||
               info.aa != first->aa || strcmp(info.mode, first->mode)) {
        rc = diag_at(err, DIAG_INPUT, path, 0, 0, "part of a %dx%d %s render with --aa %d; the "
                     "first part is %dx%d %s with --aa %d", info.width, info.height, info.mode,
                     info.aa, first->width, first->height, first->mode, first->aa);
        goto done;
    } else if (info.ids != first->ids) {
        rc = diag_at(err, DIAG_INPUT, path, 0, 0, "part %s an identity map; the first part %s",
                     info.ids ? "carries" : "carries no", first->ids ? "does" : "does not");
        goto done;
    }
    if ((rc = render_part_place(path, (const uint8_t *)data, &info, fb, *covered, err)) != 0)
        goto done;
    render_stats_add(total, &info.stats);
    if (info.stats.time_render_s > total->time_render_s)
        total->time_render_s = info.stats.time_render_s;
    if (info.stats.time_compile_s > total->time_compile_s)
        total->time_compile_s = info.stats.time_compile_s;
done:
    mem_free(data);
    return rc;
}

int cmd_merge(int argc, char **argv)
{
    const char *out_png = NULL, *out_dl = NULL, *out_ids = NULL, *deck = NULL;
    image_out_format pic_format = IMAGE_OUT_NONE;
    cli_files files;
    render_part_info first;
    render_fb fb;
    render_stats total;
    dl_image_opts dlo;
    dl_image_stats dls;
    uint8_t *covered = NULL;
    diag err;
    int i, nparts = 0, stats = 0, wireframe = 0, status = 0;
    size_t k, npx;
    if (cli_wants_help(argc, argv)) {
        cmd_merge_help(stdout);
        return CLI_OK;
    }
    memset(&fb, 0, sizeof fb);
    memset(&total, 0, sizeof total);
    memset(&dlo, 0, sizeof dlo);
    dlo.dac = 4;
    diag_init(&err);
    for (i = 1; i < argc && !status; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (!(out_png = cli_value("merge", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--dl")) {
            if (!(out_dl = cli_value("merge", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--deck")) {
            if (!(deck = cli_value("merge", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--ids")) {
            if (!(out_ids = cli_value("merge", argc, argv, &i))) status = CLI_USAGE;
        } else if (cli_sink_dl_option("merge", argc, argv, &i, &dlo, &wireframe, &status)) {
            continue;
        } else if (!strcmp(a, "--stats")) {
            stats = 1;
        } else if (a[0] == '-' && a[1]) {
            status = cli_usage_error("merge", "unknown option '%s'", a);
        } else {
            nparts++;
        }
    }
    if (!status && !nparts)
        status = cli_usage_error("merge", "no PART given");
    if (!status && !out_png && !out_dl && !out_ids)
        status = cli_usage_error("merge", "no output: give -o OUT.png, --dl OUT.dl5080 or --ids "
                                 "OUT.ids");
    if (!status && !out_dl && (dlo.dither || wireframe || dlo.dac != 4))
        status = cli_usage_error("merge", "--dac, --dither and --wireframe need --dl");
    if (!status && out_png && image_out_choose(out_png, IMAGE_OUT_NONE, &pic_format, &err)) {
        diag_print(stderr, &err);
        status = CLI_USAGE;
    }
    if (status)
        return status;
    if (cli_files_init(&files, &err)) {
        diag_print(stderr, &err);
        cli_files_free(&files);
        return CLI_USAGE;
    }
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-o") || !strcmp(a, "--output") || !strcmp(a, "--dl") || !strcmp(a, "--dac")
            || !strcmp(a, "--deck") || !strcmp(a, "--ids")) {
            i++;
            continue;
        }
        if (a[0] == '-' && a[1])
            continue;
        if (cmd_merge_one(a, &first, &fb, &covered, &total, &err))
            goto done;
    }
    npx = (size_t)first.width * (size_t)first.height;
    for (k = 0; k < npx && covered[k]; k++)
        ;
    if (k < npx) {
        diag_at(&err, DIAG_INPUT, "", 0, 0, "the parts leave pixel %zu,%zu (and maybe more) "
                "uncovered", k % (size_t)first.width, k / (size_t)first.width);
        goto done;
    }
    if (out_ids && !first.ids) {
        diag_at(&err, DIAG_INPUT, "", 0, 0, "--ids: the parts carry no identity map; render "
                "them with --part-ids");
        goto done;
    }
    /* the PNG encoder's threads, each on a CPU (cpubind.h) */
    if (out_png)
        cpubind_threads(omp_get_max_threads());
    /* every output or none */
    outfile_batch_begin();
    {
        image_meta meta;
        char deck_sum[65] = "";
        int summed = !(out_png && deck) || !cli_file_sha256(&files, deck, deck_sum, &err);
        if (out_png && summed)
            cli_sink_provenance(deck, deck_sum, first.mode, first.aa, &fb, &meta);
        if (!summed || (out_png && image_out_write(out_png, pic_format, &fb.img, &meta, &err))
            || (out_dl && cli_sink_dl(out_dl, &fb, &dlo, wireframe, &dls, &err))
            || (out_ids && idmap_write(out_ids, &fb.ids, &err))
            || outfile_batch_commit(&err)) {
            outfile_batch_abort();
            goto done;
        }
    }
    if (stats) {
        printf("numeric=%s\nparts=%d\n", first.mode, nparts);
        render_stats_print(stdout, &total);
        if (out_dl)
            printf("dl.colours=%d\ndl.bytes=%lu\ndl.psnr=%.2f\n", dls.colours,
                   (unsigned long)dls.bytes, dls.psnr);
    }
done:
    render_fb_free(&fb);
    mem_free(covered);
    cli_files_free(&files);
    if (err.status) {
        diag_print(stderr, &err);
        return err.status;
    }
    return CLI_OK;
}
