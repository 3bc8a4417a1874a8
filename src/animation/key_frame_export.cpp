// Key frames as JSON and TSV, written by hand: the library has no JSON dependency, and a fixed
// layout with millisecond numbers keeps the output byte-for-byte reproducible (golden tests).
#include <cmath>
#include <string>

#include "common/number_format.hpp"
#include "talkface/animation.hpp"
#include "talkface/errors.hpp"

namespace talkface {
inline namespace v0 {

namespace {

std::string number(double value) {
    return detail::format_fixed(value, 3);
}

// Shape names are "m" .. "h'": nothing in them needs escaping in JSON.
std::string quoted(const char* text) {
    return std::string("\"") + text + "\"";
}

}  // namespace

std::string key_frames_json(const std::vector<MouthKeyFrame>& mouth_key_frames,
                            const std::vector<ExpressionEvent>& events, double fps, double duration_s) {
    if (!std::isfinite(fps) || fps <= 0.0) {
        throw InvalidArgument("fps", "expected a frame rate > 0, got " + std::to_string(fps));
    }
    if (!std::isfinite(duration_s) || duration_s < 0.0) {
        throw InvalidArgument("duration_s", "expected a duration >= 0 s, got " + std::to_string(duration_s));
    }
    std::string json = "{\"fps\":" + number(fps) + ",\"duration\":" + number(duration_s) + ",\n\"mouth\":[";
    for (std::size_t k = 0; k < mouth_key_frames.size(); ++k) {
        const MouthKeyFrame& key = mouth_key_frames[k];
        json += k == 0 ? "\n" : ",\n";
        json += "{\"time\":" + number(key.time_s) + ",\"shape\":" + quoted(mouth_shape_name(key.shape)) +
                ",\"syllable\":" + (key.syllable ? std::to_string(*key.syllable) : std::string("null")) + "}";
    }
    json += "\n],\n\"events\":[";
    for (std::size_t k = 0; k < events.size(); ++k) {
        const ExpressionEvent& event = events[k];
        json += k == 0 ? "\n" : ",\n";
        json += "{\"kind\":" + quoted(expression_event_kind_name(event.kind)) +
                ",\"start\":" + number(event.start_s) + ",\"end\":" + number(event.end_s) +
                ",\"amount\":" + number(event.amount) + "}";
    }
    json += "\n]}\n";
    return json;
}

std::string key_frames_tsv(const std::vector<MouthKeyFrame>& mouth_key_frames) {
    std::string tsv;
    for (const MouthKeyFrame& key : mouth_key_frames) {
        tsv += number(key.time_s) + "\t" + mouth_shape_name(key.shape) + "\n";
    }
    return tsv;
}

}  // namespace v0
}  // namespace talkface
