#!/usr/bin/env python3
"""A lesson in the browser against the same lesson native: the snapshot contract's pictures from
headless Chromium (SwiftShader's WebGL 2) beside --out and --stencil-out of the native program, at
one size, time and variant.

    tests/web/web_check.py SITE NATIVE_EXE CHROMIUM OUT_DIR [--variant V] [--size WxH] [--time T]
                           [--without EXT,EXT] [--cracks]

--cracks forgives lone pixels one count off in a uniform stretch of the native stencil (crack()), for
the lessons whose shadow volumes reach infinity. --without hides those WebGL extensions from the page
(its &without=), so that the browser takes the fallback it takes without them; the native lesson is
the same.

The stencil must be the native one's except on edge pixels, judged as the ray-cast oracle judges
them (common/geometry/shadow_oracle.cpp, onEdge): a pixel whose 3x3 neighbourhood in the native
stencil holds another value. The colour likewise: every pixel within COLOUR_CHANNEL of the native
one in each channel (the goldens' per-channel tolerance, common/gl/golden.h) except on an edge of
the native picture, a pixel with a neighbour more than COLOUR_CHANNEL away from it (SwiftShader and
llvmpipe cover a triangle's edge pixels each their own way). The pictures stay in OUT_DIR. Exit 0 pass, 1 fail, 2 bad arguments, 77 (skipped) when SITE has no page for the lesson.

Plain Python: a server on 127.0.0.1 (a free port) serves SITE for the run, Chromium's --dump-dom
returns the page once it is idle, and the PNGs are read by tests/lessons/png_io.py.
"""
import argparse
import base64
import functools
import http.server
import pathlib
import re
import subprocess
import sys
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "lessons"))
from png_io import decode_png  # noqa: E402 (the shared reader, found beside the lessons' scripts)

COLOUR_CHANNEL = 5
CHROMIUM_FLAGS = ["--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--disable-gpu-sandbox", "--virtual-time-budget=10000"]


def on_edge(differs, w, h, x, y):
    """The oracle's rule: a pixel of the 3x3 neighbourhood that differs (differs(i, j)) from this one."""
    i = y * w + x
    for ny in range(max(0, y - 1), min(h, y + 2)):
        for nx in range(max(0, x - 1), min(w, x + 2)):
            if differs(i, ny * w + nx):
                return True
    return False


