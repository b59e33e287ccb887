#!/usr/bin/python3
"""Draws a speed-against-error sweep's plot from the CSV the sweep wrote.

    plot_sweeps.py SWEEP IN.csv OUT.svg

SWEEP names the sweep (its lesson): 03-recursive-mirrors, 05-light-blocking,
09-cutout-extrusion, 10-soft-shadows, 14-csg, 14-csg-opencsg (tests/bench/csg_opencsg_benchmark),
16-fast-robust-shadows or silhouette-extraction;
IN.csv is what tests/sweeps/<sweep>_sweep wrote (silhouette-extraction: what
tests/bench/silhouette_benchmark --raw wrote); OUT.svg is replaced only once the plot is drawn. A missing or malformed CSV, an unknown
sweep or a bad command line gets one line on stderr and exit 2.

Uses matplotlib (Debian's python3-matplotlib). Text stays text in the SVG (svg.fonttype
'none') and the file is the same for the same CSV (fixed ids, no date).
"""

import csv
import math
import os
import sys
import tempfile

PROGRAM = "plot_sweeps.py"
SIZE = "640x480"  # every sweep renders at this size (tests/sweeps/*_sweep.cpp, kSize)


class BadInput(Exception):
    """Anything wrong with the command line or the CSV: reported as one line, exit 2."""


def read_rows(path, numeric, text=()):
    """The CSV's rows as dicts: the `numeric` columns as floats, the `text` columns as strings.
    Raises BadInput naming the file and what is wrong (missing, no header, a column missing,
    a value that is not a finite number, no rows)."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames or []
            missing = [c for c in list(text) + list(numeric) if c not in header]
            if not header:
                raise BadInput(f"{path}: empty, no header line")
            if missing:
                raise BadInput(f"{path}: no column '{missing[0]}' in the header")
            rows = []
            for line, raw in enumerate(reader, start=2):
                row = {}
                for c in text:
                    if raw[c] is None or raw[c] == "":
                        raise BadInput(f"{path}:{line}: empty '{c}'")
                    row[c] = raw[c]
                for c in numeric:
                    if raw[c] is None:
                        raise BadInput(f"{path}:{line}: the row ends before '{c}'")
                    try:
                        v = float(raw[c])
                    except (TypeError, ValueError):
                        raise BadInput(f"{path}:{line}: '{c}' is not a number: {raw[c]!r}") from None
                    if not math.isfinite(v):
                        raise BadInput(f"{path}:{line}: '{c}' is not finite: {raw[c]!r}")
                    row[c] = v
                rows.append(row)
    except OSError as e:
        raise BadInput(f"{path}: cannot read: {e.strerror or e}") from None
    except (UnicodeDecodeError, csv.Error) as e:
        raise BadInput(f"{path}: not a CSV file: {e}") from None
    if not rows:
        raise BadInput(f"{path}: no rows after the header")
    return rows


def select(rows, path, what, **match):
    """The rows whose text columns equal `match`; BadInput if there are none."""
    picked = [r for r in rows if all(r[k] == v for k, v in match.items())]
    if not picked:
        wanted = ", ".join(f"{k}={v}" for k, v in match.items())
        raise BadInput(f"{path}: no {what} rows ({wanted})")
    return picked


def pyplot():
    """matplotlib.pyplot, set up for small SVGs that are the same for the same CSV. Imported
    only once the CSV has been read: a bad one is reported without waiting for matplotlib."""
    try:
        import matplotlib
    except ImportError:
        raise BadInput(f"matplotlib is missing for {sys.executable} (Debian: apt-get install python3-matplotlib)")
    matplotlib.use("Agg")
    matplotlib.rcParams.update({"svg.fonttype": "none", "svg.hashsalt": "stencil-sweeps", "font.size": 9,
                                "font.family": "sans-serif", "font.sans-serif": ["DejaVu Sans"]})
    import matplotlib.pyplot as plt

    return plt


def plain_log(axis):
    """Log-axis ticks at 1, 2 and 5 per decade, written as plain numbers (20, not 2x10^1)."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def plain_symlog(axis, top):
    """Symlog-axis ticks at 0 and each power of ten up to `top`, written as plain numbers."""
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator

    axis.set_major_locator(FixedLocator([0] + [10.0**k for k in range(0, int(math.log10(top)) + 1)]))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:.0f}"))
    axis.set_minor_locator(NullLocator())


