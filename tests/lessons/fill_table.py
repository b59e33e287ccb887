#!/usr/bin/env python3
"""Lesson 13's fill table: every fragment of the shadow volumes, per method, per scene file.

Runs lesson 13 (--set volumes=M) on each scene and prints its counted_fragments (the stencil's
counts summed) as a Markdown table, with lesson 16's volume-fill samples for the same scene,
method and size beside them (--set fill=1): "=" where they agree.

    tests/lessons/fill_table.py BUILD_DIR [SIZE] [BOUNDS]    # SIZE 640x480, BOUNDS 1 by default
"""
import json
import pathlib
import subprocess
import sys

METHODS = ["McGuire", "Everitt-Kilgard", "Lengyel", "z-pass"]
ROOT = pathlib.Path(__file__).resolve().parents[2]


def stats(exe, args):
    out = subprocess.run([str(exe), "--headless", "--quiet", "--time", "1", "--stats", "--out", "/dev/null.png"]
                         + args, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"{exe} {' '.join(args)}: exit {out.returncode}: {out.stderr.strip()}")
    return json.loads(out.stdout)


def main():
    build = pathlib.Path(sys.argv[1])
    size = sys.argv[2] if len(sys.argv) > 2 else "640x480"
    bounds = sys.argv[3] if len(sys.argv) > 3 else "1"
    scenes = sorted((ROOT / "tests/scenes/hard").glob("*.scene")) + [ROOT / "tests/scenes/interior-many-lights.scene"]
    print("| scene | lights | " + " | ".join(METHODS) + " | EK / McGuire | = lesson 16 |")
    print("|---|---|" + "---|" * len(METHODS) + "---|---|")
    for scene in scenes:
        row, same, lights = [], True, 0
        for m in range(4):
            common = ["--size", size, "--scene", str(scene), "--set", f"bounds={bounds}"]
            l13 = stats(build / "lessons/13-depth-complexity", common + ["--set", f"volumes={m + 1}"])
            l16 = stats(build / "lessons/16-fast-robust-shadows", common + ["--set", "fill=1", "--set", f"method={m}"])
            counted = l13["counts"]["counted_fragments"]
            fill = sum(p["samples_passed"] for p in l16["passes"] if p["name"] == "volume-fill")
            same &= counted == fill and l13["counts"]["saturated_pixels"] == 0
            lights = l13["counts"]["lights_drawn"]
            row.append(counted)
        ratio = f"{row[1] / row[0]:.2f}" if row[0] else "-"
        name = scene.relative_to(ROOT / "tests/scenes")
        print(f"| `{name}` | {lights} | " + " | ".join(f"{n:,}" for n in row) + f" | {ratio} | {'=' if same else 'DIFFERS'} |")


main()
