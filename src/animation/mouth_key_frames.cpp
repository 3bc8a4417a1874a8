// Mouth key frames of a timeline (thesis 5.4): each syllable's shapes at their onsets, the neutral
// mouth in pauses, all placed on frames.
#include <algorithm>
#include <cmath>
#include <string>

#include "animation/lip_sync_checks.hpp"
#include "common/number_format.hpp"
#include "timing/timeline_checks.hpp"
#include "talkface/errors.hpp"
#include "talkface/lip_sync.hpp"

namespace talkface {

namespace detail {

void check_lip_sync_options(const LipSyncOptions& options) {
    auto require = [](bool is_ok, const char* field, double value, const char* expected) {
        if (!is_ok) {
            throw InvalidArgument(std::string("LipSyncOptions::") + field,
                                  std::string("expected ") + expected + ", got " + format_shortest(value));
        }
    };
    require(std::isfinite(options.fps) && options.fps > 0.0 && options.fps <= 1000.0, "fps", options.fps,
            "frames per second in (0, 1000]");
    require(std::isfinite(options.rest_min_pause_s) && options.rest_min_pause_s >= 0.0, "rest_min_pause_s",
            options.rest_min_pause_s, "seconds >= 0");
    require(std::isfinite(options.rest_transition_s) && options.rest_transition_s >= 0.0, "rest_transition_s",
            options.rest_transition_s, "seconds >= 0");
    require(std::isfinite(options.max_speed_mns0_per_s) && options.max_speed_mns0_per_s > 0.0,
            "max_speed_mns0_per_s", options.max_speed_mns0_per_s, "MNS0 per second > 0");
    const auto interpolation = static_cast<int>(options.interpolation);
    require(interpolation == 0 || interpolation == 1, "interpolation", interpolation, "linear or smooth");
}

}  // namespace detail

inline namespace v0 {

namespace {

// Which of two key frames landing on one frame stays: a closure of the lips (b p m f) is never
// dropped, a syllable's shape beats the resting mouth, and otherwise the earlier one stays.
int keep_priority(const MouthKeyFrame& key) {
    if (!key.syllable) return 1;
    return detail::is_closed_mouth(key.shape) ? 3 : 2;
}

}  // namespace

std::vector<MouthKeyFrame> mouth_key_frames(const Timeline& timeline, const LipSyncOptions& options) {
    detail::check_lip_sync_options(options);
    detail::check_timeline(timeline);
    const auto& syllables = timeline.syllables;
    std::vector<MouthKeyFrame> placed{{0.0, MouthShape::m, std::nullopt}};
    if (syllables.empty()) return placed;

    const double lead_s = options.rest_transition_s;
    if (syllables.front().start_s - lead_s > 0.0) {
        placed.push_back({syllables.front().start_s - lead_s, MouthShape::m, std::nullopt});
    }
    for (std::size_t k = 0; k < syllables.size(); ++k) {
        const Syllable& syllable = syllables[k];
        SyllableShapes shapes;
        try {
            shapes = syllable_shapes(syllable.pinyin);
        } catch (const InvalidArgument& error) {
            throw InvalidArgument(detail::describe_syllable(timeline, k), error.what());
        }
        const std::vector<double> onsets = shape_onsets_s(syllable, shapes, options.onsets);
        for (std::size_t j = 0; j < onsets.size(); ++j) placed.push_back({onsets[j], shapes.shapes[j], k});

        if (k + 1 == syllables.size()) {
            placed.push_back({syllable.end_s + lead_s, MouthShape::m, std::nullopt});
        } else {
            const double gap_s = syllables[k + 1].start_s - syllable.end_s;
            if (gap_s >= options.rest_min_pause_s) {
                const double transition_s = std::min(lead_s, gap_s / 2.0);
                placed.push_back({syllable.end_s + transition_s, MouthShape::m, std::nullopt});
                placed.push_back({syllables[k + 1].start_s - transition_s, MouthShape::m, std::nullopt});
            }
        }
    }
    std::stable_sort(placed.begin(), placed.end(),
                     [](const MouthKeyFrame& a, const MouthKeyFrame& b) { return a.time_s < b.time_s; });

    // On frames, so that every shape kept is shown whole on one frame.
    std::vector<MouthKeyFrame> keys;
    long long last_frame = -1;
    for (MouthKeyFrame key : placed) {
        const long long frame = std::llround(key.time_s * options.fps);
        key.time_s = static_cast<double>(frame) / options.fps;
        if (!keys.empty() && frame == last_frame) {
            if (keep_priority(key) > keep_priority(keys.back())) keys.back() = key;
            continue;
        }
        keys.push_back(key);
        last_frame = frame;
    }
    return keys;
}

}  // namespace v0
}  // namespace talkface