def label_points(ax, xs, ys, labels, dx=4, dy=3):
    for x, y, text in zip(xs, ys, labels):
        ax.annotate(text, (x, y), xytext=(dx, dy), textcoords="offset points", fontsize=8)


# Lesson 03: error and time against the recursion depth of the hall of mirrors.
def plot_recursive_mirrors(path):
    rows = read_rows(path, ["depth", "scene_renderings", "fastest_frame_ms", "scene_renderings_no_culling",
                            "fastest_frame_ms_no_culling", "rms_error"])
    rows.sort(key=lambda r: r["depth"])
    depth = [r["depth"] for r in rows]
    plt = pyplot()
    fig, (err, ms) = plt.subplots(1, 2, figsize=(9.5, 3.8), layout="constrained")

    # The error roughly halves per bounce: a log axis shows that as a straight fall.
    if min(r["rms_error"] for r in rows) <= 0:
        raise BadInput(f"{path}: an RMS error of 0 or less cannot go on the log axis")
    err.plot(depth, [r["rms_error"] for r in rows], "o-", color="C3")
    err.set_yscale("log")
    plain_log(err.yaxis)
    err.set_xlabel("recursion depth (bounces)")
    err.set_ylabel("RMS error against 16 bounces (of 255)")
    err.set_title("Error over the mirror")
    err.grid(True, alpha=0.3)

    on = [r["fastest_frame_ms"] for r in rows]
    off = [r["fastest_frame_ms_no_culling"] for r in rows]
    ms.plot(depth, on, "o-", color="C0", label="culling on")
    ms.plot(depth, off, "s--", color="C0", alpha=0.6, label="culling off")
    label_points(ms, depth, on, [f"{r['scene_renderings']:.0f}" for r in rows], dx=-4, dy=-11)
    label_points(ms, depth, off, [f"{r['scene_renderings_no_culling']:.0f}" for r in rows], dx=-4, dy=5)
    ms.set_ylim(0, max(on + off) * 1.15)
    ms.set_xlabel("recursion depth (bounces)")
    ms.set_ylabel(f"fastest frame (ms, {SIZE}, llvmpipe)")
    ms.set_title("Time (labels: scene renderings)")
    ms.grid(True, alpha=0.3)
    ms.legend(loc="lower right")
    for ax in (err, ms):
        ax.set_xticks(depth)
    return fig


# Lesson 05: every blended shadow's darkness and the light-blocking shadow, time against error.
def plot_light_blocking(path):
    rows = read_rows(path, ["darkness", "frame_ms", "rms_error"], text=["method"])
    block = select(rows, path, "blocking", method="block")
    dampen = sorted(select(rows, path, "blended", method="dampen"), key=lambda r: r["darkness"])
    if min(r["rms_error"] for r in rows) <= 0:
        raise BadInput(f"{path}: an RMS error of 0 or less cannot go on the log axis")
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.2), layout="constrained")
    ax.plot([r["frame_ms"] for r in dampen], [r["rms_error"] for r in dampen], "o", color="C0",
            label="dampen (blended), darkness in tenths")
    label_points(ax, [r["frame_ms"] for r in dampen], [r["rms_error"] for r in dampen],
                 [f"{r['darkness']:.0f}/10" for r in dampen])
    ax.plot([r["frame_ms"] for r in block], [r["rms_error"] for r in block], "D", color="C3",
            label="block (light blocking)")
    # The error spans two decades, from the blocked shadow's edge pixels to the lightest blend.
    ax.set_yscale("log")
    plain_log(ax.yaxis)
    ax.set_xlim(0, max(r["frame_ms"] for r in rows) * 1.2)
    ax.set_xlabel(f"time per frame (ms, mean, {SIZE}, llvmpipe)")
    ax.set_ylabel("RMS error on the ground (of 255)")
    ax.set_title("Blended against light-blocking shadows")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower left")
    return fig


