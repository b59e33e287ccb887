"""Lesson 14's generated tables (docs/14-csg.md): passes, oracle, scene files and the sweep's passes."""
import csv
import subprocess

from page_tables import ROOT, lesson, merged, stats

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
    for names, cells in merged(rows):
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
    rows = list(csv.DictReader((ROOT / "docs/sweeps/14-csg.csv").open()))
    names = {("grid", "2"): "grid 1x1", ("grid", "10"): "grid 3x3", ("grid", "26"): "grid 5x5",
             ("grid3", "28"): "grid 3x3x3", ("grid", "50"): "grid 7x7", ("rack", "344"): "box rack"}
    lines = ["| scene | primitives | Goldfeather passes | layered passes | SCS passes |", "|---|---|---|---|---|"]
    for (scene, primitives), name in names.items():
        passes = {r["method"]: f"{int(r['passes']):,}" for r in rows if r["scene"] == scene and r["primitives"] == primitives}
        cells = [passes.get(m, "—") for m in ("goldfeather", "layered", "scs")]
        lines.append(f"| {name} | {primitives} | " + " | ".join(cells) + " |")
    return lines


PAGE = "docs/14-csg.md"
TABLES = {"14-passes": csg_passes, "14-oracle": csg_oracle, "14-scene-files": csg_scene_files, "14-sweep": csg_sweep}
