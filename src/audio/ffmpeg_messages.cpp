#include "audio/ffmpeg_messages.hpp"

#include <mutex>

extern "C" {
#include <libavutil/error.h>
#include <libavutil/log.h>
}

namespace talkface::detail {

void quiet_ffmpeg_log() {
    // The library prints nothing (STYLE.md section 3), but FFmpeg logs to stderr unless told
    // otherwise, and its level is one setting for the whole process. Only FFmpeg's default is
    // changed, once: a program that set its own level keeps it. Failures still reach the caller,
    // as exceptions carrying av_strerror's text.
    static std::once_flag once;
    std::call_once(once, [] {
        if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_QUIET);
    });
}

std::string ffmpeg_error_text(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

}  // namespace talkface::detail
