/* hfp_data — HFP fields in data, to and from IEEE (see hfp_data.h). */
#include "num/hfp_data.h"
#include "num/hfp.h"
#include <math.h>
#include <string.h>

int hfp_data_decode(const unsigned char *p, size_t width, double *out,
                    const char *file, long long off, diag *err)
{
    uint64_t v = 0;
    size_t i;
    if (width != 4 && width != 8)
        return diag_offset(err, DIAG_INPUT, file, off, "HFP field of %zu bytes (4 or 8)", width);
    for (i = 0; i < width; i++)
        v = v << 8 | p[i];
    *out = width == 4 ? hfp_short_to_double((hfp_short)v) : hfp_long_to_double(v);
    return 0;
}

int hfp_data_encode(double x, size_t width, unsigned char *p, const char *file,
                    long long off, diag *err)
{
    unsigned long before[HFP_EXC_N];
    uint64_t v;
    size_t i;
    if (width != 4 && width != 8)
        return diag_offset(err, DIAG_INPUT, file, off, "HFP field of %zu bytes (4 or 8)", width);
    if (x != x || isinf(x))
        return diag_offset(err, DIAG_INPUT, file, off, "%g has no HFP form", x);
    memcpy(before, hfp_exc, sizeof before);
    v = width == 4 ? hfp_short_from_double(x) : hfp_long_from_double(x);
    /* A refused value is not an arithmetic event: the counters are restored. */
    if (hfp_exc[HFP_EXC_OVERFLOW] != before[HFP_EXC_OVERFLOW]) {
        memcpy(hfp_exc, before, sizeof before);
        return diag_offset(err, DIAG_INPUT, file, off,
                           "%g is above the largest HFP %s number (about 7.2e75)", x,
                           width == 4 ? "short" : "long");
    }
    if (hfp_exc[HFP_EXC_UNDERFLOW] != before[HFP_EXC_UNDERFLOW]) {
        memcpy(hfp_exc, before, sizeof before);
        return diag_offset(err, DIAG_INPUT, file, off,
                           "%g is below the smallest HFP magnitude 16^-65 (about 5.4e-79)", x);
    }
    for (i = 0; i < width; i++)
        p[i] = (unsigned char)(v >> (8 * (width - 1 - i)));
    return 0;
}
