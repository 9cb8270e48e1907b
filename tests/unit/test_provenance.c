/* test_provenance — the pieces of a picture's provenance and the option
 * conventions: SHA-256 against the FIPS 180-4 example vectors (and a long
 * input crossing block boundaries in odd pieces), tEXt chunks read back by
 * libpng's own reader (which checks their CRCs), PPM/PAM encodings read back
 * by the PNM reader, the files image_out streams against those encodings,
 * and the edit distance behind "did you mean". */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "image/image_meta.h"
#include "image/image_out.h"
#include "image/image_png.h"
#include "image/pnm.h"
#include "util/mem.h"
#include "util/sha256.h"
#include "util/suggest.h"
#include "support.h"

static void hash_of(const char *s, size_t n, size_t piece, char hex[65])
{
    sha256 h;
    size_t i;
    sha256_init(&h);
    for (i = 0; i < n; i += piece)
        sha256_update(&h, s + i, n - i < piece ? n - i : piece);
    sha256_hex(&h, hex);
}

/* The SHA extensions' blocks against the portable rounds: every length
 * from 0 to 300 bytes and one of 100,003, whole and in pieces of 1 to 200
 * bytes, random contents. Where the processor has no SHA extensions both
 * digests come from the portable rounds, and the test says so. */
static void test_provenance_sha256_paths_agree(void **state)
{
    uint64_t seed = test_seed("test_provenance_sha256_paths_agree");
    static unsigned char data[100003];
    char hex[2][65];
    size_t n, i, piece;
    int path;
    sha256 h;
    (void)state;
    for (i = 0; i < sizeof data; i++)
        data[i] = (unsigned char)(test_rand(&seed) >> 24);
    sha256_init(&h);
    if (!h.shani)
        print_message("# no SHA extensions here: both paths are the portable rounds\n");
    for (n = 0; n <= sizeof data; n = n < 300 ? n + 1 : n == 300 ? sizeof data : n + 1) {
        piece = 1 + (size_t)(test_rand(&seed) % 200);
        for (path = 0; path < 2; path++) {
            sha256_init(&h);
            h.shani &= path;
            for (i = 0; i < n; i += piece)
                sha256_update(&h, data + i, n - i < piece ? n - i : piece);
            sha256_hex(&h, hex[path]);
        }
        assert_string_equal(hex[0], hex[1]);
        if (n == sizeof data)
            break;
    }
}

