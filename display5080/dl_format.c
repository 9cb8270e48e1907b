/* dl_format — element names and the magic (see dl_format.h). */
#include "display5080/dl_format.h"

const uint8_t dl_magic[6] = {0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0};

const unsigned dl_format_codes[DL_FORMAT_NCODES] = {
    DL_POLYLINE, DL_SEGMENTS, DL_FILL_RECT, DL_FILL_CIRCLE, DL_CIRCLE, DL_BEGIN_POLYGON,
    DL_END_POLYGON, DL_TEXT, DL_VIEWPORT, DL_SCISSOR, DL_BLT, DL_NOOP, DL_LINE_TYPE,
    DL_LINE_COLOUR, DL_INTERIOR_COLOUR, DL_LOGIC_OP, DL_PLANE_MASK, DL_LOAD_COLOURS, DL_CLEAR,
    DL_END, DL_RUN_ROW,
};

int dl_format_slot(unsigned code)
{
    int i;
    for (i = 0; i < DL_FORMAT_NCODES; i++)
        if (dl_format_codes[i] == code)
            return i;
    return -1;
}

const char *dl_format_name(unsigned code)
{
    switch (code) {
    case DL_POLYLINE: return "polyline";
    case DL_SEGMENTS: return "segments";
    case DL_FILL_RECT: return "fill-rect";
    case DL_FILL_CIRCLE: return "fill-circle";
    case DL_CIRCLE: return "circle";
    case DL_BEGIN_POLYGON: return "begin-polygon";
    case DL_END_POLYGON: return "end-polygon";
    case DL_TEXT: return "text";
    case DL_VIEWPORT: return "viewport";
    case DL_SCISSOR: return "scissor";
    case DL_BLT: return "blt";
    case DL_NOOP: return "noop";
    case DL_LINE_TYPE: return "line-type";
    case DL_LINE_COLOUR: return "line-colour";
    case DL_INTERIOR_COLOUR: return "interior-colour";
    case DL_LOGIC_OP: return "logic-op";
    case DL_PLANE_MASK: return "plane-mask";
    case DL_LOAD_COLOURS: return "load-colours";
    case DL_CLEAR: return "clear";
    case DL_END: return "end";
    case DL_RUN_ROW: return "run-row";
    default: return 0;
    }
}
