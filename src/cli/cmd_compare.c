/* cmd_compare — `maprt compare`: measures a test picture (a render) against
 * a reference picture (a scan of the paper's figure) and prints key=value
 * lines; see docs/compare.md. */
#include "cli/cli.h"
#include "compare/compare.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char compare_help[] =
    "usage: maprt compare REFERENCE TEST [options]\n"
    "\n"
    "Measures TEST (e.g. a maprt render) against REFERENCE (e.g. a scan of the\n"
    "paper's Figure 1). Both may be PNG, PNM (P2 P3 P5 P6, maxval 1..65535),\n"
    "JPEG or TIFF (any depth; the first image),\n"
    "files of up to 64 Mpixels; at most 16 Mpixels of each are compared (the\n"
    "reference after --crop). All figures are computed in the reference's\n"
    "pixel frame, over the pixels the test covers.\n"
    "\n"
    "options:\n"
    "  --register          find the scale, shift and rotation mapping TEST onto\n"
    "                      REFERENCE and resample TEST into the reference frame;\n"
    "                      without it both must have the same size\n"
    "  --scale-range LO,HI registration scale search range, in reference pixels\n"
    "                      per test pixel (default 0.25,4; 0.01 <= LO <= HI <= 100)\n"
    "  --max-angle DEG     registration angle search range, -DEG..DEG degrees\n"
    "                      (default 5; 0..45)\n"
    "  --crop X,Y,W,H      compare only this rectangle of REFERENCE (pixels, origin\n"
    "                      top left); dx, dy are then relative to X,Y\n"
    "  --grey, --gray      compare luma only (for grey scans); default R,G,B\n"
    "  --descreen SIGMA    blur both pictures with a Gaussian of SIGMA reference\n"
    "                      pixels (0..50) after registration, to remove halftone\n"
    "                      dots; the reference is also blurred for registration\n"
    "  --levels            fit TEST's levels to REFERENCE per channel (least-\n"
    "                      squares gain and offset) before measuring: for faded\n"
    "                      prints and scanner exposure\n"
    "  --threshold T       difference (0..255) above which a pixel counts in\n"
    "                      pixels_over (default 8)\n"
    "  --diff DIFF.png     write a heat map of the largest channel difference:\n"
    "                      black 0, blue 32, red 64, yellow 96, white >= 128;\n"
    "                      dark grey where the test does not cover the reference\n"
    "  --side-by-side SBS.png\n"
    "                      write reference | registered test | checkerboard of both\n"
    "  -h, --help          show this text\n"
    "\n"
    "output (stdout, key=value lines):\n"
    "  width, height   the compared frame (reference after --crop)\n"
    "  channels        rgb or luma: the channels of mse, psnr and pixels_over\n"
    "  pixels          pixels compared; overlap = pixels / (width*height)\n"
    "  mse             mean of (ref - test)^2 over pixels and channels, 0..255 units\n"
    "  psnr            10*log10(255^2/mse) in dB (peak 255; inf when identical)\n"
    "  ssim            mean SSIM (Wang et al. 2004) on Rec. 601 luma\n"
    "                  (0.299 R' + 0.587 G' + 0.114 B'), 11x11 Gaussian window,\n"
    "                  sigma 1.5, K1=0.01, K2=0.03, L=255, windows wholly inside\n"
    "                  the covered area only\n"
    "  threshold, pixels_over\n"
    "                  fraction of pixels whose largest channel |ref - test| > T\n"
    "  with --levels:  gain, offset (per channel, comma-separated)\n"
    "  with --register: scale, dx, dy, angle, register_score, where a test pixel\n"
    "                  position (xt,yt) lands at reference position\n"
    "                    xr = scale*( cos(a)*xt + sin(a)*yt) + dx\n"
    "                    yr = scale*(-sin(a)*xt + cos(a)*yt) + dy\n"
    "                  (pixel corners at integers, x right, y down; scale is\n"
    "                  reference pixels per test pixel; angle a in degrees,\n"
    "                  positive turns the test counter-clockwise on screen);\n"
    "                  register_score is the edge-map correlation (-1..1)\n"
    "\n"
    "The registration search is refused before it starts when its coarse stage\n"
    "would compare more than 2^32 pixel pairs (docs/compare.md): narrow the ranges.\n"
    "DIFF.png and SBS.png are both written or neither, and may not be an input.\n"
    "\n"
    "exit status: 0 ok, 1 bad input (unreadable picture, sizes differ without\n"
    "--register, no registration found, search over its cost cap), 2 usage, 3 I/O\n"
    "failure, 4 measured but the pair does not look like the same picture: with\n"
    "--register a register_score below 0.78, or an ssim below 0.30 (a warning on\n"
    "stderr says which; the figures are printed as usual)\n";

static void cmd_compare_help_print(FILE *f) { fputs(compare_help, f); }

/* Parses "A,B,..." into n doubles; 0 or CLI_USAGE after a message. */
static int cmd_compare_list(const char *opt, const char *s, int n, double *out)
{
    int k;
    const char *p = s;
    for (k = 0; k < n; k++) {
        char *end;
        out[k] = strtod(p, &end);
        if (end == p || !isfinite(out[k]) || (k + 1 < n ? *end != ',' : *end != '\0'))
            return cli_usage_error("compare", "%s: '%s' is not %d comma-separated numbers", opt, s, n);
        p = end + 1;
    }
    return 0;
}

