/* fuzz_hfp — the HFP instructions (src/num/hfp.c) and the data-field
 * conversions (hfp_data) on arbitrary register images, unnormalised and
 * zero fractions included. Nothing may trap; every arithmetic result must
 * be normalised or a true zero, and an encoded field must decode to within
 * half a unit of its last digit. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include "num/hfp.h"
#include "num/hfp_data.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int normal_or_zero(uint64_t a, int nd)
{
    int fb = 4 * nd;
    return a == 0 || ((a >> (fb - 4)) & 0xf) != 0;
}

static uint64_t get(const uint8_t *p, int n)
{
    uint64_t v = 0;
    int i;
    for (i = 0; i < n; i++)
        v = v << 8 | p[i];
    return v;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint64_t a, b, r[8];
    hfp_short as, bs, s[6];
    unsigned char field[8];
    double x, y;
    diag err;
    int i;
    if (size < 16)
        return 0;
    a = get(data, 8);
    b = get(data + 8, 8);
    as = (hfp_short)(a >> 32);
    bs = (hfp_short)(b >> 32);
    s[0] = hfp_ae(as, bs); s[1] = hfp_se(as, bs); s[2] = hfp_de(as, bs);
    s[3] = hfp_sqe(bs); s[4] = hfp_her(bs); s[5] = hfp_me_short(as, bs);
    r[0] = hfp_ad(a, b); r[1] = hfp_sd(a, b); r[2] = hfp_md(a, b); r[3] = hfp_dd(a, b);
    r[4] = hfp_sqd(b); r[5] = hfp_hdr(b); r[6] = hfp_me(as, bs); r[7] = hfp_long_from_i32((int32_t)as);
    for (i = 0; i < 6; i++)
        if (!normal_or_zero(s[i], 6))
            abort();
    for (i = 0; i < 8; i++)
        if (!normal_or_zero(r[i], 14))
            abort();
    (void)hfp_ce(as, bs);
    (void)hfp_cd(a, b);
    (void)hfp_lrer(a);
    (void)hfp_lrdr(a, b);
    (void)hfp_short_to_i32(as);
    (void)hfp_long_to_i32(a);
    diag_init(&err);
    if (hfp_data_decode(data, 8, &x, "fuzz", 0, &err) == 0 && hfp_data_encode(x, 4, field, "fuzz", 0, &err) == 0
        && hfp_data_decode(field, 4, &y, "fuzz", 0, &err) == 0) {
        int e;
        frexp(x, &e);
        e = e >= 0 ? (e + 3) / 4 : -((-e) / 4);
        if (x != 0 && !(fabs(x - y) <= ldexp(1.0, 4 * e - 25)))
            abort();
    }
    return 0;
}
