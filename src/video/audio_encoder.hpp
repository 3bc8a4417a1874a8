// Speech as a compressed audio file, in memory or on disk: Opus in Ogg or WebM, AAC in MP4. The
// web pages embed it (apps/: Opus in WebM at 11 kb/s, about 97 KiB a minute in base64), not a
// WAV's megabytes. What plays where (Chromium 156 headless: tests/video/test_browser_audio.py plays
// each; the rest from MDN's "Web audio codec guide" and caniuse's issues #6805 and #6997):
//   Opus in Ogg   Chromium, Firefox; Safari only from 18.4 (macOS 15.4, iOS 18.4: caniuse pull
//                 request #7284, MDN pull request #39592)
//   Opus in WebM  Chromium, Firefox; Safari from 17 on macOS, 17.4 on iOS (Apple's release notes,
//                 caniuse pull request #7074; 17.4 could not play it from a blob, fixed in 17.5)
//   AAC in MP4    Chromium, Firefox (through the system's decoder), Safari, every phone
// so the pages embed Opus in WebM: it plays in all three (Safari 17.4+), and FFmpeg's AAC-LC needs
// several times Opus's bit rate for a voice (no HE-AAC encoder in Debian's FFmpeg).
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
    // Opus only: a voice at a low bit rate (the pages' 11 kb/s), coded for intelligibility in
    // long packets, whose container overhead would otherwise be a quarter of the stream.
    bool low_rate_speech = false;
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
