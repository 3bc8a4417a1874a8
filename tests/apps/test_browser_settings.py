"""The pages under a reader's own settings and on the screens session 33 left (issue 17), in headless
Chromium (browser.py): the announcer's caption readable and whole on a 320 px phone and under a
minimum font size the reader set; the audio book's spoken sentence still marked in high contrast
(forced colours); the announcer's stage and caption on paper; a word longer than a line (an address,
a line of Latin letters without spaces) wrapped, with no sideways scroll; a title taken from a
transcript with no punctuation kept to one line, off the face.

The demo pages are made by `talkface demo`; the others by `talkface animate`, timed by hand (a
timeline JSON) over a silent recording linked beside the page.
"""
import base64
import collections
import json
import os
import re
import subprocess
import zlib

import pytest

import talkface
from browser import CHROMIUM, Browser, silent_wav, time_evenly

CLI = os.environ["TALKFACE_CLI"]

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")

LATIN = ("請看網址https://www.example.org/averyveryverylongpathwithoutanyspaces/index.html。"
         "Pneumonoultramicroscopicsilicovolcanoconiosis是一個很長的詞。")
UNPUNCTUATED = "今天我們先來看一條很長的消息市政府宣布從下個月開始全市的公共汽車和地鐵都將延長運營時間" * 5


def rect(browser, selector):
    return browser.evaluate(f"""(function () {{
        var r = document.querySelector({json.dumps(selector)}).getBoundingClientRect();
        return {{left: r.left, top: r.top, right: r.right, bottom: r.bottom}};
      }})()""")


def show_sentence(browser, index):
    """Seeks to the middle of sentence `index` and waits until the page shows it."""
    browser.evaluate("""new Promise(function (done) {
        var sentence = document.querySelectorAll('.tf-sentence')[%d];
        var audio = document.getElementById('tf-audio');
        audio.addEventListener('seeked', function () { requestAnimationFrame(function () { done(true); }); },
                               { once: true });
        audio.currentTime = (parseFloat(sentence.getAttribute('data-start')) +
                             parseFloat(sentence.getAttribute('data-end'))) / 2;
      })""" % index)
    browser.settle()


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    folder = tmp_path_factory.mktemp("demo")
    made = {}
    for app in ["announcer", "audiobook"]:
        made[app] = folder / f"{app}.html"
        subprocess.run([CLI, "demo", "-q", "--app", app, "-o", str(made[app])], check=True, timeout=120)
    return made


def timed_page(folder, name, text, app, title=None):
    """`talkface animate --app APP` of `text` timed at 0.2 s a syllable from 0.5 s, 0.4 s between
    sentences, over a silent recording linked beside the page."""
    timeline = time_evenly(talkface.read_transcript(text), 0.4)
    (folder / f"{name}.txt").write_text(text, encoding="utf-8")
    (folder / f"{name}.json").write_text(talkface.timeline_to_json(timeline), encoding="utf-8")
    silent_wav(folder / f"{name}.wav", timeline.duration_s)
    page = folder / f"{name}.html"
    subprocess.run([CLI, "animate", str(folder / f"{name}.wav"), str(folder / f"{name}.txt"), "--timing",
                    str(folder / f"{name}.json"), "--app", app, "--link-audio", "-q", "-o", str(page),
                    *(["--title", title] if title else [])], check=True, timeout=300)
    return page


