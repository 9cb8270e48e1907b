/* dl_format — the DL5080 byte format: header layout, element codes, limits and
 * big-endian field access. Shared by the encoder (dl_encode), the decoder
 * (dl_decode) and everything that reads decoded elements. The elements follow
 * IBM's MegaPel structure elements for the 5081 display as IBM's X11 driver
 * sends them, plus a few of maprt's own in the reserved 0x5Fxx block (see
 * docs/dl5080.md for the element table and its sources). */
#ifndef DL_FORMAT_H
#define DL_FORMAT_H
#include <stddef.h>
#include <stdint.h>

#define DL_HEADER_SIZE 16
#define DL_VERSION 2                /* written; version 1 lists are converted on read */
#define DL_VERSION_1 1
#define DL_FLAG_DAC8 0x0001u        /* header flags bit 0: 8-bit DAC, else 4-bit */
#define DL_MAX_SIDE 4096            /* largest width or height */
#define DL_MAX_ELEMENT 65534        /* largest element length (u16, even) */
#define DL_COLOURS 256              /* colour table entries */
#define DL_RAW_SIDE 1024            /* a raw MegaPel stream's screen: the 5081 */

/* Element codes: MegaPel codes, then maprt's own block. */
enum dl_code {
    DL_POLYLINE = 0x5000,
    DL_SEGMENTS = 0x5003,
    DL_FILL_RECT = 0x5004,
    DL_FILL_CIRCLE = 0x5005,
    DL_CIRCLE = 0x5006,
    DL_BEGIN_POLYGON = 0x500A,
    DL_END_POLYGON = 0x500B,
    DL_TEXT = 0x500D,
    DL_SRC_BLT = 0x5012,
    DL_VIEWPORT = 0x5016,
    DL_SCISSOR = 0x5017,
    DL_BLT = 0x5018,
    DL_BLT_EXPAND = 0x5019,
    DL_NOOP = 0x501C,
    DL_LINE_TYPE = 0x5040,
    DL_LINE_COLOUR = 0x5042,
    DL_TEXT_COLOUR = 0x504A,
    DL_CHAR_HEIGHT = 0x504B,
    DL_CHAR_UP = 0x504C,
    DL_INTERIOR_STYLE = 0x5051,
    DL_INTERIOR_COLOUR = 0x5053,
    DL_EDGE_FLAG = 0x5054,
    DL_EDGE_COLOUR = 0x5056,
    DL_LOGIC_OP = 0x5060,
    DL_PLANE_MASK = 0x5061,
    DL_CODE_PAGE = 0x5062,
    DL_USER_LINE_STYLE = 0x5066,
    DL_LOAD_COLOURS = 0x5F00,
    DL_CLEAR = 0x5F01,
    DL_END = 0x5F02,
    DL_RUN_ROW = 0x5F03,
    DL_LINE_WIDTH = 0x5F04
};

#define DL_LINE_SOLID 1             /* MegaPel line types (mpel.h) */
#define DL_LINE_USER 50             /* user style, restarted by each element */
#define DL_LINE_USER_CONT 150       /* user style, continued across elements */
#define DL_OP_COPY 4                /* logic ops are X11 GC functions + 1 (1..16) */
#define DL_OP_XOR 7
#define DL_BLT_BPP 8                /* the only BLT depth defined */
#define DL_INTERIOR_SOLID 2         /* the driver's solid interior style */
#define DL_EDGE_ON 1                /* edge flag: 1 draw the edge, 2 do not */
#define DL_EDGE_OFF 2
#define DL_CP_EBCDIC 37             /* text code pages: maprt's values (CCSIDs) */
#define DL_CP_PC 437
#define DL_CP_LATIN1 819
#define DL_MAX_LINE_WIDTH 64
#define DL_MAX_CHAR_HEIGHT 1024

/* The plane-mask word as the driver sends it: planes that may NOT be
 * written, in the high byte (bit 8 + k for plane k); 0 = all writable. */
static inline unsigned dl_format_mask_word(unsigned writable) { return (~writable & 0xFFu) << 8; }
static inline unsigned dl_format_mask_planes(unsigned word) { return ~(word >> 8) & 0xFFu; }

/* The six magic bytes: "DL5080" in EBCDIC. */
extern const uint8_t dl_magic[6];

static inline unsigned dl_be16(const uint8_t *p) { return (unsigned)p[0] << 8 | p[1]; }
static inline int dl_bes16(const uint8_t *p)
{
    unsigned v = dl_be16(p);
    return v >= 0x8000u ? (int)v - 0x10000 : (int)v;
}
static inline uint32_t dl_be32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* One known element code. */
typedef struct dl_format_code {
    unsigned code;
    const char *name;          /* "polyline" */
    unsigned since;            /* first DL5080 version that has it */
    int own;                   /* 1: maprt's own element, not MegaPel's */
} dl_format_code;

/* Every element code, in code order. */
#define DL_FORMAT_NCODES 32
extern const dl_format_code dl_format_codes[DL_FORMAT_NCODES];
/* Index of code in dl_format_codes, or -1. */
int dl_format_slot(unsigned code);
/* Name of an element code ("polyline"), or NULL for an unknown code. */
const char *dl_format_name(unsigned code);
#endif