# Lesson 09: the three extrusions over lattices of more holes; the flattened sphere's error
# and cost as its slices grow.
def plot_cutout_extrusion(path):
    rows = read_rows(path, ["holes", "slices", "frame_ms_min", "triangles", "count_triangles", "wrong_pixels",
                            "wrong_off_edges"], text=["sweep", "method"])
    methods = [("cpu", "CPU, rebuilt each frame"), ("matrix", "one projective matrix"),
               ("gpu", "GPU, doubled vertices")]
    plt = pyplot()
    fig, (lat, err, ms) = plt.subplots(1, 3, figsize=(13, 4.2), layout="constrained")
    for i, (method, name) in enumerate(methods):
        rs = sorted(select(rows, path, "lattice", sweep="methods", method=method), key=lambda r: r["holes"])
        xs, ys = [r["count_triangles"] for r in rs], [r["frame_ms_min"] for r in rs]
        lat.plot(xs, ys, "os^"[i] + "-", color=f"C{i}", label=name, alpha=0.85)
        if i == 0:
            label_points(lat, xs, ys, [f"{r['holes']:.0f}×{r['holes']:.0f}" for r in rs], dx=-12, dy=8)
    # 96 to 4656 triangles: nearly two decades.
    lat.set_xscale("log")
    lat.set_yscale("log")
    plain_log(lat.xaxis)
    plain_log(lat.yaxis)
    lat.set_xlabel("count-pass triangles (labels: holes in the lattice)")
    lat.set_ylabel(f"fastest frame (ms, {SIZE}, llvmpipe)")
    lat.margins(x=0.08, y=0.12)
    lat.set_title("Extrusion of the lattice")
    lat.grid(True, alpha=0.3)
    lat.legend(loc="upper left")

    rs = sorted(select(rows, path, "sphere", sweep="sphere"), key=lambda r: r["slices"])
    if min(r["slices"] for r in rs) <= 0 or min(r["frame_ms_min"] for r in rs) <= 0:
        raise BadInput(f"{path}: a sphere row with no slices or no time cannot go on the log axes")
    slices = [r["slices"] for r in rs]
    err.plot(slices, [r["wrong_pixels"] for r in rs], "o-", color="C4", label="all wrong pixels")
    err.plot(slices, [r["wrong_off_edges"] for r in rs], "s--", color="C7", label="wrong off the ray cast's edges")
    # The inscribed sphere's shadow falls short by about 1/slices²: the guide goes through the
    # coarsest sphere's error.
    s0, e0 = slices[0], rs[0]["wrong_pixels"]
    err.plot(slices, [e0 * (s0 / s) ** 2 for s in slices], ":", color="black", linewidth=1,
             label=f"{e0:.0f} × ({s0:.0f} / slices)²")
    # The error falls from thousands of pixels to none: linear below 1 so that 0 has a place.
    err.set_xscale("log")
    err.set_yscale("symlog", linthresh=1)
    top = 10 ** math.ceil(math.log10(max(max(r["wrong_pixels"] for r in rs), 1) * 1.5))
    err.set_ylim(0, top)
    plain_symlog(err.yaxis, top)
    plain_log(err.xaxis)
    err.set_xlabel("sphere slices")
    err.set_ylabel("pixels against the true sphere's shadow")
    err.set_title("Flattened sphere: error")
    err.grid(True, alpha=0.3)
    err.legend(loc="lower left")

    ms.plot(slices, [r["frame_ms_min"] for r in rs], "o-", color="C4")
    label_points(ms, slices, [r["frame_ms_min"] for r in rs], [f"{r['triangles']:.0f}" for r in rs],
                 dx=-14, dy=6)
    ms.set_xscale("log")
    ms.set_yscale("log")
    plain_log(ms.xaxis)
    plain_log(ms.yaxis)
    ms.set_xlabel("sphere slices")
    ms.set_ylabel(f"fastest frame (ms, {SIZE}, llvmpipe)")
    ms.margins(x=0.08, y=0.12)
    ms.set_title("Flattened sphere: time (labels: all triangles)")
    ms.grid(True, alpha=0.3)
    return fig


