#!/usr/bin/env python3
"""Lesson 12's strips and tables: the dissolve at several states per pattern, and what it costs.

Renders lesson 12 headless and writes docs/figures/12-dissolve-strips/strip-<pattern>.png (beside
docs/figures/12-dissolve/, which the docs-figures target rewrites): the frame at states
k = 0, 32, 64, 128, 192, 224, 256 side by side (the painted mask: k = 128 at times 0.25 s to 4 s,
the brush's stroke growing); crop-<pattern>.png for white noise, Bayer and blue noise: the centre
40x40 pixels at k = 64, 128, 192, each scene flat (A red, B blue), magnified 4 times; and
start-clamped-crop.png: the top left 80x60 pixels of the clamped reference's state 0, magnified 4
times. Then prints two Markdown tables of times: each pattern's making time (wall time, the
lesson's --stats with --set measure=1); and the CPU time per frame (llvmpipe draws on the CPU; CPU time,
unlike wall time, hardly changes when other work shares the machine) per method, pattern and state,
with and without WORK iterations of extra work per fragment: FRAMES + 1 frames less one frame
(which writes the pattern), over FRAMES. The page's counts (clumpiness, fragments) are written by
tests/docs/page_tables.py.

    tests/lessons/dissolve_figures.py BUILD_DIR [--no-strips] [--no-timing]
    tests/lessons/dissolve_figures.py BUILD_DIR --figures-only OUT_DIR    # the pictures only, into OUT_DIR

Reads and writes PNG with the standard library only (tests/lessons/png_io.py).
"""
import json
import pathlib
import resource
import sys
import tempfile

import png_io
from lesson_run import run

ROOT = pathlib.Path(__file__).resolve().parents[2]
PATTERNS = ["white noise", "Bayer", "blue noise", "linear wipe", "radial wipe", "clock wipe", "painted"]
SLUGS = ["white-noise", "bayer", "blue-noise", "linear-wipe", "radial-wipe", "clock-wipe", "painted"]
METHODS = ["stencil", "draw both, mix", "shade both, discard"]
STATES = [0, 32, 64, 128, 192, 224, 256]
PAINT_TIMES = [0.25, 0.5, 1, 1.5, 2, 3, 4]
# The crops, for the three dithers (the wipes and the painted mask have no grain to lose): states
# 64, 128, 192, each scene flat (A red, B blue), a CROP-pixel square from the frame's centre at
# 320x240, magnified ZOOM times.
CROP_SLUGS, CROP_STATES, CROP, ZOOM = ["white-noise", "bayer", "blue-noise"], [64, 128, 192], 40, 4
FRAMES, WORK, SIZE = 40, 64, "320x240"
# (method, pattern, state, cell): each scene alone, then half way through blue noise, a wipe and
# Bayer with the stencil, blue noise in 2x2, 4x4 and 8x8 cells, and blue noise and the wipe by the
# engines' two ways.
TIMED = [(0, 2, 0, 1), (0, 2, 256, 1), (0, 2, 128, 1), (0, 3, 128, 1), (0, 1, 128, 1), (0, 2, 128, 2), (0, 2, 128, 4),
         (0, 2, 128, 8), (1, 2, 128, 1), (1, 3, 128, 1), (2, 2, 128, 1), (2, 3, 128, 1)]


def read_png(path):
    """(width, height, rows): an RGBA picture's rows, top first, each a bytearray."""
    width, height, channels, pixels = png_io.read_png(path)
    if channels != 4:
        raise ValueError(f"{path}: not 8-bit RGBA")
    return width, height, [bytearray(pixels[y * 4 * width:(y + 1) * 4 * width]) for y in range(height)]


def write_png(path, width, height, rows):
    png_io.write_png(path, width, height, 4, b"".join(bytes(r) for r in rows))


def stats(exe, args):
    with tempfile.TemporaryDirectory() as tmp:
        return json.loads(run(exe, args + ["--stats", "--out", f"{tmp}/x.png"]))


def magnified(frame, left, top, width, height, zoom):
    """Rows of the width x height region at (left, top) of a read_png frame, each pixel zoom x zoom."""
    rows = []
    for y in range(top, top + height):
        row = bytearray()
        for x in range(left, left + width):
            row += bytes(frame[2][y][4 * x:4 * x + 4]) * zoom
        rows += [row] * zoom
    return rows


def side_by_side(pictures, gap=4):
    """One picture of lists of rows (all as tall) side by side, white gaps between them."""
    rows = []
    for y in range(len(pictures[0])):
        row = bytearray()
        for j, p in enumerate(pictures):
            if j:
                row += bytes([255, 255, 255, 255]) * gap
            row += p[y]
        rows.append(row)
    return len(rows[0]) // 4, len(rows), rows


