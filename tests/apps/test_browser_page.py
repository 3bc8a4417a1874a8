"""What a person sees of `talkface demo` and `talkface animate` pages: headless Chromium (browser.py)
seeks the audio, screenshots the page, and the pixels say whether the mouth is open.

Pages honour a "#t=SECONDS&pause" fragment: once the audio's metadata is loaded they seek there and
stay paused, and the script sets the animation's time from the audio clock. The page writes what it
shows into data- attributes of <body> (data-tf-time, data-tf-sentence, data-tf-ready): Page.open
waits for data-tf-ready, then the test reads the screen or the document.

Times come from the alignment of the bundled speech (`talkface align --json`): the same audio and
transcript the demo aligns, so the same times.
"""
import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "common"))
from mouth_pixels import mouth_inside_pixels  # noqa: E402
from browser import CHROMIUM  # noqa: E402

CLI = os.environ["TALKFACE_CLI"]
SPEECH_DIR = pathlib.Path(os.environ["TALKFACE_SPEECH_DIR"])
# A screenshot's pixel within 18 of 255 on each channel of a mouth colour counts as it (issue 17's tolerance).
MOUTH_TOLERANCE = 18
WINDOW = (640, 760)

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")


def screenshot(chromium, page, time_s, png_path):
    with chromium.page(*WINDOW) as browser:
        browser.open(f"file://{page}#t={time_s:.3f}&pause")
        image = browser.screenshot()
    image.save(png_path)
    return image


def body_state(chromium, page, time_s):
    with chromium.page(*WINDOW) as browser:
        browser.open(f"file://{page}#t={time_s:.3f}&pause")
        dom = browser.evaluate("document.documentElement.outerHTML")
    body = re.search(r"<body[^>]*>", dom).group(0)
    return dict(re.findall(r'data-tf-([a-z]+)="([^"]*)"', body)), dom


@pytest.fixture(scope="module")
def alignment():
    result = subprocess.run([CLI, "align", str(SPEECH_DIR / "demo.ogg"), str(SPEECH_DIR / "demo.txt"),
                             "--json", "-q"], check=True, capture_output=True, text=True, timeout=120)
    return json.loads(result.stdout)


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    folder = tmp_path_factory.mktemp("pages")
    made = {}
    for name, args in {"keyframes": [], "frames": ["--encoding", "frames"],
                       "audiobook": ["--app", "audiobook", "--title", "<b>書</b>&\"'",
                                     "--link", "Home=https://example.org/?a=1&b=<2>"]}.items():
        made[name] = folder / f"{name}.html"
        subprocess.run([CLI, "demo", "-q", *args, "-o", str(made[name])], check=True, timeout=120)
    return made


def open_vowel_time(alignment):
    """The middle of the vowel of the longest syllable whose final is a / ai / ao / an / ang."""
    open_finals = [s for s in alignment["syllables"] if re.fullmatch(r"[a-z]*?[^iuv]?a[oin]?g?\d", s["pinyin"])]
    syllable = max(open_finals, key=lambda s: s["end"] - s.get("final_start", s["start"]))
    vowel_start = syllable.get("final_start", syllable["start"])
    return vowel_start + 0.6 * (syllable["end"] - vowel_start)


def pause_time(alignment):
    """The middle of the silence before the first syllable: the mouth rests there."""
    return alignment["syllables"][0]["start"] / 2


@pytest.mark.parametrize("encoding", ["keyframes", "frames"])
def test_mouth_is_open_in_a_vowel_and_closed_in_a_pause(chromium, pages, alignment, encoding, tmp_path):
    page = pages[encoding]
    vowel = screenshot(chromium, page, open_vowel_time(alignment), tmp_path / "vowel.png")
    pause = screenshot(chromium, page, pause_time(alignment), tmp_path / "pause.png")
    open_pixels = mouth_inside_pixels(vowel, MOUTH_TOLERANCE)
    closed_pixels = mouth_inside_pixels(pause, MOUTH_TOLERANCE)
    assert open_pixels > 150, f"mouth at {open_vowel_time(alignment):.3f} s shows {open_pixels} inside pixels"
    assert closed_pixels < 20, f"mouth at {pause_time(alignment):.3f} s shows {closed_pixels} inside pixels"


def test_the_page_follows_the_seek_of_its_fragment(chromium, pages, alignment):
    time_s = open_vowel_time(alignment)
    state, _ = body_state(chromium, pages["keyframes"], time_s)
    assert state["ready"] == "1"
    assert float(state["time"]) == pytest.approx(time_s, abs=0.002)


def test_audiobook_highlights_the_sentence_being_spoken(chromium, pages, alignment):
    for index, sentence in enumerate(alignment["sentences"]):
        middle = (sentence["start"] + sentence["end"]) / 2
        state, dom = body_state(chromium, pages["audiobook"], middle)
        assert state["sentence"] == str(index)
        current = re.findall(r'<span class="tf-sentence tf-current"[^>]*data-index="(\d+)"', dom)
        assert current == [str(index)]


def test_audiobook_shows_hostile_title_and_link_as_text(chromium, pages, alignment):
    _, dom = body_state(chromium, pages["audiobook"], 0.1)
    assert "<b>" not in dom
    assert "&lt;b&gt;書&lt;/b&gt;&amp;\"'" in dom
    assert 'href="https://example.org/?a=1&amp;b=%3C2%3E"' in dom


def test_announcer_places_the_face_where_asked(chromium, tmp_path):
    page = tmp_path / "announcer.html"
    subprocess.run([CLI, "demo", "-q", "--app", "announcer", "--background", "#203040", "--stage", "600x400",
                    "--face-origin", "450,330", "--face-d", "50", "-o", str(page)], check=True, timeout=120)
    image = screenshot(chromium, page, 0.1, tmp_path / "announcer.png")
    # The stage is 600 px wide in a 640 px window (16 px padding each side, scaled 608/600): the
    # face's skin must sit right of the middle, the stage colour fill the left.
    skin = (0xF5, 0xD0, 0xA9)
    def skin_share(left, right):
        box = image.crop((left, 16, right, 400))
        hits = sum(1 for p in box.getdata() if all(abs(a - b) <= 24 for a, b in zip(p, skin)))
        return hits / (box.size[0] * box.size[1])
    assert skin_share(360, 560) > 0.05
    assert skin_share(20, 300) < 0.01