# Lesson 16: the four methods along the camera path; the sphere's triangles as slices grow.
def plot_fast_shadows(path):
    rows = read_rows(path, ["time", "slices", "frame_ms_min", "shadow_triangles", "volume_fragments_rasterized",
                            "wrong_off_edges", "sphere_case", "sphere_sides", "sphere_dark_cap",
                            "sphere_light_cap"], text=["sweep", "method", "view"])
    methods = [("mcguire", "McGuire et al."), ("everitt-kilgard", "Everitt-Kilgard"), ("lengyel", "Lengyel"),
               ("zpass", "z-pass only")]
    views = ["system", "eye-in-shadow", "looking-up"]
    from matplotlib.ticker import FuncFormatter, NullFormatter

    plt = pyplot()
    fig, axes = plt.subplots(2, 3, figsize=(12, 7.6), layout="constrained")
    width = 0.8 / len(methods)

    # One bar per method in each view: the mean over the moments of the path, and (for the time)
    # whiskers from the fastest to the slowest moment, which is the noise between moments.
    def bars(ax, column, title, ylabel, scale=1.0, worst=False, whiskers=False):
        for m, (method, name) in enumerate(methods):
            means, lows, highs = [], [], []
            for view in views:
                vs = [r[column] * scale for r in select(rows, path, "method", sweep="methods", view=view,
                                                       method=method)]
                means.append(max(vs) if worst else sum(vs) / len(vs))
                lows.append(means[-1] - min(vs))
                highs.append(max(vs) - means[-1])
            xs = [v + (m - (len(methods) - 1) / 2) * width for v in range(len(views))]
            ax.bar(xs, means, width * 0.9, color=f"C{m}", label=name,
                   yerr=[lows, highs] if whiskers else None, capsize=2, error_kw={"elinewidth": 0.8})
        ax.set_xticks(range(len(views)), views)
        ax.set_title(title)
        ax.set_ylabel(ylabel)
        ax.grid(True, axis="y", alpha=0.3)

    bars(axes[0][0], "frame_ms_min", "Fastest frame, mean of the moments",
         f"ms ({SIZE}, llvmpipe; bars: range)", whiskers=True)
    bars(axes[0][1], "shadow_triangles", "Shadow-pass triangles", "triangles per frame, mean of the moments")
    bars(axes[0][2], "volume_fragments_rasterized", "Volume fragments rasterized",
         "millions per frame, mean of the moments", scale=1e-6)
    wrong = axes[1][0]
    bars(wrong, "wrong_off_edges", "Pixels wrong off the ray cast's edges", "pixels, worst moment", worst=True)
    # 0, 1 and 170 000 in one panel: linear below 1, logarithmic above.
    wrong.set_yscale("symlog", linthresh=1)
    top = 10 ** math.ceil(math.log10(max(max(r["wrong_off_edges"] for r in rows), 1) * 3))
    wrong.set_ylim(0, top)
    plain_symlog(wrong.yaxis, top)
    for bars_of_method in wrong.containers:
        wrong.bar_label(bars_of_method, fmt="%.0f", fontsize=7, padding=1)

    # The paper's table: O(s) triangles grow with the slices (slope 1 on log axes), O(f) with
    # their square (slope 2). Series with the same counts are drawn once, naming both.
    tri = axes[1][1]
    tess = select(rows, path, "tessellation", sweep="tessellation")
    series = {}
    for view in views:
        for method, name in (("mcguire", "McGuire et al."), ("lengyel", "Lengyel")):
            rs = sorted((r for r in tess if r["view"] == view and r["method"] == method), key=lambda r: r["slices"])
            if not rs:
                raise BadInput(f"{path}: no tessellation rows (view={view}, method={method})")
            points = tuple((r["slices"], r["sphere_sides"] + r["sphere_dark_cap"] + r["sphere_light_cap"])
                           for r in rs)
            if min(min(p) for p in points) <= 0:
                raise BadInput(f"{path}: a sphere with no slices or no volume triangles cannot go on the log axes")
            series.setdefault(points, []).append(f"{name}, case {rs[-1]['sphere_case']:.0f}")
    for i, (points, names) in enumerate(series.items()):
        tri.plot([p[0] for p in points], [p[1] for p in points], "os^Dvp"[i % 6] + "-", color=f"C{i + 4}",
                 label="; ".join(names))
    tri.set_xscale("log", base=2)
    tri.set_yscale("log")
    tri.set_xticks(sorted({p[0] for points in series for p in points}))
    tri.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    tri.xaxis.set_minor_formatter(NullFormatter())
    plain_log(tri.yaxis)
    tri.set_xlabel("sphere slices (stacks: half as many)")
    tri.set_ylabel("sphere volume triangles (sides + caps)")
    tri.set_title("The sphere's volume by case, t = 1")
    tri.grid(True, alpha=0.3)
    tri.legend(fontsize=7, loc="upper left")

    key = axes[1][2]
    key.axis("off")
    handles, labels = axes[0][0].get_legend_handles_labels()
    key.legend(handles, labels, loc="center", title="method (top row and left)", frameon=False)
    return fig


