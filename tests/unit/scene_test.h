/* scene_test — parsing decks given as text in the scene-language tests
 * (test_scene_parse, test_scene_pds), with an optional image loader.
 * Include after cmocka.h. */
#ifndef SCENE_TEST_H
#define SCENE_TEST_H
#include <stdio.h>
#include <string.h>
#include "scene/scene_parse.h"
#include "util/recsrc.h"

/* Parses text as deck "t.scene" through ld (NULL: no images). */
static inline int st_parse(const char *text, const scene_loader *ld, scene **out, diag *err)
{
    recsrc src;
    recsrc_mem m;
    diag_init(err);
    recsrc_from_memory(&src, &m, "t.scene", text, strlen(text));
    return scene_parse_with(&src, ld, out, err);
}

/* Parses a deck that must be valid; fails the test, printing the error,
 * otherwise. */
static inline scene *st_parse_ok(const char *text, const scene_loader *ld)
{
    scene *s = NULL;
    diag err;
    int r = st_parse(text, ld, &s, &err);
    if (r) {
        char buf[1024];
        diag_format(&err, buf, sizeof buf);
        fprintf(stderr, "unexpected error: %s\n", buf);
    }
    assert_int_equal(r, 0);
    assert_non_null(s);
    return s;
}

/* Parses a deck that must fail with exactly the message want (as
 * diag_format writes it), leaving the output untouched. */
static inline void st_expect_error(const char *text, const scene_loader *ld, const char *want)
{
    scene *s = (scene *)(void *)&s;     /* must stay untouched */
    scene *sentinel = s;
    diag err;
    char buf[1024];
    int r = st_parse(text, ld, &s, &err);
    diag_format(&err, buf, sizeof buf);
    if (strcmp(buf, want) != 0)
        fprintf(stderr, "deck:\n%s\nwant: %s\ngot:  %s\n", text, want, buf);
    assert_int_equal(r, DIAG_INPUT);
    assert_ptr_equal(s, sentinel);
    assert_string_equal(buf, want);
}
#endif
