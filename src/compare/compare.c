/* compare — the comparison pipeline (see compare.h). */
#include "image/image_png.h"
#include "compare/compare.h"
#include "compare/diffpic.h"
#include "compare/imgload.h"
#include "compare/metrics.h"
#include "compare/ssim.h"
#include "util/outfile.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

void compare_opts_init(compare_opts *o)
{
    memset(o, 0, sizeof *o);
    o->align.scale_min = ALIGN_SCALE_MIN_DEFAULT;
    o->align.scale_max = ALIGN_SCALE_MAX_DEFAULT;
    o->align.max_angle = ALIGN_MAX_ANGLE_DEFAULT;
    o->threshold = COMPARE_THRESHOLD_DEFAULT;
}

/* Working planes of one comparison, freed together. */
typedef struct compare_work {
    plane r[3], t[3], warped[3];
    plane mask, rl, tl;        /* mask; luma planes when needed */
} compare_work;

static void compare_work_free(compare_work *w)
{
    int c;
    for (c = 0; c < 3; c++) {
        plane_free(&w->r[c]);
        plane_free(&w->t[c]);
        plane_free(&w->warped[c]);
    }
    plane_free(&w->mask);
    plane_free(&w->rl);
    plane_free(&w->tl);
}

static int compare_oom(diag *err) { return diag_at(err, DIAG_IO, "", 0, 0, "out of memory"); }

/* dst = Rec. 601 luma of the three planes src. 0 or -1. */
static int compare_luma(const plane *src, plane *dst)
{
    size_t i, n = (size_t)src[0].w * (size_t)src[0].h;
    if (plane_alloc(dst, src[0].w, src[0].h))
        return -1;
    for (i = 0; i < n; i++)
        dst->v[i] = (float)(PLANE_LUMA_R * src[0].v[i] + PLANE_LUMA_G * src[1].v[i] + PLANE_LUMA_B * src[2].v[i]);
    return 0;
}

/* Least-squares gain and offset that map test channel t onto reference
 * channel r over the mask; applied to t in place. */
static void compare_levels(const plane *r, plane *t, const plane *mask, double *gain, double *offset)
{
    size_t i, n = (size_t)r->w * (size_t)r->h;
    double sr = 0, st = 0, stt = 0, srt = 0, k = 0, vt;
    for (i = 0; i < n; i++)
        if (mask->v[i] > 0) {
            sr += r->v[i];
            st += t->v[i];
            stt += (double)t->v[i] * t->v[i];
            srt += (double)r->v[i] * t->v[i];
            k += 1;
        }
    *gain = 1;
    *offset = 0;
    if (k < 1)
        return;
    vt = stt - st * st / k;
    if (vt > 1e-9 * k)
        *gain = (srt - sr * st / k) / vt;
    *offset = (sr - *gain * st) / k;
    for (i = 0; i < n; i++)
        t->v[i] = (float)(*gain * t->v[i] + *offset);
}

/* Checks the crop rectangle and picture sizes; sets the reference frame. */
static int compare_check(const char *ref_name, const image *ref, const char *test_name, const image *test,
                         const compare_opts *o, int *x, int *y, int *w, int *h, diag *err)
{
    *x = *y = 0;
    *w = ref->width;
    *h = ref->height;
    if (o->crop) {
        if (o->cx < 0 || o->cy < 0 || o->cw < 1 || o->ch < 1 || (long)o->cx + o->cw > ref->width ||
            (long)o->cy + o->ch > ref->height)
            return diag_at(err, DIAG_INPUT, ref_name, 0, 0, "crop %d,%d,%d,%d is not inside the %dx%d reference",
                           o->cx, o->cy, o->cw, o->ch, ref->width, ref->height);
        *x = o->cx;
        *y = o->cy;
        *w = o->cw;
        *h = o->ch;
    }
    if ((size_t)*w * (size_t)*h > COMPARE_MAX_PIXELS)
        return diag_at(err, DIAG_INPUT, ref_name, 0, 0,
                       "%dx%d pixels to compare; the limit is %u: crop or scale the reference down", *w, *h,
                       COMPARE_MAX_PIXELS);
    if ((size_t)test->width * (size_t)test->height > COMPARE_MAX_PIXELS)
        return diag_at(err, DIAG_INPUT, test_name, 0, 0, "%dx%d pixels; the limit is %u: scale the test down",
                       test->width, test->height, COMPARE_MAX_PIXELS);
    if (!o->do_register && (test->width != *w || test->height != *h))
        return diag_at(err, DIAG_INPUT, test_name, 0, 0,
                       "size %dx%d differs from the reference's %dx%d%s; use --register to compare pictures "
                       "of different sizes",
                       test->width, test->height, *w, *h, o->crop ? " (after cropping)" : "");
    return 0;
}

