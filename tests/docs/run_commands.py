#!/usr/bin/env python3
"""Runs every command a page shows (ctest -L docs, docs.commands.<page>).

    run_commands.py BUILD_DIR PAGE.md

Every code block of the page must say what it holds: a fence with a language (```sh for commands,
```text, ```cpp, ```scene... for the rest); an indented block, or a fence with no language, fails
the test. Each ```sh block runs as one bash script (`set -e -o pipefail`) in a fresh temporary
folder holding `build` (a link to BUILD_DIR) and `tests` (a link to the source's tests/, for the
scene files), with BUILD_DIR/lessons on PATH, so commands run as the pages write them, from the
source's top folder. A block must exit 0, or as its page says: a command whose line ends in
`# exits N` must exit N. It must write nothing into the source tree (every file's size and mtime
compared before and after, build folders aside). A block that cannot run here says so in the page,
on its first line: `# not run by the doc tests: WHY` (a window, a long run, files it rewrites on
purpose); the test prints each such block and its reason.
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
SKIP = re.compile(r"^#\s*not run by the doc tests:\s*(.+)$")
EXITS = re.compile(r"^(.*\S)\s+#\s*exits\s+(\d+)\s*$")
TIMEOUT = 120  # seconds a block may take (times STENCIL_TIMEOUT_SCALE)


def blocks(text):
    """(line number, language, lines) for each code block; language None for an indented block."""
    out, lines, i = [], text.split("\n"), 0
    previous_blank = True
    while i < len(lines):
        line = lines[i]
        fence = re.match(r"^(```+|~~~+)\s*([\w+-]*)", line)
        if fence:
            start, mark, body = i + 1, fence.group(1), []
            i += 1
            while i < len(lines) and not lines[i].startswith(mark):
                body.append(lines[i])
                i += 1
            out.append((start, fence.group(2) or "", body))
            i += 1
            previous_blank = False
            continue
        if previous_blank and line.startswith("    ") and line.strip() and not re.match(r"\s*([-*+]|\d+\.)\s", line):
            start, body = i + 1, []
            while i < len(lines) and (lines[i].startswith("    ") or not lines[i].strip()):
                body.append(lines[i][4:])
                i += 1
            out.append((start, None, body))
            previous_blank = False
            continue
        previous_blank = not line.strip()
        i += 1
    return out


def in_a_list(text, line_number):
    """Whether the indented lines at line_number continue a list item (Markdown: not a code block)."""
    lines = text.split("\n")
    j = line_number - 2
    while j >= 0 and not lines[j].strip():
        j -= 1
    return j >= 0 and re.match(r"^\s*([-*+]|\d+\.)\s", lines[j]) is not None


def snapshot():
    """size and mtime of every file in the source tree, build folders and .git aside."""
    seen = {}
    for top in ROOT.iterdir():
        if top.name.startswith(("build", ".git", "gallery")) or top.name == "Testing":
            continue
        for dirpath, dirnames, filenames in os.walk(top) if top.is_dir() else [(str(ROOT), [], [top.name])]:
            dirnames[:] = [d for d in dirnames if not d.startswith("__pycache__")]
            for f in filenames:
                p = os.path.join(dirpath, f)
                try:
                    st = os.lstat(p)
                except FileNotFoundError:
                    continue
                seen[p] = (st.st_size, st.st_mtime_ns)
    return seen


def script(body):
    """The block as a bash script: `# exits N` lines checked for that exit code."""
    out = ["set -e -o pipefail"]
    for line in body:
        m = EXITS.match(line)
        if m:
            command, code = m.group(1), m.group(2)
            out.append(f"if {command}; then rc=0; else rc=$?; fi; "
                       f"if [ $rc -ne {code} ]; then echo \"exit $rc, the page says {code}: {command}\" >&2; exit 1; fi")
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    build, page = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    text = page.read_text()
    name = page.relative_to(ROOT)
    scale = float(os.environ.get("STENCIL_TIMEOUT_SCALE", "1"))
    failures, ran, skipped = [], 0, 0
    for start, language, body in blocks(text):
        where = f"{name}:{start}"
        if language is None:
            if in_a_list(text, start):
                continue
            failures.append(f"{where}: an indented code block; fence it and name its language "
                            "(```sh for commands the doc tests run, ```text or another for the rest)")
            continue
        if language == "":
            failures.append(f"{where}: a code block with no language (```sh, ```text, ...)")
            continue
        if language not in ("sh", "bash", "shell"):
            continue
        first = next((l.strip() for l in body if l.strip()), "")
        m = SKIP.match(first)
        if m:
            skipped += 1
            print(f"{where}: not run: {m.group(1)}")
            continue
        with tempfile.TemporaryDirectory() as tmp:
            (pathlib.Path(tmp) / "build").symlink_to(build)
            (pathlib.Path(tmp) / "tests").symlink_to(ROOT / "tests")
            env = dict(os.environ, PATH=f"{build / 'lessons'}:{os.environ['PATH']}")
            before = snapshot()
            try:
                out = subprocess.run(["bash", "-c", script(body)], cwd=tmp, env=env, capture_output=True,
                                     text=True, timeout=TIMEOUT * scale)
                rc, log = out.returncode, (out.stdout + out.stderr).strip()
            except subprocess.TimeoutExpired:
                rc, log = "timeout", f"still running after {TIMEOUT * scale:.0f} s: mark the block as not run"
            written = sorted(p for p, s in snapshot().items() if before.get(p) != s)
        ran += 1
        if rc != 0:
            failures.append(f"{where}: exit {rc}:\n" + "\n".join("    " + l for l in log.splitlines()[-15:]))
        if written:
            failures.append(f"{where}: wrote into the source tree: " + ", ".join(
                str(pathlib.Path(p).relative_to(ROOT)) for p in written[:10]))
    print(f"{name}: ran {ran} command blocks, {skipped} marked as not run")
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