@pytest.mark.parametrize("size, preferences, smallest", [
    ((320, 568), None, 12),
    ((480, 800), {"webkit": {"webprefs": {"minimum_font_size": 24}}}, 24),
], ids=["320x568", "minimum-font-24"])
def test_the_caption_is_readable_and_whole_on_a_narrow_phone_and_under_a_minimum_font_size(
        demo, size, preferences, smallest):
    # On a 320 px phone the caption inside the stage was 7.8 px; a reader's minimum font size
    # enlarged it past its band, which cut it. Either way every sentence must show whole, at a size
    # the reader reads, with the player under it on the screen.
    with Browser(*size, mobile=size[0] < 600, preferences=preferences) as browser:
        browser.open(demo["announcer"].as_uri())
        count = browser.evaluate("document.querySelectorAll('.tf-sentence').length")
        for index in range(count):
            show_sentence(browser, index)
            caption = browser.evaluate("""(function () {
                var c = document.querySelector('.tf-caption'), s = document.querySelectorAll('.tf-sentence')[%d];
                return [parseFloat(getComputedStyle(c).fontSize), c.scrollHeight, c.clientHeight,
                        c.querySelector('.tf-current') === s];
              })()""" % index)
            assert caption[3], f"sentence {index} is not the one shown"
            assert caption[0] >= smallest - 0.01, f"sentence {index}: {caption[0]:.1f} px text"
            assert caption[1] <= caption[2] + 1, f"sentence {index} cut: {caption}"
            band, player = rect(browser, ".tf-lower-third"), rect(browser, "#tf-audio")
            assert band["bottom"] <= player["top"] and player["bottom"] <= size[1], (band, player)
        assert browser.evaluate("document.documentElement.scrollWidth") <= size[0]
        assert browser.problems() == []


def test_the_spoken_sentence_stands_out_in_high_contrast(demo):
    # Forced colours (Windows' contrast themes) replace every background with the theme's: the
    # highlight of the sentence being spoken must still tell it from the rest of the text.
    with Browser(1280, 800) as browser:
        browser.call("Emulation.setEmulatedMedia", media="", features=[{"name": "forced-colors", "value": "active"}])
        browser.open(demo["audiobook"].as_uri())
        show_sentence(browser, 1)
        colours = browser.evaluate("""(function () {
            var spoken = document.querySelector('.tf-sentence.tf-current');
            var other = document.querySelectorAll('.tf-sentence')[0];
            var text = document.querySelector('.tf-text');
            return [spoken === document.querySelectorAll('.tf-sentence')[1], getComputedStyle(spoken).backgroundColor,
                    getComputedStyle(other).backgroundColor, getComputedStyle(document.body).backgroundColor,
                    getComputedStyle(text).backgroundColor];
          })()""")
        assert colours[0]
        assert colours[1] not in colours[2:] and colours[1] != "rgba(0, 0, 0, 0)", colours
        # On the screen: the sentence's first line is mostly the mark's colour, not the page's.
        spoken = browser.evaluate("(function () { var r = document.querySelector('.tf-sentence.tf-current')"
                                  ".getClientRects()[0]; return {left: r.left, top: r.top, right: r.right,"
                                  " bottom: r.bottom}; })()")
        page = tuple(int(v) for v in re.findall(r"\d+", colours[3])[:3])
        box = (int(spoken["left"]), int(spoken["top"]), int(spoken["right"]), int(spoken["bottom"]))
        pixels = list(browser.screenshot().crop(box).getdata())
        shade, count = collections.Counter(pixels).most_common(1)[0]
        assert shade != page and count > len(pixels) / 2, f"{shade} in {count} of {len(pixels)} pixels"


def test_the_announcer_prints_its_stage_and_caption(demo):
    # Printed, the announcer's page came out blank (its band a size container); on paper the stage
    # and the caption of the sentence being spoken show as on the screen.
    with Browser(1280, 800) as browser:
        browser.open(demo["announcer"].as_uri())
        show_sentence(browser, 0)
        pdf = base64.b64decode(browser.call("Page.printToPDF")["data"])
    drawn = b""
    for match in re.finditer(rb"<<(.*?)>>\s*stream\r?\n(.*?)\r?\nendstream", pdf, re.S):
        body = match.group(2)
        drawn += zlib.decompress(body) if b"FlateDecode" in match.group(1) else body
    assert b"Tj" in drawn or b"TJ" in drawn, "no text on the printed page"
    assert len(re.findall(rb"\bf\b|\bf\*", drawn)) > 20, "the stage is not drawn on the printed page"


@pytest.fixture(scope="module")
def latin(tmp_path_factory):
    folder = tmp_path_factory.mktemp("latin")
    return {"announcer": timed_page(folder, "announcer", LATIN, "announcer"),
            "audiobook": timed_page(folder, "audiobook", LATIN, "audiobook"),
            "plain": timed_page(folder, "plain", LATIN, "plain",
                                title="https://www.example.org/averyveryverylongpathwithoutanyspaces/index.html")}


