#!/usr/bin/env python3
"""The pages' figures against fresh renders (ctest -L docs, docs.figures.<FOLDER>).

    check_figures.py BUILD_DIR FOLDER [--options "FLAGS"] [--page]   # check docs/figures/FOLDER
    check_figures.py BUILD_DIR FOLDER --write                          # regenerate it (not the lessons')
    check_figures.py BUILD_DIR --coverage                              # every linked figure has a check

Every figure a page (README.md, docs/*.md) links under docs/figures/FOLDER is rendered again into
a temporary folder by the command that made it, and compared with the committed file: stencil
pictures and raw stencil values (`*.stencil*.png`) exactly, every other picture by the golden
tests' rule (a pixel differs past 5/255 in a channel, at most 0.1% of pixels may differ; the
comparison is tests/docs/figure_compare). A lesson's folder (docs/figures/<lesson>/) is rendered by
docs/figures.cmake, as `cmake --build build --target docs-figures` renders it, for only the variants
the pages link; a variant's colour picture that is byte for byte its golden
(tests/golden/<lesson>/<variant>.png), or raw stencil its golden's, is not rendered again: the
golden test renders it. A stale figure fails with the command that regenerates it.
"""
import filecmp
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
SIZE, TIME = "320x240", "1"  # the golden size and time: every lesson figure's

# Folders that are not one lesson's: FOLDER -> commands ({build}, {out}, {src}) that write its files.
OTHERS = {
    "oracle": None,  # one `--oracle` run per linked file: oracle_commands()
    "11-halo-crops": ["{python} {src}/tests/lessons/halo_crops.py {build} {out}"],
    "12-dissolve-strips": ["{python} {src}/tests/lessons/dissolve_figures.py {build} --figures-only {out}"],
    "13-depth-complexity-interior": [
        "{build}/lessons/13-depth-complexity --headless --quiet --size 320x240 --time 1"
        " --scene {src}/tests/scenes/interior-many-lights.scene --set volumes=1"
        " --out {out}/interior-mcguire-bounds.png",
        "{build}/lessons/13-depth-complexity --headless --quiet --size 320x240 --time 1"
        " --scene {src}/tests/scenes/interior-many-lights.scene --set volumes=2 --set bounds=0"
        " --out {out}/interior-everitt-kilgard-unbounded.png"],
    "shadow-profiles": [
        "{build}/lessons/16-fast-robust-shadows --quiet --size 320x240 --time 1"
        " --scene {src}/tests/scenes/shadow-profile-block.scene --shadow-hours {out}/shadow-hours-block.png"
        " --shadow-span 09:00-17:00 --shadow-step 60"],
}
# Linked, but not re-rendered here, and why (docs/testing.md says so too).
NOT_CHECKED = {
    "window": "screenshots of the classroom window (Xvfb and xdotool): `cmake --build build --target "
              "docs-window-figures`; the window tests (label window) check the window's pictures",
    "dual-space": "a matplotlib drawing, not a render; its pixels follow matplotlib's version: "
                  "docs/figures/dual-space/dual_space_2d.py redraws it",
}


