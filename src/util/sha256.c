/* sha256 — FIPS 180-4 SHA-256 (see sha256.h). Blocks go through the x86
 * SHA extensions where the processor has them (5.2 times the portable
 * rounds' speed on 20 MB; a deck of 10,000 objects is 665 KB), else
 * through the portable rounds. Kept here rather than taken from libnettle
 * or libcrypto: loading either costs every process more than hashing a
 * deck (docs/performance.md, runs H and I). */
#include "util/sha256.h"
#include <stdio.h>
#include <string.h>
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define SHA256_X86 1
#include <cpuid.h>
#include <immintrin.h>
#endif

static const uint32_t sha256_k[64] = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2,
};

#define SHA256_ROR(x, n) (((x) >> (n)) | ((x) << (32 - (n))))
/* One round on the working variables as they stand in round i + j, the
 * eight unrolled so that no variable is copied to the next: Sigma1 and
 * Sigma0 as nested rotations (one copy each), Ch as g ^ (e & (f ^ g)), Maj
 * as b ^ ((a ^ b) & (b ^ c)) with b ^ c the previous round's a ^ b. */
#define SHA256_ROUND(a, b, c, d, e, f, g, h, j)                                             \
    do {                                                                                   \
        uint32_t t1 = h + SHA256_ROR(e ^ SHA256_ROR(e ^ SHA256_ROR(e, 14), 5), 6)             \
                      + (g ^ (e & (f ^ g))) + sha256_k[i + j] + w[i + j];                   \
        uint32_t ab = a ^ b;                                                               \
        d += t1;                                                                           \
        h = t1 + SHA256_ROR(a ^ SHA256_ROR(a ^ SHA256_ROR(a, 9), 11), 2) + (b ^ (ab & bc));  \
        bc = ab;                                                                           \
    } while (0)

static void sha256_block1(uint32_t *hs, const unsigned char *p)
{
    uint32_t w[64], a, b, c, d, e, f, g, h, bc;
    int i;
    for (i = 0; i < 16; i++)
        w[i] = (uint32_t)p[4 * i] << 24 | (uint32_t)p[4 * i + 1] << 16 | (uint32_t)p[4 * i + 2] << 8
               | p[4 * i + 3];
    for (i = 16; i < 64; i++) {
        uint32_t x = w[i - 15], y = w[i - 2];
        uint32_t s0 = SHA256_ROR(x ^ SHA256_ROR(x, 11), 7) ^ (x >> 3);
        uint32_t s1 = SHA256_ROR(y ^ SHA256_ROR(y, 2), 17) ^ (y >> 10);
        w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    a = hs[0]; b = hs[1]; c = hs[2]; d = hs[3];
    e = hs[4]; f = hs[5]; g = hs[6]; h = hs[7];
    bc = b ^ c;
    for (i = 0; i < 64; i += 8) {
        SHA256_ROUND(a, b, c, d, e, f, g, h, 0);
        SHA256_ROUND(h, a, b, c, d, e, f, g, 1);
        SHA256_ROUND(g, h, a, b, c, d, e, f, 2);
        SHA256_ROUND(f, g, h, a, b, c, d, e, 3);
        SHA256_ROUND(e, f, g, h, a, b, c, d, 4);
        SHA256_ROUND(d, e, f, g, h, a, b, c, 5);
        SHA256_ROUND(c, d, e, f, g, h, a, b, 6);
        SHA256_ROUND(b, c, d, e, f, g, h, a, 7);
    }
    hs[0] += a; hs[1] += b; hs[2] += c; hs[3] += d;
    hs[4] += e; hs[5] += f; hs[6] += g; hs[7] += h;
}

#if defined(SHA256_X86)
/* n blocks by SHA256RNDS2 (two rounds), SHA256MSG1 and SHA256MSG2 (the
 * message schedule, four words at a time). The instructions keep the state
 * as ABEF and CDGH (Intel SHA extensions reference, 2013), so it is
 * shuffled in from h[] and back once per call. */
__attribute__((target("sha,sse4.1"))) static void sha256_blocks_shani(uint32_t *hs, const unsigned char *p,
                                                                      size_t n)
{
    const __m128i bswap = _mm_set_epi64x(0x0c0d0e0f08090a0bLL, 0x0405060700010203LL);
    __m128i dcba = _mm_loadu_si128((const __m128i *)(const void *)&hs[0]);
    __m128i hgfe = _mm_loadu_si128((const __m128i *)(const void *)&hs[4]);
    __m128i cdab = _mm_shuffle_epi32(dcba, 0xb1), efgh = _mm_shuffle_epi32(hgfe, 0x1b);
    __m128i abef = _mm_alignr_epi8(cdab, efgh, 8), cdgh = _mm_blend_epi16(efgh, cdab, 0xf0);
    for (; n > 0; n--, p += 64) {
        __m128i w[4], abef0 = abef, cdgh0 = cdgh;
        int g;
        for (g = 0; g < 16; g++) {
            __m128i k = _mm_loadu_si128((const __m128i *)(const void *)&sha256_k[4 * g]), m;
            if (g < 4)
                w[g] = _mm_shuffle_epi8(_mm_loadu_si128((const __m128i *)(const void *)(p + 16 * g)), bswap);
            else   /* W[4g..4g+3] from the four groups before, in place of the oldest */
                w[g & 3] = _mm_sha256msg2_epu32(
                    _mm_add_epi32(_mm_sha256msg1_epu32(w[g & 3], w[(g + 1) & 3]),
                                  _mm_alignr_epi8(w[(g + 3) & 3], w[(g + 2) & 3], 4)),
                    w[(g + 3) & 3]);
            m = _mm_add_epi32(w[g & 3], k);
            cdgh = _mm_sha256rnds2_epu32(cdgh, abef, m);
            abef = _mm_sha256rnds2_epu32(abef, cdgh, _mm_shuffle_epi32(m, 0x0e));
        }
        abef = _mm_add_epi32(abef, abef0);
        cdgh = _mm_add_epi32(cdgh, cdgh0);
    }
    {
        __m128i feba = _mm_shuffle_epi32(abef, 0x1b), dchg = _mm_shuffle_epi32(cdgh, 0xb1);
        _mm_storeu_si128((__m128i *)(void *)&hs[0], _mm_blend_epi16(feba, dchg, 0xf0));
        _mm_storeu_si128((__m128i *)(void *)&hs[4], _mm_alignr_epi8(dchg, feba, 8));
    }
}

/* SHA (CPUID leaf 7, EBX bit 29), SSSE3 and SSE4.1 (leaf 1, ECX bits 9 and
 * 19): what sha256_blocks_shani uses. */
static int sha256_have_shani(void)
{
    unsigned a, b, c, d;
    if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & (1u << 9)) || !(c & (1u << 19)))
        return 0;
    return __get_cpuid_count(7, 0, &a, &b, &c, &d) && (b & (1u << 29));
}
#else
static int sha256_have_shani(void) { return 0; }
#endif

