"""The pages' compressed audio plays in Chromium: each container that video_test's audio encoder
test wrote (Opus in Ogg and WebM, AAC in MP4, the MP4 from memory with its index at the end) is
loaded as a data: URI by an <audio> element and decoded by Web Audio, on a page of its own in the
module's Chromium (tests/apps/browser.py), which reads back what the page found.
"""
import base64
import os
import pathlib

import pytest

from browser import CHROMIUM

OUTPUT_DIR = pathlib.Path(os.environ["TALKFACE_TEST_OUTPUT_DIR"])
FILES = [("audio_encoder_16000.ogg", "audio/ogg; codecs=opus"),
         ("audio_encoder_44100.webm", "audio/webm; codecs=opus"),
         ("audio_encoder_48000.m4a", "audio/mp4; codecs=mp4a.40.2")]

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")


def page_for(name, mime):
    data = base64.b64encode((OUTPUT_DIR / name).read_bytes()).decode()
    src = f"data:{mime.split(';')[0]};base64,{data}"
    return f"""<html><body><div id=out></div><script>
const out = document.getElementById("out");
const audio = new Audio();
audio.onloadedmetadata = () => out.setAttribute("data-play", audio.canPlayType("{mime}") + " " + audio.duration);
audio.onerror = () => out.setAttribute("data-play", "error " + audio.error.code);
audio.src = "{src}";
fetch(audio.src).then(r => r.arrayBuffer())
  .then(bytes => new OfflineAudioContext(1, 48000, 48000).decodeAudioData(bytes))
  .then(decoded => out.setAttribute("data-decoded", String(decoded.duration)))
  .catch(e => out.setAttribute("data-decoded", "failed " + e));
</script></body></html>"""


@pytest.mark.parametrize("name,mime", FILES)
def test_chromium_plays_and_decodes(chromium, name, mime, tmp_path):
    page = tmp_path / "audio.html"
    page.write_text(page_for(name, mime))
    with chromium.page(320, 240) as browser:
        browser.load(page.as_uri())
        found = browser.evaluate("""new Promise(function (done) {
            var out = document.getElementById("out"), waited = 0;
            (function poll() {
              if ((out.hasAttribute("data-play") && out.hasAttribute("data-decoded")) || (waited += 50) > 30000)
                return done({play: out.getAttribute("data-play"), decoded: out.getAttribute("data-decoded")});
              setTimeout(poll, 50);
            })();
          })""")
    assert found["play"] is not None and found["decoded"] is not None, found
    can_play, duration = found["play"].split(" ")
    assert can_play == "probably"
    assert abs(float(duration) - 1.5) < 0.03
    assert abs(float(found["decoded"]) - 1.5) < 0.03
