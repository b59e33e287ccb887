"""Headless Chromium driven over the DevTools protocol, for the web tests and the frame-time script.

    with serve(site) as base, Chromium(chromium_path) as browser:
        browser.open(f"{base}/07-shadow-volumes-invert.html?snapshot=1")
        title = browser.wait_title("snapshot-ready")      # or a title starting "snapshot-error"
        value = browser.evaluate("document.title")         # any JavaScript; the value returned
        browser.click("#pass-forward")                     # a mouse click at the element's centre
        browser.href()

Standard library only: Chromium's --remote-debugging-pipe reads the protocol's JSON messages,
each ended by a NUL byte, from its fd 3 and writes its own to fd 4. One page (the browser's first
tab) is attached to and driven. serve() is the one static server of the site the tests use: on
127.0.0.1, a free port, for as long as the with block lasts.
"""
import collections
import contextlib
import fcntl
import functools
import http.server
import json
import os
import select
import shutil
import subprocess
import tempfile
import threading
import time

# SwiftShader's WebGL 2 in headless Chromium (issue 26; Debian's chromium needs all four).
FLAGS = ["--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--disable-gpu-sandbox", "--no-first-run", "--no-default-browser-check", "--mute-audio",
         "--window-size=1280,1024"]


class ChromiumError(Exception):
    """The browser went away, answered with an error, or a wait ran out."""


class Quiet(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".js": "text/javascript"}

    def log_message(self, *args):
        pass


def page_missing(tool, site, page):
    """The exit code of a test whose page is not in the site: 77 (skipped) where the site may lack it,
    1 with STENCIL_WEB_REQUIRE_SITE=1 (CI's web leg, which has built the site)."""
    required = os.environ.get("STENCIL_WEB_REQUIRE_SITE") == "1"
    print(f"{tool}: {site / page} not found: {'failed (STENCIL_WEB_REQUIRE_SITE=1)' if required else 'skipped'}; "
          "build the site first (cmake --preset web && cmake --build --preset web)")
    return 1 if required else 77


@contextlib.contextmanager
def serve(site):
    """Serves the folder SITE on 127.0.0.1 at a free port; yields the base URL."""
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=str(site)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}"
    finally:
        server.shutdown()
        server.server_close()


