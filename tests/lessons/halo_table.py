#!/usr/bin/env python3
"""Lesson 11's halo pass times, per method and size: the median over RUNS runs of the last of FRAMES
frames of the pass's CPU time, which waits for the GPU (glFinish), and its GPU time where the
driver's timer can be trusted. A recorded run, never a test: the page says the machine and its
load. The page's counts table (widths, fragments, blends) is written by tests/docs/page_tables.py
(tests/docs/tables/11.py).

    tests/lessons/halo_table.py BUILD_DIR [SIZE...] [--backend B]    # 640x480 and 320x240 by default
"""
import pathlib
import statistics
import sys

from lesson_run import stats

METHODS = ["whole object scaled (paper)", "each convex piece grown (paper's fix)", "pushed along normals",
           "outline moved k pixels (screen)"]
RUNS, FRAMES = 5, 20


def halo_pass(s):
    return next(p for p in s["passes"] if p["name"] == "halo")


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    extra = []
    if "--backend" in sys.argv:
        extra = ["--backend", sys.argv[sys.argv.index("--backend") + 1]]
        args = [a for a in args if a != extra[1]]
    if not args or "--help" in sys.argv:
        sys.exit(__doc__)
    exe = pathlib.Path(args[0]) / "lessons" / "11-halo"
    sizes = args[1:] or ["640x480", "320x240"]
    renderer = None
    rows = {name: [] for name in METHODS}
    for size in sizes:
        for m, name in enumerate(METHODS):
            cpu, gpu = [], []
            for _ in range(RUNS):
                s = stats(exe, ["--size", size] + extra + ["--set", f"method={m}", "--frames", str(FRAMES)])
                renderer = s["renderer"]
                cpu.append(halo_pass(s)["cpu_ms"])
                if halo_pass(s).get("gpu_ms") is not None:
                    gpu.append(halo_pass(s)["gpu_ms"])
            # llvmpipe's timer queries return numbers, but not the time the CPU spent rasterizing.
            gpu_text = f"{statistics.median(gpu):.3f}" if gpu and "llvmpipe" not in renderer else "n/a"
            rows[name] += [f"{statistics.median(cpu):.2f}", gpu_text]
    print("| method | " + " | ".join(f"{size} CPU ms | GPU ms" for size in sizes) + " |")
    print("|---|" + "---|---|" * len(sizes))
    for name, cells in rows.items():
        print(f"| {name} | " + " | ".join(cells) + " |")
    print(f"\n{renderer}; the halo pass, median of {RUNS} runs, the last of {FRAMES} frames each.")


if __name__ == "__main__":
    main()
