// talkface: the web page around a talking face (thesis 6.3.2 and chapter 7): the animation inline,
// an <audio> element whose clock drives it, and the two applications, the virtual announcer and
// the audio book.
//
//   talkface::WebPageOptions page;
//   page.app = talkface::WebPageApp::audiobook;
//   page.title = "春曉";
//   talkface::write_web_page("book.html", talkface::SvgAnimator(face), animation, timeline,
//                            "speech.wav", page);
//
// The page is one self-contained HTML file that works from a file:// URL with no network: the SVG
// (packed with gzip, which the page's script unpacks with DecompressionStream: Chromium 80,
// Firefox 113, Safari 16.4), the style and the script are inline, the audio is embedded as a data:
// URI (compressed for speech, or the file's own bytes) or linked. The
// script pauses the SVG's own timeline and sets its time from audio.currentTime on every animation
// frame, so play, pause, seek, playback rate and the end keep face and voice together. A URL
// fragment "#t=SECONDS" seeks there once the audio is ready; "#t=SECONDS&pause" also stays paused.
// A reader whose system asks for reduced motion (prefers-reduced-motion, WCAG 2.3.3) sees the head
// held still, the lips, blinks and brows moving on: the page carries the animation a second time
// with every pose at rest (about a seventh more page a minute) when the head moves at all.
//
// Every text that comes from the caller (title, transcript, links) is escaped: no input can add
// markup or script to the page. Functions here are pure and may be called from several threads.
#ifndef TALKFACE_WEB_PAGE_HPP
#define TALKFACE_WEB_PAGE_HPP

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "talkface/animation.hpp"
#include "talkface/export.h"
#include "talkface/svg_animator.hpp"
#include "talkface/timeline.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// What the page is for. The numeric values are stable within a major version.
enum class WebPageApp : int {
    plain = 0,      ///< the talking face and the audio controls
    announcer = 1,  ///< thesis 7.2: the face placed on a stage with a background (colour or image)
    audiobook = 2,  ///< thesis 7.3: title, the text with the spoken sentence highlighted, links, the face
};

/// "plain", "announcer", "audiobook".
TALKFACE_API const char* web_page_app_name(WebPageApp app);
/// Parses a name as web_page_app_name() writes it.
/// \throws talkface::InvalidArgument listing the valid names.
TALKFACE_API WebPageApp web_page_app_from_name(std::string_view name);

/// How the page carries its audio. The numeric values are stable within a major version.
enum class WebPageAudio : int {
    /// Embedded, encoded anew for speech: Opus in WebM, mono, WebPageOptions::audio_bitrate_bps
    /// (11 kb/s by default, about 97 KiB a minute in the page). Opus in WebM plays in Chromium,
    /// Firefox and Safari 17.4 and later (iOS too); Opus in Ogg not in Safari before 18.4.
    compressed = 0,
    original = 1,  ///< embedded as the file's own bytes (.ogg .oga .opus .wav .flac .mp3 .m4a)
    link = 2,      ///< linked as audio_url: the audio file must stay beside the page
};

/// "compressed", "original", "link".
TALKFACE_API const char* web_page_audio_name(WebPageAudio audio);
/// Parses a name as web_page_audio_name() writes it.
/// \throws talkface::InvalidArgument listing the valid names.
TALKFACE_API WebPageAudio web_page_audio_from_name(std::string_view name);

/// A link of the audio book's page.
struct WebLink {
    std::string text;  ///< what the reader sees
    std::string url;   ///< http:, https:, mailto: or a relative URL; other schemes are refused
};

/// How the page is built. Sizes are CSS pixels.
struct WebPageOptions {
    WebPageApp app = WebPageApp::plain;
    /// The page's title (and the audio book's heading); empty: the first sentence of the timeline,
    /// its first 30 characters and an ellipsis when longer (a title stands in one line).
    std::string title;
    std::vector<WebLink> links;  ///< audio book: listed under the text
    SvgAnimationOptions animation;  ///< the encoding of the face's animation

    /// How the audio is carried: compressed and embedded (the default), its own bytes embedded, or linked.
    WebPageAudio audio = WebPageAudio::compressed;
    /// compressed: the Opus bit rate, bits per second, 6000 to 128000; 0: 11000, a clear voice
    /// (wideband speech, as on a good phone call; music and noise suffer first).
    int audio_bitrate_bps = 0;
    /// The link written when audio is link, relative to the page (e.g. "speech.ogg"); empty: the
    /// audio file's name. Percent-encoded as needed.
    std::string audio_url;

    /// Announcer: the stage's size (its shape, and the pixels face_origin_px and face_d_px are in:
    /// the page shows it as large as the window lets it and the player under it be, as a video),
    /// and what is behind the face: a colour, or an image file (PNG, JPEG, GIF, WebP or SVG,
    /// embedded) scaled to cover the stage.
    int stage_width_px = 800;
    int stage_height_px = 450;
    Rgb stage_colour{0x1d, 0x3b, 0x5c};
    std::string background_image_path;
    /// Announcer: where the face's rotation origin O (the neck) stands on the stage, and its eye
    /// distance d there; the face is moved and scaled with them (thesis 7.2.3). Unset: the face
    /// stands at the stage's bottom centre, as large as fits its height.
    std::optional<Point2> face_origin_px;
    double face_d_px = 0.0;  ///< 0: as large as fits the stage's height
};

/// The page, as a UTF-8 HTML document. `audio_path` is read: compressed, any audio file
/// SpeechAligner::align_file reads; embedded as it is or linked, its type is told by its extension
/// (.ogg .oga .opus .wav .flac .mp3 .m4a).
/// `timeline` gives the sentences and their times (the audio book's text); `animation` was made
/// from it with `animator`'s face.
/// \throws talkface::FileError if the audio or the background image cannot be read;
///         talkface::ParseError if compressed audio cannot be decoded;
///         talkface::InvalidArgument naming the option that is out of range, a link whose URL has a
///         refused scheme, or an audio file of unknown type; and as render_animation_svg().
TALKFACE_API std::string build_web_page(const SvgAnimator& animator, const Animation& animation,
                                        const Timeline& timeline, const std::string& audio_path,
                                        const WebPageOptions& options = {},
                                        const ProgressCallback& progress = {});

/// Writes build_web_page() to `path` through a temporary file and a rename: a failure never leaves
/// half a page, and an existing file at `path` is kept until the new page is whole.
/// \throws talkface::FileError if it cannot be written, and as build_web_page().
TALKFACE_API void write_web_page(const std::string& path, const SvgAnimator& animator,
                                 const Animation& animation, const Timeline& timeline,
                                 const std::string& audio_path, const WebPageOptions& options = {},
                                 const ProgressCallback& progress = {});

}  // namespace v0
}  // namespace talkface

#endif
