"""Lesson 12's generated tables (docs/12-dissolve.md): each pattern's clumpiness, each method's fragments."""
from page_tables import lesson, stats

PATTERNS = ["white noise", "Bayer", "blue noise", "linear wipe", "radial wipe", "clock wipe"]
METHODS = ["stencil", "draw both, mix", "shade both, discard"]


def measured(pattern, method=0, step=128):
    """The counts of --set measure=1, 320x240, t = 1: the clumpiness tables and the fragment table
    share the stencil's runs."""
    return stats(lesson("12-dissolve"), ["--size", "320x240", "--variant", "dissolve", "--set", f"pattern={pattern}",
                                         "--set", f"step={step}", "--set", f"method={method}",
                                         "--set", "measure=1"])["counts"]


def clumpiness():
    """Per pattern, the variance of the share of B over every 8x8 window at a few states k, and its
    mean over k = 1..255 (counts in billionths)."""
    lines = ["| pattern | variance, *k* = 32 | *k* = 64 | *k* = 128 | *k* = 192 | mean over *k* = 1..255 |",
             "|---|---|---|---|---|---|"]
    for p, name in enumerate(PATTERNS):
        c = measured(p)
        cells = [c[f"coverage_variance_e9.k{k}"] * 1e-9 for k in (32, 64, 128, 192)] + [c["coverage_variance_e9.mean"] * 1e-9]
        lines.append(f"| {name} | " + " | ".join(f"{x:.2e}" for x in cells) + " |")
    return lines


def fragments():
    """Per method, blue noise and the linear wipe at k = 128: pixels, samples passed and fragment-shader
    invocations; then each scene whole, whose samples passed are the stencil's at k = 0 (A alone) and
    k = 256 (B alone)."""
    lines = ["| pattern | method | pixels | samples passed | fragment-shader invocations (llvmpipe) |",
             "|---|---|---|---|---|"]
    for p in (2, 3):
        for m, method in enumerate(METHODS):
            c = measured(p, m)
            lines.append(f"| {PATTERNS[p]} | {method} | {c['pixels']} | {c['samples_passed']} | "
                         f"{c.get('fragments_shaded', 'n/a')} |")
    a, b = measured(2, 0, 0), measured(2, 0, 256)
    lines.append(f"| (either) | scene A whole, scene B whole | | {a['samples_passed']}, {b['samples_passed']} | "
                 f"{a.get('whole_a_fragments_shaded', 'n/a')}, {a.get('whole_b_fragments_shaded', 'n/a')} |")
    return lines


PAGE = "docs/12-dissolve.md"
TABLES = {"12-clumpiness": clumpiness, "12-fragments": fragments}
