/* test_outline — outline segments cover exactly the edge pixels of an id buffer. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "render/outline.h"
#include "util/mem.h"
#include "support.h"

/* Rasterises segments into a coverage count per pixel. */
static void cover(const outline_seg *s, size_t n, int w, int h, int *count)
{
    size_t i;
    memset(count, 0, sizeof(int) * (size_t)w * h);
    for (i = 0; i < n; i++) {
        int x, y;
        assert_true(s[i].x0 == s[i].x1 || s[i].y0 == s[i].y1);
        for (y = s[i].y0; y <= s[i].y1; y++)
            for (x = s[i].x0; x <= s[i].x1; x++)
                count[y * w + x]++;
    }
}

static void test_outline_covers_each_edge_pixel_once(void **state)
{
    enum { W = 37, H = 23 };
    uint64_t s = test_seed("test_outline_covers_each_edge_pixel_once");
    int32_t id[W * H];
    int count[W * H], round;
    (void)state;
    for (round = 0; round < 50; round++) {
        outline_seg *segs = NULL;
        size_t n = 0;
        diag err;
        int x, y, k;
        /* random overlapping rectangles of ids */
        memset(id, 0, sizeof id);
        for (k = 0; k < 5; k++) {
            int x0 = (int)(test_rand(&s) % W), y0 = (int)(test_rand(&s) % H);
            int x1 = x0 + (int)(test_rand(&s) % (W - x0)), y1 = y0 + (int)(test_rand(&s) % (H - y0));
            for (y = y0; y <= y1; y++)
                for (x = x0; x <= x1; x++)
                    id[y * W + x] = k + 1;
        }
        diag_init(&err);
        assert_int_equal(outline_trace(id, W, H, &segs, &n, &err), 0);
        cover(segs, n, W, H, count);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int e = (x + 1 < W && id[y * W + x] != id[y * W + x + 1]) ||
                        (y + 1 < H && id[y * W + x] != id[(y + 1) * W + x]);
                assert_int_equal(count[y * W + x], e);
            }
        mem_free(segs);
    }
}

static void test_outline_straight_edge_is_one_segment(void **state)
{
    enum { W = 8, H = 6 };
    int32_t id[W * H];
    outline_seg *segs = NULL;
    size_t n = 0;
    diag err;
    int x, y;
    (void)state;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            id[y * W + x] = x < 3 ? 1 : 2;      /* vertical boundary after column 2 */
    diag_init(&err);
    assert_int_equal(outline_trace(id, W, H, &segs, &n, &err), 0);
    assert_int_equal(n, 1);
    assert_int_equal(segs[0].x0, 2);
    assert_int_equal(segs[0].y0, 0);
    assert_int_equal(segs[0].x1, 2);
    assert_int_equal(segs[0].y1, H - 1);
    mem_free(segs);
}

static void test_outline_out_of_memory_is_reported(void **state)
{
    int32_t id[16] = {0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0};
    long k;
    (void)state;
    for (k = 0; k < 64; k++) {
        outline_seg *segs = NULL;
        size_t n = 0;
        diag err;
        int rc;
        diag_init(&err);
        mem_fail_after(k);
        rc = outline_trace(id, 4, 4, &segs, &n, &err);
        mem_fail_after(-1);
        if (rc == 0) {
            mem_free(segs);
            return;
        }
        assert_int_equal(rc, DIAG_IO);
        assert_string_equal(err.msg, "out of memory");
    }
    fail_msg("outline_trace never succeeded");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_outline_covers_each_edge_pixel_once),
        cmocka_unit_test(test_outline_straight_edge_is_one_segment),
        cmocka_unit_test(test_outline_out_of_memory_is_reported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
