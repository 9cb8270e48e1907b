/* sha256 — SHA-256 (FIPS 180-4), for the deck checksum in a picture's
 * provenance: the same hex digest `sha256sum DECK` prints. */
#ifndef SHA256_H
#define SHA256_H
#include <stddef.h>
#include <stdint.h>

typedef struct sha256 {
    uint32_t h[8];
    uint64_t len;             /* bytes hashed so far */
    unsigned char buf[64];
    size_t nbuf;
    int shani;                /* blocks by the x86 SHA extensions (sha256_init
                                 sets it where the processor has them; 0
                                 forces the portable rounds) */
} sha256;

void sha256_init(sha256 *s);
void sha256_update(sha256 *s, const void *data, size_t len);
/* Finishes and writes the digest as 64 lowercase hex digits and a NUL. */
void sha256_hex(sha256 *s, char out[65]);
#endif
