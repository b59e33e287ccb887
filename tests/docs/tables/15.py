"""Lesson 15's generated tables (docs/15-robust-zfail.md): volume parts, depth error, the ray cast on scene files,
the cost in triangles and fragments, counting in groups and rooms."""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

import page_tables
from page_tables import ROOT, lesson, stats

LESSON = "15-robust-zfail"


def volume_parts():
    """Lesson 15's closed volumes (--stats counts), t = 1; the same runs as volume_cost's."""
    rows = [("zfail", "(one point light, three casters)"), ("directional", ""),
            ("coloured-lights", "(three point lights)")]
    lines = ["| variant (t = 1) | silhouette edges | side triangles | light cap | dark cap |", "|---|---|---|---|---|"]
    for variant, what in rows:
        c = stats(lesson(LESSON), ["--size", "640x480", "--variant", variant])["counts"]
        cells = [c[k] for k in ("silhouette_edges", "side_triangles", "light_cap_triangles", "dark_cap_triangles")]
        lines.append(f"| `{variant}`{' ' + what if what else ''} | " + " | ".join(str(x) for x in cells) + " |")
    return lines


def depth_error():
    """The largest relative depth error per decade of distance, as gl.Gl.ReversedFloatDepthKeeps... prints it."""
    exe = page_tables.BUILD / "tests/gl/gl_tests"
    out = subprocess.run([str(exe), "--gtest_filter=Gl.ReversedFloatDepthKeepsTheRelativeErrorAtEveryDistance"],
                         capture_output=True, text=True)
    if out.returncode != 0 or "[  PASSED  ] 1 test" not in out.stdout:
        sys.exit(f"{exe}: the depth error test did not pass (exit {out.returncode}):\n{out.stdout[-2000:]}")
    measured = {}
    for line in out.stdout.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 8 and not cells[0].startswith(("n = ", "---")):
            # "2.9e-06" as the page writes it, 2.9e-6
            measured[cells[0]] = ["all depth 1" if c.startswith("depth 1") else re.sub(r"e([-+])0(\d)", r"e\1\2", c)
                                  for c in cells[1:]]
    rows = [("24-bit, GL's mapping (Pinf, `pinf-fixed24`)", "fixed24, GL's mapping (Pinf)"),
            ("float, GL's mapping", "float32, GL's mapping"),
            ("float, reversed by `glDepthRange(1, 0)` alone", "float32, glDepthRange(1, 0)"),
            ("float, reversed, clip control (the default)", "float32, reversed, clip control")]
    lines = ["| largest \\|d′ − d\\| / d | d in [10⁻³, 10⁻²) | [10⁻², 0.1) | [0.1, 1) | [1, 10) | [10, 100) "
             "| [100, 1000) | [1000, 10⁴) |", "|---|---|---|---|---|---|---|---|"]
    for label, name in rows:
        if name not in measured:
            sys.exit(f"{exe}: no row '{name}' in the depth error test's table")
        lines.append(f"| {label} | " + " | ".join(measured[name]) + " |")
    return lines


_oracle_runs = {}
LIGHT_LINE = re.compile(r"^light-\d+ \(.*\): (?:ok|FAILED), \d+ receiver pixels, \d+ shadowed; "
                        r"(\d+) disagree, (\d+) of them on edges \((.*)\)$")


def oracle(name, scene, size, variant=None):
    """scene_oracle's verdict per light, [(disagreements, of them on edges)], each run once. A run that
    disagrees keeps its masks and pictures: they are removed."""
    key = (name, str(scene), size, variant)
    if key in _oracle_runs:
        return _oracle_runs[key]
    command = [str(page_tables.BUILD / "tests/scenes/scene_oracle")] + (["--variant", variant] if variant else [])
    command += [str(lesson(name)), str(scene), size, "1"]
    out = subprocess.run(command, capture_output=True, text=True)
    lights = [LIGHT_LINE.match(line) for line in out.stdout.splitlines()]
    lights = [m for m in lights if m]
    if out.returncode not in (0, 1) or not lights:
        sys.exit(f"{' '.join(command)}: exit {out.returncode}:\n{out.stdout}{out.stderr}")
    folder = pathlib.Path(lights[0].group(3)).parent
    if folder.name.startswith("scene-oracle-") and folder.exists():
        shutil.rmtree(folder)
    _oracle_runs[key] = [(int(m.group(1)), int(m.group(2))) for m in lights]
    return _oracle_runs[key]


def near_plane_scene(near, folder):
    """hard/near-plane-1e-4.scene with another near plane, written into FOLDER."""
    text = (ROOT / "tests/scenes/hard/near-plane-1e-4.scene").read_text()
    changed = re.sub(r"near 0\.0001\b", f"near {near}", text)
    if changed == text:
        sys.exit("hard/near-plane-1e-4.scene: no 'near 0.0001' in its camera line")
    path = pathlib.Path(folder) / f"near-plane-{near}.scene"
    path.write_text(changed)
    return path


