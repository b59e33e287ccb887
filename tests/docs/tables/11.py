"""Lesson 11's generated tables (docs/11-halo.md): each method's ring and what it costs in fragments."""
from page_tables import lesson, stats

METHODS = ["whole object scaled (paper)", "each convex piece grown (paper's fix)", "pushed along normals",
           "outline moved k pixels (screen)"]


def halo_measures(size):
    """Per method, t = 1, the blend counts' frame (--set show=1, whose passes and stencil are the
    shaded frame's): the ring's width along the outline (mean, min and max over the mean), halo
    pixels over the figure, pixels blended twice, the shell's fragments with every test off, the
    halo pass's samples_passed and draw calls."""
    lines = ["| method | width mean (px) | min / mean | max / mean | over the figure | blended twice | "
             "shell fragments | blended | draw calls |", "|---|---|---|---|---|---|---|---|---|"]
    for m, name in enumerate(METHODS):
        s = stats(lesson("11-halo"), ["--size", size, "--set", f"method={m}", "--set", "show=1"])
        c, halo = s["counts"], next(p for p in s["passes"] if p["name"] == "halo")
        mean = c["figure.width_mean_x100"] / 100
        lines.append(f"| {name} | {mean:.2f} | {c['figure.width_min_x100'] / 100 / mean:.2f} | "
                     f"{c['figure.width_max_x100'] / 100 / mean:.2f} | {c['figure.covered_pixels']} | "
                     f"{c['figure.multi_blended_pixels']} | {c['figure.shell_fragments']} | "
                     f"{halo['samples_passed']} | {halo['draw_calls']} |")
    return lines


PAGE = "docs/11-halo.md"
TABLES = {"11-measures-640x480": lambda: halo_measures("640x480"),
          "11-measures-320x240": lambda: halo_measures("320x240")}
