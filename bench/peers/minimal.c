/* minimal — a hand-written f64 ray tracer of bench/peers/sphere.scene and
 * nothing else: the floor under what any general tracer can do on that
 * scene (make bench-peers times maprt against it). Same camera (vertical
 * FOV, z up), same rays (one per pixel centre), the same Lambert + Phong
 * terms, ambient and hard shadows as maprt's trace.c, and the sphere and
 * plane hard-coded. Writes a binary PPM (no compression cost).
 *   usage: minimal OUT.ppm [W H] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct { double x, y, z; } v3;
static v3 mk(double x, double y, double z) { v3 v; v.x = x; v.y = y; v.z = z; return v; }
static v3 add(v3 a, v3 b) { return mk(a.x + b.x, a.y + b.y, a.z + b.z); }
static v3 sub(v3 a, v3 b) { return mk(a.x - b.x, a.y - b.y, a.z - b.z); }
static v3 mul(v3 a, double s) { return mk(a.x * s, a.y * s, a.z * s); }
static double dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static v3 cross(v3 a, v3 b) { return mk(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static v3 unit(v3 a) { return mul(a, 1 / sqrt(dot(a, a))); }

static const v3 C = {0, 0, 1};            /* sphere centre, radius 1 */
#define TMAX 1e30

/* nearest t > 0 on the sphere (skip: 1 when leaving the sphere's surface) */
static double hit_sphere(v3 o, v3 d, int from_sphere)
{
    v3 oc = sub(o, C);
    double b = dot(oc, d), c = dot(oc, oc) - 1, disc = b * b - c, h, t;
    if (disc < 0)
        return TMAX;
    h = sqrt(disc);
    if (from_sphere)
        return TMAX;                      /* convex: a ray leaving it never returns */
    t = -b - h;
    return t > 0 ? t : TMAX;
}

static double hit_plane(v3 o, v3 d, int from_plane)
{
    double t;
    if (from_plane || d.z >= 0)
        return TMAX;
    t = -o.z / d.z;
    return t > 0 ? t : TMAX;
}

static unsigned char byte(double c) { return c <= 0 ? 0 : c >= 1 ? 255 : (unsigned char)(c * 255 + 0.5); }

int main(int argc, char **argv)
{
    int w = argc > 3 ? atoi(argv[2]) : 1024, h = argc > 3 ? atoi(argv[3]) : 768, x, y, k;
    v3 eye = mk(0, -8, 3), look = mk(0, 0, 0.8), upv = mk(0, 0, 1), lpos = mk(5, -6, 10);
    v3 fwd = unit(sub(look, eye)), right = unit(cross(fwd, upv)), up = cross(right, fwd);
    double th = tan(20 * 3.14159265358979323846 / 180), aspect = (double)w / h, li = 0.9, amb = 0.1;
    unsigned char *px;
    FILE *f;
    if (argc < 2 || w < 1 || h < 1 || !(px = malloc((size_t)w * h * 3)))
        return 2;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double sx = (2 * (x + 0.5) / w - 1) * th * aspect, sy = (1 - 2 * (y + 0.5) / h) * th;
            v3 d = unit(add(fwd, add(mul(right, sx), mul(up, sy)))), p, n, col, l, c;
            double ts = hit_sphere(eye, d, 0), tp = hit_plane(eye, d, 0), t, kd, ks, ex, ndl, dist;
            int sphere = ts < tp;
            unsigned char *q = px + 3 * ((size_t)y * w + x);
            t = sphere ? ts : tp;
            if (t == TMAX) {
                c = mk(0.2, 0.3, 0.5);
            } else {
                p = add(eye, mul(d, t));
                n = sphere ? sub(p, C) : mk(0, 0, 1);
                col = sphere ? mk(0.8, 0.2, 0.1) : mk(0.6, 0.6, 0.55);
                kd = sphere ? 0.7 : 0.8;
                ks = sphere ? 0.5 : 0;
                ex = 40;
                c = mul(col, amb);
                l = sub(lpos, p);
                dist = sqrt(dot(l, l));
                l = mul(l, 1 / dist);
                ndl = dot(n, l);
                if (ndl > 0 && (sphere ? hit_plane(p, l, 1) : hit_sphere(p, l, 0)) >= dist) {
                    double spec = 0;
                    if (ks > 0) {
                        v3 rl = sub(mul(n, 2 * ndl), l);
                        double rv = -dot(rl, d);
                        if (rv > 0)
                            spec = ks * pow(rv, ex);
                    }
                    c = add(c, add(mul(col, li * kd * ndl), mk(li * spec, li * spec, li * spec)));
                }
            }
            q[0] = byte(c.x);
            q[1] = byte(c.y);
            q[2] = byte(c.z);
        }
    if (!(f = fopen(argv[1], "wb")))
        return 3;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    k = fwrite(px, 3, (size_t)w * h, f) == (size_t)w * h && fclose(f) == 0;
    free(px);
    return k ? 0 : 3;
}
