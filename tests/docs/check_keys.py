#!/usr/bin/env python3
"""Every key a lesson's window takes is on its page (ctest -L docs, docs.keys).

    check_keys.py BUILD_DIR

For each lesson, the options its `--help` lists ("name [K] ...", the key that steps the option in
the window) must each appear as `K` in the "## In the window" section of docs/<lesson>.md, and the
section must be there. The keys every lesson shares are --help's "Window keys" (gl/window_keys.h).
"""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    build = pathlib.Path(sys.argv[1])
    problems, checked = [], 0
    for page in sorted((ROOT / "docs").glob("[0-9][0-9]-*.md")):
        exe = build / "lessons" / page.stem
        out = subprocess.run([str(exe), "--help"], capture_output=True, text=True)
        if out.returncode != 0:
            problems.append(f"{exe} --help: exit {out.returncode}")
            continue
        options = out.stdout.split("\nOptions (--set NAME=VALUE, or the key in the window)\n")
        keys = re.findall(r"^  (\S+) \[(.)\] ", options[1].split("\n\n")[0], re.M) if len(options) > 1 else []
        text = page.read_text()
        section = re.search(r"^## In the window\n(.*?)(?=^## |\Z)", text, re.M | re.S)
        if keys and not section:
            problems.append(f"docs/{page.name}: no '## In the window' section for its keys "
                            + ", ".join(k for _, k in keys))
            continue
        missing = [f"{k} ({name})" for name, k in keys if f"`{k}`" not in section.group(1)]
        if missing:
            problems.append(f"docs/{page.name}: 'In the window' does not name the keys " + ", ".join(missing))
        checked += len(keys)
    print(f"{checked} option keys checked against their pages")
    if problems:
        sys.exit("\n".join(problems))


if __name__ == "__main__":
    main()