def linked():
    """Every docs/figures/... path a page links, relative to docs/figures."""
    found = set()
    for page in [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md")):
        for m in re.finditer(r"\((?:docs/)?figures/([^)\s]+\.png)\)", page.read_text()):
            found.add(m.group(1))
    return found


def run(command, cwd=None):
    out = subprocess.run(command, capture_output=True, text=True, cwd=cwd)
    return out.returncode, (out.stdout + out.stderr).strip()


def oracle_commands(build, files, out):
    """figures/oracle/NN-variant.png: lesson NN's variant at the golden size, --oracle."""
    commands = []
    lessons = {p.name[:2]: p.name for p in (ROOT / "lessons").iterdir() if re.match(r"\d\d-", p.name)}
    for f in files:
        nn, variant = f[:2], f[3:-len(".png")]
        commands.append([str(build / "lessons" / lessons[nn]), "--headless", "--quiet", "--size", SIZE,
                         "--time", TIME, "--variant", variant, "--oracle", str(out / f)])
    return commands


def render_lesson(build, folder, files, out, options, page):
    """Renders the variants behind `files` (paths inside the lesson's folder) that no golden covers;
    returns the files a golden covers."""
    golden = ROOT / "tests/golden" / folder
    covered, variants = set(), []
    for f in sorted(files):
        variant = f.split("/")[0] if "/" in f else re.sub(r"(\.stencil\.raw|\.stencil)?\.png$", "", f)
        if f == f"{variant}.png" and filecmp.cmp(ROOT / "docs/figures" / folder / f, golden / f, shallow=False):
            covered.add(f)
        elif f == f"{variant}.stencil.raw.png" and filecmp.cmp(ROOT / "docs/figures" / folder / f,
                                                               golden / f"{variant}.stencil.png", shallow=False):
            covered.add(f)
        elif variant not in variants:
            variants.append(variant)
    if variants:
        command = ["cmake", f"-DEXE={build}/lessons/{folder}", f"-DOPTIONS={options}", f"-DOUT={out / folder}",
                   f"-DSIZE={SIZE}", f"-DTIME={TIME}", f"-DVARIANTS={';'.join(variants)}"]
        if page:
            command.append(f"-DPAGE={ROOT}/docs/{folder}.md")
        rc, text = run(command + ["-P", str(ROOT / "docs/figures.cmake")])
        if rc:
            sys.exit(f"docs/figures.cmake for {folder} failed: {text}")
    print(f"{folder}: {len(covered)} of {len(files)} linked figures are their golden's files (golden tests "
          f"render them); rendered {len(variants)} variants for the rest")
    return covered


def generate(build, folder, files, out, python):
    out.mkdir(parents=True, exist_ok=True)
    if folder == "oracle":
        commands = oracle_commands(build, files, out)
    else:
        commands = [shlex.split(c.format(build=build, out=out, src=ROOT, python=python)) for c in OTHERS[folder]]
    for c in commands:
        rc, text = run(c)
        if rc not in (0, 1) or (rc == 1 and "--oracle" not in c):  # an oracle run exits 1 on a fault it shows
            sys.exit(f"{shlex.join(c)}: exit {rc}: {text}")


def regenerate_hint(folder):
    if folder in OTHERS:
        return f"tests/docs/check_figures.py build {folder} --write"
    return "cmake --build build --target docs-figures"


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    build = pathlib.Path(args[0]).resolve()
    python = sys.executable
    links = linked()
    if args[1] == "--coverage":
        lessons = {p.name for p in (ROOT / "lessons").iterdir() if (p / "main.cpp").exists()}
        bad = []
        for f in sorted(links):
            folder = f.split("/")[0]
            if not (ROOT / "docs/figures" / f).exists():
                bad.append(f"a page links docs/figures/{f}, which is not there")
            elif folder not in lessons and folder not in OTHERS and folder not in NOT_CHECKED:
                bad.append(f"a page links docs/figures/{f}, and no check renders {folder}/ (tests/docs/check_figures.py)")
        for folder, why in NOT_CHECKED.items():
            print(f"not re-rendered: docs/figures/{folder}/: {why}")
        if bad:
            sys.exit("\n".join(bad))
        print(f"{len(links)} linked figures, each in a checked folder or listed above")
        return
    folder = args[1]
    files = sorted(f[len(folder) + 1:] for f in links if f.startswith(folder + "/"))
    if not files:
        sys.exit(f"no page links a figure under docs/figures/{folder}/")
    if "--write" in args:
        if folder not in OTHERS:
            sys.exit(f"{folder}: regenerate with cmake --build build --target docs-figures")
        with tempfile.TemporaryDirectory() as tmp:  # what the pages link, not the runs' other files
            generate(build, folder, files, pathlib.Path(tmp), python)
            for f in files:
                (ROOT / "docs/figures" / folder / f).parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(pathlib.Path(tmp) / f, ROOT / "docs/figures" / folder / f)
        print(f"wrote docs/figures/{folder}/ ({len(files)} files)")
        return
    options = args[args.index("--options") + 1] if "--options" in args else ""
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp)
        out = out / folder  # figures.cmake takes the lesson's name from its folder's
        if folder in OTHERS:
            covered = set()
            generate(build, folder, files, out, python)
        else:
            covered = render_lesson(build, folder, files, out.parent, options, "--page" in args)
        stale = []
        compare = build / "tests/docs/figure_compare"
        for f in files:
            if f in covered:
                continue
            committed, fresh = ROOT / "docs/figures" / folder / f, out / f
            if not fresh.exists():
                stale.append(f"docs/figures/{folder}/{f}: the command that makes it did not write it")
                continue
            if filecmp.cmp(committed, fresh, shallow=False):
                continue
            c = [str(compare), str(committed), str(fresh)] + (["--exact"] if ".stencil" in f else [])
            rc, text = run(c)
            if rc:
                stale.append(f"docs/figures/{folder}/{f}: {text}")
        print(f"{folder}: {len(files) - len(covered)} figures compared with fresh renders")
        if stale:
            sys.exit("stale figures (regenerate: " + regenerate_hint(folder) + ", then look at them):\n  " +
                     "\n  ".join(stale))


if __name__ == "__main__":
    main()
