#!/usr/bin/env python3
"""The browser against the native lessons, per frame (issue 26, "Measured"): for each lesson's
default variant, in one run, the native program's frame time on its headless context, the frame
time of its page in headless Chromium (SwiftShader's WebGL 2), and the page's time to its first
frame from a server on 127.0.0.1.

    tests/web/web_frame_times.py BUILD SITE CHROMIUM [--size 640x480] [--frames 20] [--rounds 2]
                                 [--lesson ID]... [--csv FILE] [--no-page]

Native: `LESSON --headless --quiet --size S --time 1 --frames 3+N --stats --stats-frames` (each frame
timed alone, one glFinish at its end, no per-pass queries), the median of the N frames after the
first 3. Browser: a fresh Chromium (a new profile: nothing cached) loads `LESSON.html?time=1&size=S
&paused=1`; the first frame is the moment the page's first frame call (StencilPage.frame) has its
frame drawn, a 1x1 readPixels waiting for it, on the page's clock (performance.now(): from the
navigation's start). Then the page draws 3+N frames itself, 1/60 s apart from t = 1 as --frames
does (Module._stencil_web_time: the frame, its blit to the canvas, its pass list to the page), each
timed alone and ended by a 1x1 readPixels, which waits for the GPU process as glFinish does; the
median of the N after the first 3. Each round measures every lesson in turn, native and browser
side by side (the native first in odd rounds, the browser first in even ones); a figure is the
median of the rounds' figures.

Writes docs/sweeps/web-frame-times.csv (or --csv FILE): one row a lesson, the run's machine, load
(os.getloadavg() before and after), renderers and command in '#' lines above; then the table
web-frame-times in docs/web.md from that CSV (tests/docs/page_tables.py --write; --no-page: not).
Bad arguments: one line, exit 2, nothing written.
"""
import argparse
import datetime
import json
import os
import pathlib
import platform
import re
import shlex
import statistics
import subprocess
import sys

import chromium

ROOT = pathlib.Path(__file__).resolve().parents[2]
WARMUP = 3  # frames left out of each measurement: the first compiles shaders and fills caches
COLUMNS = ["lesson", "variant", "size", "frames", "native_ms", "native_cpu_ms", "browser_ms", "browser_over_native",
           "first_frame_ms"]

# Installed before the page's own script: the first StencilPage.frame call, its frame drawn.
FIRST_FRAME_HOOK = """
Object.defineProperty(window, 'StencilPage', {configurable: true, set(page) {
  const frame = page.frame;
  page.frame = function(...args) {
    if (window.firstFrameMs === undefined) {
      const gl = document.getElementById('canvas').getContext('webgl2');
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
      window.firstFrameMs = performance.now();
    }
    return frame.apply(this, args);
  };
  Object.defineProperty(window, 'StencilPage', {value: page, writable: true, configurable: true});
}});
"""

FRAMES = """(() => {
  const gl = document.getElementById('canvas').getContext('webgl2'), pixel = new Uint8Array(4), all = [];
  for (let i = 0; i < %d; ++i) {
    const start = performance.now();
    Module._stencil_web_time(1 + i / 60);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    all.push(performance.now() - start);
  }
  return all;
})()"""


