// Audio files libsndfile does not read, or reads wrongly, through FFmpeg's libraries: MP3 (whose
// length libsndfile only estimates, bare or inside a WAV), AAC/M4A, Opus, AC-3, and the sound track
// of a video file (MP4, MOV, MKV, WebM, MPEG-TS, MPEG). Decoded one packet at a time; only
// src/audio/ sees FFmpeg's types (issue #13).
#ifndef TALKFACE_AUDIO_FFMPEG_SOURCE_HPP
#define TALKFACE_AUDIO_FFMPEG_SOURCE_HPP

#include <cstdint>
#include <memory>
#include <string>

#include "audio/audio_source.hpp"

namespace talkface::detail {

// What a caller knows of the file before FFmpeg opens it.
struct FfmpegReading {
    // The file is known to be damaged inside (an Ogg page that fails its check): sound lost at its
    // end is kept as silence up to the length its container states, as sound lost before the end
    // is, rather than called a cut file, and sound lost at its start from time 0 (where Ogg's
    // granule positions begin) to its first page read.
    bool keeps_stated_length = false;
    // The file is a WAV whose data chunk goes on past the size its header states (a header
    // written early and never brought up to date): read to the end of the file.
    bool reads_past_stated_size = false;
    // Where an Ogg page begins whose header claims more bytes than the file holds, with whole pages
    // after it (a scratch in its segment table); -1 if none. FFmpeg's Ogg reader would wait for the
    // page to the end of the file and stop there (its 2 s after it lost, the file's length stated
    // as 1 s): the page's capture pattern is hidden from it, and it goes on at the next page.
    std::int64_t overlong_ogg_page_byte = -1;
    // Where the first damaged page of an Ogg file begins; -1 if none known. A file whose header
    // pages are damaged there ends, to FFmpeg, before any sound, as a cut file does: it was called
    // truncated, which a file of its whole length is not.
    std::int64_t damaged_ogg_page_byte = -1;
};

// Opens the audio stream FFmpeg would play in `path` (of several, the one that sounds like speech:
// its notes() say which) and decodes its first samples, so that a file with no sound at all is
// refused here rather than part way through the alignment. frame_count() is the container's
// estimate; read() goes on to the real end.
// \throws talkface::ParseError naming the file and the reason: not a format talkface reads, a video
//         without a sound track, a codec FFmpeg cannot decode; talkface::FileError if it cannot be
//         opened; talkface::InvalidArgument if it decodes to no samples.
std::unique_ptr<AudioSource> open_ffmpeg_file(const std::string& path, const FfmpegReading& reading = {});

// Whether open_ffmpeg_file can be called: inside the FFmpeg module (and a program linking FFmpeg's
// files, as the fuzz targets do) always; in libtalkface, whether the module loads (ffmpeg_module.cpp).
// A file libsndfile reads too (Ogg Opus) is libsndfile's where the module is missing.
bool ffmpeg_is_loadable();

}  // namespace talkface::detail

#endif
