// make_human_corpus: the aligner benchmark's human material (issue 12). Mandarin passages built
// from the syllables a person recorded (Debian's gcin-voice, speaker 3 only), joined the way
// running speech goes, with the start of every syllable known because the joins are ours.
//
//   make_human_corpus OUT [--seed N] [--repeats N] [--sentences FILE] [--conditions h-clean,...]
//   make_human_corpus --clip STEM [--seed N] [--tempo T] TEXT
//
// Speaker 3 is the project's development voice; the other speaker of gcin-voice is kept for
// measurement by others and is never read here (bench/README.md).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <talkface/talkface.hpp>

#include "corpus_tools.hpp"
#include "wav_file.hpp"

namespace fs = std::filesystem;
using talkface_bench::MonoAudio;
using talkface_bench::Noise;

namespace {

constexpr int kRateHz = 16000;
// The one speaker of gcin-voice this program reads (PROTOCOL: speaker 3 is for development).
constexpr const char* kSpeakerFile = "3.ogg";
// Speaker 3 says each syllable alone, in its citation form: about 0.4 s (trimmed). Read aloud in
// a sentence at a careful pace a syllable takes about 0.25 s (4 a second): tempo 1.0 is that pace,
// and 1.5 gives the 0.15-0.17 s syllables of fast speech.
constexpr double kCitationToCareful = 1.6;
// No syllable inside a phrase is heard for less than this, from its start to the next one's: the
// next does not start, nor cut its tail, earlier. A light (neutral-tone) syllable is said in about
// half a full one's time, its shortness its chief mark (bench/README.md Session 22 has the
// sources), and an initial and a vowel each take a gesture of their own. The speaker's substituted
// light syllables (nai4 for nai5, quickened 1.7 times, their tails cut) and the next voiced
// initials' cross-fades had left some at 20-45 ms (老奶奶's second 奶 at 25 ms). 60 ms lies well
// under half a full syllable of the fastest speech here (`r-fast` 169 ms, `v-fast` 149 ms at the
// median), so that only those move.
constexpr double kMinSyllableS = 0.06;
const char* const kDefaultVoiceDir = "/usr/share/gcin-voice/ogg";

struct Condition {
    const char* name;
    const char* description;
    double min_tempo;   ///< each sentence's tempo is drawn in [min_tempo, max_tempo]
    double max_tempo;
    Noise noise;
    double snr_db;
    const char* sox_effects;  ///< on the joined 16 kHz speech, before any noise ("" for none)
    bool is_running = false;  ///< joined as running speech goes (RunningDelivery), not syllable by syllable
    double max_snr_db = 0;    ///< above snr_db: each passage draws its SNR in [snr_db, max_snr_db]
    double min_ends_s = 0;    ///< each end gets min_ends_s..max_ends_s (drawn) more of the noise alone
    double max_ends_s = 0;
    bool is_phone = false;    ///< after the noise: the telephone band at 8 kHz, through the GSM 06.10 codec
    double min_voice_semitones = 0;  ///< above 0: another voice (`v-`), each passage's shift drawn in
    double max_voice_semitones = 0;  ///< [min, max] semitones, up or down (drawn), see with_voice
    bool is_other_person = false;    ///< `w-`: another person's voice and microphone, see draw_person
    double max_breath_db = 0;        ///< below 0: breath under the voice, up to this level against it, see with_breath
    bool is_lenis = false;           ///< an unaspirated stop's closure voiced through, see voice_through_closure
};

const Condition all_conditions[] = {
    {"h-clean", "speaker 3 as recorded, tempo 1.0-1.5", 1.0, 1.5, Noise::none, 0, ""},
    {"h-white30", "white noise, SNR 30 dB", 1.0, 1.5, Noise::white, 30, ""},
    {"h-pink25", "pink noise, SNR 25 dB", 1.0, 1.5, Noise::pink, 25, ""},
    {"h-fast", "tempo 1.4-1.5, white noise at SNR 30 dB", 1.4, 1.5, Noise::white, 30, ""},
    {"h-white20", "white noise, SNR 20 dB", 1.0, 1.5, Noise::white, 20, ""},
    {"h-pink15", "pink noise, SNR 15 dB", 1.0, 1.5, Noise::pink, 15, ""},
    {"h-reverb", "room reverb (sox reverb 40 50 60)", 1.0, 1.5, Noise::none, 0, "reverb 40 50 60 gain -n -3"},
    // Running speech: the same passages said as a fluent speaker runs syllables together.
    {"r-clean", "running speech, tempo 1.0-1.5", 1.0, 1.5, Noise::none, 0, "", true},
    {"r-white30", "running speech, white noise at SNR 30 dB", 1.0, 1.5, Noise::white, 30, "", true},
    {"r-pink25", "running speech, pink noise at SNR 25 dB", 1.0, 1.5, Noise::pink, 25, "", true},
    {"r-fast", "running speech, tempo 1.3-1.5, white noise at SNR 30 dB", 1.3, 1.5, Noise::white, 30, "", true},
    {"r-white20", "running speech, white noise at SNR 20 dB", 1.0, 1.5, Noise::white, 20, "", true},
    {"r-pink15", "running speech, pink noise at SNR 15 dB", 1.0, 1.5, Noise::pink, 15, "", true},
    {"r-reverb", "running speech, room reverb (sox reverb 40 50 60)", 1.0, 1.5, Noise::none, 0,
     "reverb 40 50 60 gain -n -3", true},
    // Recordings as people have them (issue 13). Each draws from its own noise stream (its index),
    // so that the conditions above keep their files.
    {"r-music", "running speech, a tune (chords, bass, melody, drums) at SNR 15-20 dB", 1.0, 1.5, Noise::song, 15, "",
     true, 20},
    {"r-hum", "running speech, mains hum (50 or 60 Hz and harmonics) and a fan at SNR 15-20 dB", 1.0, 1.5,
     Noise::mains_fan, 15, "", true, 20},
    {"r-longsil", "running speech, room noise at SNR 15-20 dB, alone for 3-10 s at each end", 1.0, 1.5, Noise::room, 15,
     "", true, 20, 3, 10},
    {"r-phone", "running speech, pink noise at SNR 30 dB, then the telephone band (300-3400 Hz) at 8 kHz through GSM 06.10",
     1.0, 1.5, Noise::pink, 30, "", true, 0, 0, 0, true},
    // Another voice made of speaker 3's (issue 12, session 11): running speech whose pitch and
    // formants are moved together by 2-4 semitones up or down (drawn per passage), and faster speech.
    {"v-clean", "another voice (2-4 semitones up or down), running speech, white noise at SNR 30 dB", 1.0, 1.5,
     Noise::white, 30, "", true, 0, 0, 0, false, 2, 4},
    {"v-fast", "another voice, running speech at tempo 1.5-1.7, white noise at SNR 30 dB", 1.5, 1.7, Noise::white,
     30, "", true, 0, 0, 0, false, 2, 4},
    {"v-fast-white15", "another voice, tempo 1.5-1.7, white noise at SNR 15-20 dB", 1.5, 1.7, Noise::white, 15, "",
     true, 20, 0, 0, false, 2, 4},
    {"v-fast-pink15", "another voice, tempo 1.5-1.7, pink noise at SNR 15-20 dB", 1.5, 1.7, Noise::pink, 15, "", true,
     20, 0, 0, false, 2, 4},
    {"v-reverb", "another voice, running speech, room reverb (sox reverb 40 50 60)", 1.0, 1.5, Noise::none, 0,
     "reverb 40 50 60 gain -n -3", true, 0, 0, 0, false, 2, 4},
    {"v-fast-reverb", "another voice, tempo 1.5-1.7, room reverb (sox reverb 40 50 60)", 1.5, 1.7, Noise::none, 0,
     "reverb 40 50 60 gain -n -3", true, 0, 0, 0, false, 2, 4},
    // Another person (issue 12, session 13), where `v-` moves pitch and formants together: formants
    // moved on their own, a pitch median and range of the person's own (praat's Change gender), a
    // microphone's tilt and bandwidth, then a breathier voice and closures voiced through.
    {"w-clean", "another person (formants, pitch, microphone of its own), running speech, white noise at SNR 30 dB",
     1.0, 1.5, Noise::white, 30, "", true, 0, 0, 0, false, 0, 0, true},
    {"w-fast", "another person, running speech at tempo 1.3-1.5, white noise at SNR 30 dB", 1.3, 1.5, Noise::white,
     30, "", true, 0, 0, 0, false, 0, 0, true},
    {"w-fast-pink15", "another person, tempo 1.3-1.5, pink noise at SNR 15-20 dB", 1.3, 1.5, Noise::pink, 15, "",
     true, 20, 0, 0, false, 0, 0, true},
    {"w-breathy", "another person, breathy (breath noise 12-20 dB under the voice), white noise at SNR 30 dB", 1.0,
     1.5, Noise::white, 30, "", true, 0, 0, 0, false, 0, 0, true, -12},
    {"w-lenis", "another person, closures of b d g j zh z voiced through, white noise at SNR 30 dB", 1.0, 1.5,
     Noise::white, 30, "", true, 0, 0, 0, false, 0, 0, true, 0, true},
};

// --- pinyin to gcin-voice's folders --------------------------------------------------------------

// Zhuyin (bopomofo) of the pinyin initials, in the order they are matched (zh ch sh before z c s).
const std::pair<const char*, const char*> kInitials[] = {
    {"zh", "ㄓ"}, {"ch", "ㄔ"}, {"sh", "ㄕ"}, {"b", "ㄅ"}, {"p", "ㄆ"}, {"m", "ㄇ"}, {"f", "ㄈ"},
    {"d", "ㄉ"},  {"t", "ㄊ"},  {"n", "ㄋ"},  {"l", "ㄌ"}, {"g", "ㄍ"}, {"k", "ㄎ"}, {"h", "ㄏ"},
    {"j", "ㄐ"},  {"q", "ㄑ"},  {"x", "ㄒ"},  {"r", "ㄖ"}, {"z", "ㄗ"}, {"c", "ㄘ"}, {"s", "ㄙ"},
};

// Finals as written after an initial (u-umlaut as v), in zhuyin. y- and w- spellings are turned
// into these first (yi -> i, wu -> u, yu -> v, you -> iou ...).
const std::map<std::string, std::string> kFinals = {
    {"a", "ㄚ"},     {"o", "ㄛ"},     {"e", "ㄜ"},     {"ê", "ㄝ"},     {"ai", "ㄞ"},    {"ei", "ㄟ"},
    {"ao", "ㄠ"},    {"ou", "ㄡ"},    {"an", "ㄢ"},    {"en", "ㄣ"},    {"ang", "ㄤ"},   {"eng", "ㄥ"},
    {"er", "ㄦ"},    {"i", "ㄧ"},     {"u", "ㄨ"},     {"v", "ㄩ"},     {"ia", "ㄧㄚ"},  {"io", "ㄧㄛ"},
    {"ie", "ㄧㄝ"},  {"iai", "ㄧㄞ"}, {"iao", "ㄧㄠ"}, {"iu", "ㄧㄡ"},  {"iou", "ㄧㄡ"}, {"ian", "ㄧㄢ"},
    {"in", "ㄧㄣ"},  {"iang", "ㄧㄤ"}, {"ing", "ㄧㄥ"}, {"ua", "ㄨㄚ"},  {"uo", "ㄨㄛ"}, {"uai", "ㄨㄞ"},
    {"ui", "ㄨㄟ"},  {"uei", "ㄨㄟ"}, {"uan", "ㄨㄢ"}, {"un", "ㄨㄣ"},  {"uen", "ㄨㄣ"}, {"uang", "ㄨㄤ"},
    {"ong", "ㄨㄥ"}, {"ueng", "ㄨㄥ"}, {"ve", "ㄩㄝ"}, {"van", "ㄩㄢ"},  {"vn", "ㄩㄣ"},  {"iong", "ㄩㄥ"},
};

struct Reading {
    std::string initial;  ///< pinyin initial ("" for none)
    std::string zhuyin;   ///< without the tone
    int tone = 1;         ///< 1-4, 5 for the neutral (light) tone
};

Reading read_pinyin(const std::string& numbered, const std::string& where) {
    std::string letters = numbered;
    Reading reading;
    if (!letters.empty() && letters.back() >= '1' && letters.back() <= '5') {
        reading.tone = letters.back() - '0';
        letters.pop_back();
    }
    for (auto& c : letters) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const auto umlaut = letters.find("u:");
    if (umlaut != std::string::npos) letters.replace(umlaut, 2, "v");
    std::string final = letters;
    // y- and w- are the medials i, u, u-umlaut spelled at the start of a syllable.
    if (letters.rfind("yu", 0) == 0) final = "v" + letters.substr(2);
    else if (letters.rfind("yi", 0) == 0) final = letters.substr(1);
    else if (letters.rfind("y", 0) == 0) final = "i" + letters.substr(1);
    else if (letters.rfind("wu", 0) == 0) final = letters.substr(1);
    else if (letters.rfind("w", 0) == 0) final = "u" + letters.substr(1);
    else {
        for (const auto& [pinyin, zhuyin] : kInitials) {
            const std::string initial = pinyin;
            if (letters.size() > initial.size() && letters.compare(0, initial.size(), initial) == 0) {
                reading.initial = initial;
                reading.zhuyin = zhuyin;
                final = letters.substr(initial.size());
                break;
            }
        }
    }
    // After j q x, u is u-umlaut; after zh ch sh r z c s a lone i is the empty rime (no zhuyin).
    const std::string& i = reading.initial;
    if ((i == "j" || i == "q" || i == "x") && !final.empty() && final[0] == 'u') final[0] = 'v';
    const bool is_apical = final == "i" && (i == "zh" || i == "ch" || i == "sh" || i == "r" || i == "z" || i == "c" || i == "s");
    if (!is_apical) {
        const auto found = kFinals.find(final);
        if (found == kFinals.end()) throw std::runtime_error(where + ": no zhuyin for the pinyin \"" + numbered + "\"");
        reading.zhuyin += found->second;
    }
    return reading;
}

// A stop or affricate: after speech it starts with a closure (SPEC "Alignment").
bool has_closure(const std::string& initial) {
    static const char* const stops[] = {"b", "p", "d", "t", "g", "k", "j", "q", "zh", "ch", "z", "c"};
    return std::find(std::begin(stops), std::end(stops), initial) != std::end(stops);
}

// The unaspirated stops and affricates: said quickly between vowels, many speakers voice them
// right through their closure (the `w-lenis` condition).
bool is_lenis(const std::string& initial) {
    return initial == "b" || initial == "d" || initial == "g" || initial == "j" || initial == "zh" || initial == "z";
}

// m n l r and the zero initial: voicing runs on from the vowel before.
bool is_voiced_onset(const std::string& initial) {
    return initial.empty() || initial == "m" || initial == "n" || initial == "l" || initial == "r";
}

// --- the recorded syllables ----------------------------------------------------------------------

// Speaker 3's recordings carry a DC offset of up to a tenth of their peak: a high-pass at 60 Hz
// (below the voice's pitch) takes it out before the levels are measured.
std::vector<float> decode(const fs::path& path) {
    const std::string command = "sox -R -V1 " + talkface_bench::quoted(path.string()) + " -t f32 -c 1 -r " +
                                std::to_string(kRateHz) + " - highpass 60 2>/dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run: " + command);
    std::vector<float> samples;
    float block[4096];
    for (std::size_t n; (n = std::fread(block, sizeof(float), 4096, pipe)) > 0;) samples.insert(samples.end(), block, block + n);
    if (pclose(pipe) != 0 || samples.empty()) throw std::runtime_error("sox could not decode " + path.string());
    return samples;
}