static void cmd_compare_print(const compare_opts *o, const compare_result *r)
{
    printf("width=%d\nheight=%d\nchannels=%s\npixels=%ld\noverlap=%.6f\n", r->width, r->height,
           r->channels == 3 ? "rgb" : "luma", r->pixels, r->overlap);
    printf("mse=%.6f\n", r->mse);
    if (isinf(r->psnr))
        printf("psnr=inf\n");
    else
        printf("psnr=%.4f\n", r->psnr);
    printf("ssim=%.6f\nthreshold=%g\npixels_over=%.6f\n", r->ssim, o->threshold, r->pixels_over);
    if (o->levels) {
        if (r->channels == 3)
            printf("gain=%.4f,%.4f,%.4f\noffset=%.3f,%.3f,%.3f\n", r->gain[0], r->gain[1], r->gain[2],
                   r->offset[0], r->offset[1], r->offset[2]);
        else
            printf("gain=%.4f\noffset=%.3f\n", r->gain[0], r->offset[0]);
    }
    if (r->registered)
        printf("scale=%.6f\ndx=%.3f\ndy=%.3f\nangle=%.4f\nregister_score=%.4f\n", r->p.scale, r->p.dx, r->p.dy,
               r->p.angle, r->register_score);
}

int cmd_compare(int argc, char **argv)
{
    compare_opts o;
    compare_result r;
    const char *files[2];
    int nfiles = 0, i, rc;
    diag err;
    if (cli_wants_help(argc, argv)) {
        fputs(compare_help, stdout);
        return CLI_OK;
    }
    compare_opts_init(&o);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v;
        double d[4];
        if (!strcmp(a, "--register")) {
            o.do_register = 1;
        } else if (!strcmp(a, "--grey") || !strcmp(a, "--gray")) {
            o.grey = 1;
        } else if (!strcmp(a, "--levels")) {
            o.levels = 1;
        } else if (!strcmp(a, "--diff") || !strcmp(a, "--side-by-side")) {
            if (!(v = cli_value("compare", argc, argv, &i)))
                return CLI_USAGE;
            *(a[2] == 'd' ? &o.diff_path : &o.sbs_path) = v;
        } else if (!strcmp(a, "--scale-range")) {
            if (!(v = cli_value("compare", argc, argv, &i)) || cmd_compare_list(a, v, 2, d))
                return CLI_USAGE;
            if (!(d[0] >= 0.01 && d[0] <= d[1] && d[1] <= 100))
                return cli_usage_error("compare", "%s: need 0.01 <= LO <= HI <= 100, got '%s'", a, v);
            o.align.scale_min = d[0];
            o.align.scale_max = d[1];
        } else if (!strcmp(a, "--max-angle")) {
            if (!(v = cli_value("compare", argc, argv, &i)) || cli_double("compare", a, v, &d[0]))
                return CLI_USAGE;
            if (d[0] < 0 || d[0] > 45)
                return cli_usage_error("compare", "%s: %g is outside 0..45", a, d[0]);
            o.align.max_angle = d[0];
        } else if (!strcmp(a, "--descreen")) {
            if (!(v = cli_value("compare", argc, argv, &i)) || cli_double("compare", a, v, &d[0]))
                return CLI_USAGE;
            if (d[0] < 0 || d[0] > COMPARE_DESCREEN_MAX)
                return cli_usage_error("compare", "%s: %g is outside 0..%g", a, d[0], COMPARE_DESCREEN_MAX);
            o.descreen = d[0];
        } else if (!strcmp(a, "--threshold")) {
            if (!(v = cli_value("compare", argc, argv, &i)) || cli_double("compare", a, v, &d[0]))
                return CLI_USAGE;
            if (d[0] < 0 || d[0] > 255)
                return cli_usage_error("compare", "%s: %g is outside 0..255", a, d[0]);
            o.threshold = d[0];
        } else if (!strcmp(a, "--crop")) {
            if (!(v = cli_value("compare", argc, argv, &i)) || cmd_compare_list(a, v, 4, d))
                return CLI_USAGE;
            for (rc = 0; rc < 4; rc++)
                if (d[rc] != floor(d[rc]) || d[rc] < (rc < 2 ? 0 : 1) || d[rc] > IMAGE_MAX_SIDE)
                    return cli_usage_error("compare", "%s: '%s' needs whole numbers X,Y >= 0 and W,H >= 1", a, v);
            o.crop = 1;
            o.cx = (int)d[0];
            o.cy = (int)d[1];
            o.cw = (int)d[2];
            o.ch = (int)d[3];
        } else if (a[0] == '-' && a[1] != '\0') {
            return cli_unknown_option("compare", a, cmd_compare_help_print);
        } else if (nfiles < 2) {
            files[nfiles++] = a;
        } else {
            return cli_usage_error("compare", "too many arguments ('%s'): give REFERENCE and TEST", a);
        }
    }
    if (nfiles != 2)
        return cli_usage_error("compare", "need REFERENCE and TEST pictures");
    if ((o.diff_path && cli_png_name("compare", "--diff", o.diff_path))
        || (o.sbs_path && cli_png_name("compare", "--side-by-side", o.sbs_path)))
        return CLI_USAGE;
    diag_init(&err);
    rc = compare_files(files[0], files[1], &o, &r, &err);
    if (rc) {
        diag_print(stderr, &err);
        return rc;
    }
    cmd_compare_print(&o, &r);
    {
        char why[96];
        if (compare_mismatch(&r, why, sizeof why)) {
            fflush(stdout);
            fprintf(stderr, "maprt: %s: warning: %s and %s do not look like the same picture (%s); "
                    "check the --side-by-side picture\n", files[1], files[0], files[1], why);
            return CLI_MISMATCH;
        }
    }
    return CLI_OK;
}