/* 1 when the plane is one flat tone (nothing to register on). */
static int compare_flat(const plane *p)
{
    size_t i, n = (size_t)p->w * (size_t)p->h;
    for (i = 1; i < n; i++)
        if (fabsf(p->v[i] - p->v[0]) >= 1.0f)
            return 0;
    return 1;
}

/* Registers the test planes onto the reference frame: w->t is replaced by
 * the resampled test and w->mask marks the covered pixels. */
static int compare_register(const char *ref_name, const char *test_name, const compare_opts *o, int nch, compare_work *w,
                            compare_result *res, diag *err)
{
    align_result ar;
    align_opts ao;
    plane rl;
    int rc, c;
    if (nch == 1 ? plane_copy(&w->r[0], &rl) : compare_luma(w->r, &rl))
        return compare_oom(err);
    if ((nch == 3 && compare_luma(w->t, &w->tl)) || plane_blur(&rl, o->descreen)) {
        plane_free(&rl);
        return compare_oom(err);
    }
    if (compare_flat(&rl) || compare_flat(nch == 1 ? &w->t[0] : &w->tl)) {
        int ref_flat = compare_flat(&rl);
        plane_free(&rl);
        plane_free(&w->tl);
        return diag_at(err, DIAG_INPUT, ref_flat ? ref_name : test_name, 0, 0,
                       "the picture is one flat tone: there is nothing to register on");
    }
    ao = o->align;
    ao.ref_blur = o->descreen;
    rc = align_find(&rl, nch == 1 ? &w->t[0] : &w->tl, &ao, &ar);
    plane_free(&rl);
    plane_free(&w->tl);
    if (rc < 0)
        return compare_oom(err);
    if (rc == 2)
        return diag_at(err, DIAG_INPUT, ref_name, 0, 0,
                       "the registration search over scale %g..%g and angles within %g degrees would compare "
                       "more than %.0f pixel pairs (%dx%d reference, %dx%d test); narrow --scale-range or "
                       "--max-angle",
                       o->align.scale_min, o->align.scale_max, o->align.max_angle,
                       o->align.max_cost > 0 ? o->align.max_cost : ALIGN_MAX_COST, w->r[0].w,
                       w->r[0].h, w->t[0].w, w->t[0].h);
    if (rc > 0)
        return diag_at(err, DIAG_INPUT, ref_name, 0, 0,
                       "registration found no placement of the test covering half of the smaller picture "
                       "(scale %g..%g, angle within %g degrees); check the pictures or widen --scale-range",
                       o->align.scale_min, o->align.scale_max, o->align.max_angle);
    if (warp_resample(&ar.p, w->t, nch, w->r[0].w, w->r[0].h, w->warped, &w->mask))
        return compare_oom(err);
    for (c = 0; c < nch; c++) {
        plane tmp = w->t[c];
        w->t[c] = w->warped[c];
        w->warped[c] = tmp;
    }
    res->registered = 1;
    res->p = ar.p;
    res->register_score = ar.score;
    return 0;
}

/* Writes one requested picture made by make. */
static int compare_picture(const char *path, int (*make)(const plane *, const plane *, int, const plane *,
                                                         image *, diag *),
                           int nch, const compare_work *w, diag *err)
{
    image img;
    int rc;
    if (!path)
        return 0;
    if (make(w->r, w->t, nch, &w->mask, &img, err))
        return err->status;
    rc = image_write_png(path, &img, err);
    image_free(&img);
    return rc;
}

/* Writes the requested pictures: both or neither. */
static int compare_pictures(const compare_opts *o, int nch, const compare_work *w, diag *err)
{
    int rc;
    outfile_batch_begin();
    if ((rc = compare_picture(o->diff_path, diffpic_heat, nch, w, err)) ||
        (rc = compare_picture(o->sbs_path, diffpic_side_by_side, nch, w, err)) ||
        (rc = outfile_batch_commit(err)))
        outfile_batch_abort();
    return rc;
}

