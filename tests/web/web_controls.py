#!/usr/bin/env python3
"""A lesson page's controls clicked through in headless Chromium (tests/web/chromium.py), as a
student uses them: another variant, an option, the pass stepper forward and back, each view. After
each, the canvas must show another picture than before (read by canvas.toDataURL: the context keeps
its drawing buffer) and the URL must carry the new state; then that URL, loaded fresh, must restore
the controls and the very same picture (the deep link). The views' legends below the canvas: the
stencil's and grey's counts add up to the canvas's pixels, grey's largest value is white. Then URLs
the lesson refuses (an unknown variant or option, a time that is not a number, a view or pass the
page cannot show): each must be one line on the page, dropped from the URL (the rest kept), the
lesson drawn.

    tests/web/web_controls.py SITE CHROMIUM OUT_DIR [--lesson 08-shadow-volumes-counting]
        [--variant torus] [--option show]

The page is loaded paused (&paused=1), so that only the controls change the canvas: a control that
does nothing leaves it as it was, and the check after it fails. Each step prints one line; the
pictures stay in OUT_DIR. Exit 0 pass, 1 fail, 2 bad arguments, 77 (skipped) without the page.
"""
import argparse
import base64
import pathlib
import sys
import time
import urllib.parse

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "lessons"))
from png_io import decode_png  # noqa: E402 (the shared reader, found beside the lessons' scripts)
import chromium  # noqa: E402 (beside this script)

VIEWS = ["stencil", "grey", "bits", "depth", "colour"]  # from colour, each in turn, and back


class Page:
    def __init__(self, browser, out):
        self.browser, self.out, self.failures, self.count = browser, out, [], 0

    def canvas(self, name):
        """The canvas's pixels now (RGBA, rows top first), kept as OUT_DIR/NN-NAME.png."""
        url = self.browser.evaluate("document.getElementById('canvas').toDataURL('image/png')")
        png = base64.b64decode(url.split(",", 1)[1])
        self.count += 1
        (self.out / f"{self.count:02d}-{name}.png").write_bytes(png)
        return decode_png(png)[3]

    def query(self):
        return urllib.parse.parse_qs(urllib.parse.urlsplit(self.browser.href()).query)

    def check(self, what, ok, detail):
        print(f"{'ok' if ok else 'FAILED'}: {what}: {detail}", flush=True)
        if not ok:
            self.failures.append(what)

    def changed(self, what, before, after):
        """The picture must differ from BEFORE; returns AFTER."""
        differ = sum(1 for i in range(0, len(after), 4) if after[i:i + 3] != before[i:i + 3]) if len(after) == len(
            before) else -1
        self.check(f"{what}: the canvas changed", differ != 0,
                   f"{differ} of {len(after) // 4} pixels differ" if differ >= 0 else "another size")
        return after

    def url_has(self, what, key, value):
        """The URL's KEY must be VALUE (None: absent)."""
        got = self.query().get(key, [None])[0]
        self.check(f"{what}: the URL's {key}", got == value, f"{key}={got} (expected {value})")

    def pass_name(self):
        return self.browser.evaluate("document.getElementById('pass-name').textContent")


