/* test_util — the allocation hook and first-error diagnostics (src/util). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "support.h"
#include "util/diag.h"
#include "util/mem.h"
#include <string.h>

/* Zero-byte requests return distinct valid pointers; NULL means failure. */
static void test_util_mem_zero_bytes(void **state)
{
    void *a, *b, *c, *r;
    size_t cap = 0;
    int *arr = NULL;
    (void)state;
    a = mem_alloc(0);
    b = mem_calloc(0, 8);
    c = mem_calloc(8, 0);
    assert_non_null(a);
    assert_non_null(b);
    assert_non_null(c);
    assert_ptr_not_equal(a, b);
    r = mem_realloc(a, 0);
    assert_non_null(r);
    assert_int_equal(mem_grow((void **)&arr, &cap, 0, sizeof *arr), 0);
    assert_non_null(arr);
    assert_true(cap >= 1);
    mem_free(r);
    mem_free(b);
    mem_free(c);
    mem_free(arr);
}

static void test_util_mem_fail_and_overflow(void **state)
{
    (void)state;
    mem_fail_after(0);
    assert_null(mem_alloc(0));
    assert_null(mem_alloc(16));
    mem_fail_after(-1);
    assert_null(mem_calloc((size_t)-1, 16));
}

/* The first error wins; line/col and offset forms format as documented. */
static void test_util_diag_first_error_and_forms(void **state)
{
    diag d;
    char buf[256];
    (void)state;
    diag_init(&d);
    assert_int_equal(diag_at(&d, DIAG_INPUT, "deck", 3, 7, "bad %s", "item"), DIAG_INPUT);
    assert_int_equal(diag_offset(&d, DIAG_IO, "other", 12, "ignored"), DIAG_IO);
    diag_format(&d, buf, sizeof buf);
    assert_string_equal(buf, "deck:3:7: error: bad item");
    diag_init(&d);
    diag_offset(&d, DIAG_INPUT, "list.dl", 40, "bad element %d", 2);
    diag_format(&d, buf, sizeof buf);
    assert_string_equal(buf, "list.dl: offset 40: error: bad element 2");
    assert_int_equal(d.line, 0);
    diag_init(&d);
    diag_at(&d, DIAG_IO, "f", 0, 0, "gone");
    diag_format(&d, buf, sizeof buf);
    assert_string_equal(buf, "f: error: gone");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_util_mem_zero_bytes),
        cmocka_unit_test(test_util_mem_fail_and_overflow),
        cmocka_unit_test(test_util_diag_first_error_and_forms),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
