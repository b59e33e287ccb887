"""Lesson 03's generated tables (docs/03-recursive-mirrors.md): scene renderings, and the counts and
errors of its sweep."""
import csv

from page_tables import ROOT, lesson, stats

# (mirrors n, bounces r, the row's name): the configurations the page counts.
RENDERINGS = [(2, 8, "2 (the hall)"), (3, 2, "3"), (3, 4, "3"), (4, 3, "4"), (5, 3, "5"), (5, 4, "5")]


def worst_case(n, r):
    """1 + n Σ_{i=1..r} (n-1)^(i-1): every mirror seen in every mirror but itself."""
    return 1 + n * sum((n - 1) ** (i - 1) for i in range(1, r + 1))


def renderings():
    """Lesson 03's scene renderings, 640x480, t = 1, culling off and on, against the formula."""
    lines = ["| mirrors n | bounces r | worst case (formula) | culling off (measured) | culling on (measured) |",
             "|---|---|---|---|---|"]
    for n, r, name in RENDERINGS:
        counted = [stats(lesson("03-recursive-mirrors"), ["--size", "640x480", "--set", f"mirrors={n}",
                                                          "--set", f"depth={r}", "--set", f"culling={c}"])
                   ["counts"]["scene_renderings"] for c in (0, 1)]
        lines.append(f"| {name} | {r} | {worst_case(n, r)} | {counted[0]} | {counted[1]} |")
    return lines


def bounces():
    """The counts and errors of lesson 03's sweep, from its committed CSV (docs/sweeps/03-recursive-mirrors.csv,
    written by `cmake --build build --target sweeps`); its times are left out."""
    lines = ["| bounces | scene renderings, culling on / off | RMS error over the mirror (of 255) | "
             "mirror pixels off by more than 5/255 |", "|---|---|---|---|"]
    for row in csv.DictReader((ROOT / "docs/sweeps/03-recursive-mirrors.csv").open()):
        lines.append(f"| {row['depth']} | {row['scene_renderings']} / {row['scene_renderings_no_culling']} | "
                     f"{float(row['rms_error']):.1f} | {row['wrong_pixels']} |")
    return lines


PAGE = "docs/03-recursive-mirrors.md"
TABLES = {"03-renderings": renderings, "03-bounces": bounces}
