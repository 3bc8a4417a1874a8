// Mouth key frames of a timeline (thesis 5.4): each syllable's shapes at their onsets, the neutral
// mouth in pauses, the audio's loudness where the speech does not say the text, all placed on
// frames.
#include <algorithm>
#include <cmath>
#include <string>

#include "animation/lip_sync_checks.hpp"
#include "animation/loudness_mouth.hpp"
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

// The stretches whose mouth follows the loudness (TextMismatch::loudness), and whether each
// syllable is one of theirs: its shapes would mouth the text where the speech says something else.
struct LoudnessStretches {
    std::vector<const TextMismatch*> stretches;
    std::vector<bool> is_covered;  // per syllable
};

LoudnessStretches loudness_stretches(const Timeline& timeline) {
    LoudnessStretches found{{}, std::vector<bool>(timeline.syllables.size(), false)};
    for (const TextMismatch& mismatch : timeline.mismatches) {
        if (mismatch.loudness.empty()) continue;
        found.stretches.push_back(&mismatch);
        for (std::size_t i = mismatch.first_syllable; i < mismatch.first_syllable + mismatch.syllable_count; ++i)
            found.is_covered[i] = true;
    }
    return found;
}

bool is_inside_stretch(const LoudnessStretches& found, double time_s) {
    return std::any_of(found.stretches.begin(), found.stretches.end(),
                       [&](const TextMismatch* m) { return m->start_s < time_s && time_s < m->end_s; });
}

// Key frames placed on frames of `fps`, so that every shape kept is shown whole on one frame.
std::vector<MouthKeyFrame> on_frames(std::vector<MouthKeyFrame> placed, double fps) {
    std::stable_sort(placed.begin(), placed.end(),
                     [](const MouthKeyFrame& a, const MouthKeyFrame& b) { return a.time_s < b.time_s; });
    std::vector<MouthKeyFrame> keys;
    long long last_frame = -1;
    for (MouthKeyFrame key : placed) {
        const long long frame = std::llround(key.time_s * fps);
        key.time_s = static_cast<double>(frame) / fps;
        if (!keys.empty() && frame == last_frame) {
            if (keep_priority(key) > keep_priority(keys.back())) keys.back() = key;
            continue;
        }
        keys.push_back(key);
        last_frame = frame;
    }
    return keys;
}

}  // namespace

std::vector<MouthKeyFrame> mouth_key_frames(const Timeline& timeline, const LipSyncOptions& options) {
    detail::check_lip_sync_options(options);
    detail::check_timeline(timeline);
    const auto& syllables = timeline.syllables;
    std::vector<MouthKeyFrame> placed{{0.0, MouthShape::m, std::nullopt}};
    const LoudnessStretches loud = loudness_stretches(timeline);
    const double lead_s = options.rest_transition_s;
    if (!syllables.empty() && syllables.front().start_s - lead_s > 0.0) {
        placed.push_back({syllables.front().start_s - lead_s, MouthShape::m, std::nullopt});
    }
    for (std::size_t k = 0; k < syllables.size(); ++k) {
        const Syllable& syllable = syllables[k];
        if (!loud.is_covered[k]) {
            SyllableShapes shapes;
            try {
                shapes = syllable_shapes(syllable.pinyin);
            } catch (const InvalidArgument& error) {
                throw InvalidArgument(detail::describe_syllable(timeline, k), error.what());
            }
            const std::vector<double> onsets = shape_onsets_s(syllable, shapes, options.onsets);
            for (std::size_t j = 0; j < onsets.size(); ++j) placed.push_back({onsets[j], shapes.shapes[j], k});
        }
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
    // Inside a stretch the loudness decides alone: the rests the syllables' gaps ask for go.
    placed.erase(std::remove_if(placed.begin() + 1, placed.end(),
                                [&](const MouthKeyFrame& key) { return is_inside_stretch(loud, key.time_s); }),
                 placed.end());
    for (const TextMismatch* mismatch : loud.stretches) {
        const auto keys = detail::loudness_key_frames(timeline, *mismatch, options.fps);
        placed.insert(placed.end(), keys.begin(), keys.end());
        // Speech after the last syllable: no syllable's rest follows it.
        if (syllables.empty() || mismatch->end_s >= syllables.back().end_s)
            placed.push_back({mismatch->end_s + lead_s, MouthShape::m, std::nullopt});
    }
    return on_frames(std::move(placed), options.fps);
}

}  // namespace v0
}  // namespace talkface
