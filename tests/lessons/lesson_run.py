"""Running a lesson headless from the scripts that make the pages' tables and figures.

    from lesson_run import run, stats
    stats(build / "lessons/11-halo", ["--size", "640x480", "--set", "method=1"])

A run that fails ends the script with the lesson's command line, exit code and message; a run
whose own oracle (`--set oracle=1`, lessons 13 and 14) found its picture wrong exits 1 with an
"oracle: ..." line, and its counts, which say how wrong, are returned as a good run's are.
"""
import json
import subprocess
import sys


def run(exe, args):
    """The lesson's standard output: `exe --headless --quiet ARGS`."""
    out = subprocess.run([str(exe), "--headless", "--quiet"] + args, capture_output=True, text=True)
    oracle_failed = out.returncode == 1 and out.stderr.startswith("oracle: ")
    if out.returncode != 0 and not oracle_failed:
        sys.exit(f"{exe} {' '.join(args)}: exit {out.returncode}: {out.stderr.strip()}")
    return out.stdout


def stats(exe, args):
    """The --stats JSON of the frame at time 1 s (a later --time in ARGS overrides it)."""
    return json.loads(run(exe, ["--time", "1", "--stats"] + args))
