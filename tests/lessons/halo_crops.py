#!/usr/bin/env python3
"""Lesson 11's faults, enlarged: for each fault variant and the variant that fixes it, both rendered
at SIZE (the golden size by default) and --time 1, cropped to the pixels where they differ (plus a
margin), scaled up by whole pixels (nearest neighbour), and set side by side: the fault, the fix,
and where they differ (magenta over the fault, dimmed). One PNG per fault in OUT_DIR.

    tests/lessons/halo_crops.py BUILD_DIR OUT_DIR [SIZE]    # SIZE 320x240 by default

Plain Python: the PNGs are read and written with zlib (8-bit RGB or RGBA, not interlaced).
"""
import pathlib
import struct
import subprocess
import sys
import tempfile
import zlib

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
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, f"{path}: unsupported PNG"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    bpp = 4 if colour == 6 else 3
    raw, stride = zlib.decompress(idat), w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, bpp)])
        prev = line
    return rows


def write_png(path, rows):
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(v for px in row for v in px) for row in rows)
    chunk = lambda kind, body: struct.pack(">I", len(body)) + kind + body + struct.pack(
        ">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    pathlib.Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                                   + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


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
