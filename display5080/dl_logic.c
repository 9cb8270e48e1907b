/* dl_logic — logic ops and plane mask (see dl_logic.h). The X11 function
 * code is a truth table: bit 0 is the result for (s=1,d=1), bit 1 for (1,0),
 * bit 2 for (0,1), bit 3 for (0,0). */
#include "display5080/dl_logic.h"

uint8_t dl_logic_apply(unsigned op, uint8_t s, uint8_t d, uint8_t m)
{
    unsigned f = (op - 1u) & 15u, r = 0;
    unsigned ns = ~(unsigned)s & 0xFFu, nd = ~(unsigned)d & 0xFFu;
    if (f & 1u) r |= (unsigned)s & d;
    if (f & 2u) r |= (unsigned)s & nd;
    if (f & 4u) r |= ns & d;
    if (f & 8u) r |= ns & nd;
    return (uint8_t)((r & m) | ((unsigned)d & ~(unsigned)m & 0xFFu));
}

void dl_logic_split(unsigned op, uint8_t s, uint8_t m, uint8_t *clr, uint8_t *set, uint8_t *inv)
{
    unsigned f = (op - 1u) & 15u, c = 0, st = 0, iv = 0, b;
    for (b = 0; b < 8; b++) {
        unsigned bit = 1u << b, one, zero;   /* results for d = 1 and d = 0 */
        if (!(m & bit))
            continue;
        if (s & bit) {
            one = f & 1u;
            zero = (f >> 1) & 1u;
        } else {
            one = (f >> 2) & 1u;
            zero = (f >> 3) & 1u;
        }
        if (!one && !zero)
            c |= bit;
        else if (one && zero)
            st |= bit;
        else if (!one && zero)
            iv |= bit;
    }
    *clr = (uint8_t)c;
    *set = (uint8_t)st;
    *inv = (uint8_t)iv;
}
