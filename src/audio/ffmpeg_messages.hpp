// FFmpeg's messages: its log to stderr kept quiet, and its error codes as text for talkface's own
// errors. Here, in the first stage that uses FFmpeg (reading audio), for every later one (video/).
#ifndef TALKFACE_AUDIO_FFMPEG_MESSAGES_HPP
#define TALKFACE_AUDIO_FFMPEG_MESSAGES_HPP

#include <string>

namespace talkface::detail {

// Turns FFmpeg's logging to stderr off if it is at FFmpeg's default level (once per process).
// Called before a stage's first FFmpeg call (opening a file, looking up an encoder).
void quiet_ffmpeg_log();

// av_strerror's text for an FFmpeg return code.
std::string ffmpeg_error_text(int code);

}  // namespace talkface::detail

#endif
