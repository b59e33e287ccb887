#!/usr/bin/env python3
"""A lesson in the browser against the same lesson native: for every variant the lesson declares
(its --list-variants, as the goldens), the snapshot contract's pictures from headless Chromium
(SwiftShader's WebGL 2) beside --out and --stencil-out of the native program, at one size and time;
with --depth, the page's depth view of the first variant beside --depth-out. One browser for all.

    tests/web/web_check.py SITE NATIVE_EXE CHROMIUM OUT_DIR [--variant V]... [--size WxH] [--time T]
                           [--without EXT,EXT] [--cracks [parity]] [--leave-out VARIANT NAME=VALUE...]...
                           [--leave-out-stencil VARIANT NAME=VALUE...]... [--depth]
                           [--scene FILE]... [--set NAME=VALUE]... [--oracle]

--variant: only those variants (else every one; with STENCIL_WEB_VARIANTS=first in the environment,
the first the lesson declares). --cracks forgives lone pixels one count off in a uniform stretch of
the native stencil (crack()), for the lessons whose shadow volumes reach infinity; --cracks parity,
lone pixels of any value (lesson 10: a parity bit a light); with either, lone colour pixels over
tolerance (lone_colour()) too. --leave-out VARIANT NAME=VALUE...: in
that variant the colour is not compared where the native frame drawn with one of those settings
(--set NAME=VALUE) differs from the native frame, nor next to it: the layer that the setting
changes. For a depth fight by design (lesson 04's z-fighting: the shadow at the ground's depth,
whose winner is each rasterizer's own rounding) and a legend drawn from counts that include edge
pixels (lesson 13's histogram). With no setting the variant's colour is not compared at all; its
stencil is, but for --leave-out-stencil VARIANT NAME=VALUE...: the same for the stencil, for a depth
fight that decides counts (lesson 14's coincident faces; lesson 10's volumes writing depth, whose
faces from neighbouring lights meet at the caster's edges: no setting, the stencil not compared).
--scene FILE (a scene file of tests/scenes, as the scene lessons' pages offer them: &scene=FILE, native --scene): each variant on each such file. --set NAME=VALUE: that setting in
both (&set=NAME:VALUE, native --set). --without hides those WebGL extensions from the page (its &without=), so that
the browser takes the fallback it takes without them; the native lesson is the same.

The stencil must be the native one's except on edge pixels, judged as the ray-cast oracle judges
them (common/geometry/shadow_oracle.cpp, onEdge): a pixel whose 3x3 neighbourhood in the native
stencil holds another value. With --oracle (the lessons with a shadow claim), also the edges of the
oracle itself where the variant makes a claim (native --oracle's FILE.edges.png): among them the
pixels where a side of a shadow volume and the surface tie within the vertex snapping GL allows a
rasterizer (1/16 pixel; SwiftShader's WebGL snaps to that, llvmpipe to 1/256), whose count a
conforming rasterizer may take either way. The colour likewise: every pixel within COLOUR_CHANNEL of the native
one in each channel (the goldens' per-channel tolerance, common/gl/golden.h) except on an edge of
the native picture, a pixel with a neighbour more than COLOUR_CHANNEL away from it (SwiftShader and
llvmpipe cover a triangle's edge pixels each their own way). The depth view (the page loaded with
&view=depth&paused=1, its canvas read by toDataURL) is judged as the colour, against --depth-out's
picture's frame rows, which the page draws (depth_view_frame()). One line a variant; the
pictures stay in OUT_DIR/VARIANT. Exit 0 pass, 1 fail, 2 bad arguments, 77 (skipped) when SITE has
no page for the lesson.

Plain Python: tests/web/chromium.py serves SITE on 127.0.0.1 (a free port) and drives Chromium over
the DevTools protocol; the PNGs are read by tests/lessons/png_io.py.
"""
import argparse
import base64
import os
import pathlib
import re
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "lessons"))
from png_io import decode_png  # noqa: E402 (the shared reader, found beside the lessons' scripts)
import chromium  # noqa: E402 (beside this script)

COLOUR_CHANNEL = 5
SCENES = pathlib.Path(__file__).resolve().parents[1] / "scenes"  # tests/scenes, which the scene lessons offer


