#!/usr/bin/env python3
"""Writes tests/scenes/opencsg/*.scene: the CSG shapes of OpenCSG's example program (OpenCSG 1.5,
example/main.cpp: setBasicShape, setWidget, setGrid2D, setGrid3D, setCubeRack, setPipe, setConcave)
as lesson 14 scene files, with its camera (gluLookAt from (0, 2, 5) at the origin, 40 degrees,
near 0.2, far 10) and no spin. Each glutSolidCube(s) is a box of half s/2, glutSolidSphere(r, sl, st)
a sphere of those slices and stacks, glutSolidTorus(inner, outer, sides, rings) a torus of minor
`inner` and major `outer` (GLUT's lies in z = 0, the scene's around y: rotated 90 about x), and the
example's solidCylinder (a gluCylinder along +z from 0 to h, capped) a cylinder of that height
centred on the origin, turned from y onto z. Transforms are written in the order they act on the
shape (the reverse of the example's glTranslate/glRotate calls). The csg line is the sum of the
example's products (OpenCSG::render calls), each the intersected primitives minus the subtracted.

Run from the repository root: python3 tests/bench/make_opencsg_scenes.py"""
import os

HEADER = """# {title} (OpenCSG 1.5's example program, {fn}): {what}
# Written by tests/bench/make_opencsg_scenes.py; rendered beside OpenCSG by csg_opencsg_benchmark.
camera eye 0 2 5 target 0 0 0 fovy 40 near 0.2 far 10
light directional 1 1 1
"""


def obj(name, shape, *settings, color=None):
    lines = [f"object {name} {shape}"]
    lines += [f"  {s}" for s in settings]
    if color:
        lines.append(f"  color {color}")
    lines.append("  casts no")
    return "\n".join(lines) + "\n"


def num(x):
    s = f"{x:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


ORANGE, BLUE, GREEN = "0.95 0.55 0.2", "0.25 0.5 0.95", "0.3 0.8 0.35"
# solidCylinder(r, h) along +z from 0 to h, then the example's glTranslatef(0, 0, -t): centred when
# t = h/2. The scene's cylinder is centred along y: rotate 90 about x takes +y to +z.
def zcyl(r, h, z_offset):
    return (f"cylinder radius {num(r)} height {num(h)} slices 20",
            ["rotate 90 1 0 0", f"translate 0 0 {num(z_offset + h / 2)}"])


def write(path, title, fn, what, body, csg):
    with open(path, "w") as f:
        f.write(HEADER.format(title=title, fn=fn, what=what))
        f.write(body)
        f.write(f"csg {csg}\n")