def compare_stencil(web, native, w, h):
    """Pixels that differ, how many of them lie on an edge of the native stencil, and how many of the
    rest are cracks (crack())."""
    differ = [i for i in range(w * h) if web[i] != native[i]]
    off_edge = [i for i in differ if not on_edge(lambda i, j: native[i] != native[j], w, h, i % w, i // w)]
    return len(differ), len(differ) - len(off_edge), sum(crack(web, native, w, h, i) for i in off_edge)


def crack(web, native, w, h, i):
    """A lone pixel one count off the native stencil (modulo 256), every neighbour of it as native:
    one shadow-volume face missed or met twice along an edge it shares with the next face.
    SwiftShader leaves a few in lessons 10, 15 and 16, whose volumes reach infinity (w = 0);
    the native frames have none there."""
    x, y = i % w, i // w
    if (web[i] - native[i]) % 256 not in (1, 255):
        return False
    for ny in range(max(0, y - 1), min(h, y + 2)):
        for nx in range(max(0, x - 1), min(w, x + 2)):
            j = ny * w + nx
            if j != i and (web[j] != native[i] or native[j] != native[i]):
                return False
    return True


def channel_diff(a, i, b, j):
    return max(abs(a[4 * i + c] - b[4 * j + c]) for c in range(3))  # alpha left out: pictures are opaque


def compare_colour(web, native, w, h):
    """Pixels over tolerance, how many of them lie on an edge of the native picture, the largest
    channel difference."""
    over = [i for i in range(w * h) if channel_diff(web, i, native, i) > COLOUR_CHANNEL]
    edges = sum(on_edge(lambda i, j: channel_diff(native, i, native, j) > COLOUR_CHANNEL, w, h, i % w, i // w)
                for i in over)
    worst = max((channel_diff(web, i, native, i) for i in range(w * h)), default=0)
    return len(over), edges, worst


def snapshot(site, chromium, page, query, timeout):
    """The page's title and its snapshot images' PNG bytes, from headless Chromium."""
    handler = functools.partial(Quiet, directory=str(site))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        url = f"http://127.0.0.1:{server.server_address[1]}/{page}?{query}"
        dom = subprocess.run([chromium, *CHROMIUM_FLAGS, "--dump-dom", url], capture_output=True, text=True,
                             timeout=timeout).stdout
    finally:
        server.shutdown()
    title = re.search(r"<title>(.*?)</title>", dom, re.S)
    images = {m.group(1): base64.b64decode(m.group(2))
              for m in re.finditer(r'<img id="(snapshot-[a-z]+)"[^>]*src="data:image/png;base64,([^"]*)"', dom)}
    return (title.group(1) if title else "(no title)"), images


class Quiet(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".js": "text/javascript"}

    def log_message(self, *args):
        pass


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("site", type=pathlib.Path)
    parser.add_argument("native", type=pathlib.Path)
    parser.add_argument("chromium")
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--variant", default="")
    parser.add_argument("--size", default="320x240")
    parser.add_argument("--time", default="1")
    parser.add_argument("--without", default="")
    parser.add_argument("--cracks", action="store_true")
    parser.add_argument("--timeout", type=float, default=120)
    args = parser.parse_args()
    lesson = args.native.name
    if not (args.site / f"{lesson}.html").is_file():
        print(f"web_check: {args.site / (lesson + '.html')} not found: skipped; build the site first "
              "(cmake --preset web && cmake --build --preset web)")
        return 77
    if not re.fullmatch(r"[1-9][0-9]{0,4}x[1-9][0-9]{0,4}", args.size):
        print(f"web_check: --size {args.size}: expected WxH")
        return 2
    args.out.mkdir(parents=True, exist_ok=True)
    variant = ["--variant", args.variant] if args.variant else []

    start = time.monotonic()
    native = subprocess.run([str(args.native), "--headless", "--quiet", "--size", args.size, "--time", args.time,
                             *variant, "--out", str(args.out / "native.png"),
                             "--stencil-out", str(args.out / "native-stencil.png")], capture_output=True, text=True)
    if native.returncode != 0:
        print(f"web_check: the native {lesson} failed (exit {native.returncode}): {native.stderr.strip()}")
        return 1
    native_s = time.monotonic() - start

    query = f"time={args.time}&size={args.size}&snapshot=1" + (f"&variant={args.variant}" if args.variant else "")
    if args.without:
        query += f"&without={args.without}"
    start = time.monotonic()
    title, images = snapshot(args.site, args.chromium, f"{lesson}.html", query, args.timeout)
    web_s = time.monotonic() - start
    if title != "snapshot-ready" or set(images) != {"snapshot-colour", "snapshot-stencil"}:
        print(f"web_check: {lesson}.html?{query}: title '{title}', images {sorted(images)}")
        return 1
    for name, png in images.items():
        (args.out / f"web-{name[len('snapshot-'):]}.png").write_bytes(png)

    w, h, channels, web_stencil = decode_png(images["snapshot-stencil"])
    nw, nh, _, native_stencil = decode_png((args.out / "native-stencil.raw.png").read_bytes())
    cw, ch, cc, web_colour = decode_png(images["snapshot-colour"])
    _, _, nc, native_colour = decode_png((args.out / "native.png").read_bytes())
    if (w, h) != (nw, nh) or (cw, ch) != (nw, nh) or channels != 1 or cc != 4 or nc != 4:
        print(f"web_check: sizes or channels differ: web stencil {w}x{h}x{channels}, colour {cw}x{ch}x{cc}; "
              f"native {nw}x{nh}")
        return 1
    differ, edges, cracks = compare_stencil(web_stencil, native_stencil, w, h)
    over, colour_edges, worst = compare_colour(web_colour, native_colour, w, h)
    passed = differ == edges + (cracks if args.cracks else 0) and over == colour_edges
    print(f"{'web ok' if passed else 'web FAILED'}: {lesson} {args.variant or '(default variant)'}"
          f"{' without ' + args.without if args.without else ''} at {args.size}, "
          f"t={args.time}: stencil {differ} of {w * h} pixels differ, {edges} of them on edges, {cracks} lone cracks"
          f"{' (forgiven: --cracks)' if args.cracks else ''}; colour {over} pixels "
          f"over {COLOUR_CHANNEL}/255, {colour_edges} of them on edges, max channel diff {worst}; "
          f"native {native_s:.1f} s, browser {web_s:.1f} s (pictures in {args.out})")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
