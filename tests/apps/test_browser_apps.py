"""The announcer and the audio book as a person sees them (issue 17), in headless Chromium driven
through the DevTools protocol (browser.py): the caption shows the sentence being spoken and never
covers the mouth; deep into a long book the spoken sentence is highlighted in view; on a phone's
390x844 screen the face and the player come first, the text below; the keys play, pause and move a
sentence, with a visible focus; the speech compressed into the page plays, lasts as long as the
recording, and face and voice stay together through seeks and playing.

The demo pages are made by `talkface demo`; the long book by the Python module, from a transcript
of 120 sentences in 20 paragraphs timed by hand, over a silent recording linked beside the page.
"""
import json
import os
import pathlib
import re
import subprocess

import pytest

import talkface
from browser import CHROMIUM, silent_wav, time_evenly

CLI = os.environ["TALKFACE_CLI"]
SPEECH_DIR = pathlib.Path(os.environ["TALKFACE_SPEECH_DIR"])
MOUTH_INSIDE = (0x6A, 0x1E, 0x22)  # FaceColors::mouth_inside of the built-in face
HIGHLIGHT = (0xFF, 0xD9, 0x5E)     # .tf-current in the audio book
SKIN = (0xF5, 0xD0, 0xA9)

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")

LINES = ["春天來了，花園裡的花都開了。", "小鳥在樹上唱歌。", "我們一起去河邊看看吧！", "河水很清，魚兒游來游去。",
         "老師說，讀書要用心。", "大家都點頭笑了。"]


def near(pixel, colour, tolerance=18):
    return all(abs(p - c) <= tolerance for p, c in zip(pixel, colour))


def pixels_of(image, colour, box=None, tolerance=18):
    """(x, y) of every pixel near `colour`, inside box = (left, top, right, bottom) if given."""
    left, top, right, bottom = box or (0, 0, image.size[0], image.size[1])
    left, top = max(0, int(left)), max(0, int(top))
    right, bottom = min(image.size[0], int(right)), min(image.size[1], int(bottom))
    data = image.load()
    return [(x, y) for y in range(top, bottom) for x in range(left, right) if near(data[x, y], colour, tolerance)]


def rect(browser, selector):
    return browser.evaluate(f"""(function () {{
        var e = document.querySelector({json.dumps(selector)});
        if (!e) return null;
        var r = e.getBoundingClientRect();
        return {{left: r.left, top: r.top, right: r.right, bottom: r.bottom}};
      }})()""")


@pytest.fixture(scope="module")
def alignment():
    result = subprocess.run([CLI, "align", str(SPEECH_DIR / "demo.ogg"), str(SPEECH_DIR / "demo.txt"),
                             "--json", "-q"], check=True, capture_output=True, text=True, timeout=120)
    return json.loads(result.stdout)


@pytest.fixture(scope="module")
def announcer(tmp_path_factory):
    page = tmp_path_factory.mktemp("announcer") / "announcer.html"
    subprocess.run([CLI, "demo", "-q", "--app", "announcer", "--title", "晚間新聞", "-o", str(page)],
                   check=True, timeout=120)
    return page


@pytest.fixture(scope="module")
def long_caption(tmp_path_factory):
    """An announcer page whose first sentence takes three lines at the caption's size on a desktop
    (0.2 s a syllable from 0.5 s), over a silent recording embedded in the page (its metadata is
    known before the page's script runs)."""
    folder = tmp_path_factory.mktemp("caption")
    text = ("今天的新聞有很多，我們先來看一條很長很長的消息：市政府宣布從下個月開始，全市的公共汽車和地鐵"
            "都將延長運營時間，方便市民晚上出行，同時票價保持不變。")
    timeline = talkface.read_transcript(text)
    for index, syllable in enumerate(timeline.syllables):
        syllable.start_s, syllable.end_s = 0.5 + 0.2 * index, 0.7 + 0.2 * index
    timeline.sentences[0].start_s, timeline.sentences[0].end_s = 0.5, timeline.syllables[-1].end_s
    timeline.duration_s = timeline.syllables[-1].end_s + 0.5
    audio = folder / "news.wav"
    silent_wav(audio, timeline.duration_s)
    face = talkface.FaceModel.default()
    animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3))
    options = talkface.WebPageOptions(app=talkface.WebPageApp.announcer, title="晚間新聞")
    page = folder / "news.html"
    talkface.write_web_page(page, talkface.SvgAnimator(face), animation, timeline, audio, options)
    return page


