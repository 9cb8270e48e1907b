/* plane — float rasters and filters for compare (see plane.h). */
#include "compare/plane.h"
#include "util/mem.h"
#include <math.h>
#include <string.h>

int plane_alloc(plane *p, int w, int h)
{
    if (w < 1 || h < 1)
        return -1;
    p->v = mem_calloc((size_t)w * (size_t)h, sizeof(float));
    if (!p->v)
        return -1;
    p->w = w;
    p->h = h;
    return 0;
}

void plane_free(plane *p)
{
    mem_free(p->v);
    p->v = NULL;
    p->w = p->h = 0;
}

int plane_copy(const plane *src, plane *dst)
{
    if (plane_alloc(dst, src->w, src->h))
        return -1;
    memcpy(dst->v, src->v, (size_t)src->w * (size_t)src->h * sizeof(float));
    return 0;
}

int plane_from_image(const image *img, int c, int x, int y, int w, int h, plane *out)
{
    int i, j;
    plane p;
    if (plane_alloc(&p, w, h))
        return -1;
    for (j = 0; j < h; j++) {
        const uint8_t *row = img->px + ((size_t)(y + j) * (size_t)img->width + (size_t)x) * (size_t)img->channels;
        float *dst = p.v + (size_t)j * (size_t)w;
        for (i = 0; i < w; i++) {
            const uint8_t *px = row + (size_t)i * (size_t)img->channels;
            if (img->channels == 1)
                dst[i] = px[0];
            else if (c >= 0)
                dst[i] = px[c];
            else
                dst[i] = (float)(PLANE_LUMA_R * px[0] + PLANE_LUMA_G * px[1] + PLANE_LUMA_B * px[2]);
        }
    }
    *out = p;
    return 0;
}

/* Normalised Gaussian taps k[0..r] (k[-i] = k[i]); r = ceil(3 sigma). */
static float *plane_kernel(double sigma, int *radius)
{
    int r = (int)ceil(3.0 * sigma), i;
    float *k;
    double sum = 0;
    if (r < 1)
        r = 1;
    k = mem_alloc((size_t)(r + 1) * sizeof(float));
    if (!k)
        return NULL;
    for (i = 0; i <= r; i++) {
        k[i] = (float)exp(-0.5 * i * i / (sigma * sigma));
        sum += i ? 2.0 * k[i] : k[i];
    }
    for (i = 0; i <= r; i++)
        k[i] = (float)(k[i] / sum);
    *radius = r;
    return k;
}

static int plane_clamp(int i, int n) { return i < 0 ? 0 : i >= n ? n - 1 : i; }

/* One separable pass with taps k over rows (horiz=1) or columns. tmp holds
 * one row or column. */
static void plane_pass(plane *p, const float *k, int r, int horiz, float *tmp)
{
    int n = horiz ? p->w : p->h, lines = horiz ? p->h : p->w, l, i, t;
    size_t step = horiz ? 1 : (size_t)p->w;
    for (l = 0; l < lines; l++) {
        float *base = horiz ? p->v + (size_t)l * (size_t)p->w : p->v + l;
        for (i = 0; i < n; i++)
            tmp[i] = base[(size_t)i * step];
        for (i = 0; i < n; i++) {
            float s = k[0] * tmp[i];
            for (t = 1; t <= r; t++)
                s += k[t] * (tmp[plane_clamp(i - t, n)] + tmp[plane_clamp(i + t, n)]);
            base[(size_t)i * step] = s;
        }
    }
}

int plane_blur(plane *p, double sigma)
{
    int r;
    float *k, *tmp;
    if (!(sigma > 0))
        return 0;
    k = plane_kernel(sigma, &r);
    tmp = mem_alloc((size_t)(p->w > p->h ? p->w : p->h) * sizeof(float));
    if (!k || !tmp) {
        mem_free(k);
        mem_free(tmp);
        return -1;
    }
    plane_pass(p, k, r, 1, tmp);
    plane_pass(p, k, r, 0, tmp);
    mem_free(k);
    mem_free(tmp);
    return 0;
}