// The recording's own silence cut off: from the first 5 ms frame within 45 dB of its loudest (a
// weak fricative's start) to the last within 35 dB (a vowel's decay goes on far below what a
// listener hears as its end), never below -70 dBFS (the recordings' own floor is lower; most start
// right at their first sound); a 2 ms fade in and a 10 ms fade out so that joins do not click.
constexpr double kSilenceDb = -70.0;
std::vector<float> trim(const std::vector<float>& samples) {
    constexpr std::size_t frame = kRateHz / 200;
    std::vector<double> level_db;
    for (std::size_t i = 0; i + frame <= samples.size(); i += frame) {
        double power = 0;
        for (std::size_t k = i; k < i + frame; ++k) power += double(samples[k]) * samples[k];
        level_db.push_back(10.0 * std::log10(power / frame + 1e-12));
    }
    if (level_db.empty()) return samples;
    const double peak_db = *std::max_element(level_db.begin(), level_db.end());
    const double start_db = std::max(peak_db - 45.0, kSilenceDb);
    const double end_db = std::max(peak_db - 35.0, kSilenceDb);
    std::size_t first = 0, last = level_db.size() - 1;
    while (first < last && level_db[first] < start_db) ++first;
    while (last > first && level_db[last] < end_db) --last;
    std::vector<float> kept(samples.begin() + static_cast<std::ptrdiff_t>(first * frame),
                            samples.begin() + static_cast<std::ptrdiff_t>((last + 1) * frame));
    const std::size_t fade_in = std::min(kept.size(), std::size_t{kRateHz / 500});
    const std::size_t fade_out = std::min(kept.size(), std::size_t{kRateHz / 100});
    for (std::size_t k = 0; k < fade_in; ++k) kept[k] *= static_cast<float>(k) / static_cast<float>(fade_in);
    for (std::size_t k = 0; k < fade_out; ++k) kept[kept.size() - 1 - k] *= static_cast<float>(k) / static_cast<float>(fade_out);
    return kept;
}

