"""Lesson 16's generated tables (docs/16-fast-robust-shadows.md): the sweep's counts, from its committed CSV, and
the shadow profile's steps."""
import csv
import re
import subprocess
import sys
import tempfile

from page_tables import ROOT, lesson

SWEEP_CSV = ROOT / "docs/sweeps/16-fast-robust-shadows.csv"
METHODS = [("mcguire", "McGuire et al."), ("everitt-kilgard", "Everitt-Kilgard"), ("lengyel", "Lengyel"),
           ("zpass", "z-pass only")]
VIEWS = ["system", "eye-in-shadow", "looking-up"]
MOMENTS = ["1", "2.5", "4"]


def sweep_rows(sweep):
    return [r for r in csv.DictReader(SWEEP_CSV.open()) if r["sweep"] == sweep]


def sweep_methods():
    """The methods sweep's counts from docs/sweeps/16-fast-robust-shadows.csv (written by `cmake --build build
    --target sweep-16-fast-robust-shadows`); its times are left out."""
    rows = sweep_rows("methods")
    lines = ["| view | method | shadow-pass triangles (t = 1 / 2.5 / 4) | fragments in front / rasterized (t = 1) "
             "| wrong pixels off edges (t = 1 / 2.5 / 4) |", "|---|---|---|---|---|"]
    for view in VIEWS:
        for method, name in METHODS:
            at = {r["time"]: r for r in rows if r["view"] == view and r["method"] == method}
            if sorted(at) != sorted(MOMENTS):
                sys.exit(f"{SWEEP_CSV}: {view}, {method}: moments {sorted(at)}, not {MOMENTS}")
            triangles = " / ".join(at[t]["shadow_triangles"] for t in MOMENTS)
            fragments = f"{at['1']['volume_fragments']} / {at['1']['volume_fragments_rasterized']}"
            wrong = " / ".join(at[t]["wrong_off_edges"] for t in MOMENTS)
            lines.append(f"| `{view}` | {name} | {triangles} | {fragments} | {wrong} |")
    return lines


def sweep_tessellation():
    """The tessellation sweep's sphere triangles (sides + dark cap + light cap) from the same CSV."""
    rows = sweep_rows("tessellation")
    views = [("system", "case 1 (`system`)"), ("eye-in-shadow", "case 2 (`eye-in-shadow`)"),
             ("looking-up", "case 3 (`looking-up`)")]
    lines = ["| slices | " + " | ".join(f"{name}: McGuire / Lengyel" for _, name in views) + " |", "|---|---|---|---|"]
    for slices in sorted({int(r["slices"]) for r in rows}):
        cells = []
        for view, _ in views:
            at = {r["method"]: r for r in rows if r["view"] == view and int(r["slices"]) == slices}
            parts = [int(at["mcguire"][k]) for k in ("sphere_sides", "sphere_dark_cap", "sphere_light_cap")]
            lengyel = sum(int(at["lengyel"][k]) for k in ("sphere_sides", "sphere_dark_cap", "sphere_light_cap"))
            cells.append(f"{sum(parts)} ({' + '.join(str(p) for p in parts)}) / {lengyel}")
        lines.append(f"| {slices} | " + " | ".join(cells) + " |")
    return lines


STEP_LINE = re.compile(r"^shadow-hours (\d\d:\d\d): sun elevation (-?[\d.]+), azimuth ([\d.]+) degrees; "
                       r"(\d+) of (\d+) pixels in shadow")


def shadow_hours():
    """The shadow profile of tests/scenes/shadow-profile-block.scene, 320x240, 09:00-17:00 hourly: each step's line
    on stderr, its frame time left out."""
    with tempfile.TemporaryDirectory() as folder:
        command = [str(lesson("16-fast-robust-shadows")), "--headless", "--size", "320x240", "--time", "1",
                   "--scene", str(ROOT / "tests/scenes/shadow-profile-block.scene"),
                   "--shadow-hours", f"{folder}/hours.png", "--shadow-span", "09:00-17:00", "--shadow-step", "60"]
        out = subprocess.run(command, capture_output=True, text=True)
    steps = [m for m in map(STEP_LINE.match, out.stderr.splitlines()) if m]
    if out.returncode != 0 or len(steps) != 9:
        sys.exit(f"{' '.join(command)}: exit {out.returncode}, {len(steps)} steps:\n{out.stderr}")
    total = int(steps[0].group(5))
    lines = [f"| local time | sun elevation | azimuth | pixels in shadow (of {total:,}) |", "|---|---:|---:|---:|"]
    for m in steps:
        lines.append(f"| {m.group(1)} | {m.group(2)} | {m.group(3)} | {m.group(4)} |")
    return lines


PAGE = "docs/16-fast-robust-shadows.md"
TABLES = {"16-sweep-methods": sweep_methods, "16-sweep-slices": sweep_tessellation, "16-shadow-hours": shadow_hours}
