#include "espeak_speech.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <espeak-ng/speak_lib.h>

namespace talkface_bench {

namespace {

// espeak-ng writes exact zeros in pauses and stop closures; -54 dBFS tells sound from silence.
constexpr float sound_threshold = 0.002f;
// A syllable whose word event has no sound in the 40 ms before it follows a pause, not speech
// (espeak-ng's stop closures inside a word run are 10-40 ms and come after the event, not before).
constexpr double pause_lookback_s = 0.040;

struct WordMark {
    std::size_t word_sample = 0;
    std::size_t first_phoneme_sample = 0;
    bool has_phoneme = false;
};

// espeak-ng's synchronous callback carries no pointer of ours that survives every chunk.
struct Capture {
    std::vector<short> pcm;
    std::vector<WordMark> words;
};
Capture* active_capture = nullptr;

int collect(short* wav, int sample_count, espeak_EVENT* events) {
    if (wav != nullptr && sample_count > 0) active_capture->pcm.insert(active_capture->pcm.end(), wav, wav + sample_count);
    for (espeak_EVENT* event = events; event->type != espeakEVENT_LIST_TERMINATED; ++event) {
        // espeak-ng may report a comma as a word of length 0, after the sentence's last word.
        if (event->type == espeakEVENT_WORD && event->length > 0) {
            WordMark mark;
            mark.word_sample = static_cast<std::size_t>(event->sample);
            active_capture->words.push_back(mark);
        } else if (event->type == espeakEVENT_PHONEME && !active_capture->words.empty()) {
            // Pause phonemes ("_", "_|", "_:") are not where a syllable's sound starts.
            WordMark& mark = active_capture->words.back();
            if (!mark.has_phoneme && event->id.string[0] != '_') {
                mark.first_phoneme_sample = static_cast<std::size_t>(event->sample);
                mark.has_phoneme = true;
            }
        }
    }
    return 0;
}

bool is_sound(float sample) { return std::fabs(sample) >= sound_threshold; }

std::size_t first_sound(const std::vector<float>& samples, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i)
        if (is_sound(samples[i])) return i;
    return from;
}

// One past the last sound in [from, to); `from` if there is none.
std::size_t sound_end(const std::vector<float>& samples, std::size_t from, std::size_t to) {
    for (std::size_t i = to; i > from; --i)
        if (is_sound(samples[i - 1])) return i;
    return from;
}

bool silent(const std::vector<float>& samples, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i)
        if (is_sound(samples[i])) return false;
    return true;
}

// SPEC "Alignment": these start with a closure, which after speech is where the syllable starts.
bool starts_with_stop(const std::string& pinyin) {
    return !pinyin.empty() && std::strchr("bpdtgkjqzc", pinyin[0]) != nullptr;
}

}  // namespace

EspeakVoice::EspeakVoice() {
    // Option bit 0: phoneme events, which mark where a fricative or vowel initial sounds.
    sample_rate_hz_ = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr, 1);
    if (sample_rate_hz_ <= 0) throw std::runtime_error("espeak-ng could not be initialised (is espeak-ng-data installed?)");
    if (espeak_SetVoiceByName("cmn-latn-pinyin") != EE_OK)
        throw std::runtime_error("espeak-ng has no voice cmn-latn-pinyin (Mandarin, pinyin input)");
    espeak_SetSynthCallback(collect);
}

EspeakVoice::~EspeakVoice() { espeak_Terminate(); }

SpokenSentence EspeakVoice::speak(const std::vector<talkface::Syllable>& syllables, int rate_wpm, int pitch,
                                  const std::string& where) const {
    std::string text;
    for (const auto& syllable : syllables) {
        if (!text.empty()) text += ' ';
        text += syllable.pinyin;
        if (syllable.pause_after) text += ',';
    }
    text += '.';

    Capture capture;
    active_capture = &capture;
    espeak_SetParameter(espeakRATE, rate_wpm, 0);
    espeak_SetParameter(espeakPITCH, pitch, 0);
    const espeak_ERROR status =
        espeak_Synth(text.c_str(), text.size() + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr, nullptr);
    espeak_Synchronize();
    active_capture = nullptr;
    if (status != EE_OK) throw std::runtime_error(where + ": espeak-ng failed to speak \"" + text + "\"");
    if (capture.words.size() != syllables.size()) {
        throw std::runtime_error(where + ": espeak-ng spoke " + std::to_string(capture.words.size()) +
                                 " words for " + std::to_string(syllables.size()) + " syllables in \"" + text +
                                 "\"; fix the reading in the transcript");
    }

    std::vector<float> all(capture.pcm.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<float>(capture.pcm[i]) / 32768.0f;
    const std::size_t total = all.size();
    const auto lookback = static_cast<std::size_t>(pause_lookback_s * sample_rate_hz_);

    std::vector<SpokenSyllable> spoken(syllables.size());
    for (std::size_t i = 0; i < syllables.size(); ++i) {
        const WordMark& mark = capture.words[i];
        const std::size_t next_word = i + 1 < syllables.size() ? capture.words[i + 1].word_sample : total;
        const std::size_t word = std::min(mark.word_sample, total);
        const std::size_t before = word > lookback ? word - lookback : 0;
        spoken[i].after_pause = silent(all, before, word);
        if (spoken[i].after_pause)
            spoken[i].start = first_sound(all, word, std::min(next_word, total));
        else if (starts_with_stop(syllables[i].pinyin) || !mark.has_phoneme)
            spoken[i].start = word;
        else
            spoken[i].start = std::min(mark.first_phoneme_sample, total);
    }
    for (std::size_t i = 0; i < spoken.size(); ++i) {
        const std::size_t next = i + 1 < spoken.size() ? spoken[i + 1].start : total;
        spoken[i].end = sound_end(all, spoken[i].start, next);
    }

    const std::size_t begin = spoken.empty() ? 0 : spoken.front().start;
    const std::size_t end = spoken.empty() ? 0 : spoken.back().end;
    SpokenSentence sentence;
    sentence.samples.assign(all.begin() + static_cast<std::ptrdiff_t>(begin), all.begin() + static_cast<std::ptrdiff_t>(end));
    for (auto& syllable : spoken) {
        syllable.start -= begin;
        syllable.end -= begin;
    }
    sentence.syllables = std::move(spoken);
    return sentence;
}

}  // namespace talkface_bench
