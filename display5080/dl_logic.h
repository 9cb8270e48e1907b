/* dl_logic — the 5081's per-pixel write rule: one of the 16 boolean logic ops
 * of source and destination (DL5080 op = X11 GC function + 1, 4 = copy,
 * 7 = xor), then the plane mask keeps unmasked bits of the destination.
 * The software raster applies it directly; the GL backends use the split
 * form, which turns any op and mask into at most three constant passes
 * (AND, OR, XOR) that glLogicOp can do exactly. */
#ifndef DL_LOGIC_H
#define DL_LOGIC_H
#include <stdint.h>

/* New destination for op (1..16), source s, destination d, plane mask m. */
uint8_t dl_logic_apply(unsigned op, uint8_t s, uint8_t d, uint8_t m);

/* Splits (op, s, m) into bit masks such that for every d:
 *   dl_logic_apply(op, s, d, m) == ((d & ~clr) | set) ^ inv.
 * Bits of clr, set and inv are disjoint and all lie inside m. */
void dl_logic_split(unsigned op, uint8_t s, uint8_t m, uint8_t *clr, uint8_t *set, uint8_t *inv);
#endif
