"""Lesson 13's generated tables (docs/13-depth-complexity.md): its oracle and its scene files."""
from page_tables import ROOT, lesson, merged, stats

def depth_oracle():
    """Lesson 13's stencil against its CPU ray count (--set oracle=1), t = 1."""
    runs = [("all", "320x240", ""), ("all", "640x480", ""),
            ("stack-saturates", "320x240", " (counts stopped at 255)"), ("stack-wraps", "320x240", " (counts wrapped)")]
    lines = ["| run (`--set oracle=1`) | pixels | disagreements | of them on edges |", "|---|---|---|---|"]
    for variant, size, note in runs:
        c = stats(lesson("13-depth-complexity"), ["--size", size, "--variant", variant, "--set", "oracle=1"])["counts"]
        lines.append(f"| `{variant}`, {size}{note} | {c['oracle_pixels']} | {c['oracle_disagreements']} | "
                     f"{c['oracle_on_edges']} |")
    return lines


# Scene files lesson 13 refuses as a still picture: the sun has set at the file's own time (only
# --shadow-hours reads it).
NOT_STILL = {"sun-box-building-dusk.scene"}


def scene_files():
    """Every scene file lesson 13 can draw: tests/scenes/ and its folders, bad/ and NOT_STILL aside."""
    return sorted(p for p in (ROOT / "tests/scenes").rglob("*.scene")
                  if "bad" not in p.relative_to(ROOT / "tests/scenes").parts and p.name not in NOT_STILL)


def histogram_cell(histogram):
    """count: pixels, every count present; past 12 of them the first 8, "...", and the last 2."""
    cells = [f"{k}: {v}" for k, v in histogram]
    return ", ".join(cells if len(cells) <= 12 else cells[:8] + ["..."] + cells[-2:])


def depth_scenes():
    """Lesson 13 on every scene file, 640x480, t = 1, every fragment, and front faces only."""
    lines = ["| scene | max | mean | max, culled | mean, culled | covered pixels | histogram (count: pixels) |",
             "|---|---|---|---|---|---|---|"]
    rows = []
    runs = [("lesson 13 `all`", ["--variant", "all"])]
    runs += [(f"`{p.relative_to(ROOT / 'tests/scenes')}`", ["--scene", str(p)]) for p in scene_files()]
    for name, args in runs:
        c = stats(lesson("13-depth-complexity"), ["--size", "640x480"] + args)["counts"]
        culled = stats(lesson("13-depth-complexity"), ["--size", "640x480", "--set", "cull=1"] + args)["counts"]
        histogram = sorted((int(k.split(".")[1]), v) for k, v in c.items() if k.startswith("histogram."))

        def mean(x):
            return f"{x['counted_fragments'] / x['covered_pixels']:.2f}" if x["covered_pixels"] else "-"
        rows.append((name, [str(c["max_count"]), mean(c), str(culled["max_count"]), mean(culled),
                            str(c["covered_pixels"]), histogram_cell(histogram)]))
    for names, cells in merged(rows):
        label = names[0] + (" (also " + ", ".join(names[1:]) + ")" if len(names) > 1 else "")
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return lines


PAGE = "docs/13-depth-complexity.md"
TABLES = {"13-oracle": depth_oracle, "13-scenes": depth_scenes}
