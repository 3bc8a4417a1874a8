"""Headless Chromium driven through the DevTools protocol over a pipe (--remote-debugging-pipe: JSON
messages ending in NUL on file descriptors 3 and 4), so that a test can press real keys (trusted
events, with the focus ring a keyboard user sees), size the window as a phone's, read the page's
layout and take screenshots, with no package beyond the standard library."""
import base64
import io
import json
import os
import shutil
import subprocess
import tempfile
import time
import wave

import pytest
from PIL import Image

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")

KEYS = {
    " ": ("Space", 32, " "),
    "ArrowLeft": ("ArrowLeft", 37, ""),
    "ArrowUp": ("ArrowUp", 38, ""),
    "ArrowRight": ("ArrowRight", 39, ""),
    "ArrowDown": ("ArrowDown", 40, ""),
    "Tab": ("Tab", 9, ""),
    "Enter": ("Enter", 13, "\r"),
}


class Chromium:
    """One headless Chromium, started once for a test module (each started costs 10-30 s on a loaded
    machine; a suite of 25 cases spent most of its time starting them). A case opens its own Page,
    in a browser context of its own: no cookies, storage, cache, scripts or emulated settings carried
    from the case before."""

    def __init__(self, preferences=None):
        """`preferences`: the profile's settings as Chromium's settings page writes them (e.g. a
        minimum font size: {"webkit": {"webprefs": {"minimum_font_size": 20}}})."""
        self._profile = tempfile.TemporaryDirectory()
        if preferences:
            os.makedirs(os.path.join(self._profile.name, "Default"))
            with open(os.path.join(self._profile.name, "Default", "Preferences"), "w") as out:
                json.dump(preferences, out)
        to_chrome_read, self._to_chrome = os.pipe()
        self._from_chrome, from_chrome_write = os.pipe()
        # The child must find the pipe's ends at 3 (it reads) and 4 (it writes).
        high_read = os.dup2(to_chrome_read, 20)
        high_write = os.dup2(from_chrome_write, 21)
        os.close(to_chrome_read)
        os.close(from_chrome_write)

        def child_fds():
            os.dup2(high_read, 3)
            os.dup2(high_write, 4)

        self._process = subprocess.Popen(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
             "--disable-component-update", "--disable-sync", "--no-first-run", "--mute-audio",
             "--autoplay-policy=no-user-gesture-required", "--hide-scrollbars",
             f"--user-data-dir={self._profile.name}", "--remote-debugging-pipe", "about:blank"],
            # close_fds=False: the descriptors that child_fds() puts at 3 and 4 must reach chromium
            # (Python's own descriptors are not inherited: they are opened close-on-exec).
            close_fds=False, preexec_fn=child_fds,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(high_read)
        os.close(high_write)
        self._buffer = b""
        self._next_id = 0
        # The open pages by their DevTools session: each gets the events of its own.
        self._pages = {}

    def page(self, width, height, mobile=False, media=None):
        """A new page, a window of `width` x `height` (see Page.emulate); close it (or use it in a
        with statement) when the case ends."""
        return Page(self, width, height, mobile, media)

    def close(self):
        try:
            self.call("Browser.close")
        except (OSError, RuntimeError):
            pass
        try:
            self._process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self._process.kill()
            self._process.wait()
        os.close(self._to_chrome)
        os.close(self._from_chrome)
        self._profile.cleanup()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def call(self, method, session=None, **params):
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params}
        if session is not None:
            message["sessionId"] = session
        os.write(self._to_chrome, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            while b"\0" not in self._buffer:
                chunk = os.read(self._from_chrome, 1 << 20)
                if not chunk:
                    raise RuntimeError("chromium closed the pipe")
                self._buffer += chunk
            raw, self._buffer = self._buffer.split(b"\0", 1)
            reply = json.loads(raw)
            if "method" in reply:
                if reply.get("sessionId") in self._pages:
                    self._pages[reply["sessionId"]].events.append(reply)
            elif reply.get("id") == self._next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
        raise RuntimeError(f"{method}: no answer in 120 s")


@pytest.fixture(scope="module")
def chromium():
    """The module's Chromium (a suite's conftest.py imports this fixture for its modules)."""
    if CHROMIUM is None:
        pytest.skip("chromium is not installed")
    with Chromium() as shared:
        yield shared


class Page:
    """A tab of a Chromium in a browser context of its own, attached to over DevTools."""

    def __init__(self, chromium, width, height, mobile=False, media=None):
        self._chromium = chromium
        self._context = chromium.call("Target.createBrowserContext")["browserContextId"]
        target = chromium.call("Target.createTarget", url="about:blank", browserContextId=self._context)["targetId"]
        self._session = chromium.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        # What the page reported while the test waited for answers: DevTools events, in order.
        self.events = []
        chromium._pages[self._session] = self
        self.call("Page.enable")
        self.call("Runtime.enable")
        self.call("Log.enable")
        self.emulate(width, height, mobile, media)

    def emulate(self, width, height, mobile=False, media=None):
        """Sizes the window (at a device pixel ratio of 1) and sets the media features a reader's
        system sets (`media`: {"prefers-color-scheme": "dark"}, ...), replacing the earlier ones. A
        phone (`mobile`) has a touch screen for its only pointer, as playwright's phones have
        (pointer: coarse, hover: none)."""
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1,
                  mobile=mobile)
        self.call("Emulation.setTouchEmulationEnabled", enabled=mobile, **({"maxTouchPoints": 5} if mobile else {}))
        self.call("Emulation.setEmulatedMedia", media="",
                  features=[{"name": name, "value": value} for name, value in (media or {}).items()])

    def close(self):
        del self._chromium._pages[self._session]
        self._chromium.call("Target.disposeBrowserContext", browserContextId=self._context)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def call(self, method, **params):
        return self._chromium.call(method, session=self._session, **params)

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, awaitPromise=True, returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def open(self, url):
        """Loads `url` and waits until the page's script says it is ready (data-tf-ready). Through
        about:blank, so that a new fragment on the same page loads it again."""
        self.call("Page.navigate", url="about:blank")
        self.events.clear()
        self.call("Page.navigate", url=url)
        ready = self.evaluate("""new Promise(function (done) {
            var waited = 0;
            (function poll() {
              if (document.body && document.body.getAttribute("data-tf-ready") === "1") return done(true);
              if ((waited += 50) > 30000) return done(false);
              setTimeout(poll, 50);
            })();
          })""")
        if not ready:
            raise RuntimeError(f"{url}: the page never said it was ready")
        self.settle()

    def load(self, url):
        """Loads `url`, any document (an SVG, a page of a test's own), and waits for its load event."""
        self.call("Page.navigate", url=url)
        loaded = self.evaluate("""new Promise(function (done) {
            var waited = 0;
            (function poll() {
              if (location.href === %s && document.readyState === "complete") return done(true);
              if ((waited += 50) > 30000) return done(false);
              setTimeout(poll, 50);
            })();
          })""" % json.dumps(url))
        if not loaded:
            raise RuntimeError(f"{url}: never loaded")
        self.settle()

    def settle(self):
        """Two animation frames: style, layout and the script's scrolling have run; then the CSS
        transitions they started (the highlight fades in over 0.15 s) have ended or been replaced, so
        that a screenshot on a loaded machine does not catch a colour half-way."""
        self.evaluate("new Promise(function (done) { requestAnimationFrame(function () { requestAnimationFrame("
                      "function () { done(true); }); }); })")
        self.evaluate("Promise.all(document.getAnimations().filter(function (a) {"
                      " return a instanceof CSSTransition; }).map(function (a) {"
                      " return a.finished.catch(function () { return null; }); }))"
                      ".then(function () { return true; })")

    def problems(self):
        """What the page threw or logged as an error since it was opened, each as "SOURCE: text":
        uncaught exceptions ("exception"), console.error ("console"), and the browser's own error
        entries under their source ("network" for a resource that failed to load)."""
        found = []
        for event in self.events:
            method, params = event["method"], event.get("params", {})
            if method == "Runtime.exceptionThrown":
                details = params["exceptionDetails"]
                found.append("exception: " + (details.get("exception", {}).get("description") or details.get("text")))
            elif method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
                found.append("console: " + " ".join(str(arg.get("value", arg.get("description")))
                                                    for arg in params.get("args", [])))
            elif method == "Log.entryAdded" and params["entry"].get("level") == "error":
                found.append(f"{params['entry'].get('source')}: {params['entry'].get('text')}")
        return found

    def press(self, key):
        code, key_code, text = KEYS[key]
        common = {"key": key, "code": code, "windowsVirtualKeyCode": key_code, "nativeVirtualKeyCode": key_code}
        self.call("Input.dispatchKeyEvent", type="keyDown", text=text, **common)
        self.call("Input.dispatchKeyEvent", type="keyUp", **common)
        self.settle()

    def screenshot(self):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        return Image.open(io.BytesIO(base64.b64decode(data))).convert("RGB")


def time_evenly(timeline, pause_s):
    """Times a transcript read by talkface.read_transcript at 0.2 s a syllable from 0.5 s, `pause_s` between
    sentences, 0.5 s after the last: made-up timing for a page under test. Returns the timeline."""
    # The bindings hand out copies of the lists: they are changed here and set back whole.
    syllables, sentences = timeline.syllables, timeline.sentences
    t = 0.5
    for index, sentence in enumerate(sentences):
        sentence.start_s = t
        for syllable in (s for s in syllables if s.sentence == index):
            syllable.start_s, syllable.end_s = t, t + 0.2
            t += 0.2
        sentence.end_s = t
        t += pause_s
    timeline.syllables, timeline.sentences, timeline.duration_s = syllables, sentences, t + 0.5
    return timeline


def silent_wav(path, duration_s):
    """Writes `duration_s` of silence, 8 kHz 8-bit mono: speech for a page whose timing is made up."""
    with wave.open(str(path), "wb") as out:
        out.setnchannels(1)
        out.setsampwidth(1)
        out.setframerate(8000)
        out.writeframes(b"\x80" * int(8000 * duration_s))