int plane_blur_masked(plane *p, const plane *mask, double sigma)
{
    plane num, den;
    size_t i, n = (size_t)p->w * (size_t)p->h;
    if (!(sigma > 0))
        return 0;
    if (plane_alloc(&num, p->w, p->h))
        return -1;
    if (plane_alloc(&den, p->w, p->h)) {
        plane_free(&num);
        return -1;
    }
    for (i = 0; i < n; i++) {
        den.v[i] = mask->v[i] > 0 ? 1.0f : 0.0f;
        num.v[i] = p->v[i] * den.v[i];
    }
    if (plane_blur(&num, sigma) || plane_blur(&den, sigma)) {
        plane_free(&num);
        plane_free(&den);
        return -1;
    }
    for (i = 0; i < n; i++)
        if (mask->v[i] > 0 && den.v[i] > 1e-6f)
            p->v[i] = num.v[i] / den.v[i];
    plane_free(&num);
    plane_free(&den);
    return 0;
}

int plane_reduce(const plane *src, plane *dst)
{
    /* even binomial taps on src 2i-2..2i+3: centred on the boundary between
     * src pixels 2i and 2i+1, which is where dst pixel i's centre lies */
    static const float k[6] = {1 / 32.f, 5 / 32.f, 10 / 32.f, 10 / 32.f, 5 / 32.f, 1 / 32.f};
    plane tmp, out;
    int i, j, t;
    int w = (src->w + 1) / 2, h = (src->h + 1) / 2;
    /* horizontal filter and decimation into tmp (w x src->h) */
    if (plane_alloc(&tmp, w, src->h))
        return -1;
    if (plane_alloc(&out, w, h)) {
        plane_free(&tmp);
        return -1;
    }
    for (j = 0; j < src->h; j++)
        for (i = 0; i < w; i++) {
            float s = 0;
            for (t = -2; t <= 3; t++)
                s += k[t + 2] * PLANE_AT(src, plane_clamp(2 * i + t, src->w), j);
            PLANE_AT(&tmp, i, j) = s;
        }
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            float s = 0;
            for (t = -2; t <= 3; t++)
                s += k[t + 2] * PLANE_AT(&tmp, i, plane_clamp(2 * j + t, src->h));
            PLANE_AT(&out, i, j) = s;
        }
    plane_free(&tmp);
    *dst = out;
    return 0;
}

int plane_gradient(const plane *src, plane *dst)
{
    plane g;
    int i, j;
    if (plane_alloc(&g, src->w, src->h))
        return -1;
    for (j = 0; j < src->h; j++)
        for (i = 0; i < src->w; i++) {
            float gx = 0.5f * (PLANE_AT(src, plane_clamp(i + 1, src->w), j) - PLANE_AT(src, plane_clamp(i - 1, src->w), j));
            float gy = 0.5f * (PLANE_AT(src, i, plane_clamp(j + 1, src->h)) - PLANE_AT(src, i, plane_clamp(j - 1, src->h)));
            PLANE_AT(&g, i, j) = sqrtf(gx * gx + gy * gy);
        }
    *dst = g;
    return 0;
}

float plane_sample(const plane *p, double x, double y)
{
    double u = x - 0.5, v = y - 0.5, fu, fv;
    int i0, j0, i1, j1;
    if (u < 0)
        u = 0;
    if (v < 0)
        v = 0;
    if (u > p->w - 1)
        u = p->w - 1;
    if (v > p->h - 1)
        v = p->h - 1;
    i0 = (int)u;
    j0 = (int)v;
    fu = u - i0;
    fv = v - j0;
    i1 = i0 + 1 < p->w ? i0 + 1 : i0;
    j1 = j0 + 1 < p->h ? j0 + 1 : j0;
    return (float)((1 - fv) * ((1 - fu) * PLANE_AT(p, i0, j0) + fu * PLANE_AT(p, i1, j0)) +
                   fv * ((1 - fu) * PLANE_AT(p, i0, j1) + fu * PLANE_AT(p, i1, j1)));
}
