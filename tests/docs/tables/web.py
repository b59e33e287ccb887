"""docs/web.md's table of frame times, browser against native: written from the CSV that
tests/web/web_frame_times.py wrote in its one run (docs/sweeps/web-frame-times.csv), so that the page
is the CSV's; nothing is measured here."""
import csv
import statistics
import sys

from page_tables import ROOT

PAGE = "docs/web.md"
CSV = ROOT / "docs/sweeps/web-frame-times.csv"


def frame_times():
    """The run's machine, load and command, then a row a lesson."""
    try:
        lines = CSV.read_text().splitlines()
    except OSError as e:
        sys.exit(f"page_tables.py: {CSV}: cannot read: {e.strerror}")
    about = dict(line[2:].split(": ", 1) for line in lines if line.startswith("# "))
    rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    out = [f"Measured {about['measured']} by `{about['command']}` on {about['machine']}; load average "
           f"{about['load']}. Native: {about['native']}. Browser: {about['browser']}. Frames: {about['frames']}; "
           "ms are wall-clock milliseconds a frame, each frame ended by a wait for the GPU (the native "
           "lesson's glFinish, the page's 1x1 readPixels); the first frame is from the navigation's start, "
           "a fresh browser profile, the site served from 127.0.0.1.",
           "",
           f"| lesson (default variant), {rows[0]['size'] if rows else ''} | native ms | native CPU ms | "
           "browser ms | browser / native | first frame, ms |",
           "|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        out.append(f"| {r['lesson']} (`{r['variant']}`) | {r['native_ms']} | {r['native_cpu_ms']} | {r['browser_ms']} "
                   f"| {r['browser_over_native']} | {r['first_frame_ms']} |")
    if rows:
        out += ["", *against_the_goals(rows)]
    return out


def against_the_goals(rows):
    """The run against the browser's goals (a frame within 2x of native, the first frame under 3 s),
    from the rows: the page's prose carries no figure of its own."""
    def lesson(r):
        return r["lesson"].split("-", 1)[0]

    def named(rs):
        return ", ".join(lesson(r) for r in rs) or "none"

    ratio = sorted(rows, key=lambda r: float(r["browser_over_native"]))
    first = sorted(rows, key=lambda r: float(r["first_frame_ms"]))
    median = statistics.median(float(r["browser_over_native"]) for r in rows)
    return [f"Against the goals: the browser took {ratio[0]['browser_over_native']} (lesson {lesson(ratio[0])}) "
            f"to {ratio[-1]['browser_over_native']} (lesson {lesson(ratio[-1])}) times the native lesson's time "
            f"a frame, {median:.2f} the median; within 2x: "
            f"{named([r for r in ratio if float(r['browser_over_native']) <= 2])}. The first frame came in "
            f"{first[0]['first_frame_ms']} ms (lesson {lesson(first[0])}) to {first[-1]['first_frame_ms']} ms "
            f"(lesson {lesson(first[-1])}); under 3 s: {named([r for r in first if float(r['first_frame_ms']) < 3000])}."]


TABLES = {"web-frame-times": frame_times}
