#!/usr/bin/env python3
"""The pages' tables of measured counts, written from a fresh run (ctest -L docs, docs.tables.*).

    page_tables.py BUILD_DIR --write [NAME...]   # measure and rewrite the tables in the pages
    page_tables.py BUILD_DIR --check [NAME...]   # measure and compare with the pages: a test
    page_tables.py BUILD_DIR --check --page P.md # the tables of one page (docs.tables.<page>)

A generated table sits in its page between two markers, which the page's reader does not see:

    <!-- table NAME: written by tests/docs/page_tables.py; do not edit by hand -->

    | ... |

    <!-- end table NAME -->

Each page's tables are made in tests/docs/tables/NN.py (NN: the lesson), which names its page (PAGE)
and its tables (TABLES: NAME -> a function returning the table's lines); they run lessons with
--stats through stats() below, each run once for all tables. Counts only: no timing is ever
measured here (times depend on the machine and its load; the pages say where theirs come from).
tests/docs/tables/web.py is docs/web.md's table of frame times, written from the CSV that
tests/web/web_frame_times.py's one run wrote: read, not measured, so that the page is the CSV's.
"""
import difflib
import importlib.util
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "lessons"))
import lesson_run  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = None


def lesson(name):
    return BUILD / "lessons" / name


_runs = {}


def stats(exe, args):
    """lesson_run.stats, each run once per process: tables that share runs share them."""
    key = (str(exe), tuple(args))
    if key not in _runs:
        _runs[key] = lesson_run.stats(exe, args)
    return _runs[key]


def merged(rows):
    """Rows with the same measured cells merged into one, their names joined: [(names, cells)]."""
    out = []
    for name, cells in rows:
        for names, other in out:
            if other == cells:
                names.append(name)
                break
        else:
            out.append(([name], cells))
    return out



def table_modules():
    """NAME -> (page, function) from every tests/docs/tables/*.py."""
    sys.modules.setdefault("page_tables", sys.modules[__name__])  # the modules import the helpers above
    tables = {}
    for path in sorted((pathlib.Path(__file__).parent / "tables").glob("*.py")):
        spec = importlib.util.spec_from_file_location(f"tables_{path.stem}", path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        for name, make in module.TABLES.items():
            tables[name] = (module.PAGE, make)
    return tables


TABLES = {}


def span(text, name):
    begin = re.search(rf"^<!-- table {re.escape(name)}:[^\n]*-->\n", text, re.M)
    end = re.search(rf"^<!-- end table {re.escape(name)} -->$", text, re.M)
    if not begin or not end or end.start() < begin.end():
        sys.exit(f"page_tables.py: no markers for table {name} in {TABLES[name][0]}")
    return begin.end(), end.start()


def main():
    global BUILD
    args = sys.argv[1:]
    if len(args) < 2 or args[1] not in ("--write", "--check"):
        sys.exit(__doc__)
    BUILD = pathlib.Path(args[0]).resolve()
    TABLES.update(table_modules())
    names = args[2:] or list(TABLES)
    if names[0] == "--page":
        names = [n for n, (page, _) in TABLES.items() if page == f"docs/{names[1]}"]
        if not names:
            sys.exit(f"page_tables.py: no generated table in docs/{args[3]}")
    for name in names:
        if name not in TABLES:
            sys.exit(f"page_tables.py: unknown table '{name}' (known: {', '.join(TABLES)})")
        page, make = TABLES[name]
        path = ROOT / page
        text = path.read_text()
        a, b = span(text, name)
        fresh = "\n" + "\n".join(make()) + "\n\n"  # blank lines: the markers stay apart from the table
        if args[1] == "--write":
            path.write_text(text[:a] + fresh + text[b:])
            print(f"{page}: table {name} written")
        elif text[a:b] != fresh:
            diff = difflib.unified_diff(text[a:b].splitlines(), fresh.splitlines(), "the page", "a fresh run", lineterm="")
            sys.exit(f"{page}: table {name} differs from a fresh run (rewrite it: tests/docs/page_tables.py build "
                     f"--write {name}, and check the page's words against it):\n" + "\n".join(diff))
        else:
            print(f"{page}: table {name} is what a fresh run measures")


if __name__ == "__main__":
    main()