def ready(browser, variant):
    """Waits for the page to have made its controls for VARIANT (a variant change loads the page again)."""
    browser.wait(f"typeof lesson !== 'undefined' && lesson !== null && lesson.variant === '{variant}' && "
                 "document.getElementById('view') !== null")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("site", type=pathlib.Path)
    parser.add_argument("chromium")
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--lesson", default="08-shadow-volumes-counting")
    parser.add_argument("--variant", default="torus", help="the variant chosen in the page's list")
    parser.add_argument("--option", default="show", help="a checkbox option clicked")
    parser.add_argument("--timeout", type=float, default=120)
    args = parser.parse_args()
    if not (args.site / f"{args.lesson}.html").is_file():
        return chromium.page_missing("web_controls", args.site, f"{args.lesson}.html")
    args.out.mkdir(parents=True, exist_ok=True)
    start = time.monotonic()
    with chromium.serve(args.site) as base, chromium.Chromium(args.chromium, timeout=args.timeout) as browser:
        page = Page(browser, args.out)
        browser.open(f"{base}/{args.lesson}.html?time=1&size=320x240&paused=1")
        first = browser.evaluate("new Promise(r => { const t = setInterval(() => { if (typeof lesson !== 'undefined'"
                                 " && lesson) { clearInterval(t); r(lesson.variant); } }, 50); })")
        ready(browser, first)
        info = browser.evaluate("({variants: lesson.variants.map(v => v.name), options: lesson.options})")
        option = next((o for o in info["options"] if o["name"] == args.option), None)
        if args.variant not in info["variants"] or args.variant == first or not option or option["max"] != 1:
            print(f"web_controls: {args.lesson} has no other variant '{args.variant}' or no checkbox option "
                  f"'{args.option}'")
            return 2
        picture = page.canvas("start")

        # A variant from the list: the page loads again with it.
        browser.choose("#variant", args.variant)
        ready(browser, args.variant)
        picture = page.changed(f"variant {args.variant}", picture, page.canvas(f"variant-{args.variant}"))
        page.url_has(f"variant {args.variant}", "variant", args.variant)
        chosen = browser.evaluate("document.getElementById('variant').value")
        page.check(f"variant {args.variant}: the list shows it", chosen == args.variant, f"'{chosen}'")

        # An option's checkbox, clicked.
        was = browser.evaluate(f"document.getElementById('option-{args.option}').checked")
        browser.click(f"#option-{args.option}")
        now = browser.evaluate(f"document.getElementById('option-{args.option}').checked")
        page.check(f"option {args.option}: the box toggled", now != was, f"{was} -> {now}")
        picture = page.changed(f"option {args.option}", picture, page.canvas(f"option-{args.option}"))
        settings = dict(s.split(":") for s in (page.query().get("set", [""])[0]).split(",") if s)
        page.check(f"option {args.option}: the URL's set", settings.get(args.option) == str(int(now)),
                   f"set={page.query().get('set', [None])[0]}")

        # The pass stepper: forward twice, back twice; each step names another pass.
        whole, passes = picture, browser.evaluate("passLabels")
        names, pictures = [page.pass_name()], []
        for button, expect in (("forward", 1), ("forward", 2), ("back", 1), ("back", 0)):
            browser.click(f"#pass-{button}")
            names.append(page.pass_name())
            expected = (f"{expect} of {len(passes)}: {passes[expect - 1]}" if expect
                        else f"whole frame ({len(passes)} passes)")
            page.check(f"pass {button} to {expect}: the pass named", names[-1] == expected,
                       f"'{names[-2]}' -> '{names[-1]}'")
            page.url_has(f"pass {button} to {expect}", "pass", str(expect) if expect else None)
            pictures.append(page.canvas(f"pass-{expect}"))
        page.changed("pass forward to 1 (the frame after the first pass)", whole, pictures[0])
        page.check("pass back to 0: the whole frame again", pictures[3] == whole,
                   "the picture before stepping" if pictures[3] == whole else "another picture")
        picture = pictures[3]

        # Each view in turn, then colour again.
        seen = {"colour": picture}
        for view in VIEWS:
            browser.choose("#view", view)
            after = page.canvas(f"view-{view}")
            if view == "colour":
                page.check("view colour again: the colour picture", after == seen["colour"],
                           "as before" if after == seen["colour"] else "another picture")
            else:
                for other, before in seen.items():
                    page.changed(f"view {view} (against {other})", before, after)
                seen[view] = after
            page.url_has(f"view {view}", "view", None if view == "colour" else view)
            legend = browser.evaluate("document.getElementById('legend').textContent")
            entries = browser.evaluate("[...document.querySelectorAll('#legend .entry')].map(e => e.textContent)")
            if view in ("stencil", "grey"):
                # Every pixel counted once, by its value: the counts add up to the canvas.
                counted = sum(int(e.split("(")[1].split(" ")[0]) for e in entries)
                page.check(f"view {view}: the legend counts every pixel", counted == len(after) // 4,
                           f"{len(entries)} values, {counted} pixels: '{legend[:60]}...'")
            if view == "grey":  # stretched: the largest value present white
                page.check("view grey: the largest value white", legend.startswith("grey: v x 255/")
                           and max(after[0::4]) == 255, f"'{legend[:40]}', brightest {max(after[0::4])}")
            if view in ("bits", "depth"):
                page.check(f"view {view}: the legend's line", legend.startswith("the eight bit planes"
                                                                                if view == "bits" else "depth: "),
                           f"'{legend[:60]}'")

        # The deep link: a state of every kind, then that URL loaded fresh.
        browser.choose("#view", "stencil")
        browser.click("#pass-forward")
        browser.click("#pass-forward")
        link, state = browser.href(), page.canvas("linked")
        name = page.pass_name()
        browser.open("about:blank")
        browser.open(link)
        ready(browser, args.variant)
        restored = {
            "variant": browser.evaluate("document.getElementById('variant').value"),
            "option": browser.evaluate(f"document.getElementById('option-{args.option}').checked"),
            "view": browser.evaluate("document.getElementById('view').value"),
            "pass": page.pass_name(),
        }
        expected = {"variant": args.variant, "option": now, "view": "stencil", "pass": name}
        for key, value in expected.items():
            page.check(f"deep link: {key} restored", restored[key] == value, f"{restored[key]!r} (expected {value!r})")
        again = page.canvas("restored")
        page.check("deep link: the same picture", again == state, "the very same" if again == state
                   else f"{sum(1 for i in range(0, len(again), 4) if again[i:i + 3] != state[i:i + 3])} pixels differ")
        print(f"deep link: {link.split('?', 1)[1]}")

        # What the URL asks for and the lesson refuses: one line on the page, and the lesson drawn
        # without it, its controls there, the URL rewritten to what it draws.
        for query, said, gone in (("variant=no-such-variant", "unknown variant 'no-such-variant'", "variant"),
                                  (f"variant={args.variant}&set=no-such-option:5", "unknown option 'no-such-option'",
                                   "set"),
                                  ("time=soon", "time expects a number", "time"),
                                  ("view=sideways", "view=sideways: expected", "view"),
                                  ("pass=999", "pass=999: expected 1 to", "pass")):
            browser.open("about:blank")
            browser.open(f"{base}/{args.lesson}.html?{query}&size=320x240&paused=1")
            # Only what is refused is left out: a good variant beside a bad option stays.
            kept = args.variant if query.startswith(f"variant={args.variant}&") else first
            ready(browser, kept)
            status = browser.evaluate("document.getElementById('status').className + ': ' + "
                                      "document.getElementById('status').textContent")
            page.check(f"{query}: said on the page", status.startswith("error: ") and said in status, f"'{status}'")
            value = page.query().get(gone, [None])[0]
            page.check(f"{query}: the URL drops it", value != query.split("=")[-1], f"{gone}={value}")
            page.url_has(f"{query}: the URL keeps the rest", "size", "320x240")
            drawn = page.canvas(f"refused-{gone}")
            page.check(f"{query}: the lesson drawn", len(set(drawn[i:i + 3] for i in range(0, len(drawn), 4))) > 1,
                       "a picture" if len(set(drawn[i:i + 3] for i in range(0, len(drawn), 4))) > 1 else "one colour")
        # Two refused at once: each said, both left out, the lesson drawn as it starts.
        browser.open("about:blank")
        browser.open(f"{base}/{args.lesson}.html?variant=no-such-variant&time=soon&size=320x240&paused=1")
        ready(browser, first)
        status = browser.evaluate("document.getElementById('status').textContent")
        page.check("two refused: each said", "unknown variant 'no-such-variant'" in status and
                   "time expects a number" in status, f"'{status}'")
        query = page.query()
        page.check("two refused: the URL drops both", query.get("variant", [None])[0] != "no-such-variant" and
                   query.get("time", [None])[0] != "soon", str(query))
    print(f"web_controls: {args.lesson}: {page.count} pictures, {len(page.failures)} checks failed, "
          f"in {time.monotonic() - start:.1f} s (pictures in {args.out})")
    return 1 if page.failures else 0


if __name__ == "__main__":
    sys.exit(main())