def native_frames(exe, size, frames):
    """(median wall ms, median CPU ms, renderer) of the native lesson's frames after the warm-up."""
    out = subprocess.run([str(exe), "--headless", "--quiet", "--size", size, "--time", "1", "--frames",
                          str(WARMUP + frames), "--stats", "--stats-frames"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"web_frame_times.py: {exe.name} failed (exit {out.returncode}): {out.stderr.strip()}")
    stats = json.loads(out.stdout)
    return (statistics.median(stats["frame_ms"]["all"][WARMUP:]),
            statistics.median(stats["frame_cpu_ms"]["all"][WARMUP:]), stats["renderer"], stats["variant"])


def browser_frames(chromium_exe, base, lesson, size, frames):
    """(median ms a frame, first frame ms, renderer, variant) of the lesson's page, in a fresh browser."""
    with chromium.Chromium(chromium_exe, timeout=180) as browser:
        browser.send("Page.addScriptToEvaluateOnNewDocument", {"source": FIRST_FRAME_HOOK})
        browser.open(f"{base}/{lesson}.html?time=1&size={size}&paused=1")
        browser.wait("typeof lesson !== 'undefined' && lesson !== null && window.firstFrameMs !== undefined || "
                     "document.getElementById('status').className === 'error'")
        error = browser.evaluate("document.getElementById('status').className === 'error' ? "
                                 "document.getElementById('status').textContent : ''")
        if error:
            sys.exit(f"web_frame_times.py: {lesson}.html: {error}")
        first = browser.evaluate("window.firstFrameMs")
        # The renderer behind WebGL's masked name: ANGLE on SwiftShader's Vulkan.
        info = browser.evaluate("(() => { const gl = document.getElementById('canvas').getContext('webgl2'), "
                                "e = gl.getExtension('WEBGL_debug_renderer_info'); return {variant: lesson.variant, "
                                "renderer: e ? gl.getParameter(e.UNMASKED_RENDERER_WEBGL) : lesson.renderer}; })()")
        info["browser"] = browser.send("Browser.getVersion", session=False)["product"].replace("Chrome", "Chromium")
        all_ms = browser.evaluate(FRAMES % (WARMUP + frames), timeout=600)
    return statistics.median(all_ms[WARMUP:]), first, info


def machine():
    cpu = next((line.split(":", 1)[1].strip() for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines()
                if line.startswith("model name")), platform.processor())
    return f"{cpu} ({os.cpu_count()} cores), {platform.system()} {platform.release()}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", type=pathlib.Path)
    parser.add_argument("site", type=pathlib.Path)
    parser.add_argument("chromium")
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--lesson", action="append", default=[])
    parser.add_argument("--csv", type=pathlib.Path, default=ROOT / "docs/sweeps/web-frame-times.csv")
    parser.add_argument("--no-page", action="store_true")
    args = parser.parse_args()
    lessons = args.lesson or sorted(p.stem for p in args.site.glob("[0-9][0-9]-*.html"))
    if not re.fullmatch(r"[1-9][0-9]{0,4}x[1-9][0-9]{0,4}", args.size):
        sys.exit(print(f"web_frame_times.py: --size {args.size}: expected WxH") or 2)
    if args.frames < 1 or args.rounds < 1:
        sys.exit(print(f"web_frame_times.py: --frames and --rounds must be 1 or more, got {args.frames} and "
                       f"{args.rounds}") or 2)
    if not lessons:
        sys.exit(print(f"web_frame_times.py: {args.site}: no lesson pages (build the site first)") or 2)
    for lesson in lessons:
        if not (args.site / f"{lesson}.html").is_file() or not (args.build / "lessons" / lesson).is_file():
            sys.exit(print(f"web_frame_times.py: {lesson}: not in {args.site} or not built in "
                           f"{args.build / 'lessons'}") or 2)

    load_before = os.getloadavg()
    rounds = {lesson: [] for lesson in lessons}
    renderers = {}
    with chromium.serve(args.site) as base:
        for r in range(args.rounds):
            for lesson in lessons:
                exe = args.build / "lessons" / lesson
                sides = ["native", "browser"] if r % 2 == 0 else ["browser", "native"]
                got = {}
                for side in sides:
                    if side == "native":
                        got["native_ms"], got["native_cpu_ms"], renderers["native"], got["variant"] = native_frames(
                            exe, args.size, args.frames)
                    else:
                        got["browser_ms"], got["first_frame_ms"], info = browser_frames(
                            args.chromium, base, lesson, args.size, args.frames)
                        renderers["browser"] = f"{info['browser']}, {info['renderer']}"
                if info["variant"] != got["variant"]:
                    sys.exit(f"web_frame_times.py: {lesson}: the page drew {info['variant']}, "
                             f"the native lesson {got['variant']}")
                variant = got["variant"]
                rounds[lesson].append(got)
                print(f"round {r + 1}: {lesson} {variant}: native {got['native_ms']:.1f} ms "
                      f"(CPU {got['native_cpu_ms']:.1f}), browser {got['browser_ms']:.1f} ms, "
                      f"first frame {got['first_frame_ms']:.0f} ms", flush=True)
    load_after = os.getloadavg()

    rows = []
    for lesson in lessons:
        med = {k: statistics.median(g[k] for g in rounds[lesson])
               for k in ("native_ms", "native_cpu_ms", "browser_ms", "first_frame_ms")}
        rows.append([lesson, rounds[lesson][0]["variant"], args.size, args.frames, f"{med['native_ms']:.2f}",
                     f"{med['native_cpu_ms']:.2f}", f"{med['browser_ms']:.2f}",
                     f"{med['browser_ms'] / med['native_ms']:.2f}", f"{med['first_frame_ms']:.0f}"])
    command = "tests/web/web_frame_times.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    header = [f"measured: {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC",
              f"command: {command}",
              f"machine: {machine()}",
              "load: " + " ".join(f"{x:.2f}" for x in load_before) + " before, "
              + " ".join(f"{x:.2f}" for x in load_after) + " after (1, 5, 15 min)",
              f"native: {renderers['native']} (headless)",
              f"browser: headless {renderers['browser']}",
              f"frames: {args.frames} a measurement after {WARMUP} left out, the median; {args.rounds} rounds, "
              "the median of the rounds'"]
    args.csv.parent.mkdir(parents=True, exist_ok=True)
    args.csv.write_text("".join(f"# {line}\n" for line in header) + ",".join(COLUMNS) + "\n"
                        + "".join(",".join(str(c) for c in row) + "\n" for row in rows))
    print(f"wrote {args.csv}")
    if not args.no_page:
        subprocess.run([sys.executable, str(ROOT / "tests/docs/page_tables.py"), str(args.build), "--write",
                        "web-frame-times"], check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
