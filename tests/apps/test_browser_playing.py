"""The pages played as a person plays them, in headless Chromium (browser.py): play, pause, seeks
back and forward, playing at 1.5 times, to the end and again, on a desktop window and a phone's,
each page opened from file://. The face's clock must be the audio's at every animation frame, the
page must throw nothing, and the player must work by keyboard. A speech that cannot be played, or
that stops coming in while it plays, is said on the page; a speech started before the page has
unpacked its animation is followed.

Pages: `talkface demo` (plain, audio book, announcer; the speech compressed into the page, or
linked beside it) and `talkface animate` of a long speech (8 minutes, 300 sentences, timed by a
timeline JSON over a silent recording).
"""
import os
import subprocess
import time

import pytest

import talkface
from browser import CHROMIUM, silent_wav, time_evenly
from served_folder import QuietHandler, served

CLI = os.environ["TALKFACE_CLI"]
FRAME_S = 1 / 25  # the pages' animation frame rate (LipSyncOptions)

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")

# The audio's clock and every clock of the face (the animation and, nested in a stage, the stage's
# own <svg>, which Chromium runs on a clock of its own) in one look.
CLOCKS = """(function () {
  var audio = document.getElementById('tf-audio');
  var clocks = [document.querySelector('svg.tf-animation')];
  while (clocks[clocks.length - 1].ownerSVGElement) clocks.push(clocks[clocks.length - 1].ownerSVGElement);
  return {audio: audio.currentTime, faces: clocks.map(function (c) { return c.getCurrentTime(); }),
          shown: parseFloat(document.body.getAttribute('data-tf-time')), paused: audio.paused,
          ended: audio.ended, duration: audio.duration};
})()"""

# Samples `frames` animation frames while something plays: per frame, the audio's clock less the
# face's, and the face's clocks less the time the page last read from the audio (data-tf-time).
FOLLOWING = """new Promise(function (done) {
  var audio = document.getElementById('tf-audio');
  var clocks = [document.querySelector('svg.tf-animation')];
  while (clocks[clocks.length - 1].ownerSVGElement) clocks.push(clocks[clocks.length - 1].ownerSVGElement);
  var samples = [];
  (function sample() {
    if (!audio.paused) {
      var shown = parseFloat(document.body.getAttribute('data-tf-time'));
      samples.push([audio.currentTime - clocks[0].getCurrentTime(),
                    Math.max.apply(null, clocks.map(function (c) { return Math.abs(c.getCurrentTime() - shown); }))]);
    }
    if (samples.length >= %d || audio.ended) return done(samples);
    requestAnimationFrame(sample);
  })();
})"""


def wait(browser, seconds):
    browser.evaluate("new Promise(function (done) { setTimeout(function () { done(true); }, %d); })" % (seconds * 1000))


def seek(browser, time_s):
    """Sets the audio's time and waits for the seek and an animation frame after it."""
    browser.evaluate("""new Promise(function (done) {
        var audio = document.getElementById('tf-audio');
        audio.addEventListener('seeked', function () { requestAnimationFrame(function () { done(true); }); },
                               { once: true });
        audio.currentTime = %f;
      })""" % time_s)


def assert_face_shows_audio_time(browser, what):
    clocks = browser.evaluate(CLOCKS)
    for face in clocks["faces"]:
        assert face == pytest.approx(clocks["audio"], abs=0.002), f"{what}: {clocks}"
    return clocks


