#!/usr/bin/env python3
"""Measures the panel's text in a window screenshot (an 8-bit RGB or RGBA PNG, top row first).

usage: measure_panel.py SHOT.png PANEL_WIDTH MIN_TEXT_PX

Text is what ImGui draws in white on the panel's dark background: a row of the panel (columns
0..PANEL_WIDTH) is a text row when one of its pixels has every channel above 200. A run of text
rows is one line of text; its height is the run's length. Prints every line's top and height;
exits 1 when the tallest line is under MIN_TEXT_PX, or when text reaches into the last
MIN_TEXT_PX / 3 rows of the window (the panel ran past its bottom edge and was cut there).
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), "8-bit RGB or RGBA only"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    bpp = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def main():
    path, panel, least = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    width, height, bpp, rows = read_png(path)
    text = []
    for row in rows:
        text.append(any(min(row[x * bpp:x * bpp + 3]) > 200 for x in range(min(panel, width))))
    lines, y = [], 0
    while y < height:
        if text[y]:
            top = y
            while y < height and text[y]:
                y += 1
            lines.append((top, y - top))
        y += 1
    for top, h in lines:
        print(f"text line at y = {top}: {h} px high")
    tallest = max((h for _, h in lines), default=0)
    bottom = max((top + h for top, h in lines), default=0)
    print(f"{len(lines)} lines; the tallest {tallest} px; the lowest ends at y = {bottom} of {height}")
    ok = True
    if tallest < least:
        print(f"text under {least} px high", file=sys.stderr)
        ok = False
    if bottom > height - least // 3:
        print(f"text reaches the window's bottom edge (y = {bottom} of {height})", file=sys.stderr)
        ok = False
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