class Chromium:
    def __init__(self, executable, extra_flags=(), timeout=60):
        self.timeout = timeout
        self.profile = tempfile.mkdtemp(prefix="stencil-chromium-")  # a fresh profile: nothing cached
        # The pipes' ends the browser keeps sit at fd 10 or above, so that bash's redirections
        # below make them its fd 3 (what it reads) and fd 4 (what it writes) whatever they were.
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()
        to_browser_r, from_browser_w = (_high(fd) for fd in (to_browser_r, from_browser_w))
        self.process = subprocess.Popen(
            ["bash", "-c", f'exec "$0" "$@" 3<&{to_browser_r} 4>&{from_browser_w} {to_browser_r}<&- {from_browser_w}>&-',
             executable, *FLAGS, *extra_flags, f"--user-data-dir={self.profile}", "--remote-debugging-pipe",
             "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            pass_fds=(to_browser_r, from_browser_w))
        os.close(to_browser_r)
        os.close(from_browser_w)
        self._buffer = b""
        self._next_id = 0
        self.events = collections.deque(maxlen=200)  # the latest events the browser sent (console, page)
        self.session = None
        try:
            targets = self.send("Target.getTargets", session=False)["targetInfos"]
            page = next((t for t in targets if t["type"] == "page"), None)
            target = page["targetId"] if page else self.send("Target.createTarget", {"url": "about:blank"},
                                                              session=False)["targetId"]
            self.session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True},
                                     session=False)["sessionId"]
            self.send("Page.enable")
            self.send("Runtime.enable")
        except BaseException:
            self.close()
            raise

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        if self.process.poll() is None:
            with contextlib.suppress(OSError, ChromiumError):
                self._write({"id": self._new_id(), "method": "Browser.close"})
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        for fd in (self._to_browser, self._from_browser):
            with contextlib.suppress(OSError):
                os.close(fd)
        shutil.rmtree(self.profile, ignore_errors=True)

    # The protocol.
    def _new_id(self):
        self._next_id += 1
        return self._next_id

    def _write(self, message):
        os.write(self._to_browser, json.dumps(message).encode() + b"\0")

    def _read(self, deadline):
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self._from_browser], [], [], left)[0]:
                raise ChromiumError("no answer from the browser in time")
            chunk = os.read(self._from_browser, 1 << 16)
            if not chunk:
                raise ChromiumError(f"the browser closed its pipe (exit {self.process.poll()})")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method, params=None, session=True, timeout=None):
        """One command; its result, or ChromiumError with the browser's message."""
        message = {"id": self._new_id(), "method": method, "params": params or {}}
        if session:
            message["sessionId"] = self.session
        self._write(message)
        deadline = time.monotonic() + (timeout or self.timeout)
        while True:
            answer = self._read(deadline)
            if answer.get("id") == message["id"]:
                if "error" in answer:
                    raise ChromiumError(f"{method}: {answer['error'].get('message')}")
                return answer.get("result", {})
            if "method" in answer:
                self.events.append(answer)

    # What the tests do with a page.
    def open(self, url):
        """Navigates the page to URL (returns once the navigation has begun; wait_title waits for it).
        The old page's title is cleared first, so that a wait cannot take it for the new page's."""
        with contextlib.suppress(ChromiumError):
            self.evaluate("document.title = ''")
        result = self.send("Page.navigate", {"url": url})
        if result.get("errorText"):
            raise ChromiumError(f"{url}: {result['errorText']}")

    def evaluate(self, expression, timeout=None):
        """The value of a JavaScript expression in the page (a promise is awaited), as JSON gives it."""
        result = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                                "awaitPromise": True}, timeout=timeout)
        if "exceptionDetails" in result:
            details = result["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text")
            raise ChromiumError(f"{expression[:60]}...: {text}")
        return result["result"].get("value")

    def wait_title(self, title, timeout=None):
        """Waits until document.title is TITLE or starts with "snapshot-error"; returns the title
        (the caller judges an error title), or raises ChromiumError with the last title seen."""
        deadline = time.monotonic() + (timeout or self.timeout)
        seen = None
        while time.monotonic() < deadline:
            with contextlib.suppress(ChromiumError):  # between two documents there may be none
                seen = self.evaluate("document.title")
            if seen == title or (seen or "").startswith("snapshot-error"):
                return seen
            time.sleep(0.05)
        raise ChromiumError(f"waited {timeout or self.timeout} s for the title '{title}'; it is '{seen}'")

    def wait(self, expression, timeout=None):
        """Waits until a JavaScript expression is true; raises ChromiumError when it never is."""
        deadline = time.monotonic() + (timeout or self.timeout)
        while time.monotonic() < deadline:
            with contextlib.suppress(ChromiumError):
                if self.evaluate(expression):
                    return
            time.sleep(0.05)
        raise ChromiumError(f"waited {timeout or self.timeout} s for {expression}")

    def click(self, selector):
        """A left click at the centre of the element SELECTOR, as a mouse gives it."""
        box = self.evaluate(f"""(() => {{
            const e = document.querySelector({json.dumps(selector)});
            if (!e) return null;
            e.scrollIntoView({{block: 'center'}});
            const r = e.getBoundingClientRect();
            return [r.left + r.width / 2, r.top + r.height / 2];
        }})()""")
        if box is None:
            raise ChromiumError(f"no element {selector} on the page")
        for kind in ("mousePressed", "mouseReleased"):
            self.send("Input.dispatchMouseEvent", {"type": kind, "x": box[0], "y": box[1], "button": "left",
                                                   "clickCount": 1})

    def choose(self, selector, value):
        """Sets a <select> or <input> to VALUE and fires its change event, as the user's choice does."""
        found = self.evaluate(f"""(() => {{
            const e = document.querySelector({json.dumps(selector)});
            if (!e) return false;
            e.value = {json.dumps(value)};
            e.dispatchEvent(new Event('input', {{bubbles: true}}));
            e.dispatchEvent(new Event('change', {{bubbles: true}}));
            return true;
        }})()""")
        if not found:
            raise ChromiumError(f"no element {selector} on the page")

    def href(self):
        return self.evaluate("location.href")


def _high(fd):
    """FD moved to a number of 10 or above (the old one closed)."""
    moved = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
    os.close(fd)
    return moved