# Lesson 10: the penumbra's error against the light's samples and against time, per sampling
# pattern and light shape; the fitted slope of each in the legend.
def plot_soft_shadows(path):
    rows = read_rows(path, ["lights", "rounds", "samples", "penumbra_rms", "frame_ms"], text=["shape", "pattern"])
    if min(r["penumbra_rms"] for r in rows) <= 0 or min(r["samples"] for r in rows) <= 0:
        raise BadInput(f"{path}: an error or a sample count of 0 or less cannot go on the log axes")
    series = []
    for r in rows:
        key = (r["shape"], r["pattern"])
        if key not in series:
            series.append(key)
    plt = pyplot()
    fig, (err, ms, key) = plt.subplots(1, 3, figsize=(13, 4.2), layout="constrained",
                                       gridspec_kw={"width_ratios": [1, 1, 0.62]})
    for i, (shape, pattern) in enumerate(series):
        s = sorted(select(rows, path, "series", shape=shape, pattern=pattern), key=lambda r: r["samples"])
        xs, ys = [r["samples"] for r in s], [r["penumbra_rms"] for r in s]
        # Least squares on log-log: the error falls as samples^slope (-0.5 for independent samples).
        # Fitted from 4 samples on, as the sweep's summary does.
        fit = [(x, y) for x, y in zip(xs, ys) if x >= 4]
        slope = 0.0
        if len(fit) > 1:
            lx, ly = [math.log(x) for x, _ in fit], [math.log(y) for _, y in fit]
            mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
            den = sum((x - mx) ** 2 for x in lx)
            slope = sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / den if den > 0 else 0.0
        style = dict(color=f"C{i % 10}", linestyle="--" if shape == "disk" else "-",
                     marker="o" if "progressive" not in pattern else "x", markersize=3.5)
        err.plot(xs, ys, label=f"{shape}, {pattern} (slope {slope:.2f})", **style)
        if "progressive" not in pattern:  # a progressive row's time is one round's, not the image's
            ms.plot([r["frame_ms"] for r in s], ys, **style)
    for ax in (err, ms):
        ax.set_xscale("log")
        ax.set_yscale("log")
        plain_log(ax.yaxis)
        plain_log(ax.xaxis)
        ax.grid(True, which="major", alpha=0.3)
        ax.set_ylabel("RMS error in the penumbra (levels of 255)")
    err.set_xlabel("samples of the light (lights x rounds)")
    err.set_title("Error against samples")
    ms.set_xlabel("time per frame (ms, 320x240, llvmpipe)")
    ms.set_title("Error against time (progressive rows left out)")
    key.axis("off")
    key.legend(*err.get_legend_handles_labels(), loc="center", fontsize=8, frameon=False,
               title="light, samples (fitted slope)")
    return fig


