#!/usr/bin/env python3
"""Reads text the window draws off its screenshots (8-bit RGB or RGBA PNGs, top row first).

usage: screen_text.py status BEFORE.png AFTER.png X0 MIN_PX
         a line shown over the picture: in AFTER, right of column X0 (the panel's edge), the rows
         where it differs from BEFORE by white text (every channel above 200) form a run at least
         MIN_PX high (the UI scale's text), and the run starts in the window's upper half
       screen_text.py legend SHOT.png PX
         the stencil legend's digits: the lowest run of rows holding white pixels (the legend's
         last row of digits, white on its grey band) is exactly PX high (5 dots of the window's
         legendDot: the panel's 13 px text x the UI scale)
Prints what it measured; exits 1 when the check fails.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from measure_panel import read_png  # noqa: E402


def runs(flags):
    """(top, height) of each run of true rows."""
    out, y = [], 0
    while y < len(flags):
        if flags[y]:
            top = y
            while y < len(flags) and flags[y]:
                y += 1
            out.append((top, y - top))
        y += 1
    return out


def white(row, x, bpp):
    return min(row[x * bpp:x * bpp + 3]) > 200


def main():
    mode = sys.argv[1]
    if mode == "status":
        before, after, x0, least = sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
        w, h, bpp, a = read_png(before)
        w2, h2, bpp2, b = read_png(after)
        assert (w, h, bpp) == (w2, h2, bpp2), "the two screenshots differ in size"
        flags = [any(a[y][x * bpp:x * bpp + 3] != b[y][x * bpp:x * bpp + 3] and white(b[y], x, bpp)
                     for x in range(x0, w)) for y in range(h)]
        found = runs(flags)
        print(f"new white text right of x = {x0}: rows (top, height) {found}")
        tall = [r for r in found if r[1] >= least and r[0] < h // 2]
        if not tall:
            print(f"no new line of text {least} px or taller in the upper half of the picture")
            return 1
        return 0
    if mode == "legend":
        shot, px = sys.argv[2], int(sys.argv[3])
        w, h, bpp, rows = read_png(shot)
        found = runs([any(white(row, x, bpp) for x in range(w)) for row in rows])
        if not found:
            print("no white text in the picture")
            return 1
        top, height = found[-1]
        print(f"the legend's last row of digits: {height} px high at y = {top} (wanted {px})")
        return 0 if height == px else 1
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main())