def assert_face_follows_playing(browser, what, frames=20):
    """At every frame the face shows what the page last read from the audio, and that is at most a
    frame or two behind the audio's own clock (the median: a loaded machine has long frames)."""
    samples = browser.evaluate(FOLLOWING % frames)
    assert len(samples) >= min(frames, 5), f"{what}: {len(samples)} frames while playing"
    assert all(from_shown < 0.001 for _, from_shown in samples), f"{what}: {samples}"
    lags = sorted(lag for lag, _ in samples)
    assert lags[0] >= -0.002 and lags[len(lags) // 2] < FRAME_S * 1.5, f"{what}: lags {lags}"


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    folder = tmp_path_factory.mktemp("pages")
    made = {}
    for name, args in {"plain": [], "audiobook": ["--app", "audiobook"], "announcer": ["--app", "announcer"],
                       "linked": ["--link-audio"]}.items():
        made[name] = folder / f"{name}.html"
        subprocess.run([CLI, "demo", "-q", *args, "-o", str(made[name])], check=True, timeout=120)
    # A long speech: 300 sentences of 5 syllables, 0.2 s each, 0.6 s between them.
    lines = ["春天來了。", "小鳥唱歌。", "河水很清。", "讀書用心。", "大家笑了。"]
    text = "".join(lines[k % len(lines)] for k in range(300))
    (folder / "long.txt").write_text(text, encoding="utf-8")
    timeline = time_evenly(talkface.read_transcript(text), 0.6)
    (folder / "long.json").write_text(talkface.timeline_to_json(timeline), encoding="utf-8")
    silent_wav(folder / "long.wav", timeline.duration_s)
    made["long"] = folder / "long.html"
    subprocess.run([CLI, "animate", str(folder / "long.wav"), str(folder / "long.txt"), "--timing",
                    str(folder / "long.json"), "-q", "-o", str(made["long"])], check=True, timeout=300)
    return made


@pytest.mark.parametrize("page, size", [
    ("plain", (640, 760)), ("plain", (390, 844)),
    ("audiobook", (1280, 800)), ("audiobook", (390, 844)),
    ("announcer", (1280, 800)), ("announcer", (390, 844)),
    ("linked", (640, 760)),
    ("long", (640, 760)),
], ids=lambda value: "x".join(map(str, value)) if isinstance(value, tuple) else value)
def test_the_face_keeps_to_the_audio_clock_whatever_the_player_does(chromium, pages, page, size):
    phone = size[0] < 600
    with chromium.page(*size, mobile=phone) as browser:
        browser.open(pages[page].as_uri())
        assert browser.evaluate("location.protocol") == "file:"
        duration = assert_face_shows_audio_time(browser, "opened")["duration"]
        browser.evaluate("document.getElementById('tf-audio').play()")
        assert_face_follows_playing(browser, "playing")
        browser.evaluate("document.getElementById('tf-audio').pause()")
        browser.settle()
        paused_at = assert_face_shows_audio_time(browser, "paused")["audio"]
        assert paused_at > 0
        for what, time_s in [("forward", duration * 0.7), ("back", 0.4), ("to the start", 0.0)]:
            seek(browser, time_s)
            assert assert_face_shows_audio_time(browser, f"seeked {what}")["audio"] == pytest.approx(time_s, abs=0.01)
        browser.evaluate("var a = document.getElementById('tf-audio'); a.playbackRate = 1.5; a.play()")
        assert_face_follows_playing(browser, "at 1.5 times")
        seek(browser, duration * 0.5)  # a seek while playing
        assert_face_follows_playing(browser, "after a seek while playing")
        browser.evaluate("""new Promise(function (done) {
            var audio = document.getElementById('tf-audio');
            audio.addEventListener('ended', function () { requestAnimationFrame(function () { done(true); }); },
                                   { once: true });
            audio.currentTime = audio.duration - 0.4;
          })""")
        ended = assert_face_shows_audio_time(browser, "ended")
        assert ended["ended"] and ended["audio"] == pytest.approx(duration, abs=0.01)
        browser.evaluate("document.getElementById('tf-audio').play()")  # again, from the start
        assert_face_follows_playing(browser, "replayed")
        assert browser.evaluate(CLOCKS)["audio"] < duration / 2
        browser.evaluate("document.getElementById('tf-audio').pause()")
        if phone:
            assert browser.evaluate("document.documentElement.scrollWidth") <= size[0]
        assert browser.problems() == []


@pytest.mark.parametrize("page", ["plain", "audiobook", "announcer"])
def test_the_player_is_reached_seen_and_worked_by_keyboard(chromium, pages, page):
    with chromium.page(1280, 800) as browser:
        browser.open(pages[page].as_uri())
        for _ in range(10):  # the audio book's links and sentences come after the player
            browser.press("Tab")
            if browser.evaluate("document.activeElement.id") == "tf-audio":
                break
        assert browser.evaluate("document.activeElement.id") == "tf-audio"
        # A ring a keyboard user finds: at least 2 px, not Chromium's 1 px default round the player.
        ring = browser.evaluate("(function () { var s = getComputedStyle(document.activeElement);"
                                " return [document.activeElement.matches(':focus-visible'), s.outlineStyle,"
                                " parseFloat(s.outlineWidth)]; })()")
        assert ring[0] and ring[1] not in ("none", "auto") and ring[2] >= 2, ring
        browser.press(" ")
        assert not browser.evaluate("document.getElementById('tf-audio').paused")
        assert_face_follows_playing(browser, "played by the space bar")
        browser.press(" ")
        assert browser.evaluate("document.getElementById('tf-audio').paused")
        before = assert_face_shows_audio_time(browser, "paused by the space bar")["audio"]
        browser.press("ArrowRight")  # the player's own seek
        wait(browser, 0.3)
        assert assert_face_shows_audio_time(browser, "moved by an arrow")["audio"] > before
        assert browser.problems() == []


@pytest.mark.parametrize("size", [(568, 320), (844, 390)], ids=["568x320", "844x390"])
@pytest.mark.parametrize("page", ["plain", "audiobook", "announcer"])
def test_a_phone_on_its_side_shows_the_face_and_the_player_on_one_screen(chromium, pages, page, size):
    # Turned on its side, a phone's screen is 320-430 px high: the face must not shrink to a thumbnail
    # nor push the player below the screen, where it cannot be reached while the face is watched.
    framed = "svg.tf-stage-art" if page == "announcer" else "svg.tf-animation"
    with chromium.page(*size, mobile=True) as browser:
        browser.open(pages[page].as_uri())
        face, player = (browser.evaluate("(function () { var r = document.querySelector('%s').getBoundingClientRect();"
                                         " return [r.top, r.bottom]; })()" % selector)
                        for selector in (framed, "#tf-audio"))
        assert face[0] >= 0 and face[1] - face[0] >= 0.4 * size[1], f"the face at {face}"
        assert player[1] <= size[1], f"the player at {player}, below the screen"
        assert browser.evaluate("document.documentElement.scrollWidth") <= size[0]
        assert browser.problems() == []


@pytest.mark.parametrize("page", ["plain", "audiobook", "announcer"])
def test_a_screen_reader_finds_the_face_and_the_player_named(chromium, pages, page):
    # Chromium's accessibility tree, as a screen reader reads it: an image or a player with no name
    # is announced as a bare "image" or "audio".
    with chromium.page(1280, 800) as browser:
        browser.open(pages[page].as_uri())
        browser.call("Accessibility.enable")
        nodes = [node for node in browser.call("Accessibility.getFullAXTree")["nodes"] if not node.get("ignored")]
        named = {}
        for node in nodes:
            role = node.get("role", {}).get("value")
            if role in ("image", "Audio"):
                named.setdefault(role, []).append(node.get("name", {}).get("value", ""))
        assert len(named.get("image", [])) == 1 and len(named.get("Audio", [])) == 1, named
        assert all(name.strip() for names in named.values() for name in names), named


def test_ready_means_the_face_shows_the_time_of_the_fragment(chromium, pages):
    # The SVG's timeline starts with the document's load event, after the audio's metadata: a page
    # that says it is ready must already show the face at the fragment's time.
    with chromium.page(640, 760) as browser:
        browser.call("Page.navigate", url=pages["plain"].as_uri() + "#t=2.5&pause")
        browser.evaluate("""new Promise(function (done) {
            (function poll() {
              if (document.body && document.body.getAttribute('data-tf-ready') === '1') return done(true);
              setTimeout(poll, 2);
            })();
          })""")
        clocks = assert_face_shows_audio_time(browser, "ready")
        assert clocks["audio"] == pytest.approx(2.5, abs=0.01)


@pytest.mark.parametrize("fragment", ["", "#t=3&pause"])
def test_a_speech_that_cannot_be_played_is_said_on_the_page(chromium, pages, tmp_path, fragment):
    page = tmp_path / "moved.html"
    page.write_text(pages["linked"].read_text(encoding="utf-8"), encoding="utf-8")  # its speech left behind
    with chromium.page(640, 760) as browser:
        browser.open(page.as_uri() + fragment)
        notice = browser.evaluate("(function () { var n = document.querySelector('.tf-audio-error');"
                                  " return n && [n.getAttribute('role'), n.textContent, n.getBoundingClientRect().height]; })()")
        assert notice is not None, "no notice on the page"
        assert notice[0] == "alert" and "linked.ogg" in notice[1] and notice[2] > 10, notice
        assert_face_shows_audio_time(browser, "no speech")
        browser.press(" ")  # nothing to play, and nothing thrown
        assert all(problem.startswith("network: ") for problem in browser.problems()), browser.problems()


class SlowSpeechServer(QuietHandler):
    """Serves a folder; a speech's first 20 kB at once, the rest at 2 kB/s, under the 5 kB a second
    it plays at: the player runs out of data and waits, as on a slow connection."""

    def copyfile(self, source, destination):
        if not self.path.endswith(".ogg"):
            return super().copyfile(source, destination)
        destination.write(source.read(20000))
        while chunk := source.read(500):
            destination.write(chunk)
            destination.flush()
            time.sleep(0.25)


def test_a_page_served_over_http_asks_for_its_speech_alone_and_the_face_waits_for_it(chromium, pages):
    # Served by a web server rather than opened from a file: the browser asks for the page and its
    # speech, nothing else (no icon: a 404 in the console), and when the speech comes slower than it
    # plays the face stops with the voice.
    with served(pages["linked"].parent, SlowSpeechServer) as origin:
        with chromium.page(640, 760) as browser:
            browser.call("Network.enable")
            browser.open(origin + "linked.html")
            browser.evaluate("window.tfWaits = 0; document.getElementById('tf-audio').addEventListener('waiting',"
                             " function () { ++window.tfWaits; }); document.getElementById('tf-audio').play()")
            assert_face_follows_playing(browser, "on a slow connection", frames=90)
            browser.evaluate("""new Promise(function (done) {
                (function poll() { if (window.tfWaits > 0) return done(true); setTimeout(poll, 50); })();
              })""")
            assert_face_follows_playing(browser, "after the speech waited for data", frames=30)
            asked = sorted({event["params"]["request"]["url"] for event in browser.events
                            if event["method"] == "Network.requestWillBeSent"
                            and not event["params"]["request"]["url"].startswith("data:")})
            assert asked == [origin + "linked.html", origin + "linked.ogg"]
            assert browser.problems() == []
            # Waiting for a slow connection is not a speech cut off: nothing is said.
            assert browser.evaluate("document.querySelector('.tf-audio-error')") is None


class DroppingServer(QuietHandler):
    """Serves a folder; of a speech, its first 40 kB (5 of its 13 s), then it closes the connection,
    as a server that goes down, every time it is asked."""

    def copyfile(self, source, destination):
        if not self.path.endswith(".ogg"):
            return super().copyfile(source, destination)
        destination.write(source.read(40000))
        self.close_connection = True


def test_a_speech_cut_off_while_it_plays_is_said_on_the_page(chromium, pages):
    # The player stopped at 5 s and waited, Chromium asking again, for 25 s with nothing said, and
    # then the page said the speech was missing or in a format the browser does not play, a speech
    # that had played for 5 s. The page says, 5 s into the wait, that the speech stopped coming in.
    with served(pages["linked"].parent, DroppingServer) as origin:
        with chromium.page(640, 760) as browser:
            browser.open(origin + "linked.html")
            browser.evaluate("document.getElementById('tf-audio').play()")
            said = browser.evaluate("""new Promise(function (done) {
                var waited = 0;
                (function poll() {
                  var notice = document.querySelector('.tf-audio-error');
                  var audio = document.getElementById('tf-audio');
                  if (notice) return done([notice.getAttribute('role'), notice.textContent, audio.error === null]);
                  if ((waited += 100) > 40000) return done(null);
                  setTimeout(poll, 100);
                })();
              })""")
            assert said is not None, "40 s after the speech was cut off, nothing said on the page"
            assert said[0] == "alert" and "stopped coming in" in said[1] and "linked.ogg" in said[1], said
            assert said[2], "said only once the browser gave up on the speech"
            clocks = assert_face_shows_audio_time(browser, "cut off")
            assert 2 < clocks["audio"] < 8 and not clocks["ended"], clocks


def test_a_speech_started_before_the_animation_is_unpacked_is_followed(chromium, pages):
    # The page's script runs once the animation is unpacked; the player works before that. Hold the
    # unpacking (the page's Response.text()) until the speech plays.
    hold = """(function () {
      var text = Response.prototype.text, held = [];
      window.tfReleaseUnpacking = function () { held.forEach(function (go) { go(); }); held = null; };
      Response.prototype.text = function () {
        var response = this;
        if (held === null) return text.call(response);
        return new Promise(function (resolve) { held.push(function () { resolve(text.call(response)); }); });
      };
    })();"""
    with chromium.page(640, 760) as browser:
        browser.call("Page.addScriptToEvaluateOnNewDocument", source=hold)
        browser.call("Page.navigate", url=pages["plain"].as_uri())
        browser.evaluate("""new Promise(function (done) {
            (function poll() {
              var audio = document.getElementById('tf-audio');
              if (audio && audio.readyState >= 1) return done(true);
              setTimeout(poll, 20);
            })();
          })""")
        browser.evaluate("document.getElementById('tf-audio').play()")
        wait(browser, 0.3)
        browser.evaluate("window.tfReleaseUnpacking()")
        browser.evaluate("""new Promise(function (done) {
            (function poll() {
              if (document.body.getAttribute('data-tf-ready') === '1') return done(true);
              setTimeout(poll, 20);
            })();
          })""")
        assert_face_follows_playing(browser, "started before the unpacking", frames=30)
        assert browser.problems() == []
