"""Lesson 08's generated table (docs/08-shadow-volumes-counting.md): what counting costs."""
from page_tables import lesson, stats

# The passes that draw shadow volumes: lesson 07's one parity pass, lesson 08's two counting passes.
VOLUME_PASSES = {"volumes", "front-faces", "back-faces"}


def counting_cost():
    """Volume triangles and the fragments passing the depth test in the volume passes, 640x480, t = 1."""
    runs = [("lesson 07 `overlap`, one bit, one pass", "07-shadow-volumes-invert", "overlap"),
            ("`silhouette`, counted in two passes", "08-shadow-volumes-counting", "silhouette"),
            ("`counting`, a volume per lit triangle", "08-shadow-volumes-counting", "counting"),
            ("`torus` (768-triangle caster), per triangle", "08-shadow-volumes-counting", "torus")]
    lines = ["| | volume triangles drawn | volume fragments |", "|---|---|---|"]
    for label, exe, variant in runs:
        passes = [p for p in stats(lesson(exe), ["--size", "640x480", "--variant", variant])["passes"]
                  if p["name"] in VOLUME_PASSES]
        lines.append(f"| {label} | {sum(p['triangles'] for p in passes)} | "
                     f"{sum(p['samples_passed'] for p in passes)} |")
    return lines


PAGE = "docs/08-shadow-volumes-counting.md"
TABLES = {"08-counting-cost": counting_cost}