@pytest.fixture(scope="module")
def long_book(tmp_path_factory):
    """120 sentences, 6 a paragraph; 0.2 s a syllable, 0.4 s between sentences; a link after them."""
    folder = tmp_path_factory.mktemp("book")
    text = "\n\n".join("".join(LINES[(p + k) % len(LINES)] for k in range(6)) for p in range(20))
    timeline = time_evenly(talkface.read_transcript(text), 0.4)
    audio = folder / "book.wav"
    silent_wav(audio, timeline.duration_s)
    face = talkface.FaceModel.default()
    animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3))
    options = talkface.WebPageOptions(app=talkface.WebPageApp.audiobook, title="春天的故事",
                                      audio=talkface.WebPageAudio.link, audio_url="book.wav",
                                      links=[talkface.WebLink("目錄", "https://example.org/book")])
    page = folder / "book.html"
    talkface.write_web_page(page, talkface.SvgAnimator(face), animation, timeline, audio, options)
    return page, timeline


def test_the_book_keeps_its_paragraphs(long_book):
    page, timeline = long_book
    html = page.read_text()
    paragraphs = re.findall(r'<p class="tf-paragraph">(.*?)</p>', html, re.S)
    assert len(paragraphs) == 20
    assert all(len(re.findall(r'class="tf-sentence"', p)) == 6 for p in paragraphs)
    assert sum(s.starts_paragraph for s in timeline.sentences) == 19  # the first needs no blank line


def test_the_announcer_caption_shows_the_sentence_being_spoken(chromium, announcer, alignment):
    with chromium.page(832, 520) as browser:
        shown = []
        for sentence in alignment["sentences"]:
            middle = (sentence["start"] + sentence["end"]) / 2
            browser.open(f"file://{announcer}#t={middle:.3f}&pause")
            caption = browser.evaluate("document.querySelector('.tf-caption .tf-current').textContent")
            assert caption == sentence["text"]
            box = rect(browser, ".tf-caption")
            image = browser.screenshot()
            # White text on the dark bar: the caption shows, and what it shows changes.
            white = pixels_of(image, (0xFF, 0xFF, 0xFF), (box["left"], box["top"], box["right"], box["bottom"]), 40)
            assert len(white) > 150, f"{len(white)} white text pixels in the caption"
            shown.append(frozenset(white))
            # The title stands apart, over the caption.
            assert browser.evaluate("document.querySelector('.tf-title').textContent") == "晚間新聞"
            assert rect(browser, ".tf-title")["bottom"] <= box["top"] + 1
        assert len(set(shown)) == len(shown)


def test_a_long_caption_fits_its_band_opened_at_a_time_and_after_the_window_changes(chromium, long_caption):
    # A link to a time shows the sentence before the caption's script runs; a phone turned or a
    # window resized changes the band the caption was fitted to.
    def caption(browser):
        return browser.evaluate("(function () { var c = document.querySelector('.tf-caption');"
                                " return [parseFloat(getComputedStyle(c).fontSize), c.scrollHeight, c.clientHeight,"
                                " c.querySelector('.tf-current') !== null]; })()")
    with chromium.page(1280, 800) as browser:
        browser.open(f"file://{long_caption}#t=3&pause")
        desktop = caption(browser)
        assert desktop[3] and desktop[1] <= desktop[2] + 1, f"opened at 3 s: {desktop}"
        for width, height in [(390, 844), (844, 390), (1280, 800)]:
            browser.call("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1,
                         mobile=width < 1000)
            browser.settle()
            resized = caption(browser)
            assert resized[1] <= resized[2] + 1, f"at {width}x{height}: {resized}"
        assert resized[0] == pytest.approx(desktop[0], rel=0.01), "the caption's size came back with the window's"
        assert browser.problems() == []


