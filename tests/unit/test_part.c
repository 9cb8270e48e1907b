/* test_part — the region record (render_part): every render_stats field
 * survives the trip, regions of random framebuffers (identity map
 * included) come back where they were, and bad headers are refused at
 * their offset. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "render/render_part.h"
#include "util/mem.h"
#include "support.h"

/* A whole-image framebuffer of random pixels, ids and identity records. */
static void part_random_fb(render_fb *fb, int w, int h, uint64_t *s)
{
    size_t i, n = (size_t)w * (size_t)h;
    diag err;
    diag_init(&err);
    memset(fb, 0, sizeof *fb);
    assert_int_equal(image_alloc(&fb->img, w, h, 3, "test", &err), 0);
    assert_int_equal(idmap_alloc(&fb->ids, w, h, &err), 0);
    fb->pid = mem_calloc(n, sizeof *fb->pid);
    assert_non_null(fb->pid);
    for (i = 0; i < n; i++) {
        fb->img.px[3 * i] = (unsigned char)test_rand(s);
        fb->img.px[3 * i + 1] = (unsigned char)test_rand(s);
        fb->img.px[3 * i + 2] = (unsigned char)test_rand(s);
        fb->pid[i] = (int32_t)(test_rand(s) % 9) - 1;
        fb->ids.px[i].prim = (int32_t)(test_rand(s) % 9) - 1;
        fb->ids.px[i].face = (int32_t)(test_rand(s) % 7) - 1;
        fb->ids.px[i].region = (int32_t)(test_rand(s) % 300) - 1;
        fb->ids.px[i].flags = (int32_t)(test_rand(s) % 2);
        fb->ids.px[i].t = test_uniform(s, -1, 1e6);
    }
}

/* Each field of render_stats (23 counters, the scene's three counts
 * among them, and 2 times) given a distinct value comes back as it went: a
 * field left out of the layout, or two counters sharing a place, fails
 * here. */
static void test_part_stats_every_field(void **state)
{
    render_fb fb;
    render_part_info in, out;
    unsigned char raw[sizeof(render_stats)];
    uint64_t s = test_seed("test_part_stats_every_field");
    uint8_t *buf;
    size_t len, k;
    diag err;
    (void)state;
    part_random_fb(&fb, 3, 2, &s);
    memset(&in, 0, sizeof in);
    in.width = 3;
    in.height = 2;
    in.region[2] = 3;
    in.region[3] = 2;
    in.aa = 2;
    strcpy(in.mode, "hfp64");
    for (k = 0; k < sizeof raw; k++)
        raw[k] = (unsigned char)(k * 7 + 1);   /* no two 8-byte fields alike */
    memcpy(&in.stats, raw, sizeof raw);
    diag_init(&err);
    assert_int_equal(render_part_encode(&fb, &in, &buf, &len, &err), 0);
    assert_int_equal(render_part_decode("t", buf, len, &out, &err), 0);
    assert_memory_equal(&out.stats, &in.stats, sizeof in.stats);
    assert_true(out.stats.objects == in.stats.objects && out.stats.inst_moved == in.stats.inst_moved
                && out.stats.inst_turned == in.stats.inst_turned);
    assert_string_equal(out.mode, "hfp64");
    assert_int_equal(out.aa, 2);
    assert_int_equal(out.ids, 0);
    mem_free(buf);
    render_fb_free(&fb);
}

/* Random regions of random framebuffers, with and without the identity
 * map, placed into an empty frame: the region's pixels, ids and records
 * equal the source's, the rest stays untouched. */