def crops(exe, tmp, out):
    """Per pattern, CROP x CROP pixels at three states magnified ZOOM times: the grain that the
    strips lose when a page shrinks them. And the clamped reference's state 0, whose 1/256 of
    pixels in B are too few to see at table size."""
    for slug in CROP_SLUGS:
        pictures = []
        for i, k in enumerate(CROP_STATES):
            png = pathlib.Path(tmp) / f"crop-{slug}-{i}.png"
            run(exe, ["--size", SIZE, "--time", "1", "--variant", "dissolve", "--set", f"pattern={SLUGS.index(slug)}",
                      "--set", f"step={k}", "--set", "which=1", "--out", str(png)])
            frame = read_png(png)
            pictures.append(magnified(frame, (frame[0] - CROP) // 2, (frame[1] - CROP) // 2, CROP, CROP, ZOOM))
        write_png(out / f"crop-{slug}.png", *side_by_side(pictures))
        print(f"wrote {out / f'crop-{slug}.png'}", file=sys.stderr)
    png = pathlib.Path(tmp) / "start-clamped.png"
    run(exe, ["--size", SIZE, "--time", "1", "--variant", "start-clamped", "--out", str(png)])
    frame = read_png(png)
    width, height = 80, 60  # a quarter of the frame's width and height, from its top left
    write_png(out / "start-clamped-crop.png", width * ZOOM, height * ZOOM, magnified(frame, 0, 0, width, height, ZOOM))
    print(f"wrote {out / 'start-clamped-crop.png'}", file=sys.stderr)


def strips(exe, out):
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for p, slug in enumerate(SLUGS):
            frames = []
            for i, k in enumerate(STATES):
                time = PAINT_TIMES[i] if slug == "painted" else 1
                step = 128 if slug == "painted" else k
                png = pathlib.Path(tmp) / f"{slug}-{i}.png"
                run(exe, ["--size", "160x120", "--time", str(time), "--variant", "dissolve", "--set", f"pattern={p}",
                          "--set", f"step={step}", "--out", str(png)])
                frames.append(read_png(png))
            gap = 4
            width = sum(f[0] for f in frames) + gap * (len(frames) - 1)
            rows = []
            for y in range(frames[0][1]):
                row = bytearray()
                for j, f in enumerate(frames):
                    if j:
                        row += bytes([255, 255, 255, 255]) * gap
                    row += f[2][y]
                rows.append(row)
            write_png(out / f"strip-{slug}.png", width, frames[0][1], rows)
            print(f"wrote {out / f'strip-{slug}.png'}", file=sys.stderr)
        crops(exe, tmp, out)


def tables(exe, timing):
    """The times only: the page's counts (clumpiness, fragments) are written by tests/docs/page_tables.py
    (tests/docs/tables/12.py)."""
    print("| pattern | making it, 320x240 (ms) |")
    print("|---|---|")
    for p in range(6):
        c = stats(exe, ["--size", "320x240", "--variant", "dissolve", "--set", f"pattern={p}", "--set", "step=128",
                        "--set", "measure=1"])["counts"]
        print(f"| {PATTERNS[p]} | {c['pattern_us'] / 1000:.0f} |")
    if not timing:
        return
    print()
    print(f"CPU time per frame (llvmpipe renders on the CPU: user + system time of the lesson's process, "
          f"{FRAMES + 1} frames less 1 frame, over {FRAMES}), ms, without and with {WORK} iterations of extra "
          f"work per fragment (the `work` option), {SIZE}:")
    print()
    print(f"| method | pattern | cell | state k | work 0 | work {WORK} |")
    print("|---|---|---|---|---|---|")
    for m, p, k, cell in TIMED:
        cells = []
        for work in (0, WORK):
            args = ["--size", SIZE, "--variant", "dissolve", "--set", f"pattern={p}", "--set", f"step={k}",
                    "--set", f"method={m}", "--set", f"work={work}", "--set", f"cell={cell}"]
            one, many = cpu_seconds(exe, args + ["--frames", "1"]), cpu_seconds(exe, args + ["--frames", str(FRAMES + 1)])
            cells.append(f"{(many - one) / FRAMES * 1000:.1f}")
        print(f"| {METHODS[m]} | {PATTERNS[p]} | {cell} x {cell} | {k} | " + " | ".join(cells) + " |")


def cpu_seconds(exe, args):
    """User + system CPU seconds of one run of the lesson (robust to other work on the machine)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with tempfile.TemporaryDirectory() as tmp:
        run(exe, args + ["--out", f"{tmp}/x.png"])
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    exe = pathlib.Path(sys.argv[1]) / "lessons/12-dissolve"
    if "--figures-only" in sys.argv:
        strips(exe, pathlib.Path(sys.argv[sys.argv.index("--figures-only") + 1]))
        return
    if "--no-strips" not in sys.argv:
        strips(exe, ROOT / "docs/figures/12-dissolve-strips")
    tables(exe, "--no-timing" not in sys.argv)


if __name__ == "__main__":
    main()
