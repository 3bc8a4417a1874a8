// talkface: lip movement (thesis chapter 5, SPEC "Mouth shapes"): a pinyin syllable becomes 1 to 4
// of the 12 basic mouth shapes, the shapes become key frames inside the syllable, and the key frames
// become the mouth of every frame.
//
// All functions here are pure: same input, same output, on every platform; safe to call from
// several threads at once.
#ifndef TALKFACE_LIP_SYNC_HPP
#define TALKFACE_LIP_SYNC_HPP

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "talkface/export.h"
#include "talkface/face_model.hpp"
#include "talkface/mouth_shape.hpp"
#include "talkface/timeline.hpp"

namespace talkface {
inline namespace v0 {

/// A syllable's mouth shapes, and whether the first one is its initial consonant's.
struct SyllableShapes {
    std::vector<MouthShape> shapes;  ///< 1 to 4 shapes, in the order they are shown
    /// True when shapes[0] is the initial consonant's shape (m f h' h r z); false for a syllable
    /// with no initial, or whose h' / h was dropped before i, u, e or o. Only then can the
    /// aligner's final_start_s move the second shape.
    bool has_initial_shape = false;
    friend bool operator==(const SyllableShapes& a, const SyllableShapes& b) {
        return a.shapes == b.shapes && a.has_initial_shape == b.has_initial_shape;
    }
    friend bool operator!=(const SyllableShapes& a, const SyllableShapes& b) { return !(a == b); }
};

/// The mouth shapes of one Mandarin syllable (SPEC "Mouth shapes", thesis 5.2.2), e.g. "bo" -> m u o,
/// "xian" -> i e n, "guo" -> u o, "hao" -> h a u, "zhi" -> r i.
///
/// `pinyin` is numbered ("lv4", "hang2", "ma5") or toneless ("lv", "hang"): one trailing tone digit
/// 0-5 is ignored, ASCII case is ignored, u-umlaut may be written v, "u:" or "ü", and after j q x y
/// it is written u as usual. Besides the ~410 ordinary syllables, the interjections m, hm, n, ng,
/// hng, ê and the erhua "r" are accepted (docs: m and hm show m; n shows n; ng, hng and r show h).
/// \throws talkface::InvalidArgument naming the syllable if it is not a Mandarin syllable.
TALKFACE_API SyllableShapes syllable_shapes(std::string_view pinyin);

/// syllable_shapes(pinyin).shapes.
/// \throws talkface::InvalidArgument naming the syllable if it is not a Mandarin syllable.
TALKFACE_API std::vector<MouthShape> syllable_mouth_shapes(std::string_view pinyin);

/// Every toneless syllable syllable_shapes() accepts, u-umlaut written v ("lv", "nve"), ê as "ê",
/// sorted by byte value. The ordinary syllables are those Unihan's readings use.
TALKFACE_API const std::vector<std::string>& mandarin_syllables();

/// When the later shapes of a syllable start, as fractions of its duration T (thesis 5.3, read as
/// SPEC says: the percentages are the shares the later shapes hold). The first shape starts with
/// the syllable. Replace the table to retime every syllable; each row must rise strictly inside
/// (0, 1).
struct ShapeOnsetTable {
    std::array<double, 1> two_shapes{0.1905};                   ///< second shape holds 80.95% of T
    std::array<double, 2> three_shapes{0.1688, 0.6025};         ///< 43.37% and 39.75% of T
    std::array<double, 3> four_shapes{0.2847, 0.5297, 0.7412};  ///< 24.5%, 21.15%, 25.88% of T
};

/// Onset of each of `shapes` inside `syllable`, seconds, one per shape, rising. From the table;
/// but when the syllable's final_start_s lies strictly inside it and shapes[0] is the initial's,
/// the second shape (the vowel) starts at final_start_s and the later ones keep the table's
/// proportions of what is left of the syllable.
/// \throws talkface::InvalidArgument naming the table row if a row does not rise inside (0, 1),
///         or naming the syllable if it has no shapes or more than 4, or its times are not
///         finite or end before they start.
TALKFACE_API std::vector<double> shape_onsets_s(const Syllable& syllable, const SyllableShapes& shapes,
                                                const ShapeOnsetTable& table = {});

/// One mouth key frame: the mouth reaches `shape` at `time_s`.
struct MouthKeyFrame {
    double time_s = 0.0;
    MouthShape shape = MouthShape::m;
    /// Index into Timeline::syllables of the syllable the shape belongs to; nullopt for the
    /// neutral mouth (m) of a pause, before the first or after the last syllable.
    std::optional<std::size_t> syllable;
    friend bool operator==(const MouthKeyFrame& a, const MouthKeyFrame& b) {
        return a.time_s == b.time_s && a.shape == b.shape && a.syllable == b.syllable;
    }
    friend bool operator!=(const MouthKeyFrame& a, const MouthKeyFrame& b) { return !(a == b); }
};

/// How the mouth moves between two key frames.
enum class MouthInterpolation : int {
    linear = 0,  ///< straight lines between key frames, as the thesis (5.4)
    smooth = 1,  ///< cosine ease in and out: (1 - cos(pi u)) / 2 of the way at fraction u
};

/// Options of the lip movement. The defaults are documented choices (the thesis gives none).
struct LipSyncOptions {
    /// Frames per second. Key frames are placed on frames, so that each shape is shown whole on
    /// at least one frame; shapes that would share a frame are merged (a closure m / f wins).
    double fps = 25.0;
    ShapeOnsetTable onsets;  ///< timing inside a syllable
    /// A gap between syllables at least this long is a pause: the mouth rests (shape m) in it.
    /// Shorter gaps, the syllables of a phrase, never close the mouth unless a shape does.
    double rest_min_pause_s = 0.3;
    /// The mouth reaches rest this long after the last syllable before a pause ends, and leaves it
    /// this long before the next syllable starts (at most half the pause each).
    double rest_transition_s = 0.1;
    MouthInterpolation interpolation = MouthInterpolation::linear;
    /// No mouth control point (8.9, 8.2, 8.4, 8.3, hence the jaw 2.1) moves faster than this,
    /// in MNS0 (mouth-nose separation) per second: 8.75 is 0.35 MNS0 per frame at 25 fps, about
    /// the distance from m to a (0.8 MNS0) in 90 ms.
    double max_speed_mns0_per_s = 8.75;
};

/// The mouth key frames of a timeline, in strictly rising time, each on a frame (a multiple of
/// 1 / fps): neutral (m) at 0 and in pauses, then each syllable's shapes at their onsets. Over a
/// stretch where the speech does not say the text (a Timeline::mismatches entry with a loudness),
/// the mouth follows the audio's loudness instead: on each frame the shape of its loudness (the
/// mean of the values within half a frame of it), closed (m) under 0.1, then z from 0.1, n from
/// 0.35, and a from 0.67 up, a key frame where the shape changes and where a
/// run of one shape ends, naming the mismatch's syllable whose span holds it (or none); the
/// shapes of that mismatch's syllables and the rests of pauses inside the stretch are left out.
/// \throws talkface::InvalidArgument naming the syllable (index, pinyin, times) if its pinyin is
///         not Mandarin, its times are not finite, it ends before it starts or starts before the
///         syllable before it; naming the mismatch if its times are not finite, it stands for
///         syllables past the last or its loudness leaves 0..1; or naming the option that is out
///         of range.
TALKFACE_API std::vector<MouthKeyFrame> mouth_key_frames(const Timeline& timeline,
                                                         const LipSyncOptions& options = {});

/// The mouth control points of frames 0 .. frame_count - 1 (frame i shows time i / fps): key
/// frames interpolated, then limited to max_speed_mns0_per_s. A key frame showing a closed mouth
/// (m or f: b p m f, and rests) is held exactly on its frame: the frames before it start closing
/// early enough, so no closure is ever lost to the speed limit.
/// \throws talkface::InvalidArgument naming the option that is out of range, or if the key
///         frames are not in rising time.
TALKFACE_API std::vector<MouthControls> mouth_frames(const FaceModel& neutral,
                                                     const std::vector<MouthKeyFrame>& key_frames,
                                                     std::size_t frame_count,
                                                     const LipSyncOptions& options = {});

}  // namespace v0
}  // namespace talkface

#endif