def test_the_announcer_caption_never_covers_the_mouth(chromium, announcer, alignment):
    # The middle of each sentence and of every open vowel (finals a, ai, ao, an, ang).
    times = [(s["start"] + s["end"]) / 2 for s in alignment["sentences"]]
    for syllable in alignment["syllables"]:
        if re.fullmatch(r"[a-z]*?[^iuv]?a[oin]?g?\d", syllable["pinyin"]):
            vowel = syllable.get("final_start", syllable["start"])
            times.append(vowel + 0.6 * (syllable["end"] - vowel))
    open_frames = 0
    with chromium.page(832, 520) as browser:
        for time_s in times:
            browser.open(f"file://{announcer}#t={time_s:.3f}&pause")
            box = rect(browser, ".tf-lower-third")
            mouth = pixels_of(browser.screenshot(), MOUTH_INSIDE)
            if len(mouth) > 20:
                open_frames += 1
                assert max(y for _, y in mouth) < box["top"], f"{time_s:.3f} s: the caption covers the mouth"
    assert open_frames >= 5, f"only {open_frames} of {len(times)} frames show an open mouth"


@pytest.mark.parametrize("size", [(390, 844), (1280, 800)], ids=["phone", "desktop"])
def test_the_highlight_is_in_view_deep_into_a_long_book(chromium, long_book, size):
    page, timeline = long_book
    index = 100
    sentence = timeline.sentences[index]
    with chromium.page(*size, mobile=size[0] < 600) as browser:
        browser.open(f"file://{page}#t={(sentence.start_s + sentence.end_s) / 2:.3f}&pause")
        assert browser.evaluate("document.body.getAttribute('data-tf-sentence')") == str(index)
        current = rect(browser, ".tf-sentence.tf-current")
        teacher = rect(browser, ".tf-teacher")
        assert browser.evaluate("window.scrollY") > 1000
        assert current["bottom"] <= size[1]
        if size[0] < 600:  # the face is held over the text: the sentence shows under it
            assert current["top"] >= teacher["bottom"]
        else:
            assert current["top"] >= 0 and current["right"] <= teacher["left"]
        image = browser.screenshot()
        highlight = pixels_of(image, HIGHLIGHT, (current["left"], current["top"], current["right"], current["bottom"]))
        assert len(highlight) > 200, f"{len(highlight)} highlight pixels in view"
        # The face is still on the screen, talking.
        skin = pixels_of(image, SKIN, (teacher["left"], teacher["top"], teacher["right"], teacher["bottom"]), 24)
        assert len(skin) > 2000


def test_a_phone_shows_the_face_and_the_player_first_and_the_text_below(chromium, long_book):
    page, _ = long_book
    with chromium.page(390, 844, mobile=True) as browser:
        browser.open(f"file://{page}#t=0.1&pause")
        face = rect(browser, "svg.tf-animation")
        player = rect(browser, "#tf-audio")
        text = rect(browser, ".tf-paragraph")
        assert face["top"] >= 0 and face["bottom"] <= 844 and face["bottom"] - face["top"] > 200
        assert player["top"] >= face["bottom"] - 1 and player["bottom"] <= 844
        assert player["right"] - player["left"] > 300
        assert text["top"] >= player["bottom"] and text["top"] < 844
        assert browser.evaluate("document.documentElement.scrollWidth") <= 390
        image = browser.screenshot()
        skin = pixels_of(image, SKIN, (face["left"], face["top"], face["right"], face["bottom"]), 24)
        assert len(skin) > 5000


@pytest.fixture(scope="module")
def demo_book(tmp_path_factory):
    page = tmp_path_factory.mktemp("demo_book") / "book.html"
    subprocess.run([CLI, "demo", "-q", "--app", "audiobook", "-o", str(page)], check=True, timeout=120)
    return page