# Lesson 14: time and passes per frame against primitives, per algorithm, on OpenCSG's scenes: a box
# minus a k x k grid of spheres (lines), the 3x3x3 grid (squares) and the cube rack (stars).
def plot_csg(path):
    rows = read_rows(path, ["primitives", "frame_ms", "passes"], text=["scene", "method"])
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    plt = pyplot()
    fig, (ms, passes) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    for i, method in enumerate(methods):
        colour = f"C{i}"
        # A method with occlusion queries makes the same passes as the one without: dashed, with
        # hollow markers drawn larger, so that the two show where they coincide.
        queries = method.endswith("+queries")
        style = dict(color=colour, markerfacecolor="none" if queries else colour, markeredgewidth=1.2)
        for ax, field in ((ms, "frame_ms"), (passes, "passes")):
            grid = sorted((r for r in rows if r["method"] == method and r["scene"] == "grid"),
                          key=lambda r: r["primitives"])
            if grid:
                ax.plot([r["primitives"] for r in grid], [r[field] for r in grid], "o--" if queries else "o-",
                        markersize=6 if queries else 3.5, label=method if ax is passes else None, **style)
            for scene, marker in (("grid3", "s"), ("rack", "*")):
                for r in rows:
                    if r["method"] == method and r["scene"] == scene:
                        ax.plot([r["primitives"]], [r[field]], marker, markersize=13 if queries else 7, **style)
    for ax, what in ((ms, "time per frame (ms, 320x240, llvmpipe)"), (passes, "passes per frame")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        plain_log(ax.xaxis)
        plain_log(ax.yaxis)
        ax.grid(True, which="major", alpha=0.3)
        ax.set_xlabel("primitives (box minus k x k spheres: lines; 3x3x3: squares; cube rack: stars)")
        ax.set_ylabel(what)
    ms.set_title("Time")
    passes.set_title("Passes")
    passes.legend(fontsize=8)
    return fig


def plot_csg_opencsg(path):
    """tests/bench/csg_opencsg_benchmark's CSV: per size, each scene's CPU time a frame (every
    thread's: llvmpipe draws on the CPU, and its CPU time hardly changes when other work shares the
    machine) by every OpenCSG setting (squares) and every lesson 14 method (circles), log scale."""
    rows = read_rows(path, ["primitives", "frame_ms", "frame_cpu_ms", "draws", "coverage_diff_px"],
                     text=["size", "scene", "renderer", "method"])
    sizes, scenes, series = [], [], []
    for r in rows:
        for key, seen in ((r["size"], sizes), (r["scene"], scenes), ((r["renderer"], r["method"]), series)):
            if key not in seen:
                seen.append(key)
    plt = pyplot()
    # The legend in a row of its own below the panels, where it hides no point.
    fig, axes = plt.subplots(2, len(sizes), figsize=(6 * len(sizes), 5.1), layout="constrained", squeeze=False,
                             gridspec_kw={"height_ratios": [4.4, 0.6]})
    for ax, size in zip(axes[0], sizes):
        for i, (renderer, method) in enumerate(series):
            lib = renderer == "opencsg"
            xs, ys = [], []
            for j, scene in enumerate(scenes):
                for r in rows:
                    if (r["size"], r["scene"], r["renderer"], r["method"]) == (size, scene, renderer, method):
                        xs.append(j + (i - len(series) / 2) * 0.05)
                        ys.append(r["frame_cpu_ms"])
            ax.plot(xs, ys, "s" if lib else "o", color=f"C{i % 10}", markerfacecolor="none" if lib else f"C{i % 10}",
                    markersize=6, label=("OpenCSG " if lib else "lesson ") + method)
        ax.set_yscale("log")
        plain_log(ax.yaxis)
        ax.set_xticks(range(len(scenes)))
        ax.set_xticklabels([f"{s}\n({int(next(r['primitives'] for r in rows if r['scene'] == s))})"
                            for s in scenes], fontsize=8)
        ax.grid(True, which="major", axis="y", alpha=0.3)
        ax.set_ylabel(f"CPU time per frame (ms, {size}, llvmpipe)")
        ax.set_title(f"OpenCSG's scenes at {size} (primitives)")
    key = fig.add_subplot(axes[1][0].get_gridspec()[1, :])
    for ax in axes[1]:
        ax.remove()
    key.axis("off")
    key.legend(*axes[0][0].get_legend_handles_labels(), loc="center", fontsize=7, ncol=5, frameon=False)
    return fig


def plot_silhouette_extraction(path):
    """tests/bench/silhouette_benchmark's raw CSV: ns per triangle against triangles. Left, the
    brute force (the prepared passes) against the scan of its arrays and the mesh version; right,
    the two dual-space structures (Wallner's hextree, the BVH over the dual edges) by the light's
    distance and motion beside the brute force for the same light, and their builds (once per
    caster)."""
    rows = read_rows(path, ["triangles", "median_cpu_ns"], text=["benchmark"])
    series = {}
    for r in rows:
        parts = r["benchmark"].split("/")
        if len(parts) != 3:
            raise BadInput(f"{path}: benchmark '{r['benchmark']}' is not KIND/SHAPE/SIZE")
        kind, shape, _ = parts
        if r["triangles"] <= 0:
            raise BadInput(f"{path}: benchmark '{r['benchmark']}' has no triangles")
        series.setdefault((kind, shape), []).append((r["triangles"], r["median_cpu_ns"] / r["triangles"]))
    for points in series.values():
        points.sort()
    if ("prepared", "sphere") not in series or ("scan-prepared", "sphere") not in series:
        raise BadInput(f"{path}: no prepared or scan-prepared rows for the sphere")
    plt = pyplot()
    fig, (scan, dual) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")

    def line(ax, kind, label, colour, style="o-"):
        for shape, dashes in (("sphere", style), ("torus", style.replace("-", "--"))):
            points = series.get((kind, shape))
            if points:
                ax.plot([p[0] for p in points], [p[1] for p in points], dashes, color=colour, markersize=3.5,
                        label=label if shape == "sphere" else None)

    line(scan, "mesh", "mesh version (facesLight + possibleSilhouetteEdges)", "C3")
    line(scan, "prepared", "brute force (prepared passes)", "C0")
    line(scan, "scan-prepared", "scan of its arrays", "C7", "s-")
    line(scan, "prepare", "preparing the caster (once)", "C2", "^-")
    line(dual, "prepared-near", "brute force, near light", "C0")
    line(dual, "prepared-far", "brute force, far light", "C9")
    line(dual, "prepared-turn0.1", "brute force, near light turning 0.1 deg a call", "C7")
    line(dual, "dual-near", "hextree, near light", "C1")
    line(dual, "dual-turn0.1", "hextree, turning 0.1 deg a call", "C5")
    line(dual, "dual-prepare", "hextree build (once)", "C2", "^-")
    line(dual, "bvh-near", "BVH, near light", "C3")
    line(dual, "bvh-far", "BVH, far light", "C6")
    line(dual, "bvh-directional", "BVH, directional", "C8")
    line(dual, "bvh-turn0.1", "BVH, turning 0.1 deg a call", "C4")
    line(dual, "bvh-prepare", "BVH build (once)", "C2", "v-")
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    for ax in (scan, dual):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_major_locator(LogLocator(base=10, subs=(1.0,)))  # 1k, 10k, 100k, 1M
        ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v / 1e6:g}M" if v >= 1e6 else f"{v / 1e3:g}k"))
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.grid(True, which="major", alpha=0.3)
        ax.set_xlabel("triangles (sphere: solid lines; torus: dashed)")
        ax.set_ylabel("CPU ns per triangle, per call")
        ax.legend(fontsize=7)
    plain_log(scan.yaxis)  # one decade: label 1, 2 and 5
    scan.set_title("Brute force against a scan of its arrays")
    dual.set_title("Dual space against the brute force")
    return fig