static void sha256_blocks(sha256 *s, const unsigned char *p, size_t n)
{
#if defined(SHA256_X86)
    if (s->shani) {
        sha256_blocks_shani(s->h, p, n);
        return;
    }
#endif
    for (; n > 0; n--, p += 64)
        sha256_block1(s->h, p);
}

void sha256_init(sha256 *s)
{
    static const uint32_t h0[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                   0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    memcpy(s->h, h0, sizeof h0);
    s->len = 0;
    s->nbuf = 0;
    s->shani = sha256_have_shani();
}

void sha256_update(sha256 *s, const void *data, size_t len)
{
    const unsigned char *p = data;
    s->len += len;
    while (len > 0) {
        size_t n = 64 - s->nbuf < len ? 64 - s->nbuf : len;
        if (s->nbuf == 0 && len >= 64) {          /* whole blocks need no copy */
            sha256_blocks(s, p, len / 64);
            p += len / 64 * 64;
            len %= 64;
            continue;
        }
        memcpy(s->buf + s->nbuf, p, n);
        s->nbuf += n;
        p += n;
        len -= n;
        if (s->nbuf == 64) {
            sha256_blocks(s, s->buf, 1);
            s->nbuf = 0;
        }
    }
}

void sha256_hex(sha256 *s, char out[65])
{
    uint64_t bits = s->len * 8;
    unsigned char pad[72];
    size_t n = (s->nbuf < 56 ? 56 : 120) - s->nbuf;
    int i;
    memset(pad, 0, sizeof pad);
    pad[0] = 0x80;
    for (i = 0; i < 8; i++)
        pad[n + (size_t)i] = (unsigned char)(bits >> (56 - 8 * i));
    sha256_update(s, pad, n + 8);
    for (i = 0; i < 8; i++)
        snprintf(out + 8 * i, 9, "%08x", (unsigned)s->h[i]);
}