static void test_part_random_regions(void **state)
{
    uint64_t s = test_seed("test_part_random_regions");
    int round;
    (void)state;
    for (round = 0; round < 200; round++) {
        int w = 1 + (int)(test_rand(&s) % 40), h = 1 + (int)(test_rand(&s) % 40), x, y;
        render_fb src, dst;
        render_part_info in, out;
        uint8_t *buf, *covered;
        size_t len;
        diag err;
        diag_init(&err);
        part_random_fb(&src, w, h, &s);
        part_random_fb(&dst, w, h, &s);
        memset(&in, 0, sizeof in);
        in.width = w;
        in.height = h;
        in.region[0] = (int)(test_rand(&s) % (unsigned)w);
        in.region[1] = (int)(test_rand(&s) % (unsigned)h);
        in.region[2] = in.region[0] + 1 + (int)(test_rand(&s) % (unsigned)(w - in.region[0]));
        in.region[3] = in.region[1] + 1 + (int)(test_rand(&s) % (unsigned)(h - in.region[1]));
        in.aa = 1;
        in.ids = (int)(test_rand(&s) % 2);
        strcpy(in.mode, "q16");
        assert_int_equal(render_part_encode(&src, &in, &buf, &len, &err), 0);
        assert_int_equal(len, render_part_bytes(in.region, in.ids));
        assert_int_equal(render_part_decode("t", buf, len, &out, &err), 0);
        assert_int_equal(out.ids, in.ids);
        assert_memory_equal(out.region, in.region, sizeof in.region);
        covered = mem_calloc((size_t)w * (size_t)h, 1);
        assert_non_null(covered);
        {
            render_fb before;
            part_random_fb(&before, w, h, &s);
            memcpy(before.img.px, dst.img.px, (size_t)w * h * 3);
            memcpy(before.pid, dst.pid, (size_t)w * h * sizeof *dst.pid);
            memcpy(before.ids.px, dst.ids.px, (size_t)w * h * sizeof *dst.ids.px);
            assert_int_equal(render_part_place("t", buf, &out, &dst, covered, &err), 0);
            for (y = 0; y < h; y++)
                for (x = 0; x < w; x++) {
                    size_t i = (size_t)y * w + x;
                    int in_r = x >= in.region[0] && x < in.region[2] && y >= in.region[1] &&
                               y < in.region[3];
                    const render_fb *want = in_r ? &src : &before;
                    assert_int_equal(covered[i], in_r);
                    assert_memory_equal(dst.img.px + 3 * i, want->img.px + 3 * i, 3);
                    assert_int_equal(dst.pid[i], want->pid[i]);
                    want = in_r && in.ids ? &src : &before;
                    assert_memory_equal(&dst.ids.px[i], &want->ids.px[i], sizeof dst.ids.px[i]);
                }
            render_fb_free(&before);
        }
        /* the same part again overlaps itself */
        assert_int_equal(render_part_place("t", buf, &out, &dst, covered, &err), DIAG_INPUT);
        mem_free(covered);
        mem_free(buf);
        render_fb_free(&src);
        render_fb_free(&dst);
    }
}

/* Formats 1 and 2 (older maprts', without the scene's counts), unknown
 * contents bits and a missing identity map are refused at the offset of
 * the field. */
static void test_part_bad_headers(void **state)
{
    render_fb fb;
    render_part_info in, out;
    uint64_t s = test_seed("test_part_bad_headers");
    uint8_t *buf;
    size_t len;
    diag err;
    (void)state;
    part_random_fb(&fb, 4, 4, &s);
    memset(&in, 0, sizeof in);
    in.width = in.height = 4;
    in.region[2] = in.region[3] = 4;
    in.aa = 1;
    in.ids = 1;
    strcpy(in.mode, "f64");
    diag_init(&err);
    assert_int_equal(render_part_encode(&fb, &in, &buf, &len, &err), 0);
    assert_memory_equal(buf, "MAPRTPT3", 8);
    buf[7] = '1';
    assert_int_equal(render_part_decode("t", buf, len, &out, &err), DIAG_INPUT);
    assert_int_equal(err.offset, 0);
    assert_non_null(strstr(err.msg, "format 1 (MAPRTPT1, made by an older maprt)"));
    buf[7] = '2';
    diag_init(&err);
    assert_int_equal(render_part_decode("t", buf, len, &out, &err), DIAG_INPUT);
    assert_int_equal(err.offset, 0);
    assert_non_null(strstr(err.msg, "format 2 (MAPRTPT2, made by an older maprt); this maprt reads "
                                    "format 3 (MAPRTPT3): render the part again"));
    buf[7] = '4';             /* a later format is no region file this maprt knows */
    diag_init(&err);
    assert_int_equal(render_part_decode("t", buf, len, &out, &err), DIAG_INPUT);
    assert_non_null(strstr(err.msg, "not a maprt region file"));
    buf[7] = '3';
    buf[46] = 1;              /* contents bit 8 */
    diag_init(&err);
    assert_int_equal(render_part_decode("t", buf, len, &out, &err), DIAG_INPUT);
    assert_int_equal(err.offset, 44);
    buf[46] = 0;
    buf[47] = 0;              /* no identity map: the records are surplus */
    diag_init(&err);
    assert_int_equal(render_part_decode("t", buf, len, &out, &err), DIAG_INPUT);
    assert_int_equal(err.offset, (long long)render_part_bytes(in.region, 0));
    buf[47] = 1;
    diag_init(&err);
    assert_int_equal(render_part_decode("t", buf, len - 1, &out, &err), DIAG_INPUT);
    assert_int_equal(err.offset, (long long)len - 1);
    diag_init(&err);
    assert_int_equal(render_part_decode("t", buf, len, &out, &err), 0);
    mem_free(buf);
    render_fb_free(&fb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_part_stats_every_field),
        cmocka_unit_test(test_part_random_regions),
        cmocka_unit_test(test_part_bad_headers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
