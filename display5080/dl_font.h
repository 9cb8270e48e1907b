/* dl_font — maprt's stroke font for the text element, in the spirit of the
 * 5081's vector text (the MegaPel's own fonts lived in adapter memory and are
 * not public): capitals, digits and common punctuation on a 4 x 6 grid,
 * drawn as strokes, with lower case shown as capitals and characters without
 * a glyph as a box. Also the byte-to-character tables of the code pages the
 * text element accepts (EBCDIC 037, and 437/819 for their ASCII range).
 * Data flow: dl_interp (text) -> dl_font -> strokes -> dl_cover. */
#ifndef DL_FONT_H
#define DL_FONT_H

#define DL_FONT_WIDTH 4        /* glyph grid: x 0..4, y 0..6, y up */
#define DL_FONT_HEIGHT 6
#define DL_FONT_ADVANCE 6      /* grid units from one character to the next */

/* The ASCII character a byte of the code page stands for, or 0 when it has
 * none (then the box is drawn). code_page: DL_CP_EBCDIC, DL_CP_PC or
 * DL_CP_LATIN1. */
unsigned dl_font_char(unsigned byte, unsigned code_page);

/* The strokes of ASCII character ch: digit pairs "xy" joined by lines, one
 * stroke per space-separated group ("" for space; the box for characters
 * without a glyph). */
const char *dl_font_glyph(unsigned ch);
#endif