// Speaker 3's syllables, decoded once, trimmed, and each pace made once (sox tempo, WSOLA with
// its speech setting: the pitch stays).
class SyllableBank {
public:
    SyllableBank(fs::path voice_dir, fs::path work_dir) : voice_dir_(std::move(voice_dir)), work_dir_(std::move(work_dir)) {}

    // The folder for `reading`: its tone if speaker 3 recorded it, else the nearest one it did
    // (neutral tones fall back to the first, then any). Empty if the syllable is missing.
    std::string folder(const Reading& reading, bool& is_exact) const {
        static const char* const suffixes[6][4] = {{"", "", "", ""},       {"", "4", "2", "3"}, {"2", "", "3", "4"},
                                                   {"3", "2", "4", ""},    {"4", "", "2", "3"}, {"1", "", "4", "2"}};
        is_exact = true;
        for (const char* suffix : suffixes[reading.tone]) {
            const fs::path candidate = voice_dir_ / (reading.zhuyin + suffix) / kSpeakerFile;
            if (fs::exists(candidate)) return reading.zhuyin + suffix;
            is_exact = false;
        }
        return {};
    }

    // The syllable in `folder` at `tempo` (rounded to 0.05: the same pace is made once).
    const std::vector<float>& at(const std::string& folder, double tempo) {
        const int step = static_cast<int>(std::lround(tempo * 20.0));
        const auto key = std::make_pair(folder, step);
        auto found = paced_.find(key);
        if (found != paced_.end()) return found->second;
        auto recorded = recorded_.find(folder);
        if (recorded == recorded_.end())
            recorded = recorded_.emplace(folder, trim(decode(voice_dir_ / folder / kSpeakerFile))).first;
        std::vector<float> paced = recorded->second;
        if (step != 20) {
            const fs::path in = work_dir_ / "syllable.wav", out = work_dir_ / "paced.wav";
            talkface_bench::write_wav(in.string(), {recorded->second, kRateHz});
            talkface_bench::run_sox(in.string(), out.string(), "-b 16", "tempo -s " + std::to_string(step / 20.0));
            paced = trim(talkface_bench::read_wav(out.string()).samples);
        }
        return paced_.emplace(key, std::move(paced)).first->second;
    }

private:
    fs::path voice_dir_, work_dir_;
    std::map<std::string, std::vector<float>> recorded_;
    std::map<std::pair<std::string, int>, std::vector<float>> paced_;
};

// --- how a passage is spoken ---------------------------------------------------------------------

// Drawn once per passage and shared by every condition (only the sentence tempo's range differs).
struct Delivery {
    std::vector<double> tempo_unit;    ///< per sentence, in [0, 1): where in the condition's range
    std::vector<double> syllable_pace; ///< per syllable: its pace against the sentence's
    std::vector<double> gain;          ///< per syllable: its level against the recording's
    std::vector<double> join_s;        ///< per syllable inside a phrase: > 0 a gap before it, < 0 an overlap
    std::vector<double> voiced_join_s; ///< the same where its initial is voiced (a cross-fade)
    std::vector<double> closure_s;     ///< per syllable: a stop's or affricate's closure after speech
    std::vector<double> pause_s;       ///< per syllable: the pause before it after a comma
    std::vector<double> sentence_gaps_s;  ///< before the first sentence, between sentences, after the last
};

