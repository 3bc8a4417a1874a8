// Speech as a compressed audio file, in memory or on disk: Opus in Ogg or WebM, AAC in MP4. The
// web pages embed it (apps/), so a page carries a few hundred kilobytes a minute, not a WAV's
// megabytes. What plays where (checked in Chromium 156 headless, the rest from MDN's "Media
// container formats" and "Web audio codec guide"; tests/video/test_browser_audio.py plays each):
//   Opus in Ogg   Chromium, Firefox; Safari only from 18.4 (macOS 15.4 / iOS 18.4)
//   Opus in WebM  Chromium, Firefox; Safari from 15 (macOS 12)
//   AAC in MP4    Chromium, Firefox (through the system's decoder), Safari, every phone
// so a page that must play everywhere offers AAC in MP4, or Opus in WebM with an MP4 fallback.
#ifndef TALKFACE_VIDEO_AUDIO_ENCODER_HPP
#define TALKFACE_VIDEO_AUDIO_ENCODER_HPP

#include <string>
#include <string_view>

#include "audio/audio_source.hpp"
#include "talkface/speech_aligner.hpp"

namespace talkface::detail {

enum class AudioContainer {
    ogg_opus,   // .ogg (.opus), audio/ogg
    webm_opus,  // .webm, audio/webm
    mp4_aac,    // .m4a, audio/mp4
};

struct AudioEncodeOptions {
    AudioContainer container = AudioContainer::ogg_opus;
    // Bits per second; 0: 48 kb/s for Opus, 96 kb/s for AAC (mono speech).
    int bitrate_bps = 0;
};

// The MIME type with its codecs parameter, for a data: URI or a <source type>: "audio/ogg; codecs=opus",
// "audio/webm; codecs=opus", "audio/mp4; codecs=mp4a.40.2".
const char* audio_container_mime_type(AudioContainer container);
// The file extension, dot included: ".ogg", ".webm", ".m4a".
const char* audio_container_extension(AudioContainer container);

// `audio` (mixed down to mono, resampled to 48 kHz) as the bytes of a whole file.
// \throws talkface::InvalidArgument if the system's FFmpeg lacks the encoder (naming it) or the
//         audio is malformed; what `audio`'s reads throw (FileError for a truncated file).
std::string encode_audio(AudioSource& audio, const AudioEncodeOptions& options);
// The same from samples the caller holds. \throws as above and as open_audio_view().
std::string encode_audio(const AudioView& audio, const AudioEncodeOptions& options);
// The same from an audio file (as open_audio_file() reads it).
std::string encode_audio_file(const std::string& audio_path, const AudioEncodeOptions& options);

// Writes encode_audio() to `path` through a temporary file and a rename: a failure leaves no
// partial file. An MP4 has its index in front (faststart), so it plays while it downloads.
// \throws talkface::FileError if it cannot be written, and as encode_audio().
void write_encoded_audio(const std::string& path, AudioSource& audio, const AudioEncodeOptions& options);

}  // namespace talkface::detail

#endif