def on_edge(differs, w, h, x, y):
    """The oracle's rule: a pixel of the 3x3 neighbourhood that differs (differs(i, j)) from this one."""
    i = y * w + x
    for ny in range(max(0, y - 1), min(h, y + 2)):
        for nx in range(max(0, x - 1), min(w, x + 2)):
            if differs(i, ny * w + nx):
                return True
    return False


def compare_stencil(web, native, w, h, parity=False, sides=None, oracle_edges=None):
    """Pixels that differ, how many of them lie on an edge of the native stencil or of the oracle
    (ORACLE_EDGES: native --oracle's edges, one flag a pixel), how many on the oracle's alone, how many of the
    rest the comparison leaves out (SIDES as compare_colour's, native stencils of the same frame
    drawn with other settings: every pixel when SIDES is empty), and how many of the rest are cracks
    (crack())."""
    differ = [i for i in range(w * h) if web[i] != native[i]]
    off_native_edge = [i for i in differ if not on_edge(lambda i, j: native[i] != native[j], w, h, i % w, i // w)]
    off_edge = [i for i in off_native_edge if not (oracle_edges and oracle_edges[i])]
    rest = off_edge
    if sides is not None:
        def in_layer(i, j):  # the layer the settings change shows at j
            return any(native[j] != side[j] for side in sides)
        rest = [i for i in off_edge if sides and not on_edge(in_layer, w, h, i % w, i // w)]
    return (len(differ), len(differ) - len(off_edge), len(off_native_edge) - len(off_edge), len(off_edge) - len(rest),
            sum(crack(web, native, w, h, i, parity) for i in rest))


def crack(web, native, w, h, i, parity=False):
    """A lone pixel one count off the native stencil (modulo 256), every neighbour of it as native:
    one shadow-volume face missed or met twice along an edge it shares with the next face.
    SwiftShader leaves a few in lessons 10, 15 and 16, whose volumes reach infinity (w = 0);
    the native frames have none there. PARITY: the lesson keeps a parity bit a light (lesson 10's
    Kilgard variants INVERT bit i for light i), so a crack flips one bit a light whose volume has
    it, any bits in all: any other value is one."""
    x, y = i % w, i // w
    if not parity and (web[i] - native[i]) % 256 not in (1, 255):
        return False
    for ny in range(max(0, y - 1), min(h, y + 2)):
        for nx in range(max(0, x - 1), min(w, x + 2)):
            j = ny * w + nx
            if j != i and (web[j] != native[i] or native[j] != native[i]):
                return False
    return True


def channel_diff(a, i, b, j):
    return max(abs(a[4 * i + c] - b[4 * j + c]) for c in range(3))  # alpha left out: pictures are opaque


def compare_colour(web, native, w, h, sides=None):
    """Pixels over tolerance; how many of them lie on an edge of the native picture; how many of the
    rest the comparison leaves out; how many of the rest are lone (lone_colour()); the largest
    channel difference. Left out, with SIDES (native pictures of the same frame drawn with other
    settings): the pixels within one of a pixel where the native picture and a side's are not within
    tolerance, where the layer that the settings change shows at all (and its edge pixels); every
    pixel when SIDES is empty."""
    over = [i for i in range(w * h) if channel_diff(web, i, native, i) > COLOUR_CHANNEL]
    off_edge = [i for i in over
                if not on_edge(lambda i, j: channel_diff(native, i, native, j) > COLOUR_CHANNEL, w, h, i % w, i // w)]
    rest = off_edge
    if sides is not None:
        def in_layer(i, j):  # the layer shows at j: its edge pixels, as i's 3x3, with it
            return any(channel_diff(native, j, side, j) > COLOUR_CHANNEL for side in sides)
        rest = [i for i in off_edge if sides and not on_edge(in_layer, w, h, i % w, i // w)]
    worst = max((channel_diff(web, i, native, i) for i in range(w * h)), default=0)
    return (len(over), len(over) - len(off_edge), len(off_edge) - len(rest),
            sum(lone_colour(web, native, w, h, i) for i in rest), worst)


def lone_colour(web, native, w, h, i):
    """A pixel over tolerance whose eight neighbours are all within it: in the lessons with cracks
    (crack()), a crack of a light whose stencil the frame does not end with shows only in the colour
    (lessons 10 and 16 add many lights' terms), or one whose stencil is a crack there too."""
    x, y = i % w, i // w
    return all(channel_diff(web, j, native, j) <= COLOUR_CHANNEL
               for ny in range(max(0, y - 1), min(h, y + 2)) for nx in range(max(0, x - 1), min(w, x + 2))
               if (j := ny * w + nx) != i)


def depth_view_frame(picture, w, h):
    """The native depth picture (--depth-out: w x (h + legend band)) as the page's depth view shows
    it: its frame's rows, the legend written as text below the canvas (common/gl/web_run.cpp,
    depthViewPicture)."""
    pw, ph, channels, pixels = picture
    if (pw, channels) != (w, 4) or ph < h:
        raise ValueError(f"--depth-out's picture is {pw}x{ph}x{channels}, expected {w} wide, RGBA, at least {h} rows")
    return pixels[:4 * w * h]


def run_native(native, args, variant, flags):
    """The native lesson's frame of VARIANT at the size and time, FLAGS its outputs (and settings):
    its seconds and None, or None and what failed."""
    start = time.monotonic()
    scene = ["--scene", str(SCENES / args.scene_now)] if args.scene_now else []
    settings = [a for setting in args.set for a in ("--set", setting)]
    run = subprocess.run([str(native), "--headless", "--quiet", "--size", args.size, "--time", args.time,
                          "--variant", variant, *scene, *settings, *flags], capture_output=True, text=True)
    if run.returncode != 0:
        return None, f"the native lesson failed (exit {run.returncode}): {run.stderr.strip()}"
    return time.monotonic() - start, None


def native_oracle_edges(args, variant, out):
    """The oracle's edges of the native frame of VARIANT (--oracle's FILE.edges.png: 255 where a
    disagreement is forgiven), one flag a pixel, and None; None and None where the variant makes no
    shadow claim; None and what failed. A frame the oracle fails (exit 1: a variant that shows a
    method's failure) still has its edges."""
    picture = out / "native-oracle.png"
    scene = ["--scene", str(SCENES / args.scene_now)] if args.scene_now else []
    settings = [a for setting in args.set for a in ("--set", setting)]
    run = subprocess.run([str(args.native), "--headless", "--quiet", "--size", args.size, "--time", args.time,
                          "--variant", variant, *scene, *settings, "--oracle", str(picture)],
                         capture_output=True, text=True)
    if run.returncode == 2 and "makes no shadow claim" in run.stderr:
        return None, None
    if run.returncode not in (0, 1):
        return None, f"the native lesson failed (exit {run.returncode}): {run.stderr.strip()}"
    return [v == 255 for v in decode_png(picture.with_suffix(".edges.png").read_bytes())[3]], None


def check_variant(browser, base, args, lesson, variant, out):
    """One variant's snapshot against the native lesson: (passed, the line that says so)."""
    out.mkdir(parents=True, exist_ok=True)
    native_s, error = run_native(args.native, args, variant, ["--out", str(out / "native.png"),
                                                              "--stencil-out", str(out / "native-stencil.png")])
    if error:
        return False, f"web FAILED: {lesson} {variant}: {error}"
    query = f"variant={variant}&time={args.time}&size={args.size}&snapshot=1"
    if args.scene_now:
        query += f"&scene={args.scene_now}"
    if args.set:
        query += "&set=" + ",".join(setting.replace("=", ":") for setting in args.set)
    if args.without:
        query += f"&without={args.without}"
    start = time.monotonic()
    browser.open(f"{base}/{lesson}.html?{query}")
    title = browser.wait_title("snapshot-ready")
    images = browser.evaluate("Object.fromEntries([...document.querySelectorAll('img[id^=snapshot-]')]"
                              ".map(i => [i.id, i.src]))") or {}
    web_s = time.monotonic() - start
    if title != "snapshot-ready" or set(images) != {"snapshot-colour", "snapshot-stencil"}:
        return False, f"web FAILED: {lesson}.html?{query}: title '{title}', images {sorted(images)}"
    pngs = {name: base64.b64decode(src.split(",", 1)[1]) for name, src in images.items()}
    for name, png in pngs.items():
        (out / f"web-{name[len('snapshot-'):]}.png").write_bytes(png)

    w, h, channels, web_stencil = decode_png(pngs["snapshot-stencil"])
    nw, nh, _, native_stencil = decode_png((out / "native-stencil.raw.png").read_bytes())
    cw, ch, cc, web_colour = decode_png(pngs["snapshot-colour"])
    _, _, nc, native_colour = decode_png((out / "native.png").read_bytes())
    if (w, h) != (nw, nh) or (cw, ch) != (nw, nh) or channels != 1 or cc != 4 or nc != 4:
        return False, (f"web FAILED: {lesson} {variant}: sizes or channels differ: web stencil {w}x{h}x{channels}, "
                       f"colour {cw}x{ch}x{cc}; native {nw}x{nh}")
    def drawn_with(leave_out, picture):
        """The native frame of the variant drawn with each setting LEAVE_OUT gives it (PICTURE:
        "colour" or "stencil"): a list of pixels each, or None where LEAVE_OUT does not name it."""
        settings = dict((f[0], f[1:]) for f in leave_out).get(variant)
        if settings is None:
            return None, ""
        sides = []
        for setting in settings:
            side = out / f"native-{'' if picture == 'colour' else 'stencil-'}{setting.replace('=', '-')}.png"
            flag = "--out" if picture == "colour" else "--stencil-out"
            _, error = run_native(args.native, args, variant, ["--set", setting, flag, str(side)])
            if error:
                raise RuntimeError(f"web FAILED: {lesson} {variant} --set {setting}: {error}")
            pixels = decode_png((side if picture == "colour" else side.with_suffix(".raw.png")).read_bytes())
            sides.append(pixels[3])
        return sides, (f", {{}} left out (where the native frame and {' and '.join(settings)} differ)" if sides
                       else f", {{}} left out (the variant's {picture} is not compared)")
    oracle_edges = None
    if args.oracle:
        oracle_edges, error = native_oracle_edges(args, variant, out)
        if error:
            return False, f"web FAILED: {lesson} {variant} --oracle: {error}"
    try:
        sides, fight = drawn_with(args.leave_out, "colour")
        stencil_sides, stencil_fight = drawn_with(args.leave_out_stencil, "stencil")
    except RuntimeError as error:
        return False, str(error)
    differ, edges, oracle_only, stencil_fought, cracks = compare_stencil(web_stencil, native_stencil, w, h,
                                                            args.cracks == "parity", stencil_sides, oracle_edges)
    over, colour_edges, fought, lone, worst = compare_colour(web_colour, native_colour, w, h, sides)
    oracle_note = f" ({oracle_only} of them the oracle's alone)" if oracle_edges else ""
    passed = differ == edges + stencil_fought + (cracks if args.cracks else 0) and over == colour_edges + fought + (
        lone if args.cracks else 0)
    return passed, (f"{'web ok' if passed else 'web FAILED'}: {lesson} {variant}"
                    f"{' without ' + args.without if args.without else ''}: stencil {differ} of {w * h} pixels "
                    f"differ, {edges} on edges{oracle_note}"
                    f"{stencil_fight.format(stencil_fought)}, {cracks} lone cracks"
                    f"{' (forgiven)' if args.cracks else ''}; "
                    f"colour {over} over {COLOUR_CHANNEL}/255, {colour_edges} on edges{fight.format(fought)}, {lone} lone"
                    f"{' (forgiven)' if args.cracks else ''}, max diff {worst}; "
                    f"native {native_s:.1f} s, browser {web_s:.1f} s")


def check_depth_view(browser, base, args, lesson, variant, out):
    """The page's depth view (view=depth, paused at the time) against the native --depth-out."""
    out.mkdir(parents=True, exist_ok=True)
    _, error = run_native(args.native, args, variant, ["--depth-out", str(out / "native-depth.png")])
    if error:
        return False, f"web FAILED: {lesson} {variant} depth view: {error}"
    url = f"{base}/{lesson}.html?variant={variant}&time={args.time}&size={args.size}&paused=1&view=depth"
    browser.open(url)
    browser.wait("document.getElementById('view')?.value === 'depth' || document.getElementById('status')"
                 ".className === 'error'")
    status = browser.evaluate("document.getElementById('status').className === 'error' ? "
                              "document.getElementById('status').textContent : ''")
    if status:
        return False, f"web FAILED: {lesson} {variant} depth view: the page says: {status}"
    png = base64.b64decode(browser.evaluate("document.getElementById('canvas').toDataURL('image/png')").split(",", 1)[1])
    (out / "web-depth.png").write_bytes(png)
    w, h, channels, web = decode_png(png)
    native = decode_png((out / "native-depth.png").read_bytes())
    if (w, h) != tuple(map(int, args.size.split("x"))) or channels != 4 or native[2] != 4:
        return False, f"web FAILED: {lesson} depth view: canvas {w}x{h}x{channels}, native {native[:3]}"
    over, edges, _, _, worst = compare_colour(web, depth_view_frame(native, w, h), w, h)
    passed = over == edges
    return passed, (f"{'web ok' if passed else 'web FAILED'}: {lesson} {variant} depth view: {over} pixels over "
                    f"{COLOUR_CHANNEL}/255, {edges} on edges, max diff {worst}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("site", type=pathlib.Path)
    parser.add_argument("native", type=pathlib.Path)
    parser.add_argument("chromium")
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--variant", action="append", default=[])
    parser.add_argument("--size", default="320x240")
    parser.add_argument("--time", default="1")
    parser.add_argument("--without", default="")
    parser.add_argument("--cracks", nargs="?", const="count", choices=["count", "parity"])
    parser.add_argument("--depth", action="store_true")
    parser.add_argument("--leave-out", nargs="+", action="append", metavar=("VARIANT", "NAME=VALUE"), default=[])
    parser.add_argument("--leave-out-stencil", nargs="+", action="append", metavar=("VARIANT", "NAME=VALUE"),
                        default=[])
    parser.add_argument("--scene", action="append", default=[])
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--oracle", action="store_true")
    args = parser.parse_args()
    lesson = args.native.name
    for scene in args.scene:
        if not re.fullmatch(r"[a-z0-9-]+(/[a-z0-9-]+)*[.]scene", scene) or not (SCENES / scene).is_file():
            print(f"web_check: --scene {scene}: expected a scene file of tests/scenes, such as csg/drilled-box.scene")
            return 2
    for setting in args.set:
        if not re.fullmatch(r"[a-z0-9-]+=-?[0-9]+", setting):
            print(f"web_check: --set {setting}: expected NAME=VALUE")
            return 2
    if not re.fullmatch(r"[1-9][0-9]{0,4}x[1-9][0-9]{0,4}", args.size):
        print(f"web_check: --size {args.size}: expected WxH")
        return 2
    listing = subprocess.run([str(args.native), "--list-variants"], capture_output=True, text=True)
    if listing.returncode != 0:
        print(f"web_check: {args.native} --list-variants failed (exit {listing.returncode})")
        return 1
    declared = [line.split("\t")[0] for line in listing.stdout.splitlines() if line]
    unknown = [v for v in args.variant if v not in declared]
    if unknown:
        print(f"web_check: --variant {unknown[0]}: {lesson} has {', '.join(declared)}")
        return 2
    for flag, fights in (("--leave-out", args.leave_out), ("--leave-out-stencil", args.leave_out_stencil)):
        for fight in fights:
            if fight[0] not in declared or not all(re.fullmatch(r"[a-z0-9-]+=-?[0-9]+", s) for s in fight[1:]):
                print(f"web_check: {flag} {' '.join(fight)}: expected a variant of {lesson}, then NAME=VALUE settings")
                return 2
    # The goldens' variants: every one the lesson declares; STENCIL_WEB_VARIANTS=first (CI's web leg,
    # for its hour) the first alone.
    variants = args.variant or (declared[:1] if os.environ.get("STENCIL_WEB_VARIANTS") == "first" else declared)
    if not (args.site / f"{lesson}.html").is_file():
        return chromium.page_missing("web_check", args.site, f"{lesson}.html")

    start = time.monotonic()
    results = []
    with chromium.serve(args.site) as base, chromium.Chromium(args.chromium, timeout=args.timeout) as browser:
        for scene in args.scene or [None]:  # each variant on each scene file given, else its own scene
            args.scene_now = scene
            for variant in variants:
                where = args.out / variant / scene.replace("/", "-")[:-len(".scene")] if scene else args.out / variant
                passed, line = check_variant(browser, base, args, lesson, variant, where)
                results.append((passed, line + (f" (scene {scene})" if scene else "")))
                print(results[-1][1], flush=True)
        args.scene_now = None
        if args.depth:
            results.append(check_depth_view(browser, base, args, lesson, variants[0], args.out / "depth-view"))
            print(results[-1][1], flush=True)
    failed = sum(not passed for passed, _ in results)
    print(f"{lesson}: {len(results) - failed} of {len(results)} passed at {args.size}, t={args.time}, "
          f"in {time.monotonic() - start:.1f} s (pictures in {args.out})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