// How a person reads a sentence, as far as joined syllables can show it:
// - the pace wanders inside a sentence: the log of a syllable's pace against the sentence's tempo
//   is a random walk pulled back to 0 (standard deviation 0.25, correlated over about five
//   syllables), so that a run of syllables comes quicker or slower than the sentence as a whole;
//   a light (neutral) tone is said quicker and the last syllable of a phrase slower;
// - syllables differ in level (standard deviation 4 dB), a light tone 6 dB weaker;
// - inside a phrase a syllable runs into the one before: 60% of joins overlap by up to 40 ms (the
//   next sound starts under the last one's end, no dip between them), the rest leave a gap of up
//   to 30 ms; no overlap starts before the middle of the vowel before (see speak); a stop or
//   affricate after speech is preceded by its closure, 20-60 ms of silence;
// - a comma's pause lasts 0.15-0.35 s, a sentence's 0.4-1.0 s.
Delivery draw_delivery(const talkface::Timeline& transcript, std::mt19937_64& rng) {
    using talkface_bench::gaussian;
    using talkface_bench::uniform;
    Delivery delivery;
    for (std::size_t k = 0; k < transcript.sentences.size(); ++k) delivery.tempo_unit.push_back(uniform(rng, 0, 1));
    double walk = 0.0;
    for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
        if (i == 0 || transcript.syllables[i - 1].sentence != transcript.syllables[i].sentence) walk = 0.25 * gaussian(rng);
        else walk = 0.8 * walk + 0.15 * gaussian(rng);
        delivery.syllable_pace.push_back(std::exp(walk));
        delivery.gain.push_back(std::pow(10.0, 4.0 * gaussian(rng) / 20.0));
        delivery.join_s.push_back(uniform(rng, 0, 1) < 0.6 ? -uniform(rng, 0.0, 0.04) : uniform(rng, 0.0, 0.03));
        delivery.voiced_join_s.push_back(-uniform(rng, 0.03, 0.08));
        delivery.closure_s.push_back(uniform(rng, 0.02, 0.06));
        delivery.pause_s.push_back(uniform(rng, 0.15, 0.35));
    }
    delivery.sentence_gaps_s.push_back(uniform(rng, 0.3, 0.6));
    for (std::size_t k = 1; k < transcript.sentences.size(); ++k) delivery.sentence_gaps_s.push_back(uniform(rng, 0.4, 1.0));
    delivery.sentence_gaps_s.push_back(uniform(rng, 0.4, 0.8));
    return delivery;
}

// What running speech adds to a Delivery (the `r-` conditions). Citation syllables joined one by
// one keep what a person says alone: a fresh attack, a long decay, a closure before every stop, a
// pause at every comma, a steady pitch. A fluent speaker at 1.3-1.5 times a careful pace does not:
// - a syllable's decay is cut short where the next begins: 60-85% of its sound is heard, the rest
//   is spoken over (the next syllable starts there, with a 10 ms fade of the one before);
// - a voiced initial (m n l r, or none) loses the first 10-40 ms of its recorded attack, then
//   cross-fades with the vowel before over 30-70 ms, from no earlier than the middle of its heard
//   part; other initials overlap the one before by up to 30 ms or follow after up to 15 ms; a
//   stop's or affricate's closure lasts 0-40 ms;
// - the pace jitters per syllable (standard deviation 0.12 of its log) on top of the wandering of
//   Delivery, and the last syllable of a phrase is said 0.75 times as fast;
// - the pitch falls through a sentence by 100-300 cents (declination), from a level of its own
//   (standard deviation 100 cents), each syllable 40 cents up or down; the level falls by 3-6 dB
//   through a sentence, from a sentence level of its own (standard deviation 3 dB);
// - only 45% of commas are heard as a pause (0.08-0.25 s); the others run on.
// Drawn from a stream of its own, so that the other conditions' files do not change.
constexpr double kMeanTailKeep = 0.725;
struct RunningDelivery {
    std::vector<double> tail_keep;      ///< per syllable: share of its sound heard before the next starts
    std::vector<double> attack_cut_s;   ///< per syllable: its attack left out after a voiced join
    std::vector<double> voiced_join_s;  ///< per syllable: the cross-fade of a voiced join (negative)
    std::vector<double> join_s;         ///< per syllable: the gap (> 0) or overlap (< 0) of another join
    std::vector<double> closure_s;      ///< per syllable: a stop's or affricate's closure
    std::vector<double> pace_jitter;    ///< per syllable: its pace against the wandering one
    std::vector<double> pitch_cents;    ///< per syllable: its pitch against the sentence's line
    std::vector<bool> comma_is_pause;   ///< per syllable after a comma: heard as a pause
    std::vector<double> pause_s;        ///< per syllable: that pause
    std::vector<double> sentence_cents;      ///< per sentence: its pitch level
    std::vector<double> declination_cents;   ///< per sentence: how far its pitch falls
    std::vector<double> sentence_gain_db;    ///< per sentence: its level
    std::vector<double> fading_db;           ///< per sentence: how far its level falls
};

RunningDelivery draw_running(const talkface::Timeline& transcript, std::mt19937_64& rng) {
    using talkface_bench::gaussian;
    using talkface_bench::uniform;
    RunningDelivery running;
    for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
        running.tail_keep.push_back(uniform(rng, kMeanTailKeep - 0.125, kMeanTailKeep + 0.125));
        running.attack_cut_s.push_back(uniform(rng, 0.01, 0.04));
        running.voiced_join_s.push_back(-uniform(rng, 0.03, 0.07));
        running.join_s.push_back(uniform(rng, 0, 1) < 0.6 ? -uniform(rng, 0.0, 0.03) : uniform(rng, 0.0, 0.015));
        running.closure_s.push_back(uniform(rng, 0.0, 0.04));
        running.pace_jitter.push_back(std::exp(0.12 * gaussian(rng)));
        running.pitch_cents.push_back(40.0 * gaussian(rng));
        running.comma_is_pause.push_back(uniform(rng, 0, 1) < 0.45);
        running.pause_s.push_back(uniform(rng, 0.08, 0.25));
    }
    for (std::size_t k = 0; k < transcript.sentences.size(); ++k) {
        running.sentence_cents.push_back(100.0 * gaussian(rng));
        running.declination_cents.push_back(uniform(rng, 100.0, 300.0));
        running.sentence_gain_db.push_back(3.0 * gaussian(rng));
        running.fading_db.push_back(uniform(rng, 3.0, 6.0));
    }
    return running;
}

// `sound` read `factor` times faster by linear interpolation: its pitch (and its formants) raised
// by `factor`, its length divided by it. Speaker 3's syllables are near 8 kHz-band speech, and
// the factors here are within 0.8-1.25, so the interpolation's own roll-off does not matter.
std::vector<float> resampled(const std::vector<float>& sound, double factor) {
    std::vector<float> out;
    if (sound.size() < 2) return sound;
    const auto count = static_cast<std::size_t>(static_cast<double>(sound.size() - 1) / factor);
    out.reserve(count);
    for (std::size_t n = 0; n < count; ++n) {
        const double at = static_cast<double>(n) * factor;
        const auto k = static_cast<std::size_t>(at);
        const double share = at - static_cast<double>(k);
        out.push_back(static_cast<float>(sound[k] * (1.0 - share) + sound[k + 1] * share));
    }
    return out;
}

struct Recording {
    MonoAudio audio;
    talkface::Timeline truth;
    std::vector<bool> after_pause;
    std::vector<double> tempo;  ///< per sentence
    int fallbacks = 0;          ///< syllables spoken in another tone than the transcript's (not recorded)
    std::map<std::string, double> drawn;  ///< what the condition drew for the passage (the person), for the truth file
};

