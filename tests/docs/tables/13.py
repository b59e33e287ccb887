"""Lesson 13's generated tables (docs/13-depth-complexity.md): its oracle, its scene files and the
shadow volumes' fill."""
import concurrent.futures
import os

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


FILL_METHODS = ["McGuire", "Everitt-Kilgard", "Lengyel", "z-pass"]


def prefetch(runs):
    """stats() of every (exe, args) in RUNS, as many at once as the machine has cores: the fill
    table's 240 runs one after the other pass ctest's time limit on a loaded machine."""
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 1) as pool:
        list(pool.map(lambda run: stats(*run), runs))  # list(): a failed run ends the script here


def shadow_fill():
    """Every fragment of the shadow volumes (--set volumes=M: counted_fragments), per method, on each
    hard-case scene file and the interior, 640x480, t = 1, the lights' bounds on (the interior once
    more with them off), against lesson 16's volume-fill samples for the same run (--set fill=1).
    Where the 8-bit count saturates, lesson 13's sum falls short: the cell shows lesson 16's count,
    with a dagger; a row whose totals are not lesson 16's says DIFFERS, and a note gives lesson 16's."""
    interior = ROOT / "tests/scenes/interior-many-lights.scene"
    runs = [(s, "1") for s in sorted((ROOT / "tests/scenes/hard").glob("*.scene"))] + [(interior, "1"), (interior, "0")]
    lines = ["| scene | bounds | lights | " + " | ".join(FILL_METHODS) + " | EK / McGuire | = lesson 16 |",
             "|---|---|---|" + "---|" * len(FILL_METHODS) + "---|---|"]
    def common(scene, bounds):
        return ["--size", "640x480", "--scene", str(scene), "--set", f"bounds={bounds}"]
    prefetch([run for scene, bounds in runs for m in range(len(FILL_METHODS)) for run in (
        (lesson("13-depth-complexity"), common(scene, bounds) + ["--set", f"volumes={m + 1}"]),
        (lesson("16-fast-robust-shadows"), common(scene, bounds) + ["--set", "fill=1", "--set", f"method={m}"]))])
    saturated_notes, differs_notes = [], []
    for scene, bounds in runs:
        row, differs, lights, stopped = [], [], 0, False
        for m, method in enumerate(FILL_METHODS):
            l13 = stats(lesson("13-depth-complexity"), common(scene, bounds) + ["--set", f"volumes={m + 1}"])["counts"]
            l16 = stats(lesson("16-fast-robust-shadows"), common(scene, bounds) + ["--set", "fill=1", "--set", f"method={m}"])
            counted, lights = l13["counted_fragments"], l13["lights_drawn"]
            fill = sum(p["samples_passed"] for p in l16["passes"] if p["name"] == "volume-fill")
            if l13["saturated_pixels"]:  # the stencil stopped at 255: lesson 16's count, and how short the sum fell
                stopped = True
                row.append((fill, f"{fill:,}&dagger;"))
                saturated_notes.append(f"{scene.name}, {method}: {counted:,} stored, "
                                       f"{l13['saturated_pixels']:,} pixels at 255+")
            else:
                if counted != fill:
                    differs.append(f"{method} {fill:,}")
                row.append((counted, f"{counted:,}"))
        ratio = f"{row[1][0] / row[0][0]:.2f}" if row[0][0] else "-"
        if differs:
            differs_notes.append(f"{scene.name}: " + ", ".join(differs))
        same = "DIFFERS" if differs else "255+" if stopped else "="
        lines.append(f"| `{scene.relative_to(ROOT / 'tests/scenes')}` | {'on' if bounds == '1' else 'off'} | {lights} | "
                     + " | ".join(text for _, text in row) + f" | {ratio} | {same} |")
    if saturated_notes:
        lines += ["", "&dagger; lesson 16's count; lesson 13's stencil saturated: " + "; ".join(saturated_notes) + "."]
    if differs_notes:
        lines += ["", "DIFFERS: lesson 16's `volume-fill` count where it is not lesson 13's: "
                  + "; ".join(differs_notes) + "."]
    return lines


PAGE = "docs/13-depth-complexity.md"
TABLES = {"13-oracle": depth_oracle, "13-scenes": depth_scenes, "13-fill": shadow_fill}
