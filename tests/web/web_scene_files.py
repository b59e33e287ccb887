#!/usr/bin/env python3
"""Scene files on a scene lesson's page in headless Chromium (tests/web/chromium.py), as a reader
gives them: a scene file the URL names that cannot be read, then files picked with the page's file
input (a .scene file with the OBJ mesh it names; a bad scene file with its OBJ; a file that is no
scene), checking what the page says and draws after each.

    tests/web/web_scene_files.py SITE NATIVE_EXE CHROMIUM OUT_DIR [--good FILE] [--bad FILE]

FILE: a scene file of tests/scenes (the good one must name an OBJ mesh; the bad one is read with
the OBJ files beside it). NATIVE_EXE is the native lesson, which gives the message a bad file must
get on the page (the same reader's line, after the file's path). Checks:
- &scene= naming no file: the page says the native's message for it, and the lesson draws its own
  scene (its scene list on "(the lesson's own)");
- the good file and its mesh picked: the lesson draws that scene (the canvas changes) and the page
  says no error;
- options the native lesson refuses with a scene file (scene 1, method 0) set with their boxes:
  the page says why in its words, the box shows the value drawn, the picture stays;
- the bad file picked: the page says what the native says of it, and the picture stays the good
  scene's;
- a PNG picked: the page says it is no scene file, and the picture stays.
Exit 0 pass, 1 fail, 2 bad arguments, 77 (skipped) without the page.
"""
import argparse
import base64
import pathlib
import re
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import chromium  # noqa: E402 (beside this script)

SCENES = pathlib.Path(__file__).resolve().parents[1] / "scenes"


def without_folders(message):
    """A message with each path's folders left out: the page's files lie elsewhere than the disk's."""
    return re.sub(r"[^\s:']*/([^/\s:']+)", r"\1", message)


def native_message(native, scene):
    """What the native lesson says of SCENE (its one line after 'error: '), without folders."""
    run = subprocess.run([str(native), "--headless", "--quiet", "--set", "method=4", "--scene", str(scene)],
                         capture_output=True, text=True)
    return run.returncode, without_folders(run.stderr.strip().split("error: ", 1)[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("site", type=pathlib.Path)
    parser.add_argument("native", type=pathlib.Path)
    parser.add_argument("chromium")
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--good", default="csg/drilled-box.scene")
    parser.add_argument("--bad", default="bad/obj-index-past-end.scene")
    parser.add_argument("--timeout", type=float, default=120)
    args = parser.parse_args()
    lesson = args.native.name
    good, bad = SCENES / args.good, SCENES / args.bad
    meshes = [SCENES / line.split()[-1].replace("../", "") for line in good.read_text().splitlines()
              if " mesh " in line] if good.is_file() else []
    if not good.is_file() or not bad.is_file() or not meshes or not all(m.is_file() for m in meshes):
        print(f"web_scene_files: --good {args.good} (with the OBJ meshes it names) and --bad {args.bad}: "
              "expected scene files of tests/scenes")
        return 2
    if not (args.site / f"{lesson}.html").is_file():
        return chromium.page_missing("web_scene_files", args.site, f"{lesson}.html")
    args.out.mkdir(parents=True, exist_ok=True)
    failures = []

    def check(what, ok, detail=""):
        print(f"{'ok' if ok else 'FAILED'}: {what}{': ' + detail if detail and not ok else ''}", flush=True)
        if not ok:
            failures.append(what)

    start = time.monotonic()
    with chromium.serve(args.site) as base, chromium.Chromium(args.chromium, timeout=args.timeout) as browser:
        def status():
            kind, text = browser.evaluate("[document.getElementById('status').className, "
                                      "document.getElementById('status').textContent]")
            return kind, without_folders(text)

        def canvas(name):
            png = base64.b64decode(browser.evaluate("document.getElementById('canvas').toDataURL('image/png')")
                                   .split(",", 1)[1])
            (args.out / f"{name}.png").write_bytes(png)
            return png

        def pick(files):
            """The files set on the page's file input, as a reader picks them (its change event)."""
            document = browser.send("DOM.getDocument")
            node = browser.send("DOM.querySelector", {"nodeId": document["root"]["nodeId"],
                                                      "selector": "#scene-file"})["nodeId"]
            browser.send("DOM.setFileInputFiles", {"nodeId": node, "files": [str(f) for f in files]})

        missing = "csg/no-such-file.scene"
        browser.open(f"{base}/{lesson}.html?time=1&size=320x240&paused=1&set=method:4&scene={missing}")
        browser.wait("typeof lesson !== 'undefined' && lesson !== null && document.getElementById('scene') !== null")
        _, expected = native_message(args.native, SCENES / missing)
        kind, text = status()
        check("a scene file the URL names that cannot be read is said on the page",
              kind == "error" and expected == text, f"the page says '{text}', the native '{expected}'")
        check("the lesson then draws its own scene", browser.evaluate("document.getElementById('scene').value") == "")
        own = canvas("own-scene")

        pick([good, *meshes])
        browser.wait(f"lesson.scene.endsWith('/{good.name}')")
        kind, text = status()
        shown = canvas("good-scene")
        check(f"{args.good} picked with its mesh is drawn", kind != "error" and shown != own, f"the page says '{text}'")

        # Options the native lesson refuses with a scene file (--set scene=1, --set method=0), set
        # with their boxes: said, the box put back, the scene still drawn.
        for name, value, says in (("scene", 1, "picks among the lesson's own scenes"),
                                  ("method", 0, "method 0 draws the demo's two solids")):
            before = browser.evaluate(f"document.getElementById('option-{name}').value")
            browser.evaluate("document.getElementById('status').className = ''")
            browser.evaluate(f"(b => {{ b.value = '{value}'; b.dispatchEvent(new Event('change')); }})"
                             f"(document.getElementById('option-{name}'))")
            kind, text = status()
            check(f"option {name} set to {value} with the scene file: refused on the page",
                  kind == "error" and says in text and "--" not in text, f"the page says '{text}'")
            check(f"the box shows {name} drawn, the scene still drawn",
                  browser.evaluate(f"document.getElementById('option-{name}').value") == before and
                  canvas(f"after-{name}-{value}") == shown)

        pick([bad, *bad.parent.glob(bad.stem + ".obj")])
        code, expected = native_message(args.native, bad)
        browser.wait("document.getElementById('status').className === 'error'")
        kind, text = status()
        check(f"{args.bad} picked: the page says what the native says (exit {code})",
              code == 2 and expected == text, f"the page says '{text}', the native '{expected}'")
        check("the lesson keeps the last good scene", canvas("after-bad") == shown and
              browser.evaluate(f"lesson.scene.endsWith('/{good.name}')"))

        browser.evaluate("document.getElementById('status').className = ''")
        pick([args.out / "own-scene.png"])
        browser.wait("document.getElementById('status').className === 'error'")
        kind, text = status()
        check("a picture picked is no scene file", "not a scene file" in text, f"the page says '{text}'")
        check("the picture stays", canvas("after-png") == shown)
    print(f"web_scene_files: {lesson}: {len(failures)} of the checks failed, in {time.monotonic() - start:.1f} s "
          f"(pictures in {args.out})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