// A closed tract still voiced: from `from` to `to` (a closure), the sound before it (`last_sound`,
// mixed in at `last_at` with `last_gain`) goes on low-passed at 400 Hz (a one-pole filter: the
// voice bar of a stop said between vowels, its formants gone) at a fifth of its level, 2 ms ramps
// at either end. Where `last_sound` ends first, so does the voicing.
void voice_through_closure(std::vector<float>& samples, std::size_t from, std::size_t to, const std::vector<float>& last_sound,
                           std::size_t last_at, double last_gain) {
    constexpr double kBarGain = 0.2;
    constexpr std::size_t kRamp = kRateHz / 500;
    const double alpha = 1.0 - std::exp(-2.0 * 3.141592653589793 * 400.0 / kRateHz);
    double low = 0.0;
    // The filter runs from 10 ms before the closure, so that it starts on the vowel's level.
    const std::size_t warm = std::max(last_at, from >= kRateHz / 100 ? from - kRateHz / 100 : 0);
    for (std::size_t n = warm; n < to && n - last_at < last_sound.size(); ++n) {
        low += alpha * (last_sound[n - last_at] - low);
        if (n < from) continue;
        const double ramp = std::min(1.0, static_cast<double>(std::min(n - from, to - 1 - n)) / kRamp);
        samples[n] += static_cast<float>(kBarGain * last_gain * ramp * low);
    }
}

// Where the vowel of a recorded syllable begins: the first 5 ms frame whose level below 1 kHz (a
// second-order Butterworth low-pass, the power over the 20 ms around the frame, longer than a pitch
// period) comes within 10 dB of the syllable's loudest. A vowel's first formant lies there; the
// voiceless initials (s sh x f h, aspiration, a burst) carry little below 1 kHz and stay 20 dB and
// more under it, while m n l r, voiced, mostly count with the vowel as the syllable's sonorant part.
std::size_t vowel_start(const std::vector<float>& sound) {
    constexpr std::size_t kHop = kRateHz / 200, kHalfWindow = kRateHz / 100;
    const double k = std::tan(3.141592653589793 * 1000.0 / kRateHz), q = std::sqrt(0.5);
    const double norm = 1.0 / (1.0 + k / q + k * k);
    const double b0 = k * k * norm, a1 = 2.0 * (k * k - 1.0) * norm, a2 = (1.0 - k / q + k * k) * norm;
    std::vector<double> power(sound.size() + 1, 0.0);
    double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
    for (std::size_t n = 0; n < sound.size(); ++n) {
        const double y = b0 * (sound[n] + 2.0 * x1 + x2) - a1 * y1 - a2 * y2;
        x2 = x1, x1 = sound[n], y2 = y1, y1 = y;
        power[n + 1] = power[n] + y * y;
    }
    std::vector<double> level;
    for (std::size_t centre = kHop / 2; centre < sound.size(); centre += kHop) {
        const std::size_t from = centre > kHalfWindow ? centre - kHalfWindow : 0,
                          to = std::min(sound.size(), centre + kHalfWindow);
        level.push_back((power[to] - power[from]) / static_cast<double>(to - from));
    }
    if (level.empty()) return 0;
    const double loudest = *std::max_element(level.begin(), level.end());
    std::size_t frame = 0;
    while (level[frame] < loudest * 0.1) ++frame;
    return frame * kHop;
}

// The level of the joined speech: speaker 3's syllables are recorded near -10 dBFS at their peak.
constexpr double kOverallGain = 0.7;