SWEEPS = {
    "03-recursive-mirrors": plot_recursive_mirrors,
    "05-light-blocking": plot_light_blocking,
    "09-cutout-extrusion": plot_cutout_extrusion,
    "10-soft-shadows": plot_soft_shadows,
    "14-csg": plot_csg,
    "14-csg-opencsg": plot_csg_opencsg,
    "16-fast-robust-shadows": plot_fast_shadows,
    "silhouette-extraction": plot_silhouette_extraction,
}

USAGE = f"usage: {PROGRAM} SWEEP IN.csv OUT.svg   (SWEEP: {', '.join(SWEEPS)})"


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(USAGE)
        print(__doc__.split("\n\n", 2)[2].strip())
        return 0
    if len(argv) != 4:
        raise BadInput(f"expected SWEEP IN.csv OUT.svg, got {len(argv) - 1} arguments ({USAGE})")
    sweep, csv_path, svg_path = argv[1:]
    if sweep not in SWEEPS:
        raise BadInput(f"unknown sweep '{sweep}' (known: {', '.join(SWEEPS)})")
    if not svg_path.endswith(".svg"):
        raise BadInput(f"'{svg_path}': the output must be an .svg file")
    out_dir = os.path.dirname(os.path.abspath(svg_path))
    if not os.path.isdir(out_dir):
        raise BadInput(f"'{svg_path}': no folder {out_dir}")

    fig = SWEEPS[sweep](csv_path)
    # Written beside the target and renamed over it: never a half-written plot.
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(suffix=".svg", dir=out_dir)
        with os.fdopen(fd, "wb") as f:
            fig.savefig(f, format="svg", metadata={"Date": None})
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, svg_path)
    except OSError as e:
        raise BadInput(f"'{svg_path}': cannot write: {e.strerror or e}") from None
    finally:
        if tmp and os.path.exists(tmp):
            os.unlink(tmp)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except BadInput as e:
        print(f"{PROGRAM}: {e}", file=sys.stderr)
        sys.exit(2)
