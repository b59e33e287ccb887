#!/usr/bin/env python3
"""Checks that no slider's text sits over its grab in a window screenshot (measure_panel.py reads it).

usage: grab_clear.py SHOT.png PANEL_WIDTH

A grab is drawn in ImGui's dark style's SliderGrab colour, (61, 133, 224) within 3 a channel, in the
panel (columns 0..PANEL_WIDTH). Each row's grab pixels span a grab's width; text over the grab is a
pixel inside that span that is light (every channel above 150: white text, or its anti-aliased edge
blended over the blue). Prints the grabs' rows and the text pixels found over them; exits 1 when
there is any, or when no grab is found at all (the check would see nothing).
"""
import sys

from measure_panel import read_png

GRAB = (61, 133, 224)


def main():
    path, panel = sys.argv[1], int(sys.argv[2])
    width, height, bpp, rows = read_png(path)
    grab_rows, over = 0, 0
    for y, row in enumerate(rows):
        pixel = [row[x * bpp:x * bpp + 3] for x in range(min(panel, width))]
        xs = [x for x, p in enumerate(pixel) if all(abs(p[i] - GRAB[i]) <= 3 for i in range(3))]
        if not xs:
            continue
        grab_rows += 1
        # Runs of grab pixels no more than a glyph's gap apart are one grab (the text cuts it).
        runs, start, last = [], xs[0], xs[0]
        for x in xs[1:]:
            if x - last > 12:
                runs.append((start, last))
                start = x
            last = x
        runs.append((start, last))
        for a, b in runs:
            light = [x for x in range(a, b + 1) if min(pixel[x]) > 150]
            if light:
                over += len(light)
                print(f"y = {y}: text over the grab at x = {light[0]}..{light[-1]} (grab {a}..{b})")
    print(f"{grab_rows} rows of grab; {over} text pixels over a grab")
    if grab_rows == 0:
        print("no slider grab in the picture", file=sys.stderr)
        sys.exit(1)
    sys.exit(1 if over else 0)


main()
