"""Lesson 10's generated tables (docs/10-soft-shadows.md): the sweep's error against N, the
penumbra's width, and what the penumbra wedges cost in fragments."""
import csv

from page_tables import ROOT, lesson, stats

PATTERNS = {"grid": "grid", "jittered": "jittered", "halton": "Halton"}


def minus(x):
    return f"{x:.2f}".replace("-", "−")


def errors():
    """Penumbra RMS error by N and the slope of log error against log samples, from the committed
    sweep (docs/sweeps/10-soft-shadows.csv and .summary.csv, written by `cmake --build build
    --target sweep-10-soft-shadows`); the best pattern of each light in bold."""
    rows = list(csv.DictReader((ROOT / "docs/sweeps/10-soft-shadows.csv").open()))
    slopes = {r["what"]: float(r["value"]) for r in csv.DictReader((ROOT / "docs/sweeps/10-soft-shadows.summary.csv").open())
              if r["kind"] == "slope"}
    lines = ["| light | pattern | N = 1 | 16 | 64 | 256 | max error at 256 | slope |", "|---|---|---|---|---|---|---|---|"]
    for shape in ("rectangle", "disk"):
        rms = {(r["pattern"], int(r["lights"])): r for r in rows if r["shape"] == shape and r["rounds"] == "1"}
        best_rms = min(float(rms[p, 256]["penumbra_rms"]) for p in PATTERNS)
        best_slope = min(slopes[f"{shape} {p}"] for p in PATTERNS)
        for pattern, name in PATTERNS.items():
            cells = [f"{float(rms[pattern, n]['penumbra_rms']):.1f}" for n in (1, 16, 64, 256)]
            if float(rms[pattern, 256]["penumbra_rms"]) == best_rms:
                cells[-1] = f"**{cells[-1]}**"
            slope = minus(slopes[f"{shape} {pattern}"])
            if slopes[f"{shape} {pattern}"] == best_slope:
                slope = f"**{slope}**"
            cells += [f"{float(rms[pattern, 256]['penumbra_max']):.0f}", slope]
            lines.append(f"| {shape} | {name} | " + " | ".join(cells) + " |")
    return lines


def penumbra_width():
    """The penumbra's width the lesson measures on its picture (--stats), against W h / (H - h), t = 1."""
    lines = ["| size | picture | x: measured | W h / (H − h), W = 1.5 | z: measured | W h / (H − h), W = 1.0 |",
             "|---|---|---|---|---|---|"]
    for size in ("320x240", "640x480", "1280x960"):
        for variant in ("reference", "visibility"):
            c = stats(lesson("10-soft-shadows"), ["--size", size, "--variant", variant])["counts"]
            name = f"`{variant}`" + (" (64 Halton)" if (size, variant) == ("320x240", "visibility") else "")
            cells = [c[f"penumbra_width_{e}{k}_milli"] / 1000 for e in "xz" for k in ("", "_predicted")]
            lines.append(f"| {size} | {name} | " + " | ".join(f"{x:.3f}" for x in cells) + " |")
    return lines


def wedge_run(casters, lights, wedges):
    return stats(lesson("10-soft-shadows"), ["--size", "320x240", "--set", "pattern=2", "--set", f"casters={casters}",
                                             "--set", f"lights={lights}", "--set", f"wedges={wedges}"])


def wedges():
    """Fragments that passed every pass, plain loop against wedges, Halton lights, 320x240, t = 1."""
    lines = ["| casters | N | plain: fragments | wedges: fragments (of them the wedges') | ratio |",
             "|---|---|---|---|---|"]
    for casters, name in ((1, "slab"), (3, "slab and ball")):
        for n in (1, 4, 16, 64, 256):
            plain, wedged = wedge_run(casters, n, 0), wedge_run(casters, n, 1)
            a, b = plain["total"]["samples_passed"], wedged["total"]["samples_passed"]
            own = sum(p["samples_passed"] for p in wedged["passes"] if p["name"] == "wedges")
            ratio = f"{b / a:.2f}" if n < 256 else f"**{b / a:.2f}**"
            lines.append(f"| {name} | {n} | {a:,} | {b:,} ({own:,}) | {ratio} |")
    return lines


PAGE = "docs/10-soft-shadows.md"
TABLES = {"10-errors": errors, "10-penumbra-width": penumbra_width, "10-wedges": wedges}