Recording speak(const talkface::Timeline& transcript, const Delivery& delivery, const RunningDelivery& running,
                const Condition& condition, SyllableBank& bank, const std::string& where, double voice_factor = 1.0) {
    Recording recording;
    recording.truth = transcript;
    recording.audio.sample_rate_hz = kRateHz;
    auto& samples = recording.audio.samples;
    recording.after_pause.assign(transcript.syllables.size(), false);
    const bool is_running = condition.is_running;
    // `end` is where the last syllable's sound ends; sounds are added (mixed) from `at` on.
    std::size_t end = 0;
    // The last syllable mixed in, its gain and where it starts: running speech cuts its tail.
    std::vector<float> last_sound;
    double last_gain = 0.0;
    std::size_t last_at = 0;
    std::size_t last_vowel = 0;  // where its vowel begins, counted from last_at
    std::size_t last_start = 0;  // its start in the truth
    const auto to_samples = [](double seconds) { return static_cast<std::size_t>(std::lround(seconds * kRateHz)); };
    const auto seconds = [](std::size_t at) { return static_cast<double>(at) / kRateHz; };
    for (std::size_t k = 0; k < transcript.sentences.size(); ++k) {
        end += to_samples(delivery.sentence_gaps_s[k]);
        const double tempo = condition.min_tempo + (condition.max_tempo - condition.min_tempo) * delivery.tempo_unit[k];
        recording.tempo.push_back(tempo);
        // with_voice will play it `voice_factor` times faster: said that much slower here.
        const double said_tempo = tempo / voice_factor;
        std::size_t sentence_first = transcript.syllables.size(), sentence_count = 0;
        for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
            if (transcript.syllables[i].sentence != k) continue;
            sentence_first = std::min(sentence_first, i);
            ++sentence_count;
        }
        bool is_first = true;
        for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
            auto& syllable = recording.truth.syllables[i];
            if (syllable.sentence != k) continue;
            const Reading reading = read_pinyin(syllable.pinyin, where + " \"" + syllable.text + "\"");
            bool is_exact = true;
            const std::string folder = bank.folder(reading, is_exact);
            if (folder.empty()) throw std::runtime_error(where + ": speaker 3 has no recording of " + syllable.pinyin);
            recording.fallbacks += !is_exact;
            const bool after_comma = !is_first && transcript.syllables[i - 1].pause_after;
            const bool ends_phrase = syllable.pause_after || i + 1 == transcript.syllables.size() ||
                                     transcript.syllables[i + 1].sentence != k;
            // Where in its sentence the syllable comes, 0 to 1: pitch and level fall along it.
            const double position = sentence_count > 1 ? static_cast<double>(i - sentence_first) / static_cast<double>(sentence_count - 1) : 0.0;
            double pace = said_tempo * delivery.syllable_pace[i] * (is_running ? running.pace_jitter[i] : 1.0);
            double gain = kOverallGain * delivery.gain[i];
            if (reading.tone == 5) {
                pace *= is_exact ? 1.2 : 1.7;
                gain *= 0.5;
            }
            if (ends_phrase) pace *= is_running ? 0.75 : 0.85;
            std::vector<float> sound;
            if (is_running) {
                gain *= std::pow(10.0, (running.sentence_gain_db[k] - running.fading_db[k] * position) / 20.0);
                const double cents = running.sentence_cents[k] - running.declination_cents[k] * position + running.pitch_cents[i];
                const double factor = std::pow(2.0, cents / 1200.0);
                // Read `factor` times faster after sox's tempo: sox makes up the rest of the pace. Its
                // tail spoken over, a syllable is said slower for the same pace: kMeanTailKeep of it
                // is heard before the next, which then comes when it would at that pace.
                const double citation_pace = std::clamp(kCitationToCareful * pace * kMeanTailKeep, 0.8, 4.0);
                sound = resampled(bank.at(folder, citation_pace / factor), factor);
            } else {
                sound = bank.at(folder, std::clamp(kCitationToCareful * pace, 1.0, 4.0));
            }
            const bool after_pause = is_first || (after_comma && (!is_running || running.comma_is_pause[i]));
            if (after_comma && after_pause) end += to_samples(is_running ? running.pause_s[i] : delivery.pause_s[i]);
            const bool is_voiced_join = !after_pause && is_voiced_onset(reading.initial);
            if (is_running && !after_pause) {
                // The last syllable's decay is spoken over: it ends (a 10 ms fade) where this one begins.
                const std::size_t heard =
                    std::max(last_at + static_cast<std::size_t>(running.tail_keep[i] *
                                                                static_cast<double>(last_sound.size())),
                             std::min(end, last_start + to_samples(kMinSyllableS)));
                if (heard < end) {
                    const std::size_t fade = std::min<std::size_t>(kRateHz / 100, heard - last_at);
                    for (std::size_t n = heard - fade; n < end; ++n) {
                        const double kept = n < heard ? static_cast<double>(heard - n) / static_cast<double>(fade) : 0.0;
                        samples[n] -= static_cast<float>((1.0 - kept) * last_gain * last_sound[n - last_at]);
                    }
                    end = heard;
                }
                if (is_voiced_join) {
                    const std::size_t cut = std::min(to_samples(running.attack_cut_s[i]), sound.size() / 4);
                    sound.erase(sound.begin(), sound.begin() + static_cast<std::ptrdiff_t>(cut));
                }
            }
            // The truth (SPEC "Alignment"): after a pause, the first sound (a stop's burst); after
            // speech, a stop's or affricate's closure start, any other initial's first sound.
            std::size_t at = end;
            std::size_t start = end;
            if (!after_pause && has_closure(reading.initial)) {
                start = std::max(end, last_start + to_samples(kMinSyllableS));
                at = start + to_samples(is_running ? running.closure_s[i] : delivery.closure_s[i]);
            } else if (!after_pause) {
                // A voiced initial (m n l r, or none: a vowel, y-, w-) after a vowel is voiced right
                // through: the two cross-fade over the whole overlap, with no dip and no attack.
                // An overlap starts no earlier than the middle of the heard part of the vowel before:
                // a listener hears that syllable's vowel before the next sound grows in, and a light
                // 了 or 的, or a 是 that is mostly sh, is not spoken over from its first frames.
                const double join = is_voiced_join ? (is_running ? running.voiced_join_s[i] : delivery.voiced_join_s[i])
                                                    : (is_running ? running.join_s[i] : delivery.join_s[i]);
                const std::size_t vowel_middle = std::min(end, last_at + (last_vowel + end - last_at) / 2);
                at = join >= 0 ? end + to_samples(join)
                               : std::max(end - std::min(to_samples(-join), sound.size() / 4), vowel_middle);
                at = std::max(at, std::min(end, last_start + to_samples(kMinSyllableS)));
                start = at;
            }
            syllable.start_s = seconds(start);
            recording.after_pause[i] = after_pause;
            const std::size_t fade = is_voiced_join && at < end ? end - at : 0;
            if (samples.size() < at + sound.size()) samples.resize(at + sound.size(), 0.0f);
            if (condition.is_lenis && is_running && !after_pause && is_lenis(reading.initial) && at > end)
                voice_through_closure(samples, end, at, last_sound, last_at, last_gain);
            for (std::size_t n = 0; n < fade; ++n) {
                const double share = 0.5 - 0.5 * std::cos(3.141592653589793 * static_cast<double>(n) / static_cast<double>(fade));
                samples[at + n] = static_cast<float>(samples[at + n] * (1.0 - share) + share * gain * sound[n]);
            }
            for (std::size_t n = fade; n < sound.size(); ++n) samples[at + n] += static_cast<float>(gain) * sound[n];
            end = at + sound.size();
            last_vowel = vowel_start(sound);
            last_sound = std::move(sound);
            last_gain = gain;
            last_at = at;
            last_start = start;
            syllable.end_s = seconds(end);
            // A syllable ends where the next starts, or at its last sound before a pause.
            if (!is_first && !after_pause) recording.truth.syllables[i - 1].end_s = syllable.start_s;
            is_first = false;
        }
        // A sentence runs from its first syllable's start to its last sound.
        auto& sentence = recording.truth.sentences[k];
        bool has_start = false;
        for (const auto& syllable : recording.truth.syllables) {
            if (syllable.sentence != k) continue;
            if (!has_start) sentence.start_s = syllable.start_s;
            has_start = true;
            sentence.end_s = syllable.end_s;
        }
    }
    samples.resize(end + to_samples(delivery.sentence_gaps_s.back()), 0.0f);
    recording.truth.duration_s = seconds(samples.size());
    return recording;
}

std::string truth_json(const Recording& recording, const std::string& condition, const std::string& set) {
    auto document = talkface_bench::truth_document("talkface bench/make_human_corpus, gcin-voice speaker 3", condition, set,
                                                   recording.truth, recording.after_pause);
    for (std::size_t k = 0; k < recording.tempo.size(); ++k)
        document["sentences"][k]["tempo"] = std::round(recording.tempo[k] * 1000.0) / 1000.0;
    for (const auto& [name, value] : recording.drawn) document["drawn"][name] = std::round(value * 1000.0) / 1000.0;
    return document.dump(1) + "\n";
}

// `recording` with `lead_s` of silence before it and `trail_s` after, its truth moved with it.
Recording with_ends(Recording recording, double lead_s, double trail_s) {
    const auto lead = static_cast<std::size_t>(std::lround(lead_s * kRateHz));
    const auto trail = static_cast<std::size_t>(std::lround(trail_s * kRateHz));
    auto& samples = recording.audio.samples;
    samples.insert(samples.begin(), lead, 0.0f);
    samples.resize(samples.size() + trail, 0.0f);
    const double shift_s = static_cast<double>(lead) / kRateHz;
    for (auto& syllable : recording.truth.syllables) syllable.start_s += shift_s, syllable.end_s += shift_s;
    for (auto& sentence : recording.truth.sentences) sentence.start_s += shift_s, sentence.end_s += shift_s;
    recording.truth.duration_s = static_cast<double>(samples.size()) / kRateHz;
    return recording;
}

// `recording` as another voice: played `factor` times faster (sox `speed`, resampled), so its pitch
// and its formants, a vocal tract's resonances, move together by `factor` (2-4 semitones: a
// shorter or longer tract than speaker 3's, as between men, or a man and a woman); speak said it
// `factor` times slower, so the pace is the condition's. The truth is scaled with it, exactly.
Recording with_voice(Recording recording, double factor, const fs::path& work) {
    const fs::path in = work / "voice-in.wav", out = work / "voice-out.wav";
    talkface_bench::write_wav(in.string(), recording.audio);
    talkface_bench::run_sox(in.string(), out.string(), "-b 16", "speed " + std::to_string(factor) + " rate -v 16k");
    recording.audio = talkface_bench::read_wav(out.string());
    for (auto& syllable : recording.truth.syllables) syllable.start_s /= factor, syllable.end_s /= factor;
    for (auto& sentence : recording.truth.sentences) sentence.start_s /= factor, sentence.end_s /= factor;
    recording.truth.duration_s = static_cast<double>(recording.audio.samples.size()) / kRateHz;
    return recording;
}

