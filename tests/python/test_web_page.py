import base64
import gzip
import html as html_module
import pathlib
import re
import subprocess
import xml.dom.minidom

import pytest

import talkface

SPEECH = pathlib.Path(__file__).resolve().parents[2] / "samples" / "speech" / "demo.ogg"


def html_escaped(text):
    """The page's escaping (render/html_text.hpp, tested in C++): & < > " ' as character references."""
    return html_module.escape(text, quote=True).replace("&#x27;", "&#39;")


# A pose's animation in a packed face, with the line it ends when it stands alone (the tilt's).
POSE = r'<animate(?:Transform)? class="tf-pose" [^>]*/>\n?'

HOSTILE = "</script><img src=x onerror=alert(1)>\"'&"


@pytest.fixture
def timeline():
    timeline = talkface.read_transcript("媽媽好。")
    for k, syllable in enumerate(timeline.syllables):
        syllable.start_s = 0.5 + 0.25 * k
        syllable.end_s = syllable.start_s + 0.25
    timeline.syllables = list(timeline.syllables)
    sentence = timeline.sentences[0]
    sentence.text = HOSTILE
    sentence.start_s, sentence.end_s = 0.5, 1.25
    timeline.sentences = [sentence]
    timeline.duration_s = 2.0
    return timeline


@pytest.fixture
def animation(face, timeline):
    return talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3))


@pytest.mark.parametrize("encoding, marker", [(talkface.AnimationEncoding.keyframes, "<animate "),
                                              (talkface.AnimationEncoding.frames, "<set ")])
def test_render_animation_svg_writes_each_encoding(face, animation, encoding, marker):
    svg = talkface.SvgAnimator(face).render_animation_svg(animation, talkface.SvgAnimationOptions(encoding=encoding))
    root = xml.dom.minidom.parseString(svg).documentElement
    assert root.getAttribute("class") == "tf-animation"
    assert marker in svg


def test_write_animation_svg_writes_the_file(face, animation, tmp_path):
    path = tmp_path / "talk.svg"
    talkface.SvgAnimator(face).write_animation_svg(path, animation)
    assert path.read_text().startswith("<?xml")


def test_audiobook_page_escapes_every_caller_text(face, animation, timeline):
    options = talkface.WebPageOptions(app=talkface.WebPageApp.audiobook, title=HOSTILE,
                                      links=[talkface.WebLink(HOSTILE, "https://example.org/?a=1&b=2")])
    html = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, SPEECH, options)
    assert html.startswith("<!DOCTYPE html>")
    assert "<img" not in html
    # The page's script and the packed animation's data block, nothing else.
    assert html.count("</script>") == 2
    assert html.count("<script") == 2 and html.count('<script type="application/gzip" id="tf-animation-data">') == 1
    assert html_escaped(HOSTILE) in html
    assert "data:audio/webm;base64," in html


def test_the_audio_is_embedded_compressed_or_as_it_is(face, animation, timeline):
    def embedded_bytes(options):
        html = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, SPEECH, options)
        src = html.split('<audio id="tf-audio"')[1].split(' src="')[1].split('"')[0]
        mime, data = src.split(";base64,")
        return mime, base64.b64decode(data)

    mime, compressed = embedded_bytes(talkface.WebPageOptions())
    assert mime == "data:audio/webm" and compressed.startswith(b"\x1a\x45\xdf\xa3")  # an EBML header
    assert b"A_OPUS" in compressed
    mime, richer = embedded_bytes(talkface.WebPageOptions(audio_bitrate_bps=48000))
    assert len(richer) > 2 * len(compressed)
    mime, original = embedded_bytes(talkface.WebPageOptions(audio=talkface.WebPageAudio.original))
    assert mime == "data:audio/ogg" and original == SPEECH.read_bytes()
    with pytest.raises(talkface.InvalidArgument, match="audio_bitrate_bps"):
        talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, SPEECH,
                                talkface.WebPageOptions(audio_bitrate_bps=200000))


