/* hfp — System/370 hexadecimal floating point, as the IBM 3081 did it.
 *
 * Numbers are register images: a short number (hfp_short) is bit 0 sign,
 * bits 1-7 characteristic (exponent + 64), bits 8-31 a six-digit hex
 * fraction; a long number (hfp_long) has a 14-digit fraction in bits 8-63.
 * Value = (-1)^sign * 0.fraction(hex) * 16^(characteristic - 64).
 *
 * Each function is one instruction of the System/370 Principles of
 * Operation (GA22-7000-10, 1987), named by its mnemonic; the rules and
 * their sources are in docs/numerics.md:
 *   AE AD  SE SD   normalised add/subtract, one guard digit, truncation
 *   ME             short operands, exact long product (MER/ME)
 *   MD             long product truncated to 14 digits
 *   DE DD          quotient truncated
 *   SQE SQD        square root rounded to nearest (ESA/390 square-root
 *                  facility, as Hercules executes it; the 3081 had none)
 *   HER HDR        halve: shift right one bit into the guard digit, normalise
 *   CE CD          compare (condition code as -1, 0, +1)
 *   LRER LRDR      load rounded: long to short, extended to long
 * Operands may be unnormalised. Every result is normalised or a true zero
 * (all bits zero), except LRER/LRDR, which do not normalise (of a normalised
 * operand they give a normalised result).
 *
 * Program interruptions are modelled as a program that handles them: each
 * exception adds one to hfp_exc[kind] (per thread, like fx_overflows) and
 * the result is fixed up:
 *   exponent overflow    the largest magnitude, of the result's sign
 *   exponent underflow   true zero (what the hardware gives with the
 *                        exponent-underflow mask off)
 *   significance         true zero (the hardware result with the
 *                        significance mask off)
 *   divide by zero       the largest magnitude, of the quotient's sign
 *                        (signs of dividend and divisor), or true zero
 *                        for 0/0
 *   square root < 0      true zero
 *   conversion           a NaN or out-of-range integer conversion:
 *                        zero or the nearest integer limit */
#ifndef HFP_H
#define HFP_H
#include <stdint.h>

typedef uint32_t hfp_short;
typedef uint64_t hfp_long;

enum hfp_exc_kind {
    HFP_EXC_OVERFLOW, HFP_EXC_UNDERFLOW, HFP_EXC_SIGNIFICANCE,
    HFP_EXC_DIVIDE, HFP_EXC_SQRT, HFP_EXC_CONVERT, HFP_EXC_N
};
extern unsigned long hfp_exc[HFP_EXC_N];
#pragma omp threadprivate(hfp_exc)
/* Counter names as --stats prints them ("overflows", ...). */
extern const char *const hfp_exc_name[HFP_EXC_N];

#define HFP_SHORT_MAX ((hfp_short)0x7fffffffu)
#define HFP_LONG_MAX  ((hfp_long)0x7fffffffffffffffu)

hfp_short hfp_ae(hfp_short a, hfp_short b);
hfp_short hfp_se(hfp_short a, hfp_short b);
hfp_long hfp_me(hfp_short a, hfp_short b);
hfp_short hfp_de(hfp_short a, hfp_short b);
hfp_short hfp_sqe(hfp_short a);
hfp_short hfp_her(hfp_short a);
int hfp_ce(hfp_short a, hfp_short b);
hfp_short hfp_lrer(hfp_long a);

hfp_long hfp_ad(hfp_long a, hfp_long b);
hfp_long hfp_sd(hfp_long a, hfp_long b);
hfp_long hfp_md(hfp_long a, hfp_long b);
hfp_long hfp_dd(hfp_long a, hfp_long b);
hfp_long hfp_sqd(hfp_long a);
hfp_long hfp_hdr(hfp_long a);
int hfp_cd(hfp_long a, hfp_long b);
/* Extended operand as its two long parts (high, low); the low part's sign
 * and characteristic are ignored, as the PoO says. */
hfp_long hfp_lrdr(hfp_long hi, hfp_long lo);

/* A short product as a FORTRAN REAL*4 expression uses it: the leading word
 * of the ME result (the short instructions read only that word). */
static inline hfp_short hfp_me_short(hfp_short a, hfp_short b) { return (hfp_short)(hfp_me(a, b) >> 32); }

/* Integers. The 370 has no convert instruction; compilers built the long
 * number X'4E000000 nnnnnnnn' and normalised it, exact for every int32_t.
 * A short result keeps the leading six digits (truncation, as storing the
 * leading word does). To integer: truncation toward zero; out of range
 * saturates and counts HFP_EXC_CONVERT. */
hfp_long hfp_long_from_i32(int32_t i);
hfp_short hfp_short_from_i32(int32_t i);
int32_t hfp_long_to_i32(hfp_long a);
int32_t hfp_short_to_i32(hfp_short a);

/* IEEE binary64. Every double in the HFP range is exactly a long number
 * (53 significant bits fit in 14 hex digits), so hfp_long_from_double is
 * exact; hfp_short_from_double is that long number loaded rounded (LRER:
 * nearest, ties away from zero). Out of range: overflow or underflow
 * counted, largest magnitude or true zero; NaN: counted as a conversion
 * exception, true zero. hfp_short_to_double is exact; hfp_long_to_double
 * rounds 56 bits to 53, to nearest with ties to even. */
hfp_long hfp_long_from_double(double x);
hfp_short hfp_short_from_double(double x);
double hfp_long_to_double(hfp_long a);
double hfp_short_to_double(hfp_short a);
#endif
