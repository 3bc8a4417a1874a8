// What every timing import reads before it meets the transcript: timed pieces of text (a TextGrid
// interval, a subtitle cue, a text-to-speech engine's word), each with the line it came from; and
// the one matcher that times a transcript's syllables by them, naming the first place they part.
#ifndef TALKFACE_TIMING_TIMED_UNITS_HPP
#define TALKFACE_TIMING_TIMED_UNITS_HPP

#include <string>
#include <string_view>
#include <vector>

#include "talkface/timeline.hpp"

namespace talkface::detail {

struct TimedUnit {
    std::string text;      // as written in the file: characters, pinyin, or a cue's sentence(s)
    double start_s = 0.0;  // seconds
    double end_s = 0.0;
    int line = 0;  // 1-based line of the file where the unit starts
    // WebVTT cue timestamps (<00:00:01.250>) inside the text: the start of each piece of text
    // after the first, in order, with the byte offset in `text` where that piece starts.
    std::vector<std::pair<std::size_t, double>> inner_starts_s;
};

// How the units time the syllables.
enum class UnitKind {
    words,  // each unit's span is shared among the syllables it covers (a word, or one syllable)
    cues,   // sentence-level spans: the same sharing without audio; align_with_cues() pins the aligner
};

// The transcript's syllables matched in order to the units' text (characters, or pinyin with or
// without tones) and timed by them; units with no text (silences) are skipped. Sentences span their
// syllables; duration_s is set to `duration_s`.
// \throws ParseError naming source:line for times out of order or past duration_s, and for the
//         first place where the units' text and the transcript part (the unit, the sentence, the
//         syllable and what each holds), or where one ends before the other.
Timeline match_timed_units(const Timeline& transcript, const std::vector<TimedUnit>& units, double duration_s,
                           const std::string& source, UnitKind kind);

// match_timed_units of units whose times are checked (check_unit_times) and whose syllables are
// found (`ranges`, unit_syllable_ranges's) already.
Timeline time_matched_units(const Timeline& transcript, const std::vector<TimedUnit>& units,
                            const std::vector<std::pair<std::size_t, std::size_t>>& ranges, double duration_s,
                            UnitKind kind);

// Which syllables each unit covered, as match_timed_units found them: first and one past the last
// index into transcript.syllables, one pair per unit.
std::vector<std::pair<std::size_t, std::size_t>> unit_syllable_ranges(const Timeline& transcript,
                                                                      const std::vector<TimedUnit>& units,
                                                                      const std::string& source);

// Each sentence spans its syllables (first start to latest end); a sentence without syllables 0..0.
void span_sentences(Timeline& timeline);

// Refuses units out of order, with negative times, ending before they start, or ending past
// duration_s (when it is > 0), naming source:line.
void check_unit_times(const std::vector<TimedUnit>& units, double duration_s, const std::string& source);

}  // namespace talkface::detail

#endif