SCROLL_ROOM = """(function () {
    var sentences = document.querySelectorAll('.tf-sentence');
    var last = sentences[sentences.length - 1].getBoundingClientRect();
    return {scroll: document.documentElement.scrollHeight - window.innerHeight,
            below_last: document.documentElement.scrollHeight - (window.scrollY + last.bottom)};
  })()"""


@pytest.mark.parametrize("size", [(390, 844), (844, 390), (1280, 800)], ids=["phone", "phone-sideways", "desktop"])
def test_a_book_that_fits_the_window_does_not_scroll_and_a_long_one_keeps_room_below(chromium, demo_book, long_book,
                                                                                     size):
    # The demo's three sentences fit a phone's screen: main's room below the text scrolled them 49 px
    # to show nothing more. A long book keeps the room, for its last sentence to come up the screen.
    mobile = size != (1280, 800)
    with chromium.page(*size, mobile=mobile) as browser:
        browser.open(f"file://{demo_book}#t=1&pause")
        assert browser.evaluate(SCROLL_ROOM)["scroll"] <= 0
        page, _ = long_book
        browser.open(f"file://{page}#t=1&pause")
        assert browser.evaluate(SCROLL_ROOM)["below_last"] > size[1] / 4
        # Back to the short book on a window too small for it: the room comes back with the need.
        browser.open(f"file://{demo_book}#t=1&pause")
        browser.emulate(size[0], 200, mobile)
        browser.settle()
        assert browser.evaluate(SCROLL_ROOM)["below_last"] > 200 / 4


@pytest.mark.parametrize("size", [(390, 844), (1280, 800)], ids=["phone", "desktop"])
def test_the_keys_hint_shows_where_there_are_keys(chromium, demo_book, size):
    # A phone's only pointer is a finger, and it has no Space or arrow keys to press.
    phone = size == (390, 844)
    with chromium.page(*size, mobile=phone) as browser:
        browser.open(f"file://{demo_book}#t=1&pause")
        shown = browser.evaluate("document.querySelector('.tf-keys').getClientRects().length > 0")
        assert shown != phone
        assert browser.problems() == []


def test_keys_play_pause_and_move_a_sentence_with_a_visible_focus(chromium, long_book):
    page, timeline = long_book
    with chromium.page(1280, 800) as browser:
        browser.open(f"file://{page}#t=0.1&pause")
        assert browser.evaluate("document.body.getAttribute('data-tf-sentence')") == "-1"
        moves = []
        for key in ["ArrowRight", "ArrowRight", "ArrowDown", "ArrowLeft"]:
            browser.press(key)
            moves.append(browser.evaluate("[document.body.getAttribute('data-tf-sentence'), "
                                          "document.activeElement.getAttribute('data-index'), "
                                          "document.getElementById('tf-audio').currentTime]"))
        assert [m[0] for m in moves] == ["0", "1", "2", "1"]
        assert [m[1] for m in moves] == ["0", "1", "2", "1"]
        assert moves[-1][2] == pytest.approx(timeline.sentences[1].start_s, abs=0.01)
        # The focus ring shows on the focused sentence, outside its highlight.
        style = browser.evaluate("(function () { var s = getComputedStyle(document.activeElement);"
                                 " return [document.activeElement.matches(':focus-visible'), s.outlineStyle,"
                                 " parseFloat(s.outlineWidth)]; })()")
        assert style[0] and style[1] != "none" and style[2] >= 2
        assert browser.evaluate("document.getElementById('tf-audio').paused")
        browser.press(" ")
        assert not browser.evaluate("document.getElementById('tf-audio').paused")
        browser.evaluate("new Promise(function (done) { setTimeout(function () { done(true); }, 400); })")
        browser.press(" ")
        assert browser.evaluate("document.getElementById('tf-audio').paused")
        assert browser.evaluate("document.getElementById('tf-audio').currentTime") > timeline.sentences[1].start_s


