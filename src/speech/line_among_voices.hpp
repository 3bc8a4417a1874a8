// A line said among quieter voices (issues 12 and 13): other people talking 10-20 dB under a
// short line (babble) fill the recording from its first frame to its last, so the profile finds
// no pause before or after the line and its syllables were spread from the recording's start
// (bench/README.md, session 28: babble's first syllable 128 ms early in tuning, p-babble's 28 ms)
// or drawn out to its end (session 33: the last 180-630 ms late in 11 of babble's 38 tuning lines).
// The line is its speaker's loud voice; sound before or after it that never comes near that level
// is not the line's. A phone's gain lifts the voices before a short line toward it (p-vfast-combo:
// the line's first syllable 420 ms early, session 33), and the line's voicing still stands over them.
#ifndef TALKFACE_SPEECH_LINE_AMONG_VOICES_HPP
#define TALKFACE_SPEECH_LINE_AMONG_VOICES_HPP

#include <cstddef>
#include <optional>

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// Where the line of `syllables` syllables lies inside `speech` (the recording's speech as
// measure_loudness finds it in `loudness`): from the foot of the rise to the foot of the fall of
// the run of frames whose activity stands most above kUnspokenSpeechBelowDb under the speech's
// loud level in sum, and of every frame within kNearLoudVoiceDb of that level (the line's own
// syllables a dip parts from the run; the other voices never come so near). An edge of `speech`
// stays unless it is the recording's (no pause beyond it: sound that never stopped, as other
// voices' does), or, for the start, where `track`'s pitch was read (FeatureTrack::pitch) and the
// sound left out holds no run of one clear voice at the line's pitch (the line's own syllable after
// a silence; the other voices' own quiet stretches are pauses too). It moves only where the sound
// left out there is at least a pause long and rises and falls by kNearLoudVoiceDb as a voice's
// syllables do (a gain's lift only climbs toward the line), the line keeps at least as many voiced
// peaks (count_nuclei) as it has syllables, and `speech` is slower than its syllables could be
// said or both its edges move. Where a phone's gain lifted the voices before the line to its
// activity, the start is found on the whole band of `track` (kEnergyDb),
// which the line's voicing keeps over them (bench/README.md, session 34).
FrameSpan line_among_quieter_voices(const FeatureTrack& track, const LoudnessProfile& loudness,
                                    const FrameSpan& speech, std::size_t syllables);

// Whether `transcript` has one spoken sentence: a line that line_cut_among_voices may narrow, and
// whose recording is read with its pitch (FeatureTrack::pitch) for line_among_quieter_voices.
bool is_one_spoken_line(const Timeline& transcript);

// `cut` (cut_sentences') with the span of `transcript`'s only spoken sentence narrowed to its line
// (line_among_quieter_voices), for the syllables' placement, and its search kept within a pause
// of the edges it moved (SentenceCut::limits): searched the usual 0.3 s past them, the path gave
// the first or last syllables to the other voices there (short_kinds_bench's babble, the line's
// true edges as its span: 71.0% within 50 ms in tuning, and 86.4% with its search kept to them;
// bench/README.md, session 33). Nothing where the transcript has several spoken sentences or the
// span stays as it is. The checks judge the text on `cut`: on the line alone a wrong text of as
// many syllables fits about as well as the right one (with the line's span for the checks too,
// short_kinds_bench caught 51 -> 42 of 760 wrong texts in tuning: bench/README.md, session 29).
std::optional<SentenceCut> line_cut_among_voices(const FeatureTrack& track, const LoudnessProfile& loudness,
                                                 const Timeline& transcript, const SentenceCut& cut);

}  // namespace talkface::detail

#endif
