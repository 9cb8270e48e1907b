#!/usr/bin/env python3
"""Writes the PNG images the sample scenes name (scenes/*.png), with the
standard library only, so that they can be regenerated exactly:
  pds-pixel.png  32 x 32, three flat colours (a pixel-array PDS whose colours
                 map to attributes through KEY #RRGGBB lines)
  label.png      256 x 64 RGB label for the foil-sealed container's side
Usage: python3 tools/scene_images.py [DIR]   (default: scenes)"""
import math
import struct
import sys
import zlib


def write_png(path, width, height, rows):
    """rows: list of bytes objects, RGB, top row first."""
    raw = b"".join(b"\x00" + r for r in rows)

    def chunk(tag, data):
        c = struct.pack(">I", len(data)) + tag + data
        return c + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def pixel_pds(path):
    """A diamond (red) inside a ring (blue) on white, 32 x 32."""
    colours = {0: (255, 255, 255), 1: (200, 40, 30), 2: (30, 60, 200)}
    rows = []
    for y in range(32):
        row = bytearray()
        for x in range(32):
            cx, cy = x - 15.5, y - 15.5
            r = math.hypot(cx, cy)
            k = 1 if abs(cx) + abs(cy) < 9 else 2 if 11 <= r < 14.5 else 0
            row += bytes(colours[k])
        rows.append(bytes(row))
    write_png(path, 32, 32, rows)


def label(path):
    """Horizontal stripes and a row of diamonds: a printed label."""
    w, h = 256, 64
    rows = []
    for y in range(h):
        row = bytearray()
        for x in range(w):
            if y < 6 or y >= h - 6:
                c = (30, 40, 120)
            elif y < 9 or y >= h - 9:
                c = (220, 180, 60)
            else:
                cx = (x % 32) - 15.5
                cy = y - 31.5
                c = (200, 30, 40) if abs(cx) + abs(cy) < 14 else (245, 240, 225)
            row += bytes(c)
        rows.append(bytes(row))
    write_png(path, w, h, rows)


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "scenes"
    pixel_pds(d + "/pds-pixel.png")
    label(d + "/label.png")


if __name__ == "__main__":
    main()
