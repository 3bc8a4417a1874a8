#include "timing/rhubarb_cues.hpp"

#include <cmath>
#include <string>

#include "talkface/errors.hpp"

namespace talkface::detail {

char rhubarb_letter(const MouthKeyFrame& key_frame) {
    // A key frame of no syllable is the mouth at rest: Rhubarb's idle X, not its talking A.
    if (!key_frame.syllable) return 'X';
    // docs/timing-formats.md, "Mouth shapes in Rhubarb's letters": each shape where Rhubarb's
    // README puts the English sounds that look like it.
    switch (key_frame.shape) {
        case MouthShape::m: return 'A';        // b p m: lips pressed together
        case MouthShape::f: return 'G';        // f: upper teeth on the lower lip
        case MouthShape::h_prime: return 'B';  // d t n l j q x: teeth nearly closed, as Rhubarb's T, D
        case MouthShape::h: return 'C';        // g k h, the e of de, er, eng: open, unrounded
        case MouthShape::r: return 'B';        // zh ch sh r: teeth together, as Rhubarb's CH, SH
        case MouthShape::z: return 'B';        // z c s: clenched teeth, as Rhubarb's S
        case MouthShape::a: return 'D';        // a: wide open, as Rhubarb's AA
        case MouthShape::i: return 'B';        // i: spread, teeth nearly closed, as Rhubarb's EE
        case MouthShape::u: return 'F';        // u, ü: puckered, as Rhubarb's UW
        case MouthShape::e: return 'C';        // ê of ie, ue, ei: open, as Rhubarb's EH
        case MouthShape::o: return 'E';        // o: slightly rounded, as Rhubarb's AO
        case MouthShape::n: return 'H';        // final n: tongue behind the upper teeth, as Rhubarb's L
    }
    return 'X';
}

long rhubarb_end_cs(double duration_s) {
    // A hair of tolerance, so that 0.47 s read from a file (0.46999999...) stays 47 cs.
    return static_cast<long>(std::floor(duration_s * 100.0 + 1e-6));
}

std::vector<RhubarbCue> rhubarb_cues(const ExportInput& input) {
    const long end_cs = rhubarb_end_cs(input.timeline.duration_s);
    if (!(input.timeline.duration_s > 0.0) || end_cs < 1) {
        throw InvalidArgument("timeline.duration_s", "expected the audio's length, at least 0.01 s, found " +
                                                         std::to_string(input.timeline.duration_s));
    }
    std::vector<RhubarbCue> cues;
    cues.push_back({0, end_cs, 'X'});  // Rhubarb's first cue always starts at 0.00
    double previous_time_s = -1.0;
    for (std::size_t k = 0; k < input.mouth_key_frames.size(); ++k) {
        const MouthKeyFrame& key_frame = input.mouth_key_frames[k];
        if (!(key_frame.time_s > previous_time_s)) {
            throw InvalidArgument("mouth_key_frames", "key frame " + std::to_string(k) + " at " +
                                                          std::to_string(key_frame.time_s) +
                                                          " s does not come after the one before it");
        }
        previous_time_s = key_frame.time_s;
        const long start_cs = std::lround(key_frame.time_s * 100.0);
        if (start_cs >= end_cs) break;
        const char letter = rhubarb_letter(key_frame);
        if (start_cs <= cues.back().start_cs) {
            cues.back().letter = letter;  // two key frames in one centisecond: the later one shows
        } else {
            cues.push_back({start_cs, end_cs, letter});
        }
    }
    std::vector<RhubarbCue> joined;
    for (const RhubarbCue& cue : cues) {
        if (!joined.empty() && joined.back().letter == cue.letter) continue;
        joined.push_back(cue);
    }
    for (std::size_t k = 0; k + 1 < joined.size(); ++k) joined[k].end_cs = joined[k + 1].start_cs;
    joined.back().end_cs = end_cs;
    return joined;
}

std::string rhubarb_seconds(long centiseconds) {
    const std::string fraction = std::to_string(centiseconds % 100);
    return std::to_string(centiseconds / 100) + "." + (fraction.size() < 2 ? "0" : "") + fraction;
}

}  // namespace talkface::detail
