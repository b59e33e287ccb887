#!/usr/bin/env python3
"""The pages' tables of measured counts, written from a fresh run (ctest -L docs, docs.tables.*).

    page_tables.py BUILD_DIR --write [NAME...]   # measure and rewrite the tables in the pages
    page_tables.py BUILD_DIR --check [NAME...]   # measure and compare with the pages: a test
    page_tables.py BUILD_DIR --check --page P.md # the tables of one page (docs.tables.<page>)

A generated table sits in its page between two markers, which the page's reader does not see:

    <!-- table NAME: written by tests/docs/page_tables.py; do not edit by hand -->

    | ... |

    <!-- end table NAME -->

Each NAME below runs a lesson with --stats and formats what it reports. Counts only: no timing is
ever measured here (times depend on the machine and its load; the pages say where theirs come from).
"""
import difflib
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "lessons"))
import lesson_run  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = None


def lesson(name):
    return BUILD / "lessons" / name


_runs = {}


def stats(exe, args):
    """lesson_run.stats, each run once per process: tables that share runs share them."""
    key = (str(exe), tuple(args))
    if key not in _runs:
        _runs[key] = lesson_run.stats(exe, args)
    return _runs[key]


def merged(rows, key_columns):
    """Rows with the same measured cells merged into one, their names joined: [(names, cells)]."""
    out = []
    for name, cells in rows:
        for names, other in out:
            if other == cells:
                names.append(name)
                break
        else:
            out.append(([name], cells))
    return out


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
    for names, cells in merged(rows, None):
        label = names[0] + (" (also " + ", ".join(names[1:]) + ")" if len(names) > 1 else "")
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return lines


CSG_PASS_VARIANTS = {
    "goldfeather": "A − B", "goldfeather-rounded-cube": "cube * sphere − (x + y + z)",
    "goldfeather-nested": "A − (B − C)", "goldfeather-torus": "*c* = 2", "goldfeather-grid": "box − 25 spheres",
    "layered-torus": "", "layered-rounded-cube": "", "layered-grid": ""}
CSG_ORACLE_VARIANTS = [
    "a-minus-b", "union", "intersection", "b-minus-a", "goldfeather", "goldfeather-grid",
    "goldfeather-rounded-cube", "goldfeather-nested", "goldfeather-torus", "layered-torus", "layered-rounded-cube",
    "layered-grid", "scs-rounded-cube", "scs-grid", "no-stencil", "goldfeather-torus-convexity-1",
    "eye-in-b", "goldfeather-eye-in-b", "coincident", "coincident-grown"]


def csg_passes():
    """Lesson 14's passes per variant, 320x240, t = 1."""
    lines = ["| variant | products | primitives | select | parity | far | merge | layers counted |",
             "|---|---|---|---|---|---|---|---|"]
    for variant, what in CSG_PASS_VARIANTS.items():
        c = stats(lesson("14-csg"), ["--size", "320x240", "--set", "oracle=1", "--variant", variant])["counts"]
        cells = [c.get(k, "") for k in ("products", "literals", "select_passes", "parity_passes", "far_passes",
                                         "merge_passes", "layers_counted")]
        lines.append(f"| {variant}{f' ({what})' if what else ''} | " + " | ".join(str(x) for x in cells) + " |")
    return lines


def csg_disagreements(args):
    c = stats(lesson("14-csg"), ["--size", "320x240", "--set", "oracle=1"] + args)["counts"]
    return [f"{c['oracle_primitive_disagreements']:,}", f"{c['oracle_depth_disagreements']:,}", f"{c['oracle_on_edges']:,}"]


def csg_oracle():
    """Lesson 14 against its ray cast (--set oracle=1), 320x240, t = 1."""
    lines = ["| variant | another primitive | another depth | of these on edges |", "|---|---|---|---|"]
    rows = [(v, csg_disagreements(["--variant", v])) for v in CSG_ORACLE_VARIANTS]
    for names, cells in merged(rows, None):
        lines.append("| " + ", ".join(names) + " | " + " | ".join(cells) + " |")
    return lines