// Another person (`w-`), drawn per passage. `v-` moves pitch and formants together, as one vocal
// tract scaled; people differ otherwise too:
// - the formants alone move by a ratio of 1.08-1.20 (a shorter tract: a woman's, a child's) or
//   0.86-0.93 (a longer one), up or down at even odds;
// - the pitch has a median of its own, 95-240 Hz (log-uniform; speaker 3's is about 135 Hz), drawn
//   apart from the formants, and a range of its own: its excursions 0.6-1.5 times speaker 3's;
// - a microphone and room of its own: a shelf of -8 to +6 dB below 150 Hz (a thin microphone or
//   a close one's boom), another above 3 kHz (muffled or bright), and half of the passages cut
//   above 4.5-7 kHz (a cheap microphone, a compressed file);
// - a breathier voice (`w-breathy`): breath noise that follows the voice's loudness, 12-20 dB under it.
struct Person {
    double formant_ratio = 1.0;
    double pitch_median_hz = 0.0;
    double pitch_range = 1.0;
    double bass_db = 0.0;
    double treble_db = 0.0;
    double lowpass_hz = 0.0;  ///< 0: none
    double breath_db = 0.0;   ///< 0: none
};

Person draw_person(const Condition& condition, std::mt19937_64& rng) {
    using talkface_bench::uniform;
    Person person;
    person.formant_ratio = uniform(rng, 0, 1) < 0.5 ? uniform(rng, 1.08, 1.20) : uniform(rng, 0.86, 0.93);
    person.pitch_median_hz = std::exp(uniform(rng, std::log(95.0), std::log(240.0)));
    person.pitch_range = uniform(rng, 0.6, 1.5);
    person.bass_db = uniform(rng, -8.0, 6.0);
    person.treble_db = uniform(rng, -8.0, 6.0);
    if (uniform(rng, 0, 1) < 0.5) person.lowpass_hz = uniform(rng, 4500.0, 7000.0);
    if (condition.max_breath_db < 0) person.breath_db = uniform(rng, condition.max_breath_db - 8.0, condition.max_breath_db);
    return person;
}

// praat's Change gender (the pitch found at 75-600 Hz): the sound resampled by the formant ratio,
// then pitch-synchronous overlap-add (PSOLA) brings its length back and sets the new pitch median
// and range, so every sound stays where it was and the truth stands as it is. Peak at 0.9 so
// that nothing clips on the way to sox.
constexpr const char* kChangeVoiceScript = R"(form Change voice
  sentence in
  sentence out
  real formant_ratio 1
  real pitch_median 0
  real pitch_range 1
endform
Read from file: in$
Change gender: 75, 600, formant_ratio, pitch_median, pitch_range, 1
Scale peak: 0.9
Save as WAV file: out$
)";

// `recording` as `person` says it into its microphone (praat, then sox's shelves and low-pass,
// peak at -3 dBFS), with its breath. Times do not move. The breath's noise comes from `rng`.
Recording with_person(Recording recording, const Person& person, const fs::path& work, std::mt19937_64& rng) {
    const fs::path script = work / "change_voice.praat", in = work / "person-in.wav", changed = work / "person-changed.wav",
                   out = work / "person-out.wav";
    talkface_bench::write_text(script, kChangeVoiceScript);
    talkface_bench::write_wav(in.string(), recording.audio);
    const std::string command = "praat --run " + talkface_bench::quoted(script.string()) + " " +
                                talkface_bench::quoted(in.string()) + " " + talkface_bench::quoted(changed.string()) + " " +
                                std::to_string(person.formant_ratio) + " " + std::to_string(person.pitch_median_hz) + " " +
                                std::to_string(person.pitch_range) + " >/dev/null";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("praat failed: " + command);
    std::string effects = "bass " + std::to_string(person.bass_db) + " 150 treble " + std::to_string(person.treble_db) + " 3000";
    if (person.lowpass_hz > 0) effects += " lowpass " + std::to_string(person.lowpass_hz);
    talkface_bench::run_sox(changed.string(), out.string(), "-b 16", effects + " gain -n -3");
    const std::size_t count = recording.audio.samples.size();
    recording.audio = talkface_bench::read_wav(out.string());
    if (recording.audio.samples.size() != count)
        throw std::runtime_error("praat and sox changed the length of " + in.string() + ": its truth would not hold");
    if (person.breath_db < 0) {
        // Breath: white noise tilted up (a first difference: aspiration is a high sound), its
        // level following the voice's over 20 ms, `breath_db` under it.
        auto& samples = recording.audio.samples;
        constexpr std::size_t kWindow = kRateHz / 50;
        std::vector<double> power(samples.size() + 1, 0.0);
        for (std::size_t n = 0; n < samples.size(); ++n) power[n + 1] = power[n] + double(samples[n]) * samples[n];
        const double gain = std::pow(10.0, person.breath_db / 20.0) / std::sqrt(2.0);  // the difference doubles white noise's power
        double last = talkface_bench::gaussian(rng);
        std::vector<float> breathy = samples;
        for (std::size_t n = 0; n < samples.size(); ++n) {
            const std::size_t from = n >= kWindow / 2 ? n - kWindow / 2 : 0, to = std::min(samples.size(), n + kWindow / 2);
            const double level = std::sqrt((power[to] - power[from]) / static_cast<double>(to - from));
            const double white = talkface_bench::gaussian(rng);
            breathy[n] += static_cast<float>(gain * level * (white - last));
            last = white;
        }
        samples = std::move(breathy);
    }
    recording.drawn = {{"formant_ratio", person.formant_ratio}, {"pitch_median_hz", person.pitch_median_hz},
                       {"pitch_range", person.pitch_range},     {"bass_db", person.bass_db},
                       {"treble_db", person.treble_db},         {"lowpass_hz", person.lowpass_hz},
                       {"breath_db", person.breath_db}};
    return recording;
}

// The condition applied to the joined speech: sox's effects, then noise at the condition's SNR,
// then the telephone's band and codec. A condition that draws (its SNR, its ends) draws from
// `noise_rng` before the noise does.
MonoAudio record(const Recording& recording, const Condition& condition, const fs::path& work, std::mt19937_64& noise_rng) {
    MonoAudio audio = recording.audio;
    if (*condition.sox_effects) {
        const fs::path in = work / "joined.wav", out = work / "effects.wav";
        talkface_bench::write_wav(in.string(), audio);
        talkface_bench::run_sox(in.string(), out.string(), "-b 16", condition.sox_effects);
        audio = talkface_bench::read_wav(out.string());
    }
    const double snr_db = condition.max_snr_db > condition.snr_db ? talkface_bench::uniform(noise_rng, condition.snr_db, condition.max_snr_db)
                                                                  : condition.snr_db;
    if (condition.noise != Noise::none) audio = talkface_bench::add_noise(audio, recording.truth, condition.noise, snr_db, noise_rng);
    if (condition.is_phone) {
        // sox's GSM 06.10 (the full-rate codec of 2G calls, still what many phone recorders and
        // voice mails store) takes 8 kHz mono; decoded back to 16-bit WAV at 8 kHz.
        const fs::path in = work / "mixed.wav", coded = work / "phone.gsm", out = work / "phone.wav";
        talkface_bench::write_wav(in.string(), audio);
        talkface_bench::run_sox(in.string(), coded.string(), "-r 8000 -c 1", "sinc 300-3400 rate -v 8k");
        talkface_bench::run_sox(coded.string(), out.string(), "-b 16", "");
        audio = talkface_bench::read_wav(out.string());
    }
    return audio;
}

