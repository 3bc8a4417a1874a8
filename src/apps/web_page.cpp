// The web page of thesis 6.3.2 and chapter 7, as a single HTML file: the animation inline (packed
// with gzip, packed_animation.hpp), the audio embedded or linked, and a script that makes the
// audio element the animation's clock.
//
// The thesis played its audio through a plug-in's extension element that no browser has now, and
// let audio and animation run on separate clocks. Here the SVG's own timeline is paused for good
// and set from audio.currentTime on every animation frame (and on seek, pause, rate change and
// end), so the face can never drift from the voice, whatever the user does with the controls.
#include <cmath>
#include <cstddef>
#include <fstream>
#include <string>

#include "apps/apps.hpp"
#include "apps/packed_animation.hpp"
#include "apps/page_fonts.hpp"
#include "audio/audio_source.hpp"
#include "common/atomic_file.hpp"
#include "common/number_format.hpp"
#include "render/html_text.hpp"
#include "render/svg_animation.hpp"
#include "render/svg_document.hpp"
#include "talkface/errors.hpp"
#include "talkface/web_page.hpp"
#include "video/audio_encoder.hpp"

namespace talkface {
inline namespace v0 {

namespace {

// Also reads the page's "#t=SECONDS[&pause]" fragment, once the audio knows its length, and writes
// what it shows into data- attributes of <body> (data-tf-time, data-tf-sentence, data-tf-ready)
// for tests and for pages that embed this one.
constexpr const char* kScript = R"js((function () {
  "use strict";
  var audio = document.getElementById("tf-audio");
  // The animation and, when it is nested in a stage, the stage's own <svg>: Chromium keeps a
  // nested <svg> on a clock of its own, other browsers use the outermost one's.
  var clocks = [document.querySelector("svg.tf-animation")];
  while (clocks[clocks.length - 1].ownerSVGElement) clocks.push(clocks[clocks.length - 1].ownerSVGElement);
  var sentences = Array.prototype.slice.call(document.querySelectorAll(".tf-sentence"));
  var current = -1;
  clocks.forEach(function (clock) { clock.pauseAnimations(); });
  function show() {
    var t = audio.currentTime || 0;
    clocks.forEach(function (clock) { clock.setCurrentTime(t); });
    var index = -1;
    for (var k = 0; k < sentences.length; ++k) {
      if (parseFloat(sentences[k].getAttribute("data-start")) <= t) index = k;
    }
    // The sentence being spoken is marked for a screen reader too (aria-current), not by its
    // colour alone: focused, it is read out as the current one.
    if (index !== current) {
      if (current >= 0) {
        sentences[current].classList.remove("tf-current");
        sentences[current].removeAttribute("aria-current");
      }
      if (index >= 0) {
        sentences[index].classList.add("tf-current");
        sentences[index].setAttribute("aria-current", "true");
      }
      current = index;
      document.dispatchEvent(new CustomEvent("tf-sentence",
        { detail: { index: index, element: index >= 0 ? sentences[index] : null } }));
    }
    document.body.setAttribute("data-tf-time", t.toFixed(3));
    document.body.setAttribute("data-tf-sentence", String(index));
  }
  // One loop of animation frames while the speech plays, however often play and pause come.
  var following = false;
  function tick() {
    show();
    following = !audio.paused && !audio.ended;
    if (following) window.requestAnimationFrame(tick);
  }
  function follow() {
    if (following) return;
    following = true;
    window.requestAnimationFrame(tick);
  }
  audio.addEventListener("play", follow);
  ["pause", "seeking", "seeked", "timeupdate", "ended", "ratechange", "loadedmetadata"].forEach(function (name) {
    audio.addEventListener(name, show);
  });
  function play() {
    var started = audio.play();
    if (started && started.catch) started.catch(function () {});
  }
  function seek_to(index) {
    audio.currentTime = parseFloat(sentences[index].getAttribute("data-start"));
    show();
  }
  sentences.forEach(function (sentence, index) {
    function seek() { seek_to(index); play(); }
    sentence.addEventListener("click", seek);
    sentence.addEventListener("keydown", function (event) {
      if (event.key === "Enter") { event.preventDefault(); seek(); }
    });
  });
  // Keys (issue 17): space plays and pauses, the arrows move a sentence back or on (the audio keeps
  // playing or stays paused); a sentence that can hold the focus (the audio book's) takes it. Keys
  // typed into a control (the audio element's own, a link, a field) are the control's.
  document.addEventListener("keydown", function (event) {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    var target = event.target;
    if (target && target.closest && target.closest("audio,input,textarea,select,button,a,[contenteditable]")) return;
    if (event.key === " " || event.key === "Spacebar") {
      event.preventDefault();
      if (audio.paused || audio.ended) play(); else audio.pause();
    } else if (sentences.length > 0 && ["ArrowLeft", "ArrowUp", "ArrowRight", "ArrowDown"].indexOf(event.key) >= 0) {
      event.preventDefault();
      var back = event.key === "ArrowLeft" || event.key === "ArrowUp";
      var index = Math.max(0, Math.min(sentences.length - 1, current + (back ? -1 : 1)));
      seek_to(index);
      if (sentences[index].hasAttribute("tabindex")) sentences[index].focus({ preventScroll: true });
    }
  });
  var source = audio.getAttribute("src") || "";
  var wanted = /(?:^#|&)t=([0-9]+(?:\.[0-9]+)?)/.exec(window.location.hash);
  var stays = /(?:^#|&)pause(?:&|$)/.test(window.location.hash);
  // Ready once the face shows the audio's time: the SVG's timeline starts only with the document's
  // load event (which the audio's first data holds back), and reads 0 until then.
  function ready() {
    show();
    if (document.readyState !== "complete") {
      window.addEventListener("load", ready, { once: true });
      return;
    }
    document.body.setAttribute("data-tf-ready", "1");
  }
  // Served by a server that does not send byte ranges (python -m http.server), a linked speech
  // cannot be seeked in Chromium (its seekable range stays [0, 0]): a page opened at a time opened
  // at 0. The speech is then fetched whole and played from memory, where every time can be sought.
  function reachable(time) {
    for (var k = 0; k < audio.seekable.length; ++k) {
      if (audio.seekable.start(k) <= time && time <= audio.seekable.end(k)) return true;
    }
    return false;
  }
  function start() {
    if (!wanted) { ready(); return; }
    var time = Math.min(parseFloat(wanted[1]), isFinite(audio.duration) ? audio.duration : Infinity);
    if (!reachable(time) && /^https?:/.test(audio.currentSrc)) {
      fetch(audio.currentSrc).then(function (response) { return response.blob(); }).then(function (whole) {
        audio.addEventListener("loadedmetadata", start, { once: true });
        audio.src = URL.createObjectURL(whole);
      }).catch(failed);
      return;
    }
    audio.addEventListener("seeked", ready, { once: true });
    audio.currentTime = time;
    if (!stays) play();
  }
  // What goes wrong with the speech is said on the page, under the player.
  function notice(text) {
    var said = document.createElement("p");
    said.className = "tf-audio-error";
    said.setAttribute("role", "alert");
    said.textContent = text;
    audio.insertAdjacentElement("afterend", said);
    return said;
  }
  // A speech that cannot be played (a linked file missing, a format this browser lacks), rather
  // than a face that never moves unexplained.
  var linked = !/^data:/.test(source);
  function failed() {
    notice("The speech could not be played: " + (linked
      ? "\u201c" + source + "\u201d is missing beside this page, or in a format this browser does not play."
      : "this browser does not play its format."));
    ready();
  }
  // A speech that stops coming in while it plays (a server closing the connection part-way through
  // a linked speech) left the player waiting with nothing said: Chromium asks again and again and
  // raises only "waiting" and "stalled", which a slow connection raises too, until it gives up 25 s
  // later. A slow connection still brings data ("progress" events); waiting with none for 5 s, the
  // page says the speech stopped coming in, and takes it back once the speech plays on.
  var quiet = null, stopped = null;
  function cut_off() {
    if (stopped) return;
    var at = Math.floor(audio.currentTime);
    stopped = notice("The speech stopped coming in at " + Math.floor(at / 60) + ":" +
      String(at % 60).padStart(2, "0") + ": the connection to \u201c" + source + "\u201d was lost. " +
      "It plays on if the rest arrives; reloading the page asks for it again.");
  }
  function expect_data() {
    window.clearTimeout(quiet);
    if (linked && !audio.paused && !audio.ended && audio.readyState < 3) quiet = window.setTimeout(cut_off, 5000);
  }
  ["waiting", "progress"].forEach(function (name) { audio.addEventListener(name, expect_data); });
  audio.addEventListener("pause", function () { window.clearTimeout(quiet); });
  audio.addEventListener("playing", function () {
    window.clearTimeout(quiet);
    if (stopped) { stopped.remove(); stopped = null; }
  });
  // Chromium's network error once it gives up on such a speech is that, not a speech missing (which
  // is what the page said of it).
  function went_wrong() {
    if (audio.readyState >= 1 && audio.error.code === audio.error.MEDIA_ERR_NETWORK) cut_off();
    else if (!document.querySelector(".tf-audio-error")) failed();
  }
  audio.addEventListener("error", went_wrong);
  if (audio.error) went_wrong();
  else if (audio.readyState >= 1) start();
  else audio.addEventListener("loadedmetadata", start, { once: true });
  show();
  // The animation is unpacked before this script runs: the speech may be playing already.
  if (!audio.paused) follow();
})();
)js";

// Compressed speech: at 11 kb/s libopus codes a voice as wideband speech (its SILK layer, up to
// 8 kHz, where speech is intelligible): 97 KiB a minute in base64, which leaves room for the face
// in 200 KiB (12 kb/s, the first choice, took 105 and the page 204). Measured on the demo speech
// five times over (65 s) against its decoded original: STOI (short-time objective
// intelligibility) 0.969 at 11 kb/s, 0.975 at 12, 0.961 at 10, 0.947 for FFmpeg's default 8 kb/s
// narrowband; the energy above 6 kHz within 0.1 dB of the original's at 11 kb/s (it is 35 dB
// below at 8 kb/s); the aligner's syllable onsets on the decoded speech as on the original's
// (98.5% within 20 ms, 98.0% at 12 kb/s). At 16 kb/s libopus moves to its hybrid super-wideband
// mode (17.5 kb/s measured, 170 KB a minute), adding sibilance above 8 kHz; RFC 7587 (section
// 3.1.1) gives 8-12 kb/s for narrowband and 16-20 for wideband speech in calls, whose 20 ms
// packets cost more than a file's 60 ms ones. 6 kb/s is libopus's floor; 128 kb/s is transparent
// even for stereo music.
constexpr int kSpeechBitrateBps = 11000;
constexpr int kLowestBitrateBps = 6000;
constexpr int kHighestBitrateBps = 128000;

// A focus ring a keyboard user finds on every page (Chromium's own round the player is 1 px), and
// the notice of a speech that cannot be played. A word longer than its line (an address, a line of
// Latin letters without spaces) is broken where it reaches the edge: it pushed a phone's page to
// 1105 px, shown shrunk and cut, and ran out of the announcer's caption. On paper the player, which
// cannot be pressed there, is left out. On a dark page the ring is light.
constexpr const char* kCommonStyle =
    "*{box-sizing:border-box}"
    "body{overflow-wrap:anywhere}"
    "@media print{audio{display:none}}"
    ":focus-visible{outline:3px solid #1d4ed8;outline-offset:3px}"
    "@media screen and (prefers-color-scheme:dark){:focus-visible{outline-color:#93c5fd}}"
    ".tf-audio-error{margin:8px 0 0;padding:8px 12px;border-radius:6px;background:#fee2e2;color:#7f1d1d;"
    "font-size:.95rem;line-height:1.4}";

void validate(const WebPageOptions& options) {
    const int app = static_cast<int>(options.app);
    if (app < 0 || app > static_cast<int>(WebPageApp::audiobook)) {
        throw InvalidArgument("app", "expected plain, announcer or audiobook, found " + std::to_string(app));
    }
    if (options.stage_width_px <= 0 || options.stage_height_px <= 0) {
        throw InvalidArgument("stage_width_px", "the stage must be at least 1 x 1 px, found " +
                                                    std::to_string(options.stage_width_px) + " x " +
                                                    std::to_string(options.stage_height_px));
    }
    if (!std::isfinite(options.face_d_px) || options.face_d_px < 0.0) {
        throw InvalidArgument("face_d_px", "expected a finite number >= 0 (0: fit the stage), found " +
                                               detail::format_shortest(options.face_d_px));
    }
    if (options.face_origin_px &&
        (!std::isfinite(options.face_origin_px->x) || !std::isfinite(options.face_origin_px->y))) {
        throw InvalidArgument("face_origin_px", "expected finite coordinates");
    }
    const int audio = static_cast<int>(options.audio);
    if (audio < 0 || audio > static_cast<int>(WebPageAudio::link)) {
        throw InvalidArgument("audio", "expected compressed, original or link, found " + std::to_string(audio));
    }
    if (options.audio_bitrate_bps != 0 &&
        (options.audio_bitrate_bps < kLowestBitrateBps || options.audio_bitrate_bps > kHighestBitrateBps)) {
        throw InvalidArgument("audio_bitrate_bps", "expected 0 (11000) or 6000 to 128000 bits a second, found " +
                                                       std::to_string(options.audio_bitrate_bps));
    }
    for (std::size_t k = 0; k < options.links.size(); ++k) {
        detail::require_safe_link(options.links[k].url, "links[" + std::to_string(k) + "].url");
    }
}

std::string file_name_of(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string audio_element(const std::string& audio_path, const WebPageOptions& options) {
    std::string source;
    if (options.audio == WebPageAudio::compressed) {
        detail::AudioEncodeOptions encoding;
        encoding.container = detail::AudioContainer::webm_opus;
        encoding.bitrate_bps = options.audio_bitrate_bps > 0 ? options.audio_bitrate_bps : kSpeechBitrateBps;
        encoding.low_rate_speech = true;
        source = detail::data_uri("audio/webm", detail::encode_audio_file(audio_path, encoding));
    } else {
        // Named by the file, as every interface's user knows it, with what to do: the page would
        // otherwise say only, in the browser, that the speech cannot be played.
        const std::string as_it_is = options.audio == WebPageAudio::link ? "linked" : "embedded as it is";
        const std::string mime = detail::audio_mime_type(audio_path);
        if (mime.empty()) {
            throw InvalidArgument(audio_path, "cannot be " + as_it_is +
                                                  ": browsers play .ogg, .oga, .opus, .wav, .flac, .mp3 and .m4a "
                                                  "files; embed it compressed (the default), or convert it to one of those");
        }
        if (mime == "audio/wav") {
            if (const std::string codec = detail::wav_codec_browsers_do_not_play(audio_path); !codec.empty())
                throw InvalidArgument(audio_path, "cannot be " + as_it_is + ": its sound is " + codec +
                                                      ", which browsers do not play (they play PCM, float, A-law and "
                                                      "mu-law WAV); embed it compressed (the default), or convert it "
                                                      "to 16-bit PCM");
        }
        if (options.audio == WebPageAudio::link) {
            if (!std::ifstream(audio_path, std::ios::binary)) throw FileError(audio_path, "cannot be opened");
            const std::string url = options.audio_url.empty() ? file_name_of(audio_path) : options.audio_url;
            detail::require_safe_link(url, "audio_url");
            source = detail::percent_encode_url(url);
        } else {
            source = detail::data_uri(mime, detail::read_file(audio_path));
        }
    }
    // Named for a screen reader, which otherwise announces a bare "audio" before the player's buttons.
    return "<audio id=\"tf-audio\" controls preload=\"auto\" aria-label=\"Speech\" src=\"" +
           escape_html(source) + "\"></audio>\n";
}

// The face as a screen reader names it: an <svg> has no name of its own, and an image without one
// is announced as a bare "image" (the announcer's stage, which holds the face, is named by its title).
std::string named_face(const std::string& root) {
    return "<svg role=\"img\" aria-label=\"Talking face\"" + root.substr(4);
}

// A title stands in one line (the announcer's title bar, a heading over the face, a browser's tab):
// taken from a transcript with no punctuation, the first sentence was the whole text, and its title
// bar of 2000 characters covered the stage. Cut between characters, never inside one.
constexpr std::size_t kDefaultTitleCharacters = 30;

std::string default_title(const Timeline& timeline) {
    if (timeline.sentences.empty()) return "talkface";
    const std::string& sentence = timeline.sentences.front().text;
    std::size_t characters = 0;
    for (std::size_t k = 0; k < sentence.size(); ++k) {
        const bool starts_character = (static_cast<unsigned char>(sentence[k]) & 0xC0) != 0x80;
        if (starts_character && ++characters > kDefaultTitleCharacters)
            return sentence.substr(0, k) + "\xE2\x80\xA6";  // U+2026, an ellipsis
    }
    return sentence;
}

std::string without_prolog(std::string svg) {
    if (svg.compare(0, 5, "<?xml") == 0) svg.erase(0, svg.find('\n') + 1);
    return svg;
}

// The page's face and, when its head moves, the face with the head held still (every pose at rest:
// the lips, blinks and brows as they were), which the page shows a reader whose system asks for
// reduced motion (WCAG 2.3.3) without the page's writer having to ask for it. In the keyframes
// encoding the face is drawn at rest and the pose carried apart, in animations the page takes out
// (a still head then costs its lips' and brows' key frames, not a second face); in the frames
// encoding each frame is a drawing of its own, and the still face a second document.
detail::PackedAnimation packed_face(const SvgAnimator& animator, const Animation& animation,
                                    const SvgAnimationOptions& options, const ProgressCallback& progress) {
    Animation still = animation;
    bool moves = false;
    for (FaceState& frame : still.frames) {
        moves = moves || frame.pose != Pose{};
        frame.pose = Pose{};
    }
    if (!moves)
        return detail::pack_animation(
            without_prolog(animator.render_animation_svg(animation, options, progress)), "");
    if (options.encoding == AnimationEncoding::keyframes) {
        const SvgOptions& svg_options = animator.options();
        return detail::pack_animation(
            without_prolog(detail::render_animation_with_pose_apart(
                animator.face(), svg_options,
                detail::face_svg_canvas(animator.face(), svg_options.width_px, svg_options.height_px),
                animation, options, progress)),
            "");
    }
    // Two renderings of about the same work: each reports half of the whole.
    const auto half = [&progress](double start) -> ProgressCallback {
        if (!progress) return {};
        return [&progress, start](double fraction, const std::string& stage) {
            return progress(start + 0.5 * fraction, stage);
        };
    };
    return detail::pack_animation(
        without_prolog(animator.render_animation_svg(animation, options, half(0.0))),
        without_prolog(animator.render_animation_svg(still, options, half(0.5))));
}

}  // namespace

const char* web_page_app_name(WebPageApp app) {
    switch (app) {
        case WebPageApp::plain: return "plain";
        case WebPageApp::announcer: return "announcer";
        case WebPageApp::audiobook: return "audiobook";
    }
    return "unknown";
}

WebPageApp web_page_app_from_name(std::string_view name) {
    if (name == "plain") return WebPageApp::plain;
    if (name == "announcer") return WebPageApp::announcer;
    if (name == "audiobook") return WebPageApp::audiobook;
    throw InvalidArgument("app", "expected plain, announcer or audiobook, found \"" + std::string(name) + "\"");
}

const char* web_page_audio_name(WebPageAudio audio) {
    switch (audio) {
        case WebPageAudio::compressed: return "compressed";
        case WebPageAudio::original: return "original";
        case WebPageAudio::link: return "link";
    }
    return "unknown";
}

WebPageAudio web_page_audio_from_name(std::string_view name) {
    if (name == "compressed") return WebPageAudio::compressed;
    if (name == "original") return WebPageAudio::original;
    if (name == "link") return WebPageAudio::link;
    throw InvalidArgument("audio", "expected compressed, original or link, found \"" + std::string(name) + "\"");
}

std::string build_web_page(const SvgAnimator& animator, const Animation& animation, const Timeline& timeline,
                           const std::string& audio_path, const WebPageOptions& options,
                           const ProgressCallback& progress) {
    validate(options);
    const std::string audio = audio_element(audio_path, options);
    const std::string title = !options.title.empty() ? options.title : default_title(timeline);

    detail::PageParts parts;
    detail::PackedAnimation packed;
    if (options.app == WebPageApp::announcer) {
        // The stage is the background: the face is drawn without its own.
        SvgOptions svg_options = animator.options();
        svg_options.background.reset();
        const SvgAnimator stage_animator(animator.face(), svg_options);
        packed = packed_face(stage_animator, animation, options.animation, progress);
        parts = detail::announcer_page(packed.root, animator.face(), animation, timeline, options, title, audio);
    } else {
        packed = packed_face(animator, animation, options.animation, progress);
        const std::string svg = named_face(packed.root);
        if (options.app == WebPageApp::audiobook) {
            parts = detail::audiobook_page(svg, timeline, options, title, audio);
        } else {
            const detail::StageBox face = detail::root_view_box(packed.root);
            parts.style =
                std::string(":root{color-scheme:light dark}body{margin:0;background:#eef2f6;font-family:") +
                detail::kSansFonts +
                "}"
                // As wide as the face is when it fills the window's height, as a video fills a page
                // that shows nothing else (at 4K, held to 520 px, it stood small in the middle).
                ".tf-plain{max-width:max(520px,calc((100vh - 170px) * " +
                detail::format_fixed(face.width / face.height, 4) +
                " + 32px));margin:24px auto;padding:0 16px}"
                ".tf-plain h1{font-size:1.2rem;color:#334155}"
                // No taller than the window leaves beside the title and the player: on a phone turned
                // on its side (568x320) the face took 580 px and the player lay below the screen.
                "svg.tf-animation{display:block;width:100%;height:auto;max-height:calc(100vh - 170px);"
                "border-radius:8px;background:#fff}"
                "audio{display:block;width:100%;margin-top:12px}"
                // A reader's dark scheme: the page around the face dark (it was white at night); the
                // face keeps its own colours, as a picture does.
                "@media screen and (prefers-color-scheme:dark){body{background:#0f172a;color:#e2e8f0}"
                ".tf-plain h1{color:#cbd5e1}}";
            parts.body = "<main class=\"tf-plain\">\n<h1>" + escape_html(title) + "</h1>\n" + svg + audio + "</main>\n";
        }
    }
    return "<!DOCTYPE html>\n<html lang=\"zh\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
           "<meta name=\"generator\" content=\"talkface\">\n"
           // No icon to ask for: served over HTTP, the browser asked the server for /favicon.ico
           // (twice in Chromium), a request of its own and a 404 in the console on most servers.
           "<link rel=\"icon\" href=\"data:,\">\n<title>" +
           escape_html(title) + "</title>\n<style>" + kCommonStyle + parts.style +
           "</style>\n</head>\n<body class=\"tf-" + web_page_app_name(options.app) + "-page\">\n" +
           parts.body + packed.data + "<script>\n" + detail::after_unpacking(kScript + parts.script) +
           "</script>\n</body>\n</html>\n";
}

void write_web_page(const std::string& path, const SvgAnimator& animator, const Animation& animation,
                    const Timeline& timeline, const std::string& audio_path, const WebPageOptions& options,
                    const ProgressCallback& progress) {
    detail::write_file_atomically(path,
                                  build_web_page(animator, animation, timeline, audio_path, options, progress));
}

}  // namespace v0
}  // namespace talkface
