"""docs/web.md's table of frame times, browser against native: written from the CSV that
tests/web/web_frame_times.py wrote in its one run (docs/sweeps/web-frame-times.csv), so that the page
is the CSV's; nothing is measured here."""
import csv
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
    return out


TABLES = {"web-frame-times": frame_times}