def test_the_text_is_one_tab_stop_the_sentence_being_spoken(chromium, long_book):
    # Tab from the player: the sentence being spoken, then the link after the text, not every
    # sentence of the book on the way.
    page, timeline = long_book
    index = 50
    sentence = timeline.sentences[index]
    with chromium.page(1280, 800) as browser:
        browser.open(f"file://{page}#t={(sentence.start_s + sentence.end_s) / 2:.3f}&pause")
        browser.evaluate("document.getElementById('tf-audio').focus()")
        focused = "document.activeElement.getAttribute('data-index') || document.activeElement.tagName"
        for _ in range(12):  # through the player's own buttons
            browser.press("Tab")
            if browser.evaluate(focused) != "AUDIO":
                break
        assert browser.evaluate(focused) == str(index)
        browser.press("ArrowRight")  # the arrows move the focus along the text
        assert browser.evaluate(focused) == str(index + 1)
        browser.press("Tab")
        assert browser.evaluate(focused) == "A"
        assert browser.problems() == []


@pytest.fixture(scope="module")
def compressed_page(tmp_path_factory):
    page = tmp_path_factory.mktemp("compressed") / "demo.html"
    subprocess.run([CLI, "demo", "-q", "-o", str(page)], check=True, timeout=120)
    return page


def test_the_compressed_speech_plays_as_long_as_the_recording_with_the_face_on_its_clock(chromium, compressed_page,
                                                                                        alignment):
    html = compressed_page.read_text()
    assert 'src="data:audio/webm;base64,' in html
    fps = 25.0  # the demo's frame rate (LipSyncOptions)
    with chromium.page(640, 760) as browser:
        browser.open(f"file://{compressed_page}#t=0&pause")
        state = browser.evaluate("""(function () {
            var audio = document.getElementById('tf-audio');
            return [audio.error === null, audio.duration, audio.canPlayType('audio/webm; codecs=opus')];
          })()""")
        assert state[0] and state[2] == "probably"
        assert state[1] == pytest.approx(alignment["duration"], abs=1 / fps)
        # Seeks anywhere, forwards and back: the face's clock is the audio's.
        for time_s in [alignment["duration"] * 0.8, 1.234, alignment["duration"] - 0.05, 0.0, 5.5]:
            times = browser.evaluate("""new Promise(function (done) {
                var audio = document.getElementById('tf-audio');
                audio.addEventListener('seeked', function () {
                  requestAnimationFrame(function () {
                    done([audio.currentTime, document.querySelector('svg.tf-animation').getCurrentTime()]);
                  });
                }, { once: true });
                audio.currentTime = %f;
              })""" % time_s)
            assert times[0] == pytest.approx(time_s, abs=0.002)
            assert times[1] == pytest.approx(times[0], abs=0.001)
        # Playing: the audio's clock moves, and at every animation frame the face shows the time the
        # page last read from it (data-tf-time). The audio's own clock reads ahead by the time since
        # then, a frame or two; on a loaded machine some frames are long, hence the median.
        played, samples = browser.evaluate("""new Promise(function (done) {
            var audio = document.getElementById('tf-audio');
            var svg = document.querySelector('svg.tf-animation');
            var samples = [], start = audio.currentTime, last = null;
            audio.play();
            (function sample(now) {
              if (last !== null && audio.currentTime > start) {
                samples.push([audio.currentTime - svg.getCurrentTime(), (now - last) / 1000,
                              svg.getCurrentTime() - parseFloat(document.body.getAttribute('data-tf-time'))]);
              }
              last = now;
              if (audio.currentTime - start > 1.0) { audio.pause(); done([audio.currentTime - start, samples]); return; }
              requestAnimationFrame(sample);
            })(performance.now());
          })""")
        assert played > 1.0
        assert len(samples) >= 10
        assert all(abs(from_shown) < 0.001 for _, _, from_shown in samples)
        lags = sorted(lag for lag, _, _ in samples)
        assert lags[0] >= -0.002
        # The face was set at the frame before, so it lags by as much as that frame lasted, which on a
        # loaded machine is longer than a frame of the face (52 ms once); past that, it must not lag
        # by a frame of its own (a page reading the audio at its `timeupdate`, 4 times a second, does).
        late = sorted(lag - frame_s for lag, frame_s, _ in samples)
        assert late[len(late) // 2] < 1 / fps, samples