static void test_provenance_sha256_vectors(void **state)
{
    static const char two[] = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    char hex[65], *mill;
    (void)state;
    hash_of("", 0, 1, hex);
    assert_string_equal(hex, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    hash_of("abc", 3, 1, hex);
    assert_string_equal(hex, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    hash_of(two, strlen(two), 5, hex);
    assert_string_equal(hex, "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    mill = malloc(1000000);
    assert_non_null(mill);
    memset(mill, 'a', 1000000);
    hash_of(mill, 1000000, 4093, hex);
    assert_string_equal(hex, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
    hash_of(mill, 1000000, 1000000, hex);          /* whole blocks straight from the input */
    assert_string_equal(hex, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
    free(mill);
}

/* Lengths either side of the padding's and the block's edges, each fed in
 * one piece, by 64 and by 7 bytes (digests from Python's hashlib). */
static void test_provenance_sha256_block_edges(void **state)
{
    static const struct { size_t n; const char *hex; } v[] = {
        {55, "e7313d333c272e639f790978283f9eb392e843d0f29b7016828bb1daa4aac70b"},
        {56, "4324d65f3c103567f5589c710bc08f8523f929a9272e3af36fc968e52abc6c27"},
        {57, "35df609437dcfea3279283ab79fd554e2bf78f8f7ae2de532d8ee300b09e8f73"},
        {63, "81c80242132f230c3bd41b3e63bbcff16107339549214a99614ff26664625055"},
        {64, "39e3d7b6b5d075d37d053ad89b24b41bef4f3c29760c84447cab3f3be1882241"},
        {65, "aacca6ff74fdbb296d165a45cecfa04e5127bc008770fbbdd48006f2d2fae95e"},
        {119, "9ce7368e4daf32341631b492e80359dc9f594b48453cd0dd5bf0b19279cc177e"},
        {120, "7836b787757e95e58b3ca5aec90b1b004e8deba1e50e9675af9cabf1a13a04b5"},
        {128, "d2742f1f4ac6bb7ca2b239ee18402ba8b3f9f8e652d2a72973c2b9ba11c08cf6"},
        {1000, "1e9bc38cbf860b9ec31918b065f9b52476c549a782e0e7990bed8ce3868d2371"}};
    static const size_t piece[3] = {1000, 64, 7};
    char data[1000], hex[65];
    size_t i, k;
    (void)state;
    for (i = 0; i < sizeof data; i++)
        data[i] = (char)((i * 7 + 3) & 255);
    for (i = 0; i < sizeof v / sizeof v[0]; i++)
        for (k = 0; k < 3; k++) {
            hash_of(data, v[i].n, piece[k], hex);
            assert_string_equal(hex, v[i].hex);
        }
}

static void test_provenance_png_text(void **state)
{
    image img;
    image_meta m;
    void *png = NULL, *tagged = NULL;
    size_t len = 0, tlen = 0;
    diag err;
    png_structp rd;
    png_infop info;
    png_textp text;
    FILE *f;
    char path[] = "/tmp/maprt-prov-XXXXXX";
    int fd, n, i, x;
    (void)state;
    diag_init(&err);
    assert_int_equal(image_alloc(&img, 5, 3, 3, "t", &err), 0);
    for (x = 0; x < 45; x++)
        img.px[x] = (uint8_t)(x * 5);
    image_meta_init(&m);
    image_meta_add(&m, "Software", "maprt %s", "test");
    image_meta_add(&m, "maprt:deck", "a deck\twith a tab");   /* becomes '?' */
    image_meta_add(&m, "", "refused: empty key");
    assert_int_equal(m.n, 2);
    assert_int_equal(image_encode_png(&img, &png, &len, &err), 0);
    assert_int_equal(image_meta_png(png, len, &m, &tagged, &tlen, &err), 0);
    assert_int_equal(image_meta_png((char *)png + 1, len - 1, &m, &tagged, &tlen, &err), DIAG_INPUT);
    fd = mkstemp(path);
    assert_true(fd >= 0);
    f = fdopen(fd, "w+b");
    assert_int_equal(fwrite(tagged, 1, tlen, f), tlen);
    rewind(f);
    rd = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(rd);
    assert_non_null(info);
    if (setjmp(png_jmpbuf(rd)))
        fail_msg("libpng refused the tagged PNG");
    png_init_io(rd, f);
    png_read_info(rd, info);
    n = png_get_text(rd, info, &text, NULL);
    assert_int_equal(n, 2);
    for (i = 0; i < n; i++) {
        if (!strcmp(text[i].key, "Software"))
            assert_string_equal(text[i].text, "maprt test");
        else
            assert_string_equal(text[i].text, "a deck?with a tab");
    }
    png_destroy_read_struct(&rd, &info, NULL);
    fclose(f);
    remove(path);
    /* the pixels are unchanged */
    {
        image back;
        assert_int_equal(image_read_png_memory("t", tagged, tlen, 3, &back, &err), 0);
        assert_memory_equal(back.px, img.px, 45);
        image_free(&back);
    }
    mem_free(png);
    mem_free(tagged);
    image_free(&img);
}

static void test_provenance_pnm_roundtrip(void **state)
{
    image img, back;
    void *buf;
    size_t len;
    diag err;
    int c, x;
    (void)state;
    for (c = 1; c <= 3; c += 2) {
        diag_init(&err);
        assert_int_equal(image_alloc(&img, 7, 4, c, "t", &err), 0);
        for (x = 0; x < 28 * c; x++)
            img.px[x] = (uint8_t)(x * 37 + 11);
        assert_int_equal(pnm_encode(&img, 0, "# maprt:deck: x\n", &buf, &len, &err), 0);
        assert_int_equal(pnm_read_memory("t", buf, len, c, &back, &err), 0);
        assert_memory_equal(back.px, img.px, (size_t)(28 * c));
        image_free(&back);
        mem_free(buf);
        assert_int_equal(pnm_encode(&img, 1, NULL, &buf, &len, &err), 0);
        assert_memory_equal((char *)buf + len - 28 * c, img.px, (size_t)(28 * c));
        assert_non_null(strstr(buf, c == 1 ? "TUPLTYPE GRAYSCALE\nENDHDR\n" : "TUPLTYPE RGB\nENDHDR\n"));
        mem_free(buf);
        image_free(&img);
    }
}

/* The files image_out_write streams (the header, then the raster straight
 * from the picture) hold byte for byte what pnm_encode builds in memory,
 * provenance comments included; a header with no room for itself is
 * refused (0), not cut. */
static void test_provenance_pnm_streamed(void **state)
{
    char dir[] = "/tmp/maprt-pnm-XXXXXX", path[64], comments[4096], small[16];
    image img;
    image_meta m;
    void *buf;
    size_t len, flen;
    diag err;
    int c, pam, x;
    (void)state;
    assert_non_null(mkdtemp(dir));
    image_meta_init(&m);
    image_meta_add(&m, "maprt:deck", "%s", "streamed.scene");
    image_meta_comments(&m, comments, sizeof comments);
    for (c = 1; c <= 3; c += 2)
        for (pam = 0; pam <= 1; pam++) {
            char *file;
            diag_init(&err);
            assert_int_equal(image_alloc(&img, 5, 3, c, "t", &err), 0);
            for (x = 0; x < 15 * c; x++)
                img.px[x] = (uint8_t)(x * 53 + 7);
            snprintf(path, sizeof path, "%s/p.%s", dir, pam ? "pam" : "ppm");
            assert_int_equal(image_out_write(path, pam ? IMAGE_OUT_PAM : IMAGE_OUT_PPM, &img, &m, &err), 0);
            assert_int_equal(pnm_encode(&img, pam, comments, &buf, &len, &err), 0);
            file = test_read_file(path, &flen);
            assert_non_null(file);
            assert_int_equal(flen, len);
            assert_memory_equal(file, buf, len);
            assert_int_equal(pnm_header(&img, pam, comments, small, sizeof small), 0);
            mem_free(file);
            mem_free(buf);
            assert_int_equal(unlink(path), 0);
            image_free(&img);
        }
    assert_int_equal(rmdir(dir), 0);
}

static void test_provenance_output_names(void **state)
{
    image_out_format f;
    diag err;
    (void)state;
    diag_init(&err);
    assert_int_equal(image_out_choose("a/b.PNG", IMAGE_OUT_NONE, &f, &err), 0);
    assert_int_equal(f, IMAGE_OUT_PNG);
    assert_int_equal(image_out_choose("x.pam", IMAGE_OUT_PAM, &f, &err), 0);
    assert_int_equal(f, IMAGE_OUT_PAM);
    assert_int_equal(image_out_choose("-", image_out_parse("PpM"), &f, &err), 0);
    assert_int_equal(f, IMAGE_OUT_PPM);
    assert_int_equal(image_out_choose("-", IMAGE_OUT_NONE, &f, &err), DIAG_USAGE);
    diag_init(&err);
    assert_int_equal(image_out_choose("x.jpg", IMAGE_OUT_PNG, &f, &err), DIAG_USAGE);
    diag_init(&err);
    assert_int_equal(image_out_choose("dir.png/x", IMAGE_OUT_NONE, &f, &err), DIAG_USAGE);
    diag_init(&err);
    assert_int_equal(image_out_choose("x.ppm", IMAGE_OUT_PNG, &f, &err), DIAG_USAGE);
}

static void test_provenance_suggest(void **state)
{
    suggest s;
    (void)state;
    assert_int_equal(suggest_distance("--szie", "--size", 0), 1);    /* a transposition */
    assert_int_equal(suggest_distance("LOKAT", "lookat", 0), 1);
    assert_int_equal(suggest_distance("kitten", "sitting", 0), 3);
    assert_int_equal(suggest_distance("--sizeXX", "--size", 0), 2);
    assert_int_equal(suggest_distance("abc", "abcdef", 3), 0);
    suggest_init(&s, "--thread");
    suggest_try(&s, "--threads", 0);
    suggest_try(&s, "--threshold", 0);
    assert_string_equal(suggest_best(&s), "--threads");
    suggest_init(&s, "--q");
    suggest_try(&s, "--numeric", 0);
    assert_null(suggest_best(&s));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_provenance_sha256_vectors),
        cmocka_unit_test(test_provenance_sha256_paths_agree),
        cmocka_unit_test(test_provenance_sha256_block_edges),
        cmocka_unit_test(test_provenance_png_text),
        cmocka_unit_test(test_provenance_pnm_roundtrip),
        cmocka_unit_test(test_provenance_pnm_streamed),
        cmocka_unit_test(test_provenance_output_names),
        cmocka_unit_test(test_provenance_suggest),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
