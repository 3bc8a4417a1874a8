// A sentence's syllables as a left-to-right chain of broad phone-class states with duration
// priors (SPEC "Alignment": a hidden semi-Markov model; consonants do not stretch with the
// speaking rate, vowels do).
#ifndef TALKFACE_SPEECH_PHONE_CHAIN_HPP
#define TALKFACE_SPEECH_PHONE_CHAIN_HPP

#include <cstddef>
#include <limits>
#include <string_view>
#include <vector>

#include "talkface/timeline.hpp"

namespace talkface::detail {

// Broad classes of Mandarin sounds; each has one emission model. Stop and affricate closures
// share silence's.
enum PhoneClass : int {
    kSilence = 0,
    kBurst,        // release of b p d t g k
    kAspiration,   // aspiration of p t k, and the weak fricatives f h
    kSibilant,     // s sh x, and the frication of z c zh ch j q
    kNasal,        // m n, and the codas n ng
    kLiquid,       // l r
    kVowelA,
    kVowelE,
    kVowelI,
    kVowelO,
    kVowelU,
    kVowelV,       // u-umlaut
    kVowelApical,  // the empty rime of zi ci si zhi chi shi ri
    kPhoneClassCount,
    // Not a class with a model: any sound at all, scored at each frame by the class that fits it
    // best (hsmm.cpp). Lenient alignment (lenient_chain.hpp) lets it stand for speech the text
    // does not say.
    kGenericSpeech = kPhoneClassCount,
};

enum class StateRole : int {
    edge_silence,   // before the first and after the last syllable of a sentence
    short_pause,    // optional, between syllables
    comma_pause,    // optional, where the transcript has ，、：
    closure,        // of a stop or affricate after speech: the syllable starts here (SPEC)
    initial,
    final,
    generic_speech, // optional, of class kGenericSpeech: speech other than the text's (lenient_chain.hpp)
};

// The silences between and around the syllables (a stop's closure is not one: it belongs to its syllable).
inline bool is_pause(StateRole role) {
    return role == StateRole::edge_silence || role == StateRole::short_pause || role == StateRole::comma_pause;
}

// How much a state's duration prior counts against the emissions (PhoneState::duration_weight).
// Each 10 ms frame scores as if independent of the next, though a 25 ms window and the deltas make
// neighbours overlap, so a run of frames weakly favouring a wrong class outvoted the priors: at
// weight 1 a run of syllables slid a syllable early or late, squeezing some to a few frames and
// stretching one over a pause (bench/ human running speech, a room and pink noise at 15 dB). Set
// on the tuning passages of those two conditions: 1.25 and 1.75 help less, 2 refuses a right one.
inline constexpr double kDurationWeight = 1.5;

struct PhoneState {
    PhoneClass phone_class = kSilence;
    StateRole role = StateRole::initial;
    std::size_t syllable = 0;       // index into the sentence's syllables (pauses: the one before)
    double median_frames = 1.0;     // log-normal duration prior; vowels are scaled to the rate
    double log_sigma = 0.5;
    std::size_t min_frames = 1;
    std::size_t max_frames = 1;
    bool is_optional = false;       // the path may skip it
    bool stretches = false;         // scaled with the speaking rate (vowels)
    double entry_log_penalty = 0.0; // added when the state is used (a cheap short pause)
    bool has_tail = false;          // may last past max_frames, paying the prior's slope there per frame
    // A state the path must pass may still be skipped where this is finite, paying it (lenient
    // alignment: a syllable the speech does not say). Optional states are skipped for nothing.
    double skip_log_penalty = -std::numeric_limits<double>::infinity();
    double frame_log_penalty = 0.0; // paid per frame held (generic speech fits every frame well)
    double duration_weight = kDurationWeight; // how much its duration prior counts (hsmm.cpp)
};

// A state of the text's syllable: neither a pause nor generic speech in its stead.
inline bool is_syllable_state(const PhoneState& state) {
    return !is_pause(state.role) && state.role != StateRole::generic_speech;
}

// What a state of generic speech pays per frame held (PhoneState::frame_log_penalty), for a word
// no table reads and for lenient alignment's generic stretches alike; why 0.1: lenient_chain.cpp.
constexpr double kGenericSpeechFrameLogPenalty = -0.1;

// The chain of one sentence, or of neighbouring sentences aligned together: edge silence,
// syllables (with optional pauses between them, of a comma's kind after a comma or a sentence's
// end), edge silence. `frames` is the sentence's length including the edge silences, `speech_frames` the
// part that is speech; vowel durations are scaled to fill it.
// \throws talkface::InvalidArgument naming the syllable if its pinyin is not Mandarin.
std::vector<PhoneState> build_phone_chain(const std::vector<const Syllable*>& syllables, std::size_t frames,
                                          std::size_t speech_frames);

// A pause the text does not mark lasts at most this long where the aligner keeps the text's pauses
// to its marks (keep_pauses_to_marks, cut_alignment.cpp): 0.25 s, a breath between two words. A
// longer pause is one the text marks, which an alignment a syllable or a phrase off gave to a
// place the text does not. bench/ Session 12: 20-50 frames alike on the tuning passages, 15 lets
// a right one be refused.
inline constexpr std::size_t kMaxUnmarkedPauseFrames = 25;

// Whether the chain's text marks a pause (a comma's or a sentence end's, StateRole::comma_pause).
bool has_marked_pause(const std::vector<PhoneState>& states);

// In a chain whose text marks pauses, every pause it does not mark lasts at most
// kMaxUnmarkedPauseFrames, with no tail.
void keep_pauses_to_marks(std::vector<PhoneState>& states);

// What skipping the closure of a stop or affricate after a nasal costs where the aligner allows it
// (let_closures_after_nasals_be_skipped): 3 nats, step 9b's priced skip (bench/README.md, sessions
// 11 and 13), taken as it was measured then.
inline constexpr double kClosureAfterNasalSkipLogPenalty = -3.0;

// Lets the closure of each stop or affricate right after a nasal (n ng m ending the syllable
// before; a short pause between them or none) be skipped for kClosureAfterNasalSkipLogPenalty:
// the tongue or the lips, closed for the nasal, may release straight into the burst (天都 n + d,
// 門口 n + k), with no silence between them.
void let_closures_after_nasals_be_skipped(std::vector<PhoneState>& states);

// Multiplies the duration priors of the vowels (the states that stretch with the speaking rate).
void scale_vowels(std::vector<PhoneState>& states, double factor);

}  // namespace talkface::detail

#endif