int compare_images(const char *ref_name, const image *ref, const char *test_name, const image *test,
                   const compare_opts *o, compare_result *out, diag *err)
{
    compare_work w;
    compare_result res;
    metrics m;
    int x, y, fw, fh, c, nch = o->grey ? 1 : 3, rc;
    size_t i, n;
    memset(&w, 0, sizeof w);
    memset(&res, 0, sizeof res);
    if (compare_check(ref_name, ref, test_name, test, o, &x, &y, &fw, &fh, err))
        return err->status;
    for (c = 0; c < nch; c++)
        if (plane_from_image(ref, o->grey ? -1 : c, x, y, fw, fh, &w.r[c]) ||
            plane_from_image(test, o->grey ? -1 : c, 0, 0, test->width, test->height, &w.t[c])) {
            rc = compare_oom(err);
            goto done;
        }
    if (o->do_register) {
        if ((rc = compare_register(ref_name, test_name, o, nch, &w, &res, err)))
            goto done;
    } else {
        if (plane_alloc(&w.mask, fw, fh)) {
            rc = compare_oom(err);
            goto done;
        }
        for (i = 0, n = (size_t)fw * (size_t)fh; i < n; i++)
            w.mask.v[i] = 1;
    }
    for (c = 0; c < nch; c++)
        if (plane_blur_masked(&w.r[c], &w.mask, o->descreen) || plane_blur_masked(&w.t[c], &w.mask, o->descreen)) {
            rc = compare_oom(err);
            goto done;
        }
    for (c = 0; c < 3; c++) {
        res.gain[c] = 1;
        res.offset[c] = 0;
    }
    if (o->levels)
        for (c = 0; c < nch; c++)
            compare_levels(&w.r[c], &w.t[c], &w.mask, &res.gain[c], &res.offset[c]);
    if (metrics_compute(w.r, w.t, nch, &w.mask, o->threshold, &m)) {
        rc = diag_at(err, DIAG_INPUT, test_name, 0, 0, "the registered test covers no reference pixel");
        goto done;
    }
    if (nch == 3 && (compare_luma(w.r, &w.rl) || compare_luma(w.t, &w.tl))) {
        rc = compare_oom(err);
        goto done;
    }
    rc = ssim_mean(nch == 3 ? &w.rl : &w.r[0], nch == 3 ? &w.tl : &w.t[0], &w.mask, &res.ssim, &res.ssim_windows);
    if (rc) {
        rc = rc < 0 ? compare_oom(err)
                    : diag_at(err, DIAG_INPUT, test_name, 0, 0,
                              "the compared area has no 11x11 patch for SSIM (%dx%d reference frame)", fw, fh);
        goto done;
    }
    if ((rc = compare_pictures(o, nch, &w, err)))
        goto done;
    res.width = fw;
    res.height = fh;
    res.channels = nch;
    res.pixels = m.pixels;
    res.overlap = (double)m.pixels / ((double)fw * fh);
    res.mse = m.mse;
    res.psnr = m.psnr;
    res.pixels_over = m.pixels_over;
    *out = res;
done:
    compare_work_free(&w);
    return rc;
}

int compare_files(const char *ref_path, const char *test_path, const compare_opts *o, compare_result *out,
                  diag *err)
{
    image ref, test;
    const char *outs[2];
    int rc;
    outs[0] = o->diff_path;
    outs[1] = o->sbs_path;
    /* outputs checked before and after the inputs are read: a bad
     * directory fails before any reading, an output that is an input before
     * any work */
    if (outfile_check_set(outs, 2, err))
        return err->status;
    if (imgload_read(ref_path, COMPARE_MAX_READ_PIXELS, &ref, err))
        return err->status;
    if (imgload_read(test_path, COMPARE_MAX_READ_PIXELS, &test, err)) {
        image_free(&ref);
        return err->status;
    }
    if (outfile_check_set(outs, 2, err)) {
        image_free(&ref);
        image_free(&test);
        return err->status;
    }
    rc = compare_images(ref_path, &ref, test_path, &test, o, out, err);
    image_free(&ref);
    image_free(&test);
    return rc;
}

int compare_mismatch(const compare_result *r, char *why, size_t cap)
{
    if (r->registered && r->register_score < COMPARE_MATCH_MIN_SCORE) {
        snprintf(why, cap, "register_score %.4f < %.2f", r->register_score, COMPARE_MATCH_MIN_SCORE);
        return 1;
    }
    if (r->ssim_windows > 0 && r->ssim < COMPARE_MATCH_MIN_SSIM) {
        snprintf(why, cap, "ssim %.4f < %.2f", r->ssim, COMPARE_MATCH_MIN_SSIM);
        return 1;
    }
    return 0;
}
