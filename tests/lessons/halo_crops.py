#!/usr/bin/env python3
"""Lesson 11's faults, enlarged: for each fault variant and the variant that fixes it, both rendered
at SIZE (the golden size by default) and --time 1, cropped to the pixels where they differ (plus a
margin), scaled up by whole pixels (nearest neighbour), and set side by side: the fault, the fix,
and where they differ (magenta over the fault, dimmed). One PNG per fault in OUT_DIR.

    tests/lessons/halo_crops.py BUILD_DIR OUT_DIR [SIZE]    # SIZE 320x240 by default

Plain Python: the PNGs are read and written by tests/lessons/png_io.py.
"""
import pathlib
import subprocess
import sys
import tempfile

import png_io

# name: (fault variant, fixed variant)
PAIRS = {
    "no-invert": ("no-invert", "recipe"),
    "counts-no-invert": ("counts-no-invert", "counts"),
    "floor-cut": ("floor-cut", "recipe"),
    "two-halos-one-bit": ("counts-two-halos-one-bit", "counts-two-halos"),
    "occluder": ("occluder", "occluder-fixed"),
}
MARGIN, TARGET, GAP = 8, 360, 4  # pixels of margin; the crop's longer side scaled to about TARGET


def read_png(path):
    """Rows of (r, g, b) tuples, top row first."""
    w, h, c, pixels = png_io.read_png(path)
    return [[tuple(pixels[(y * w + x) * c:(y * w + x) * c + 3]) for x in range(w)] for y in range(h)]


def write_png(path, rows):
    png_io.write_png(path, len(rows[0]), len(rows), 3, b"".join(bytes(v for px in row for v in px) for row in rows))


def render(exe, variant, size, folder):
    out = folder / f"{variant}.png"
    subprocess.run([str(exe), "--headless", "--quiet", "--size", size, "--time", "1", "--variant", variant,
                    "--out", str(out)], check=True)
    return read_png(out)


def main():
    if len(sys.argv) < 3 or "--help" in sys.argv:
        sys.exit(__doc__)
    exe = pathlib.Path(sys.argv[1]) / "lessons" / "11-halo"
    out_dir = pathlib.Path(sys.argv[2])
    size = sys.argv[3] if len(sys.argv) > 3 else "320x240"
    out_dir.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for name, (fault, fixed) in PAIRS.items():
            a, b = render(exe, fault, size, pathlib.Path(tmp)), render(exe, fixed, size, pathlib.Path(tmp))
            h, w = len(a), len(a[0])
            diff = [(x, y) for y in range(h) for x in range(w) if a[y][x] != b[y][x]]
            if not diff:
                sys.exit(f"{fault} and {fixed} are the same picture")
            x0, x1 = max(0, min(x for x, _ in diff) - MARGIN), min(w, max(x for x, _ in diff) + MARGIN + 1)
            y0, y1 = max(0, min(y for _, y in diff) - MARGIN), min(h, max(y for _, y in diff) + MARGIN + 1)
            scale = max(2, min(8, TARGET // max(x1 - x0, y1 - y0)))
            marked = set(diff)
            where = [[(255, 0, 255) if (x, y) in marked else tuple(v // 3 for v in a[y][x]) for x in range(w)]
                     for y in range(h)]
            panels = [[row[x0:x1] for row in img[y0:y1]] for img in (a, b, where)]
            rows = []
            for y in range(y1 - y0):
                row = []
                for i, p in enumerate(panels):
                    row += [px for px in p[y] for _ in range(scale)]
                    if i < 2:
                        row += [(255, 255, 255)] * GAP
                rows += [row] * scale
            write_png(out_dir / f"{name}.png", rows)
            print(f"{name}: {fault} | {fixed} | {len(diff)} pixels differ; "
                  f"crop x {x0}..{x1 - 1}, y {y0}..{y1 - 1} (of {size}), {scale}x")


if __name__ == "__main__":
    main()
