#!/usr/bin/python3
"""Lesson 16's dual-space figure, the 2D analogue: a polygon's edge lines n.x = d (|n| = 1) are
the points (angle of n, d); a light L faces an edge line when n.L > d, below the curve
d = n(angle).L; a corner, where two edge lines meet, is on the silhouette exactly when the
segment between their two points crosses that curve.
Run: /usr/bin/python3 docs/figures/dual-space/dual_space_2d.py docs/figures/dual-space/dual-space-2d.png"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

corners = [(1.0, 0.0), (0.6, 0.8), (-0.3, 0.9), (-1.0, 0.2), (-0.7, -0.7), (0.3, -0.9)]
light = (2.2, 1.4)
n = len(corners)
lines = []  # per polygon edge: (angle of the outward normal, d)
for i in range(n):
    (ax, ay), (bx, by) = corners[i], corners[(i + 1) % n]
    nx, ny = by - ay, -(bx - ax)
    length = math.hypot(nx, ny)
    nx, ny = nx / length, ny / length
    lines.append((math.atan2(ny, nx), nx * ax + ny * ay))
lit = [math.cos(a) * light[0] + math.sin(a) * light[1] > d for a, d in lines]

fig, (left, right) = plt.subplots(1, 2, figsize=(3.2 * 2, 2.4), dpi=100)
for i in range(n):
    (ax, ay), (bx, by) = corners[i], corners[(i + 1) % n]
    left.plot([ax, bx], [ay, by], color="#e0a030" if lit[i] else "#4060a0", lw=2)
for i in range(n):  # corner i + 1 joins edge lines i and i + 1
    j = (i + 1) % n
    if lit[i] != lit[j]:
        cx, cy = corners[j]
        left.plot([cx], [cy], "o", color="#c02020", ms=6)
        left.plot([light[0], cx + 3 * (cx - light[0])], [light[1], cy + 3 * (cy - light[1])], color="#c02020", lw=0.6, ls=":")
left.plot([light[0]], [light[1]], "*", color="#e0c000", ms=12, mec="k")
left.set_xlim(-2, 2.6)
left.set_ylim(-1.6, 1.8)
left.set_aspect("equal")
left.set_title("primal: lit (amber) and unlit (blue) faces", fontsize=7)
left.tick_params(labelsize=6)

theta = [-math.pi + k * 2 * math.pi / 400 for k in range(401)]
right.plot(theta, [math.cos(t) * light[0] + math.sin(t) * light[1] for t in theta], color="#e0c000", lw=1.5,
           label="the light: d = n.L")
for i in range(n):
    j = (i + 1) % n
    (a0, d0), (a1, d1) = lines[i], lines[j]
    if a1 < a0 - math.pi:
        a1 += 2 * math.pi
    crosses = lit[i] != lit[j]
    right.plot([a0, a1], [d0, d1], color="#c02020" if crosses else "#909090", lw=2 if crosses else 1)
for (a, d), l in zip(lines, lit):
    right.plot([a], [d], "o", color="#e0a030" if l else "#4060a0", ms=5)
right.set_xlim(-math.pi, math.pi + 1.2)
right.set_xlabel("angle of the face's normal", fontsize=6)
right.set_ylabel("d (n.x = d)", fontsize=6)
right.set_title("dual: faces are points, corners segments", fontsize=7)
right.legend(fontsize=6, loc="lower right")
right.tick_params(labelsize=6)
fig.tight_layout()
fig.savefig(sys.argv[1])