def main():
    out = "tests/scenes/opencsg"
    os.makedirs(out, exist_ok=True)

    body = obj("a", "sphere radius 1 slices 20 stacks 20", "translate -0.25 0 0", color=ORANGE)
    body += obj("b", "sphere radius 1 slices 20 stacks 20", "translate 0.25 0 0", color=ORANGE)
    body += obj("c", "sphere radius 1 slices 20 stacks 20", "scale 0.5 0.5 2", "translate 0 0 0.5",
                color=BLUE)
    write(f"{out}/simple.scene", "Simple", "setBasicShape", "two balls intersected minus an ellipsoid",
          body, "a * b - c")

    body = obj("ball", "sphere radius 1.2 slices 20 stacks 20", color=ORANGE)
    body += obj("cube", "box half 0.9", color=ORANGE)
    shape, moves = zcyl(0.6, 2.5, -1.25)
    body += obj("z", shape, *moves, color=BLUE)
    body += obj("x", shape, *moves, "rotate 90 0 1 0", color=GREEN)
    body += obj("y", shape, *moves, "rotate 90 1 0 0", color=BLUE)
    write(f"{out}/widget.scene", "Widget", "setWidget", "a ball times a cube minus three drills",
          body, "ball * cube - z - x - y")

    # The box: glutSolidCube(2.5), translated by (0, -1.25, 0), then scaled by (1, 0.2, 1).
    body = obj("box", "box half 1.25", "translate 0 -1.25 0", "scale 1 0.2 1", color=ORANGE)
    names = []
    for x in range(-2, 3):
        for z in range(-2, 3):
            n = f"s{len(names)}"
            names.append(n)
            body += obj(n, "sphere radius 0.22 slices 15 stacks 15", f"translate {num(x * 0.5)} 0 {num(z * 0.5)}",
                        color=BLUE)
    write(f"{out}/grid2d.scene", "2D grid", "setGrid2D",
          "a slab minus 5x5 spheres of radius 0.22, 0.5 apart (none overlap)", body,
          "box - " + " - ".join(names))

    body = obj("box", "box half 1", color=ORANGE)
    names = []
    for x in range(-1, 2):
        for y in range(-1, 2):
            for z in range(-1, 2):
                n = f"s{len(names)}"
                names.append(n)
                body += obj(n, "sphere radius 0.58 slices 20 stacks 20", f"translate {x} {y} {z}", color=BLUE)
    write(f"{out}/grid3d.scene", "3D grid", "setGrid3D",
          "a cube minus 3x3x3 spheres of radius 0.58, 1 apart (neighbours overlap)", body,
          "box - " + " - ".join(names))

    # The example's order: each axis -3, 3, -2, 2, -1, 1, 0 (sixths), x outermost.
    body = obj("box", "box half 1", color=ORANGE)
    names = []
    for x in range(3, -1, -1):
        for y in range(3, -1, -1):
            for z in range(3, -1, -1):
                for mx in (-1, 1):
                    if mx > x: break
                    for my in (-1, 1):
                        if my > y: break
                        for mz in (-1, 1):
                            if mz > z: break
                            n = f"s{len(names)}"
                            names.append(n)
                            body += obj(n, "sphere radius 0.58 slices 20 stacks 20",
                                        f"translate {num(x * mx / 6)} {num(y * my / 6)} {num(z * mz / 6)}",
                                        color=BLUE)
    assert len(names) == 343
    write(f"{out}/cuberack.scene", "Cube rack", "setCubeRack",
          "a cube minus 7x7x7 spheres of radius 0.58, 1/6 apart", body, "box - " + " - ".join(names))

    body = ""
    shape, moves = zcyl(0.6, 2.5, -2.5)
    body += obj("c1", shape, *moves, color=ORANGE)
    shape, moves = zcyl(0.5, 2.52, -2.51)
    body += obj("c2", shape, *moves, color=BLUE)
    shape, moves = zcyl(0.6, 2.5, -2.5)
    body += obj("c3", shape, *moves, "rotate 90 0 1 0", color=ORANGE)
    shape, moves = zcyl(0.5, 2.52, -2.51)
    body += obj("c4", shape, *moves, "rotate 90 0 1 0", color=BLUE)
    body += obj("s5", "sphere radius 0.6 slices 20 stacks 20", color=ORANGE)
    body += obj("s6", "sphere radius 0.5 slices 20 stacks 20", color=BLUE)
    body += obj("c7", "box half 1", "translate -0.8 1 -0.8", color=GREEN)
    write(f"{out}/pipe.scene", "Pipe", "setPipe", "two pipes and a ball, hollow, cut open by a cube",
          body, "(c1 - c2 - c4 - c7) + (c3 - c2 - c4 - c7) + (s5 - s6 - c2 - c4 - c7)")

    body = obj("ring", "torus major 1 minor 0.6 segments 25 sides 25", "rotate 90 1 0 0", color=ORANGE)
    names = []
    for i in range(4):
        n = f"t{i}"
        names.append(n)
        body += obj(n, "torus major 0.6 minor 0.3 segments 15 sides 15", "rotate 90 1 0 0", "translate 0 1 0",
                    f"rotate {num(i * 90 + 45)} 1 0 0", "rotate 90 0 1 0", color=BLUE)
    shape, moves = zcyl(0.3, 3.3, -1.65)
    body += obj("dx", shape, *moves, "rotate 90 0 1 0", color=GREEN)
    body += obj("dy", shape, *moves, "rotate 90 1 0 0", color=GREEN)
    write(f"{out}/concave.scene", "Concave", "setConcave",
          "a ring minus four small rings and two drills (tori: convexity 2)", body,
          "ring - " + " - ".join(names) + " - dx - dy")


main()