def near_plane():
    """hard/near-plane-1e-4.scene against the ray cast, both paths, at two sizes and two further near planes."""
    scene = ROOT / "tests/scenes/hard/near-plane-1e-4.scene"
    lines = ["| near-plane-1e-4, disagreements (on edges) | 320x240 | 640x480 |", "|---|---|---|"]
    with tempfile.TemporaryDirectory() as folder:
        runs = [("`pinf-fixed24` (the old path)", LESSON, scene, "pinf-fixed24"),
                ("reversed float (the default)", LESSON, scene, None),
                ("lesson 16, `pinf-fixed24`", "16-fast-robust-shadows", scene, "pinf-fixed24"),
                ("lesson 16, reversed float", "16-fast-robust-shadows", scene, None),
                ("`pinf-fixed24` with near 10⁻³", LESSON, near_plane_scene("0.001", folder), "pinf-fixed24"),
                ("`pinf-fixed24` with near 10⁻²", LESSON, near_plane_scene("0.01", folder), "pinf-fixed24")]
        for label, name, path, variant in runs:
            cells = []
            for size in ("320x240", "640x480"):
                (all_, edges), = oracle(name, path, size, variant)  # the scene has one light
                cells.append(f"{all_} ({edges})")
            lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return lines


def volume_passes(args):
    """The volumes passes' triangles and samples_passed, summed over the lights."""
    s = stats(lesson(LESSON), args)
    passes = [p for p in s["passes"] if p["name"] == "volumes"]
    return (sum(p["draw_calls"] for p in passes), sum(p["triangles"] for p in passes),
            sum(p["samples_passed"] for p in passes))


COST_ROWS = [("`zfail`", ["--variant", "zfail"]),
             ("`pinf-fixed24` (the old path: 24-bit depth)", ["--variant", "pinf-fixed24"]),
             ("`zpass` (the same closed volumes)", ["--variant", "zpass"]),
             ("`zpass --set caps=0` (the sides alone)", ["--variant", "zpass", "--set", "caps=0"]),
             ("`zfail-finite-far` (wrong)", ["--variant", "zfail-finite-far"]),
             ("`depth-clamp`", ["--variant", "depth-clamp"]),
             ("`directional`", ["--variant", "directional"]),
             ("`coloured-lights` (three lights)", ["--variant", "coloured-lights"])]


def volume_cost():
    """The volumes passes per variant, 640x480, t = 1 (--stats); their times are on the page, measured apart."""
    lines = ["| | volume triangles | volume fragments passing depth |", "|---|---|---|"]
    for label, args in COST_ROWS:
        _, triangles, fragments = volume_passes(["--size", "640x480"] + args)
        lines.append(f"| {label} | {triangles} | {fragments} |")
    return lines


def count_groups():
    """The "regions" column today: the volumes passes at 320x240, t = 1, without the mark (as the columns before
    were measured); the "before" and "runs of 127 faces" columns are the record of the old code."""
    old = {"built-in (`zfail`)": ("3, 1544, 11817", "3, 1544, 11818 (no fold: the bounds add up to less than 256)"),
           "`staircase-256-nested-volumes`": ("1, 2566, 8644320", "10, 2588, 8764173 (5 pieces, 5 folds)"),
           "`slabs-1000-nested-volumes`": ("1, 20000, 9544970", "32, 12064, 9672522 (16 pieces, 16 folds)")}
    hard = ROOT / "tests/scenes/hard"
    scenes = {"built-in (`zfail`)": ["--variant", "zfail"],
              "`staircase-256-nested-volumes`": ["--scene", str(hard / "staircase-256-nested-volumes.scene")],
              "`slabs-1000-nested-volumes`": ["--scene", str(hard / "slabs-1000-nested-volumes.scene")]}
    lines = ["| scene | before | runs of 127 faces | regions |", "|---|---|---|---|"]
    for name, args in scenes.items():
        run = ["--size", "320x240", "--set", "mark=0"] + args
        calls, triangles, fragments = volume_passes(run)
        c = stats(lesson(LESSON), run)["counts"]
        folds = c.get("count_groups", 0)
        how = f"{c.get('volume_pieces', 0)} pieces, {folds} folds" if folds else "no fold"
        lines.append(f"| {name} | {old[name][0]} | {old[name][1]} | {calls}, {triangles}, {fragments} ({how}) |")
    return lines


def rooms():
    """The rooms against the ray cast, 320x240, both lessons, every light's disagreements; the "before" columns are
    the record of the old code."""
    old = {"room-eye-inside-a-box": ("76176, 2", "0, 2"), "room-faces-inward": ("76800, 66816", "0, 66816")}
    lines = ["| scene | lesson 15 before | lesson 16 before | both after |", "|---|---|---|---|"]
    for name, (before15, before16) in old.items():
        scene = ROOT / f"tests/scenes/hard/{name}.scene"
        after = [", ".join(str(d) for d, _ in oracle(n, scene, "320x240")) for n in (LESSON, "16-fast-robust-shadows")]
        cell = after[0] if after[0] == after[1] else f"lesson 15: {after[0]}; lesson 16: {after[1]}"
        lines.append(f"| `{name}` | {before15} | {before16} | {cell} |")
    return lines


PAGE = "docs/15-robust-zfail.md"
TABLES = {"15-volume-parts": volume_parts, "15-depth-error": depth_error, "15-near-plane": near_plane,
          "15-cost": volume_cost, "15-count-groups": count_groups, "15-rooms": rooms}