def csg_scene_files():
    """Lesson 14 on the scene files in tests/scenes/csg/, each method, 320x240, t = 1; a method that
    refuses a scene (exit 2: SCS and a concave primitive) says so."""
    lines = ["| scene | method | another primitive | another depth | of these on edges |", "|---|---|---|---|---|"]
    for scene in sorted((ROOT / "tests/scenes/csg").glob("*.scene")):
        for method, name in ((1, "Goldfeather"), (2, "layered"), (3, "SCS"), (4, "automatic")):
            args = ["--scene", str(scene), "--set", f"method={method}"]
            probe = subprocess.run([str(lesson("14-csg")), "--headless", "--quiet", "--size", "8x8"] + args,
                                   capture_output=True, text=True)
            if probe.returncode == 2:
                cells = ["refused (exit 2)", "", ""]
            else:
                cells = csg_disagreements(args)
            lines.append(f"| `{scene.relative_to(ROOT / 'tests/scenes')}` | {method} ({name}) | " + " | ".join(cells) + " |")
    return lines


def csg_sweep():
    """The passes of lesson 14's sweep, from its committed CSV (docs/sweeps/14-csg.csv, written by
    `cmake --build build --target sweep-14-csg`); its times are left out."""
    import csv
    rows = list(csv.DictReader((ROOT / "docs/sweeps/14-csg.csv").open()))
    names = {("grid", "2"): "grid 1x1", ("grid", "10"): "grid 3x3", ("grid", "26"): "grid 5x5",
             ("grid3", "28"): "grid 3x3x3", ("grid", "50"): "grid 7x7", ("rack", "344"): "box rack"}
    lines = ["| scene | primitives | Goldfeather passes | layered passes | SCS passes |", "|---|---|---|---|---|"]
    for (scene, primitives), name in names.items():
        passes = {r["method"]: f"{int(r['passes']):,}" for r in rows if r["scene"] == scene and r["primitives"] == primitives}
        cells = [passes.get(m, "—") for m in ("goldfeather", "layered", "scs")]
        lines.append(f"| {name} | {primitives} | " + " | ".join(cells) + " |")
    return lines


TABLES = {
    "13-oracle": ("docs/13-depth-complexity.md", depth_oracle),
    "13-scenes": ("docs/13-depth-complexity.md", depth_scenes),
    "14-passes": ("docs/14-csg.md", csg_passes),
    "14-oracle": ("docs/14-csg.md", csg_oracle),
    "14-scene-files": ("docs/14-csg.md", csg_scene_files),
    "14-sweep": ("docs/14-csg.md", csg_sweep),
}


def span(text, name):
    begin = re.search(rf"^<!-- table {re.escape(name)}:[^\n]*-->\n", text, re.M)
    end = re.search(rf"^<!-- end table {re.escape(name)} -->$", text, re.M)
    if not begin or not end or end.start() < begin.end():
        sys.exit(f"page_tables.py: no markers for table {name} in {TABLES[name][0]}")
    return begin.end(), end.start()


def main():
    global BUILD
    args = sys.argv[1:]
    if len(args) < 2 or args[1] not in ("--write", "--check"):
        sys.exit(__doc__)
    BUILD = pathlib.Path(args[0]).resolve()
    names = args[2:] or list(TABLES)
    if names[0] == "--page":
        names = [n for n, (page, _) in TABLES.items() if page == f"docs/{names[1]}"]
        if not names:
            sys.exit(f"page_tables.py: no generated table in docs/{args[3]}")
    for name in names:
        if name not in TABLES:
            sys.exit(f"page_tables.py: unknown table '{name}' (known: {', '.join(TABLES)})")
        page, make = TABLES[name]
        path = ROOT / page
        text = path.read_text()
        a, b = span(text, name)
        fresh = "\n" + "\n".join(make()) + "\n\n"  # blank lines: the markers stay apart from the table
        if args[1] == "--write":
            path.write_text(text[:a] + fresh + text[b:])
            print(f"{page}: table {name} written")
        elif text[a:b] != fresh:
            diff = difflib.unified_diff(text[a:b].splitlines(), fresh.splitlines(), "the page", "a fresh run", lineterm="")
            sys.exit(f"{page}: table {name} differs from a fresh run (rewrite it: tests/docs/page_tables.py build "
                     f"--write {name}, and check the page's words against it):\n" + "\n".join(diff))
        else:
            print(f"{page}: table {name} is what a fresh run measures")


if __name__ == "__main__":
    main()
