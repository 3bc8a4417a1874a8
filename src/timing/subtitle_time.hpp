// Subtitle clock times: "00:01:02,345" (SubRip) and "00:01:02.345" (WebVTT), milliseconds.
#ifndef TALKFACE_TIMING_SUBTITLE_TIME_HPP
#define TALKFACE_TIMING_SUBTITLE_TIME_HPP

#include <optional>
#include <string>
#include <string_view>

namespace talkface::detail {

// `seconds` rounded to the millisecond as HH:MM:SS<separator>mmm.
std::string subtitle_time(double seconds, char separator);

// Reads HH:MM:SS<separator>mmm (WebVTT also allows MM:SS.mmm); nullopt if `text` is not one.
std::optional<double> parse_subtitle_time(std::string_view text, char separator);

}  // namespace talkface::detail

#endif