@pytest.mark.parametrize("page", ["announcer", "audiobook", "plain"])
def test_a_word_longer_than_a_line_wraps_on_a_phone(latin, page):
    # An address or a line of Latin letters has no place to break: it widened a phone's page to
    # 1105 px (shown shrunk, and scrolled sideways) and ran out of the announcer's caption.
    with Browser(390, 844, mobile=True) as browser:
        browser.open(latin[page].as_uri() + "#t=3&pause")
        widths = browser.evaluate("[window.innerWidth, document.documentElement.scrollWidth]")
        assert widths == [390, 390], widths
        if page == "announcer":
            caption = browser.evaluate("(function () { var c = document.querySelector('.tf-caption');"
                                       " return [c.scrollWidth, c.clientWidth, c.scrollHeight, c.clientHeight]; })()")
            assert caption[0] <= caption[1] and caption[2] <= caption[3] + 1, caption
        assert browser.problems() == []


@pytest.mark.parametrize("title", [None, "晚間新聞特別報導" * 12], ids=["first-sentence", "given"])
def test_a_long_title_is_one_line_off_the_face(tmp_path, title):
    # With no punctuation the first sentence is the whole transcript: as the title its bar covered
    # the stage. A title, given or taken, stays one line over the caption.
    page = timed_page(tmp_path, "news", UNPUNCTUATED, "announcer", title=title)
    with Browser(1280, 800) as browser:
        browser.open(page.as_uri() + "#t=3&pause")
        shown = browser.evaluate("""(function () {
            var t = document.querySelector('.tf-title'), r = t.getBoundingClientRect();
            return [r.height, parseFloat(getComputedStyle(t).fontSize), document.title];
          })()""")
        band, caption = rect(browser, ".tf-lower-third"), rect(browser, ".tf-caption")
        assert shown[0] < 2 * shown[1], f"the title is {shown[0]:.0f} px high at {shown[1]:.1f} px a line"
        assert rect(browser, ".tf-title")["top"] >= band["top"] - 1
        assert rect(browser, ".tf-title")["bottom"] <= caption["top"] + 1
        if not title:
            assert shown[2] == UNPUNCTUATED[:30] + "\u2026"
        assert browser.problems() == []


def test_a_sentence_longer_than_the_caption_scrolls_through_it_as_it_is_spoken(tmp_path):
    # A transcript with no punctuation is one sentence: its caption, cut at the band's edge, showed
    # its first lines for minutes. The line being spoken must be in the caption.
    text = UNPUNCTUATED * 4
    page = timed_page(tmp_path, "long", text, "announcer", title="晚間新聞")
    with Browser(1280, 800) as browser:
        browser.open(page.as_uri() + "#t=1&pause")
        for share in [0.1, 0.5, 0.85]:
            browser.evaluate("""new Promise(function (done) {
                var audio = document.getElementById('tf-audio');
                audio.addEventListener('seeked', function () { requestAnimationFrame(function () { done(true); }); },
                                       { once: true });
                audio.currentTime = 0.5 + %f * %f;
              })""" % (share, 0.2 * len(text)))
            browser.settle()
            seen = browser.evaluate("""(function () {
                var caption = document.querySelector('.tf-caption'), box = caption.getBoundingClientRect();
                var words = document.querySelector('.tf-caption .tf-current').firstChild, range = document.createRange();
                range.setStart(words, %d);
                range.setEnd(words, %d);
                var spoken = range.getBoundingClientRect();
                return [spoken.top, spoken.bottom, box.top, box.bottom, caption.scrollHeight > caption.clientHeight];
              })()""" % (int(share * len(text)), int(share * len(text)) + 1))
            assert seen[4], "the sentence fits the caption: nothing to scroll"
            assert seen[0] >= seen[2] - 1 and seen[1] <= seen[3] + 1, f"at {share:.0%} of the sentence: {seen}"
        assert browser.problems() == []