def test_a_wav_browsers_do_not_play_is_not_embedded_as_it_is(face, animation, timeline, tmp_path):
    # GSM 06.10 in WAV, as voice mail stores it: the C++ check (apps/web_page.cpp) raises the
    # matching exception here, naming the file and the codec.
    gsm = tmp_path / "voicemail.wav"
    subprocess.run(["ffmpeg", "-nostdin", "-loglevel", "error", "-i", SPEECH, "-ar", "8000", "-ac", "1", "-c:a", "libgsm_ms",
                    gsm], check=True)
    with pytest.raises(talkface.InvalidArgument, match=f"{gsm}: cannot be embedded as it is: its sound is GSM 6.10"):
        talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, gsm,
                                talkface.WebPageOptions(audio=talkface.WebPageAudio.original))
    html = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, gsm, talkface.WebPageOptions())
    assert "data:audio/webm;base64," in html


@pytest.mark.parametrize("app", [talkface.WebPageApp.plain, talkface.WebPageApp.announcer,
                                 talkface.WebPageApp.audiobook])
def test_the_page_packs_the_animation_it_draws(face, animation, timeline, app):
    html = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, SPEECH,
                                   talkface.WebPageOptions(app=app))
    packed = html.split('<script type="application/gzip" id="tf-animation-data">')[1].split("</script>")[0]
    text = gzip.decompress(base64.b64decode(packed)).decode()
    # libdeflate's best level packs it smaller than zlib's (Python's gzip), by 13% on 3 minutes.
    assert len(base64.b64decode(packed)) < 0.95 * len(gzip.compress(text.encode(), 9, mtime=0))
    # The face drawn with its head at rest, and what the pose adds (the tilt, the turn and the nod) in
    # additive animations of class tf-pose, which the page takes out for a reader who asks for reduced
    # motion: without them, the face as the simulator draws it with no tilt, turn or nod.
    assert "\f" not in text
    poses = re.findall(POSE, text)
    assert len(poses) > 3 and all('additive="sum"' in pose for pose in poses)
    style = talkface.ExpressionStyle()
    style.is_tilt_simulated = style.is_turn_simulated = style.is_nod_simulated = False
    still = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3, style))
    drawn_still = talkface.SvgAnimator(face).render_animation_svg(still)
    at_rest = re.sub(r"<(\w+)([^<>]*)></\1>", r"<\1\2/>", re.sub(POSE, "", text))
    if app != talkface.WebPageApp.announcer:  # the announcer's face is drawn without a background
        assert drawn_still.endswith(at_rest + "</svg>\n")
    assert html.count('class="tf-animation"') == 1
    assert "<animate " not in html


def test_a_page_of_frames_packs_the_still_face_after_the_moving_one(face, animation, timeline):
    # Each frame a drawing of its own: no animation to add a pose to, so the still head is a second
    # document, after a form feed.
    options = talkface.WebPageOptions()
    options.animation = talkface.SvgAnimationOptions(encoding=talkface.AnimationEncoding.frames)
    html = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, SPEECH, options)
    packed = html.split('<script type="application/gzip" id="tf-animation-data">')[1].split("</script>")[0]
    content, still_content = gzip.decompress(base64.b64decode(packed)).decode().split("\f")
    assert talkface.SvgAnimator(face).render_animation_svg(animation, options.animation).endswith(
        content + "</svg>\n")
    assert "<set " in still_content and "tf-pose" not in content + still_content


def test_announcer_page_links_the_audio_when_asked(face, animation, timeline):
    options = talkface.WebPageOptions(app=talkface.WebPageApp.announcer, audio=talkface.WebPageAudio.link,
                                      audio_url="my speech.ogg",
                                      face_origin_px=(600.0, 330.0), face_d_px=60.0, stage_colour="#203040")
    html = talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, SPEECH, options)
    assert 'src="my%20speech.ogg"' in html
    assert 'fill="#203040"' in html


def test_a_script_link_is_refused_and_no_page_is_left(face, animation, timeline, tmp_path):
    page = tmp_path / "page.html"
    options = talkface.WebPageOptions(links=[talkface.WebLink("run", "JavaScript:alert(1)")])
    with pytest.raises(talkface.InvalidArgument, match=r"links\[0\]\.url"):
        talkface.write_web_page(page, talkface.SvgAnimator(face), animation, timeline, SPEECH, options)
    assert not page.exists()


def test_a_missing_audio_file_is_named(face, animation, timeline, tmp_path):
    with pytest.raises(talkface.FileError, match="nowhere.ogg"):
        talkface.build_web_page(talkface.SvgAnimator(face), animation, timeline, tmp_path / "nowhere.ogg")


