/* dl_format — the element code table and the magic (see dl_format.h). */
#include "display5080/dl_format.h"

const uint8_t dl_magic[6] = {0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0};

const dl_format_code dl_format_codes[DL_FORMAT_NCODES] = {
    {.code = DL_POLYLINE, .name = "polyline", .since = 1},
    {.code = DL_SEGMENTS, .name = "segments", .since = 1},
    {.code = DL_FILL_RECT, .name = "fill-rect", .since = 1},
    {.code = DL_FILL_CIRCLE, .name = "fill-circle", .since = 1},
    {.code = DL_CIRCLE, .name = "circle", .since = 1},
    {.code = DL_BEGIN_POLYGON, .name = "begin-polygon", .since = 1},
    {.code = DL_END_POLYGON, .name = "end-polygon", .since = 1},
    {.code = DL_TEXT, .name = "text", .since = 1},
    {.code = DL_SRC_BLT, .name = "src-blt", .since = 2},
    {.code = DL_VIEWPORT, .name = "viewport", .since = 1},
    {.code = DL_SCISSOR, .name = "scissor", .since = 1},
    {.code = DL_BLT, .name = "blt", .since = 1},
    {.code = DL_BLT_EXPAND, .name = "blt-expand", .since = 2},
    {.code = DL_NOOP, .name = "noop", .since = 1},
    {.code = DL_LINE_TYPE, .name = "line-type", .since = 1},
    {.code = DL_LINE_COLOUR, .name = "line-colour", .since = 1},
    {.code = DL_TEXT_COLOUR, .name = "text-colour", .since = 2},
    {.code = DL_CHAR_HEIGHT, .name = "char-height", .since = 2},
    {.code = DL_CHAR_UP, .name = "char-up", .since = 2},
    {.code = DL_INTERIOR_STYLE, .name = "interior-style", .since = 2},
    {.code = DL_INTERIOR_COLOUR, .name = "interior-colour", .since = 1},
    {.code = DL_EDGE_FLAG, .name = "edge-flag", .since = 2},
    {.code = DL_EDGE_COLOUR, .name = "edge-colour", .since = 2},
    {.code = DL_LOGIC_OP, .name = "logic-op", .since = 1},
    {.code = DL_PLANE_MASK, .name = "plane-mask", .since = 1},
    {.code = DL_CODE_PAGE, .name = "code-page", .since = 2},
    {.code = DL_USER_LINE_STYLE, .name = "user-line-style", .since = 2},
    {.code = DL_LOAD_COLOURS, .name = "load-colours", .since = 1, .own = 1},
    {.code = DL_CLEAR, .name = "clear", .since = 1, .own = 1},
    {.code = DL_END, .name = "end", .since = 1, .own = 1},
    {.code = DL_RUN_ROW, .name = "run-row", .since = 1, .own = 1},
    {.code = DL_LINE_WIDTH, .name = "line-width", .since = 2, .own = 1},
};

int dl_format_slot(unsigned code)
{
    int i;
    for (i = 0; i < DL_FORMAT_NCODES; i++)
        if (dl_format_codes[i].code == code)
            return i;
    return -1;
}

const char *dl_format_name(unsigned code)
{
    int i = dl_format_slot(code);
    return i < 0 ? 0 : dl_format_codes[i].name;
}
