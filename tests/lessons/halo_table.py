#!/usr/bin/env python3
"""Lesson 11's measurement table: per method, the ring's width along the figure's outline (mean,
and min and max as fractions of the mean), halo pixels over the figure, pixels blended more than
once, the fragments the shell rasterizes (every test off) and those the halo pass lets through
(samples_passed), its draw calls, and the halo pass's time (the median over RUNS runs of FRAMES
frames of its CPU time, which waits for the GPU: glFinish; and its GPU time where the driver's
timer can be trusted).

    tests/lessons/halo_table.py BUILD_DIR [SIZE] [--backend B]    # SIZE 640x480 by default
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
    size = args[1] if len(args) > 1 else "640x480"
    common = ["--size", size] + extra
    renderer = None
    print("| method | width mean (px) | min / mean | max / mean | over the figure | blended twice | "
          "shell fragments | blended | draw calls | halo pass CPU ms | GPU ms |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for m, name in enumerate(METHODS):
        counted = stats(exe, common + ["--set", f"method={m}", "--set", "show=1"])
        c = counted["counts"]
        mean = c["figure.width_mean_x100"] / 100
        cpu, gpu = [], []
        for _ in range(RUNS):
            s = stats(exe, common + ["--set", f"method={m}", "--frames", str(FRAMES)])
            renderer = s["renderer"]
            cpu.append(halo_pass(s)["cpu_ms"])
            if halo_pass(s).get("gpu_ms") is not None:
                gpu.append(halo_pass(s)["gpu_ms"])
        h = halo_pass(counted)
        # llvmpipe's timer queries return numbers, but not the time the CPU spent rasterizing.
        gpu_text = f"{statistics.median(gpu):.3f}" if gpu and "llvmpipe" not in renderer else "n/a"
        print(f"| {name} | {mean:.2f} | {c['figure.width_min_x100'] / 100 / mean:.2f} | "
              f"{c['figure.width_max_x100'] / 100 / mean:.2f} | {c['figure.covered_pixels']} | "
              f"{c['figure.multi_blended_pixels']} | {c['figure.shell_fragments']} | {h['samples_passed']} | "
              f"{h['draw_calls']} | {statistics.median(cpu):.2f} | {gpu_text} |")
    print(f"\n{size}, {renderer}; times: median of {RUNS} runs, the last of {FRAMES} frames each.")


if __name__ == "__main__":
    main()
