// Words an editor silenced while the transcript keeps them (issue 13, "Recordings as people have
// them"): a user puts digital silence over a word (a slip, a name, a swear word) and aligns the
// recording to the text as written. The aligner has no sound for the word's syllables, leaps the
// zeros as a pause and squeezes them against its edges: 漁 of the person's 漁夫 silenced takes 30 ms
// and 個 before it 50 ms, where the recording's syllables take 100-200 ms (bench/README.md session 39).
// The samples cannot tell such a silence from a pause recorded as exact zeros (h-clean's syllables
// are joined over them, the intro set's beds gap to them), and the syllables' confidence beside a
// good file's joins is as low as beside an edit (session 37); the syllables' lengths against the
// recording's own can: beside a pause they keep their length.
#ifndef TALKFACE_SPEECH_SILENCED_WORDS_HPP
#define TALKFACE_SPEECH_SILENCED_WORDS_HPP

#include <optional>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "speech/frame_features.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// The shortest run of digital silence (frames at or under kDigitalSilenceDb) judged: a syllable's
// length at a quick reader's pace; a word silenced takes two or more.
constexpr double kShortestSilencedS = 0.1;
// The syllables judged beside the run, on each side.
constexpr std::size_t kSyllablesBeside = 2;
// A syllable beside the run is squeezed when it takes under this share of the recording's median
// syllable length; at least kLeastSqueezed of the kSyllablesBeside either side must be, or one
// syllable must lie on the silence for kLeastOnSilenceShare of its length, where no sound is.
constexpr double kSqueezedShare = 0.5;
constexpr std::size_t kLeastSqueezed = 2;
constexpr double kLeastOnSilenceShare = 0.5;
// Where the text marks a pause, or a sentence (or the recording) begins or ends there, a pause may
// be recorded as exact zeros and the syllables next to it are often short ones (来 of 進來, 今年 at a
// sentence's start: 0.43-0.48 of the median in h-clean and r-clean): one side alone tells, and
// both of its kSyllablesBeside must take under this share (an editor's silence leaves them
// 0.14-0.44 in session 40's tuning edits), or one lie on the silence.
constexpr double kEdgeSqueezedShare = 0.4;

// The warnings for `aligned` (times on the recording) where a run of digital silence has squeezed
// syllables or a syllable aligned over it: inside a sentence, after a syllable the text marks no
// pause after, two of the syllables either side; at a pause the text marks or a sentence's edge,
// all of one side's. Each names the span, the sentence and the syllables beside it. `track` is the
// recording's reading whose frame 0 starts at `track_start_s` of the recording. A run that meets
// sound its reader could not decode (`lost`, read as silence) is left to the warning that names the
// damage, and one its reader found cut off mid-wave (`cuts`) to the note that names the cut, which
// says an editor's silence leaves it too (one warning for one run), and one that meets the time a
// second recording joined to the file begins (`second_starts_s`, describe_second_stream's: a chained
// Ogg file's second recording opening in zeros) to the join's.
std::vector<std::string> describe_silenced_words(const FeatureTrack& track, double track_start_s,
                                                 const Timeline& aligned, const std::vector<LostAudio>& lost,
                                                 const std::vector<CutToZeros>& cuts,
                                                 std::optional<double> second_starts_s);

// A run of digital silence inside a refused sentence, in syllables (its span shared evenly among
// them): this near a pause its text marks, it may be that pause recorded as exact zeros (h-clean's
// commas); one an editor put over a word lasts this many or more. The runs inside the sentences of
// h-clean and r-clean refused for a wrong text (another passage's sentence in place of the 2nd or
// the 4th) last 0.6-1.5 of them in the tuning passages, once 4.3 (a wrong text's span over a
// sentence's gap), and four syllables silenced 2.8-5.1 (bench/README.md session 41).
constexpr double kSyllablesFromPauseMark = 1.5;
constexpr double kLeastSyllablesSilenced = 2.5;

// What the refusal of a sentence (`refusal`, opening as describe_sentence names it, its times those
// of `track`) adds where a run of digital silence of kShortestSilencedS or more lies inside the span
// it names, kLeastSyllablesSilenced long, away from the pauses its text marks: a word an editor silenced
// while the text keeps it leaves syllables with no sound, and a sentence with four such was mostly refused
// ("does not sound like its text", 10 of 15 in bench/README.md session 40) with no word of the zeros. nullopt
// where no such run lies there. Runs meeting `lost`, `cuts` or `second_starts_s` (times of the recording,
// whose `track_start_s` is the track's frame 0) are named by their own messages.
std::optional<std::string> describe_zeros_in_refused_sentence(const FeatureTrack& track, double track_start_s,
                                                              const Timeline& transcript,
                                                              const std::string& refusal,
                                                              const std::vector<LostAudio>& lost,
                                                              const std::vector<CutToZeros>& cuts,
                                                              std::optional<double> second_starts_s);

}  // namespace talkface::detail

#endif
