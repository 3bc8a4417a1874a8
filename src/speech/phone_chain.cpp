#include "speech/phone_chain.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "talkface/errors.hpp"
#include "talkface/transcript.hpp"

namespace talkface::detail {

namespace {

// A pause the text does not mark, before f h s sh x, lasts at least this long (longer than such a
// sound's own prior: f 9, h 7, s 11 frames). In noise the start of a weak fricative sounds like
// the pause's noise and fits the silence model better than its own: a short pause took the first
// 40-80 ms of it, and its onset came that late (espeak-ng at SNR 10 dB: three f or h in four,
// and a sibilant in three, more than 50 ms late; a person at SNR 20 dB alike). A person stops
// before a fricative for longer than that or not at all; a shorter silence there is its start.
constexpr std::size_t kMinPauseBeforeFricativeFrames = 15;

// A phrase's last syllable (before a comma or the sentence's end) is said slower: its vowels' priors
// are this much longer than the others'. Without it the priors gave a sentence's last syllable, long
// in people's speech, the share of any other, and to make room the path placed a run of quick
// syllables before it a syllable early or late (bench/ human running speech: a sentence opening with
// four syllables in 0.43 s ran 0.2-0.5 s late through its second half; its last syllable got 0.11 s
// of its 0.55). 1.2-1.7 all helped there, 1.5-1.7 the most; espeak-ng's rows moved under half a point.
constexpr double kPhraseFinalLengthening = 1.5;

// Typical durations of Mandarin segments in 10 ms frames (read speech, phonetic literature:
// unaspirated bursts ~15-20 ms, aspiration ~70-90 ms, sibilants ~100-130 ms, closures ~50 ms);
// the rate scaling of vowels fits the rest to the sentence.
PhoneState consonant(PhoneClass phone_class, double median_frames, double log_sigma, std::size_t max_frames) {
    PhoneState state;
    state.phone_class = phone_class;
    state.role = StateRole::initial;
    state.median_frames = median_frames;
    state.log_sigma = log_sigma;
    state.max_frames = max_frames;
    return state;
}

PhoneState vowel(PhoneClass phone_class, double median_frames) {
    PhoneState state;
    state.phone_class = phone_class;
    state.role = StateRole::final;
    state.median_frames = median_frames;
    state.log_sigma = 0.5;
    state.stretches = true;
    return state;
}

PhoneClass vowel_class(char letter) {
    switch (letter) {
        case 'a': return kVowelA;
        case 'e': return kVowelE;
        case 'i': return kVowelI;
        case 'o': return kVowelO;
        case 'u': return kVowelU;
        default: return kVowelV;
    }
}

bool is_vowel_letter(char letter) { return std::string_view("aeiouv").find(letter) != std::string_view::npos; }

struct SplitSyllable {
    std::string initial;
    std::string final;  // u-umlaut as v, y- and w- spelled out as medials
};

SplitSyllable split(std::string toneless) {
    for (auto& c : toneless) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::size_t colon = toneless.find("u:");
    if (colon != std::string::npos) toneless.replace(colon, 2, "v");
    const std::size_t umlaut = toneless.find("\xC3\xBC");  // ü
    if (umlaut != std::string::npos) toneless.replace(umlaut, 2, "v");
    SplitSyllable result;
    static const char* const kInitials[] = {"zh", "ch", "sh", "b", "p", "m", "f", "d", "t", "n", "l", "g",
                                            "k", "h", "j", "q", "x", "r", "z", "c", "s", "y", "w"};
    // The bare nasal interjections m, n, ng, hm, hng are not initial + final.
    if (toneless == "m" || toneless == "n" || toneless == "ng" || toneless == "hm" || toneless == "hng" ||
        toneless == "r") {
        result.final = toneless;
        return result;
    }
    for (const char* initial : kInitials) {
        const std::string_view candidate(initial);
        if (toneless.size() > candidate.size() && toneless.compare(0, candidate.size(), candidate) == 0) {
            result.initial = std::string(candidate);
            result.final = toneless.substr(candidate.size());
            break;
        }
    }
    if (result.initial.empty()) result.final = toneless;
    // After j q x y, u is u-umlaut; y and w are the medials i, u, u-umlaut.
    if ((result.initial == "j" || result.initial == "q" || result.initial == "x" || result.initial == "y") &&
        !result.final.empty() && result.final[0] == 'u')
        result.final[0] = 'v';
    if (result.initial == "y") {
        if (result.final[0] != 'i' && result.final[0] != 'v') result.final = "i" + result.final;
        result.initial.clear();
    } else if (result.initial == "w") {
        if (result.final[0] != 'u') result.final = "u" + result.final;
        result.initial.clear();
    }
    return result;
}

// States of the initial; a stop or affricate after speech begins with its closure.
void add_initial(const std::string& initial, bool after_speech, std::vector<PhoneState>& states) {
    auto closure = [&] {
        if (!after_speech) return;
        PhoneState state = consonant(kSilence, 5.0, 0.5, 20);
        state.role = StateRole::closure;
        states.push_back(state);
    };
    if (initial == "b" || initial == "d" || initial == "g") {
        closure();
        states.push_back(consonant(kBurst, 2.0, 0.5, 6));
    } else if (initial == "p" || initial == "t" || initial == "k") {
        closure();
        states.push_back(consonant(kBurst, 2.0, 0.5, 6));
        states.push_back(consonant(kAspiration, 6.0, 0.4, 16));
    } else if (initial == "j" || initial == "zh" || initial == "z") {
        closure();
        states.push_back(consonant(kSibilant, 5.0, 0.45, 14));
    } else if (initial == "q" || initial == "ch" || initial == "c") {
        closure();
        states.push_back(consonant(kSibilant, 9.0, 0.4, 22));
    } else if (initial == "s" || initial == "sh" || initial == "x") {
        states.push_back(consonant(kSibilant, 11.0, 0.35, 28));
    } else if (initial == "f") {
        states.push_back(consonant(kAspiration, 9.0, 0.4, 22));
    } else if (initial == "h") {
        states.push_back(consonant(kAspiration, 7.0, 0.45, 20));
    } else if (initial == "m" || initial == "n") {
        states.push_back(consonant(kNasal, 6.0, 0.45, 16));
    } else if (initial == "l" || initial == "r") {
        states.push_back(consonant(kLiquid, 5.0, 0.45, 16));
    }
}

void add_final(const std::string& initial, const std::string& final, std::vector<PhoneState>& states) {
    if (final == "m" || final == "n" || final == "ng" || final == "hm" || final == "hng") {
        if (final[0] == 'h') states.push_back(consonant(kAspiration, 7.0, 0.45, 20));
        PhoneState nasal = vowel(kNasal, 14.0);
        states.push_back(nasal);
        return;
    }
    if (final == "r") {
        states.push_back(vowel(kLiquid, 12.0));
        return;
    }
    const bool is_apical = final == "i" && (initial == "z" || initial == "c" || initial == "s" || initial == "zh" ||
                                            initial == "ch" || initial == "sh" || initial == "r");
    if (is_apical) {
        states.push_back(vowel(kVowelApical, 14.0));
        return;
    }
    if (final == "er") {
        states.push_back(vowel(kVowelE, 10.0));
        states.push_back(vowel(kLiquid, 6.0));
        return;
    }
    std::string letters = final;
    bool has_nasal_coda = false;
    if (letters.size() >= 3 && letters.compare(letters.size() - 2, 2, "ng") == 0) {
        letters.resize(letters.size() - 2);
        has_nasal_coda = true;
    } else if (letters.size() >= 2 && letters.back() == 'n') {
        letters.pop_back();
        has_nasal_coda = true;
    }
    // ong and iong are [ʊŋ], ao ends in [u]; ê is e.
    for (std::size_t i = 0; i < letters.size(); ++i) {
        if (letters[i] == 'o' && (has_nasal_coda || (i > 0 && letters[i - 1] == 'a'))) letters[i] = 'u';
        if (!is_vowel_letter(letters[i])) letters[i] = 'e';
    }
    const std::size_t count = letters.size();
    const bool has_medial = count > 1 && (letters[0] == 'i' || letters[0] == 'u' || letters[0] == 'v');
    for (std::size_t i = 0; i < count; ++i) {
        const bool is_medial = has_medial && i == 0;
        const bool is_offglide = i + 1 == count && i >= 1 && !(i == 1 && has_medial) &&
                                 (letters[i] == 'i' || letters[i] == 'u');
        states.push_back(vowel(vowel_class(letters[i]), is_medial ? 4.0 : is_offglide ? 6.0 : 14.0));
    }
    if (has_nasal_coda) {
        PhoneState coda = vowel(kNasal, 6.0);
        coda.log_sigma = 0.55;
        states.push_back(coda);
    }
}

// Initials heard only as frication, with no closure before them: f h s sh x.
bool is_fricative(const std::string& initial) {
    return initial == "f" || initial == "h" || initial == "s" || initial == "sh" || initial == "x";
}

// A syllable of a word no table reads (Syllable::generic_speech): one state of any sound at all,
// a syllable long (an initial and a vowel), stretched with the rate as vowels are. Any sound fits
// it as well as the best class, so it pays per frame about what a right syllable's frames lose to
// their best class (lenient_chain.cpp), or it would take its neighbours' sounds.
PhoneState generic_syllable() {
    PhoneState state = vowel(kGenericSpeech, 20.0);
    state.log_sigma = 0.6;
    state.frame_log_penalty = kGenericSpeechFrameLogPenalty;
    return state;
}

PhoneState pause_state(StateRole role, std::size_t syllable, double median_frames, std::size_t max_frames,
                       double entry_log_penalty) {
    PhoneState state;
    state.phone_class = kSilence;
    state.role = role;
    state.syllable = syllable;
    state.median_frames = median_frames;
    state.log_sigma = 0.7;
    state.max_frames = max_frames;
    state.is_optional = true;
    state.entry_log_penalty = entry_log_penalty;
    // A speaker may stop for any time between two syllables: where the transcript marks no sentence
    // end (a transcript without punctuation), the pause between two sentences is one of these.
    state.has_tail = role != StateRole::edge_silence;
    return state;
}

}  // namespace

std::vector<PhoneState> build_phone_chain(const std::vector<const Syllable*>& syllables, std::size_t frames,
                                          std::size_t speech_frames) {
    std::vector<PhoneState> states;
    // The cutter leaves at most ~0.3 s of pause on each side; 1.1 s covers a cut that is off by
    // a weak first or last sound, and bounds the search (the edge states would otherwise be the
    // costliest, quadratic in the sentence's length).
    const std::size_t edge_max_frames = std::min<std::size_t>(std::max<std::size_t>(frames, 1), 110);
    PhoneState leading = pause_state(StateRole::edge_silence, 0, 1.0, edge_max_frames, 0.0);
    states.push_back(leading);
    for (std::size_t index = 0; index < syllables.size(); ++index) {
        const Syllable& syllable = *syllables[index];
        std::string_view toneless = syllable.pinyin;
        if (!toneless.empty() && toneless.back() >= '0' && toneless.back() <= '5') toneless.remove_suffix(1);
        if (toneless.empty()) throw InvalidArgument("syllable " + std::to_string(index) + " (\"" + syllable.text + "\")",
                                                    "empty pinyin \"" + syllable.pinyin + "\"");
        const SplitSyllable parts = split(std::string(toneless));
        if (index > 0) {
            // Sentences aligned together (run together by the speaker) may still have a pause
            // between them, as long as a comma's or longer.
            const bool has_comma = syllables[index - 1]->pause_after || syllables[index - 1]->sentence != syllable.sentence;
            if (has_comma) {
                states.push_back(pause_state(StateRole::comma_pause, index - 1, 20.0, 200, 0.0));
            } else {
                states.push_back(pause_state(StateRole::short_pause, index - 1, 6.0, 60, -3.0));
                if (is_fricative(parts.initial)) states.back().min_frames = kMinPauseBeforeFricativeFrames;
            }
        }
        const std::size_t first_state = states.size();
        if (syllable.generic_speech) {
            states.push_back(generic_syllable());
        } else {
            add_initial(parts.initial, index > 0, states);
            add_final(parts.initial, parts.final, states);
        }
        if (states.size() == first_state) throw InvalidArgument("syllable " + std::to_string(index) + " (\"" + syllable.text + "\")",
                                                                "\"" + syllable.pinyin + "\" is not a Mandarin syllable");
        for (std::size_t s = first_state; s < states.size(); ++s) states[s].syllable = index;
        // A light tone (a particle: 吧, 了, 的) stays short even there.
        const bool is_light_tone = !syllable.pinyin.empty() && syllable.pinyin.back() == '5';
        const bool is_phrase_end = !is_light_tone && (syllable.pause_after || index + 1 == syllables.size() ||
                                                      syllables[index + 1]->sentence != syllable.sentence);
        if (is_phrase_end)
            for (std::size_t s = first_state; s < states.size(); ++s)
                if (states[s].stretches) states[s].median_frames *= kPhraseFinalLengthening;
    }
    states.push_back(pause_state(StateRole::edge_silence, syllables.size() - 1, 1.0, edge_max_frames, 0.0));

    // Consonants keep their durations; vowels share what the speech leaves them.
    double fixed_frames = 0.0;
    double stretch_frames = 0.0;
    for (const auto& state : states) {
        if (state.role == StateRole::edge_silence || state.is_optional) continue;
        (state.stretches ? stretch_frames : fixed_frames) += state.median_frames;
    }
    scale_vowels(states, std::clamp((static_cast<double>(speech_frames) - fixed_frames) / std::max(stretch_frames, 1.0), 0.35, 4.0));
    for (auto& state : states) {
        if (state.role == StateRole::edge_silence) continue;
        state.max_frames = std::min(state.max_frames, std::max<std::size_t>(frames, 1));
    }
    return states;
}

bool has_marked_pause(const std::vector<PhoneState>& states) {
    return std::any_of(states.begin(), states.end(), [](const PhoneState& state) { return state.role == StateRole::comma_pause; });
}

void keep_pauses_to_marks(std::vector<PhoneState>& states) {
    if (!has_marked_pause(states)) return;
    for (auto& state : states) {
        if (state.role != StateRole::short_pause) continue;
        state.has_tail = false;
        state.max_frames = std::min(state.max_frames, kMaxUnmarkedPauseFrames);
    }
}

void let_closures_after_nasals_be_skipped(std::vector<PhoneState>& states) {
    for (std::size_t s = 1; s < states.size(); ++s) {
        if (states[s].role != StateRole::closure) continue;
        std::size_t before = s - 1;
        while (before > 0 && is_pause(states[before].role)) --before;
        const PhoneState& sound = states[before];
        if (sound.phone_class == kNasal && sound.role == StateRole::final && sound.syllable + 1 == states[s].syllable)
            states[s].skip_log_penalty = kClosureAfterNasalSkipLogPenalty;
    }
}

void scale_vowels(std::vector<PhoneState>& states, double factor) {
    for (auto& state : states) {
        if (!state.stretches) continue;
        state.median_frames *= factor;
        state.max_frames = static_cast<std::size_t>(std::ceil(state.median_frames * 3.5)) + 4;
    }
}

}  // namespace talkface::detail