struct CorpusOptions {
    std::string out_dir;
    std::uint64_t seed = 1;
    int repeats = 3;
    std::string sentences_path;
    std::string voice_dir;
    std::vector<const Condition*> conditions;
};

void make_corpus(const CorpusOptions& options) {
    const auto sentences = talkface_bench::load_sentences(options.sentences_path);
    std::mt19937_64 rng(options.seed);
    std::vector<talkface_bench::PlannedPassage> passages;
    std::vector<Delivery> deliveries;
    talkface_bench::plan_passages(sentences, options.repeats, rng, [&](const talkface_bench::PlannedPassage& planned) {
        passages.push_back(planned);
        deliveries.push_back(draw_delivery(talkface::read_transcript(planned.transcript, {}, planned.name), rng));
    });
    // Running speech's draws come from a stream of their own per passage: the h- files stay as they were.
    std::vector<RunningDelivery> runnings;
    for (std::size_t p = 0; p < passages.size(); ++p) {
        std::seed_seq running_seed{options.seed, static_cast<std::uint64_t>(p), std::uint64_t{12}};
        std::mt19937_64 running_rng(running_seed);
        runnings.push_back(draw_running(talkface::read_transcript(passages[p].transcript, {}, passages[p].name), running_rng));
    }
    const fs::path out = options.out_dir;
    const fs::path work = out / ".work";
    fs::create_directories(work);
    SyllableBank bank(options.voice_dir, work);
    std::string listing;
    for (const Condition* condition : options.conditions) {
        fs::create_directories(out / condition->name);
        listing += std::string(condition->name) + "\t" + condition->description + "\n";
    }
    talkface_bench::write_text(out / "conditions.txt", listing);
    double seconds = 0;
    int fallbacks = 0;
    for (std::size_t p = 0; p < passages.size(); ++p) {
        const auto& passage = passages[p];
        const auto transcript = talkface::read_transcript(passage.transcript, {}, passage.name);
        for (const Condition* condition : options.conditions) {
            const auto condition_index = static_cast<std::uint64_t>(condition - all_conditions);
            // The noise comes from a stream of its own per passage and condition.
            std::seed_seq noise_seed{options.seed, static_cast<std::uint64_t>(p), condition_index};
            std::mt19937_64 noise_rng(noise_seed);
            double voice_factor = 1.0;
            if (condition->max_voice_semitones > 0) {
                const double semitones = talkface_bench::uniform(noise_rng, condition->min_voice_semitones, condition->max_voice_semitones);
                voice_factor = std::pow(2.0, (talkface_bench::uniform(noise_rng, 0, 1) < 0.5 ? -semitones : semitones) / 12.0);
            }
            const Person person = condition->is_other_person ? draw_person(*condition, noise_rng) : Person{};
            Recording recording = speak(transcript, deliveries[p], runnings[p], *condition, bank, passage.name, voice_factor);
            if (voice_factor != 1.0) recording = with_voice(std::move(recording), voice_factor, work);
            if (condition->is_other_person) recording = with_person(std::move(recording), person, work, noise_rng);
            if (condition->max_ends_s > 0) {
                const double lead_s = talkface_bench::uniform(noise_rng, condition->min_ends_s, condition->max_ends_s);
                recording = with_ends(std::move(recording), lead_s,
                                      talkface_bench::uniform(noise_rng, condition->min_ends_s, condition->max_ends_s));
            }
            const fs::path stem = out / condition->name / passage.name;
            talkface_bench::write_wav(stem.string() + ".wav", record(recording, *condition, work, noise_rng));
            talkface_bench::write_text(stem.string() + ".txt", passage.transcript);
            talkface_bench::write_text(stem.string() + ".json", truth_json(recording, condition->name, passage.set));
            if (condition == options.conditions.front()) {
                seconds += recording.truth.duration_s;
                fallbacks += recording.fallbacks;
            }
        }
        std::cout << passage.name << " (" << p + 1 << "/" << passages.size() << ")\n" << std::flush;
    }
    fs::remove_all(work);
    std::cout << passages.size() << " passages, " << std::lround(seconds) << " s of speech per condition, "
              << options.conditions.size() << " conditions in " << out.string() << "; " << fallbacks
              << " syllables spoken in a tone speaker 3 has instead of the missing one\n";
}

void make_clip(const std::string& stem, const std::string& text, std::uint64_t seed, double tempo,
               const std::string& voice_dir) {
    const auto transcript = talkface::read_transcript(text, {}, "<clip text>");
    std::mt19937_64 rng(seed);
    const Delivery delivery = draw_delivery(transcript, rng);
    const Condition condition{"clip", "", tempo, tempo, Noise::none, 0, ""};
    const fs::path work = fs::path(stem).parent_path() / (fs::path(stem).filename().string() + ".work");
    fs::create_directories(work);
    SyllableBank bank(voice_dir, work);
    const Recording recording = speak(transcript, delivery, draw_running(transcript, rng), condition, bank, stem);
    talkface_bench::write_wav(stem + ".wav", recording.audio);
    talkface_bench::write_text(stem + ".txt", text + "\n");
    talkface_bench::write_text(stem + ".json", truth_json(recording, "clip", "test"));
    fs::remove_all(work);
}

}  // namespace

int main(int argc, char** argv) {
    talkface_bench::CorpusUsage usage{
        "make_human_corpus",
        "usage: make_human_corpus OUT [--seed N] [--repeats N] [--sentences FILE] [--voice DIR] "
        "[--conditions A,B,...]\n"
        "       make_human_corpus --clip STEM [--seed N] [--tempo T] [--voice DIR] TEXT\n",
        {}};
    for (const auto& condition : all_conditions) usage.conditions.push_back(condition.name);
    try {
        std::string voice_dir = kDefaultVoiceDir;
        double clip_tempo = 1.2;
        const talkface_bench::CorpusCommand command = talkface_bench::parse_corpus_command(
            argc, argv, usage, TALKFACE_BENCH_SENTENCES,
            {{"--voice", [&](auto&, auto& value) { voice_dir = value; }},
             {"--tempo", [&](auto& name, auto& value) {
                  clip_tempo = talkface_bench::parse_number<double>(name, value);
              }}});
        if (!command.clip_stem.empty()) {
            make_clip(command.clip_stem, command.clip_text, command.seed, clip_tempo, voice_dir);
            return 0;
        }
        CorpusOptions corpus{command.out_dir,        command.seed, command.repeats,
                             command.sentences_path, voice_dir,    {}};
        corpus.conditions = talkface_bench::select_conditions(all_conditions, command.conditions);
        make_corpus(corpus);
        return 0;
    } catch (const std::invalid_argument& error) {
        usage.fail(error.what());
    } catch (const std::exception& error) {
        std::cerr << "make_human_corpus: " << error.what() << "\n";
        return 1;
    }
}
