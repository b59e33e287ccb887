#!/usr/bin/env python3
"""Lesson 13's fill table: every fragment of the shadow volumes, per method, per scene file.

Runs lesson 13 (--set volumes=M) on each hard-case scene and the interior, with the lights'
bounds on (and the interior once more with them off), and prints its counted_fragments (the
stencil's counts summed) as a Markdown table, checked against lesson 16's volume-fill samples for
the same scene, method, bounds and size (--set fill=1). Where the 8-bit count saturates (pixels
at 255+), lesson 13's sum falls short: the cell shows lesson 16's figure, marked with a dagger.

    tests/lessons/fill_table.py BUILD_DIR [SIZE]    # SIZE 640x480 by default
"""
import pathlib
import sys

from lesson_run import stats

METHODS = ["McGuire", "Everitt-Kilgard", "Lengyel", "z-pass"]
ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    build = pathlib.Path(sys.argv[1])
    size = sys.argv[2] if len(sys.argv) > 2 else "640x480"
    interior = ROOT / "tests/scenes/interior-many-lights.scene"
    runs = [(s, "1") for s in sorted((ROOT / "tests/scenes/hard").glob("*.scene"))]
    runs += [(interior, "1"), (interior, "0")]
    print("| scene | bounds | lights | " + " | ".join(METHODS) + " | EK / McGuire | = lesson 16 |")
    print("|---|---|---|" + "---|" * len(METHODS) + "---|---|")
    notes = []
    for scene, bounds in runs:
        row, same, lights, stopped = [], True, 0, False
        for m in range(4):
            common = ["--size", size, "--scene", str(scene), "--set", f"bounds={bounds}"]
            l13 = stats(build / "lessons/13-depth-complexity", common + ["--set", f"volumes={m + 1}"])
            l16 = stats(build / "lessons/16-fast-robust-shadows", common + ["--set", "fill=1", "--set", f"method={m}"])
            counted = l13["counts"]["counted_fragments"]
            fill = sum(p["samples_passed"] for p in l16["passes"] if p["name"] == "volume-fill")
            saturated = l13["counts"]["saturated_pixels"]
            lights = l13["counts"]["lights_drawn"]
            if saturated:  # the stencil stopped at 255: lesson 16's count, and how short the sum fell
                stopped = True
                row.append((fill, f"{fill:,}&dagger;"))
                notes.append(f"{scene.name}, {METHODS[m]}: {counted:,} stored, {saturated:,} pixels at 255+")
            else:
                same &= counted == fill
                row.append((counted, f"{counted:,}"))
        ratio = f"{row[1][0] / row[0][0]:.2f}" if row[0][0] else "-"
        name = scene.relative_to(ROOT / "tests/scenes")
        cells = " | ".join(text for _, text in row)
        print(f"| `{name}` | {'on' if bounds == '1' else 'off'} | {lights} | {cells} | {ratio} | {'DIFFERS' if not same else '255+' if stopped else '='} |")
    if notes:
        print("\n&dagger; lesson 16's count; lesson 13's stencil saturated: " + "; ".join(notes) + ".")


main()
