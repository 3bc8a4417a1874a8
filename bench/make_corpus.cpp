// make_corpus: the aligner benchmark's corpus. Mandarin passages spoken by espeak-ng with the
// start of every syllable known, in the recording conditions of bench/README.md (made with sox).
//
//   make_corpus OUT [--seed N] [--repeats N] [--sentences FILE] [--conditions clean,white10,...]
//   make_corpus --clip STEM [--seed N] [--rate-wpm N] [--pitch N] [--pause-s S] TEXT
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <talkface/talkface.hpp>

#include "espeak_speech.hpp"
#include "wav_file.hpp"

namespace fs = std::filesystem;
using talkface_bench::MonoAudio;

namespace {

// The noises under the voice (issue #13 adds the steady and the musical ones, which are not blamed
// on the transcript either): hum is mains hum (50 Hz and its harmonics), tone_pink a steady 440 Hz
// tone under pink noise, music a synthetic tune (chords of harmonic notes, a bass, changing every
// 0.2-0.6 s), room a ventilated room (low-passed pink noise with a 120 Hz motor line).
enum class Noise { none, white, pink, brown, hum, tone_pink, music, room };

struct Condition {
    const char* name;
    const char* description;
    double rate_factor;       ///< speaking rate against the corpus's drawn rate
    Noise noise;              ///< added to the clean recording at snr_db
    double snr_db;
    const char* sox_effects;  ///< applied to espeak-ng's 22.05 kHz output when noise is none
    const char* sox_output_options;
    const char* extension;
    bool runs_together;       ///< sentences 0-kMaxJointGapS apart instead of the passage's pauses
    double silent_ends_s = 0; ///< extra silence before and after the passage (truth moved with it)
};

// A speaker who runs sentences together leaves at most a breath's catch between them: shorter than
// the 0.12 s that talkface's cutter takes for a pause, so that no sentence end can be cut at one.
constexpr double kMaxJointGapS = 0.12;

// Every output is 16-bit except OGG; resampling is sox's linear-phase "rate -v", which keeps times.
const Condition all_conditions[] = {
    {"clean", "16 kHz mono 16-bit", 1.0, Noise::none, 0, "rate -v 16k", "-b 16", "wav", false},
    {"white30", "white noise, SNR 30 dB", 1.0, Noise::white, 30, "", "", "wav", false},
    {"white20", "white noise, SNR 20 dB", 1.0, Noise::white, 20, "", "", "wav", false},
    {"white10", "white noise, SNR 10 dB", 1.0, Noise::white, 10, "", "", "wav", false},
    {"pink20", "pink noise, SNR 20 dB", 1.0, Noise::pink, 20, "", "", "wav", false},
    {"brown20", "brown noise, SNR 20 dB", 1.0, Noise::brown, 20, "", "", "wav", false},
    {"reverb", "room reverb (sox reverb 40 50 60)", 1.0, Noise::none, 0, "rate -v 16k reverb 40 50 60 gain -n -3",
     "-b 16", "wav", false},
    {"telephone", "300-3400 Hz band, 8 kHz", 1.0, Noise::none, 0, "sinc 300-3400 rate -v 8k", "-b 16", "wav", false},
    {"ogg", "Ogg Vorbis quality 2, 16 kHz", 1.0, Noise::none, 0, "rate -v 16k", "-C 2", "ogg", false},
    {"quiet", "peak at -30 dBFS", 1.0, Noise::none, 0, "rate -v 16k gain -n -30", "-b 16", "wav", false},
    {"loud", "peak at -0.1 dBFS", 1.0, Noise::none, 0, "rate -v 16k gain -n -0.1", "-b 16", "wav", false},
    {"stereo44", "stereo 44.1 kHz, right channel 2 dB lower", 1.0, Noise::none, 0, "remix 1 1v0.8 rate -v 44100",
     "-b 16", "wav", false},
    {"fast", "speaking rate +40%", 1.4, Noise::none, 0, "rate -v 16k", "-b 16", "wav", false},
    {"slow", "speaking rate -30%", 0.7, Noise::none, 0, "rate -v 16k", "-b 16", "wav", false},
    {"joined", "sentences run together, 0-0.12 s apart", 1.0, Noise::none, 0, "rate -v 16k", "-b 16", "wav", true},
    {"hum15", "mains hum (50 Hz and harmonics), SNR 15 dB", 1.0, Noise::hum, 15, "", "", "wav", false},
    {"tonepink15", "a steady 440 Hz tone under pink noise, SNR 15 dB", 1.0, Noise::tone_pink, 15, "", "", "wav", false},
    {"music15", "synthetic music, SNR 15 dB", 1.0, Noise::music, 15, "", "", "wav", false},
    {"music20", "synthetic music, SNR 20 dB", 1.0, Noise::music, 20, "", "", "wav", false},
    {"room15", "room noise (ventilation and a motor's hum), SNR 15 dB", 1.0, Noise::room, 15, "", "", "wav", false},
    {"silentends", "6 s of silence before and after", 1.0, Noise::none, 0, "rate -v 16k pad 6 6", "-b 16", "wav", false,
     6.0},
};

struct BenchSentence {
    std::string text;  ///< as written in sentences.txt, reading fixes kept
    std::string set;   ///< "tuning" or "held-out"
};

/// How one passage is spoken: drawn once, shared by every condition.
struct Delivery {
    std::vector<int> rate_wpm;  ///< per sentence
    std::vector<int> pitch;     ///< per sentence, espeak-ng's 0..100
    std::vector<double> gaps_s;  ///< silence before the first sentence, between sentences, after the last
};

struct Passage {
    std::string name;
    std::string set;
    std::string transcript;  ///< one sentence a line
    Delivery delivery;
};

/// A spoken passage and its ground truth (Timeline times in seconds).
struct Recording {
    MonoAudio audio;
    talkface::Timeline truth;
    std::vector<bool> after_pause;  ///< per syllable
};

double uniform(std::mt19937_64& rng, double low, double high) {
    // Not std::uniform_real_distribution, whose output differs between standard libraries.
    const double unit = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    return low + (high - low) * unit;
}

int uniform_int(std::mt19937_64& rng, int low, int high) {
    return low + static_cast<int>(std::floor(uniform(rng, 0.0, 1.0) * (high - low + 1)));
}

double gaussian(std::mt19937_64& rng) {
    const double u1 = 1.0 - uniform(rng, 0.0, 1.0);
    const double u2 = uniform(rng, 0.0, 1.0);
    constexpr double two_pi = 6.283185307179586;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(two_pi * u2);
}

std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

void run_sox(const std::string& input, const std::string& output, const Condition& condition) {
    // -R: sox's dither and any other randomness repeat from run to run.
    const std::string command = std::string("sox -R -V1 ") + quoted(input) + " " + condition.sox_output_options + " " +
                                quoted(output) + " " + condition.sox_effects;
    if (std::system(command.c_str()) != 0) throw std::runtime_error("sox failed: " + command);
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    file << text;
    if (!file) throw std::runtime_error(path.string() + ": cannot write");
}

std::string read_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error(path.string() + ": cannot read");
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

std::vector<BenchSentence> load_sentences(const std::string& path) {
    std::istringstream lines(read_text(path));
    std::vector<BenchSentence> sentences;
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        if (line.empty() || line[0] == '#') continue;
        const std::string where = path + ":" + std::to_string(number);
        const auto tab = line.find('\t');
        if (tab == std::string::npos) throw std::runtime_error(where + ": expected SET<TAB>SENTENCE");
        BenchSentence sentence{line.substr(tab + 1), line.substr(0, tab)};
        if (sentence.set != "tuning" && sentence.set != "held-out")
            throw std::runtime_error(where + ": set \"" + sentence.set + "\" is neither tuning nor held-out");
        const auto timeline = talkface::read_transcript(sentence.text, {}, where);
        if (timeline.sentences.size() != 1 || !timeline.warnings.empty())
            throw std::runtime_error(where + ": expected one sentence of characters with readings");
        sentences.push_back(std::move(sentence));
    }
    if (sentences.empty()) throw std::runtime_error(path + ": no sentences");
    return sentences;
}

Delivery draw_delivery(std::size_t sentence_count, std::mt19937_64& rng) {
    Delivery delivery;
    for (std::size_t i = 0; i < sentence_count; ++i) {
        delivery.rate_wpm.push_back(uniform_int(rng, 170, 230));
        delivery.pitch.push_back(uniform_int(rng, 35, 65));
    }
    delivery.gaps_s.push_back(uniform(rng, 0.3, 0.6));
    for (std::size_t i = 1; i < sentence_count; ++i) delivery.gaps_s.push_back(uniform(rng, 0.4, 1.2));
    delivery.gaps_s.push_back(uniform(rng, 0.4, 0.8));
    return delivery;
}

// The passage's delivery with every pause between two sentences replaced by 0-kMaxJointGapS, drawn
// per joint from a stream seeded by the corpus seed, the passage and the condition.
Delivery join_sentences(Delivery delivery, std::uint64_t seed, std::size_t passage, std::uint64_t condition_index) {
    std::seed_seq joint_seed{seed, static_cast<std::uint64_t>(passage), condition_index};
    std::mt19937_64 rng(joint_seed);
    for (std::size_t i = 1; i + 1 < delivery.gaps_s.size(); ++i) delivery.gaps_s[i] = uniform(rng, 0.0, kMaxJointGapS);
    return delivery;
}

// Each repeat shuffles each set and splits it into passages of about five sentences, so that a
// sentence is heard in different neighbours, rates and pitches.
std::vector<Passage> plan_passages(const std::vector<BenchSentence>& sentences, int repeats, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Passage> passages;
    for (const std::string set : {"tuning", "held-out"}) {
        std::vector<std::string> texts;
        for (const auto& sentence : sentences)
            if (sentence.set == set) texts.push_back(sentence.text);
        if (texts.empty()) continue;
        const std::size_t per_repeat = std::max<std::size_t>(1, (texts.size() + 2) / 5);
        int number = 1;
        for (int repeat = 0; repeat < repeats; ++repeat) {
            for (std::size_t i = texts.size(); i > 1; --i)
                std::swap(texts[i - 1], texts[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(i) - 1))]);
            for (std::size_t part = 0; part < per_repeat; ++part) {
                const std::size_t begin = part * texts.size() / per_repeat;
                const std::size_t end = (part + 1) * texts.size() / per_repeat;
                Passage passage;
                char name[32];
                std::snprintf(name, sizeof name, "%s-%03d", set.c_str(), number++);
                passage.name = name;
                passage.set = set;
                for (std::size_t i = begin; i < end; ++i) passage.transcript += texts[i] + "\n";
                passage.delivery = draw_delivery(end - begin, rng);
                passages.push_back(std::move(passage));
            }
        }
    }
    return passages;
}

/// A passage's sentences as espeak-ng spoke them, each trimmed to its sounds, before they are joined.
struct SpokenPassage {
    talkface::Timeline transcript;
    std::vector<talkface_bench::SpokenSentence> sentences;
    int sample_rate_hz = 0;
};

SpokenPassage speak_passage(const talkface_bench::EspeakVoice& voice, const std::string& transcript,
                            const Delivery& delivery, double rate_factor, const std::string& where) {
    SpokenPassage passage;
    passage.transcript = talkface::read_transcript(transcript, {}, where);
    if (!passage.transcript.warnings.empty()) throw std::runtime_error(passage.transcript.warnings.front());
    const std::size_t sentence_count = passage.transcript.sentences.size();
    if (delivery.rate_wpm.size() != sentence_count)
        throw std::runtime_error(where + ": " + std::to_string(sentence_count) + " sentences, expected " +
                                 std::to_string(delivery.rate_wpm.size()));
    passage.sample_rate_hz = voice.sample_rate_hz();
    for (std::size_t k = 0; k < sentence_count; ++k) {
        std::vector<talkface::Syllable> syllables;
        for (const auto& syllable : passage.transcript.syllables)
            if (syllable.sentence == k) syllables.push_back(syllable);
        const auto rate_wpm = static_cast<int>(std::lround(delivery.rate_wpm[k] * rate_factor));
        passage.sentences.push_back(
            voice.speak(syllables, rate_wpm, delivery.pitch[k], where + " sentence " + std::to_string(k + 1)));
    }
    return passage;
}

// The spoken sentences one after the other with gaps_s of silence before, between and after them.
Recording join_passage(const SpokenPassage& passage, const std::vector<double>& gaps_s) {
    Recording recording;
    recording.truth = passage.transcript;
    const double rate = passage.sample_rate_hz;
    auto& samples = recording.audio.samples;
    recording.audio.sample_rate_hz = passage.sample_rate_hz;
    recording.after_pause.resize(recording.truth.syllables.size());
    for (std::size_t k = 0; k < passage.sentences.size(); ++k) {
        samples.resize(samples.size() + static_cast<std::size_t>(std::lround(gaps_s[k] * rate)), 0.0f);
        const auto& spoken = passage.sentences[k];
        const double offset_s = static_cast<double>(samples.size()) / rate;
        std::size_t j = 0;
        for (std::size_t i = 0; i < recording.truth.syllables.size(); ++i) {
            auto& syllable = recording.truth.syllables[i];
            if (syllable.sentence != k) continue;
            syllable.start_s = offset_s + static_cast<double>(spoken.syllables[j].start) / rate;
            syllable.end_s = offset_s + static_cast<double>(spoken.syllables[j].end) / rate;
            recording.after_pause[i] = spoken.syllables[j].after_pause;
            ++j;
        }
        auto& sentence = recording.truth.sentences[k];
        sentence.start_s = offset_s;
        sentence.end_s = offset_s + static_cast<double>(spoken.samples.size()) / rate;
        samples.insert(samples.end(), spoken.samples.begin(), spoken.samples.end());
    }
    samples.resize(samples.size() + static_cast<std::size_t>(std::lround(gaps_s.back() * rate)), 0.0f);
    recording.truth.duration_s = static_cast<double>(samples.size()) / rate;
    return recording;
}

double rounded(double seconds) { return std::round(seconds * 1e5) / 1e5; }

// The recording's truth `by_s` later, as the silence sox put before it moves it.
Recording shifted(const Recording& recording, double by_s) {
    Recording moved{{}, recording.truth, recording.after_pause};
    for (auto& sentence : moved.truth.sentences) sentence.start_s += by_s, sentence.end_s += by_s;
    for (auto& syllable : moved.truth.syllables) {
        syllable.start_s += by_s;
        syllable.end_s += by_s;
        if (syllable.final_start_s) *syllable.final_start_s += by_s;
    }
    moved.truth.duration_s += 2 * by_s;
    return moved;
}

std::string truth_json(const Recording& recording, const Delivery& delivery, double rate_factor,
                       const std::string& condition, const std::string& set) {
    nlohmann::ordered_json document;
    document["generator"] = "talkface bench/make_corpus, espeak-ng voice cmn-latn-pinyin";
    document["condition"] = condition;
    document["set"] = set;
    document["duration"] = rounded(recording.truth.duration_s);
    document["sentences"] = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < recording.truth.sentences.size(); ++k) {
        const auto& sentence = recording.truth.sentences[k];
        document["sentences"].push_back({{"text", sentence.text},
                                         {"start", rounded(sentence.start_s)},
                                         {"end", rounded(sentence.end_s)},
                                         {"rate_wpm", std::lround(delivery.rate_wpm[k] * rate_factor)},
                                         {"pitch", delivery.pitch[k]}});
    }
    document["syllables"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < recording.truth.syllables.size(); ++i) {
        const auto& syllable = recording.truth.syllables[i];
        document["syllables"].push_back({{"text", syllable.text},
                                         {"pinyin", syllable.pinyin},
                                         {"start", rounded(syllable.start_s)},
                                         {"end", rounded(syllable.end_s)},
                                         {"sentence", syllable.sentence},
                                         {"after_pause", static_cast<bool>(recording.after_pause[i])}});
    }
    return document.dump(1) + "\n";
}

// Paul Kellet's pink filter (within 0.05 dB of -3 dB/octave above 10 Hz at these rates) and a
// leaky integrator for brown (-6 dB/octave); the SNR is set from the measured power afterwards.
std::vector<float> make_noise(Noise colour, std::size_t count, std::mt19937_64& rng) {
    std::vector<float> noise(count);
    double b0 = 0, b1 = 0, b2 = 0, integrated = 0;
    for (auto& sample : noise) {
        const double white = gaussian(rng);
        double value = white;
        if (colour == Noise::pink) {
            b0 = 0.99765 * b0 + white * 0.0990460;
            b1 = 0.96300 * b1 + white * 0.2965164;
            b2 = 0.57000 * b2 + white * 1.0526913;
            value = b0 + b1 + b2 + white * 0.1848;
        } else if (colour == Noise::brown) {
            integrated = 0.995 * integrated + white;
            value = integrated;
        }
        sample = static_cast<float>(value);
    }
    return noise;
}

constexpr double kPi = 3.14159265358979323846;

// A sum of harmonics of `frequency_hz` with amplitudes 1/k, at time `t_s`: a note, a hum.
double harmonics(double frequency_hz, int count, double t_s) {
    double value = 0;
    for (int k = 1; k <= count; ++k) value += std::sin(2 * kPi * k * frequency_hz * t_s) / k;
    return value;
}

// The steady and musical noises, at `rate_hz`.
std::vector<float> make_tonal_noise(Noise kind, std::size_t count, int rate_hz, std::mt19937_64& rng) {
    std::vector<float> noise(count, 0.0f);
    if (kind == Noise::hum || kind == Noise::tone_pink) {
        const std::vector<float> pink = kind == Noise::tone_pink ? make_noise(Noise::pink, count, rng) : std::vector<float>();
        double pink_power = 0;
        for (float v : pink) pink_power += double(v) * v;
        // Tone and pink noise of equal power (the tone's is 1/2).
        const double pink_gain = pink.empty() ? 0.0 : std::sqrt(0.5 / (pink_power / static_cast<double>(count)));
        for (std::size_t i = 0; i < count; ++i) {
            const double t = static_cast<double>(i) / rate_hz;
            noise[i] = static_cast<float>(kind == Noise::hum ? harmonics(50.0, 8, t) : std::sin(2 * kPi * 440.0 * t) + pink_gain * pink[i]);
        }
        return noise;
    }
    if (kind == Noise::room) {
        const std::vector<float> pink = make_noise(Noise::pink, count, rng);
        double low = 0;
        for (std::size_t i = 0; i < count; ++i) {
            low += 0.15 * (pink[i] - low);  // one pole near 400 Hz at 16 kHz: the rumble of air
            noise[i] = static_cast<float>(low + 0.15 * std::sin(2 * kPi * 120.0 * static_cast<double>(i) / rate_hz));
        }
        return noise;
    }
    // Music: a pentatonic tune of three-note chords over a bass, each chord 0.2-0.6 s with a soft
    // attack and a decay, so that its onsets come as often as syllables do.
    const double scale[] = {220.0, 246.9, 277.2, 329.6, 370.0, 440.0, 493.9, 554.4};
    std::size_t i = 0;
    while (i < count) {
        const auto length = static_cast<std::size_t>(uniform(rng, 0.2, 0.6) * rate_hz);
        const double root = scale[static_cast<std::size_t>(uniform(rng, 0, 5.999))];
        const double third = root * 1.25, fifth = root * 1.5, bass = root / 4;
        for (std::size_t j = 0; j < length && i < count; ++j, ++i) {
            const double t = static_cast<double>(i) / rate_hz;
            const double since = static_cast<double>(j) / rate_hz;
            const double envelope = std::min(1.0, since / 0.02) * std::exp(-since * 3.0);
            noise[i] = static_cast<float>(envelope * (harmonics(root, 6, t) + harmonics(third, 5, t) + harmonics(fifth, 5, t)) +
                                          0.8 * harmonics(bass, 4, t));
        }
    }
    return noise;
}

// SNR against the speech's active level: mean power inside the sentences, pauses left out.
MonoAudio add_noise(const MonoAudio& clean, const talkface::Timeline& truth, Noise colour, double snr_db,
                    std::mt19937_64& rng) {
    double speech_power = 0;
    std::size_t speech_count = 0;
    for (const auto& sentence : truth.sentences) {
        const auto begin = static_cast<std::size_t>(sentence.start_s * clean.sample_rate_hz);
        const auto end = std::min(clean.samples.size(), static_cast<std::size_t>(sentence.end_s * clean.sample_rate_hz));
        for (std::size_t i = begin; i < end; ++i) speech_power += double(clean.samples[i]) * clean.samples[i];
        speech_count += end > begin ? end - begin : 0;
    }
    speech_power /= static_cast<double>(std::max<std::size_t>(speech_count, 1));
    const bool is_tonal = colour == Noise::hum || colour == Noise::tone_pink || colour == Noise::music || colour == Noise::room;
    const auto noise = is_tonal ? make_tonal_noise(colour, clean.samples.size(), clean.sample_rate_hz, rng)
                                : make_noise(colour, clean.samples.size(), rng);
    double noise_power = 0;
    for (float sample : noise) noise_power += double(sample) * sample;
    noise_power /= static_cast<double>(std::max<std::size_t>(noise.size(), 1));
    const double gain = std::sqrt(speech_power / (noise_power * std::pow(10.0, snr_db / 10.0)));
    MonoAudio mixed = clean;
    float peak = 0;
    for (std::size_t i = 0; i < mixed.samples.size(); ++i) {
        mixed.samples[i] += static_cast<float>(gain * noise[i]);
        peak = std::max(peak, std::fabs(mixed.samples[i]));
    }
    // Scaling speech and noise together keeps the SNR and avoids clipping.
    if (peak > 0.98f)
        for (auto& sample : mixed.samples) sample *= 0.98f / peak;
    return mixed;
}

struct CorpusOptions {
    std::string out_dir;
    std::uint64_t seed = 1;
    int repeats = 3;
    std::string sentences_path = TALKFACE_BENCH_SENTENCES;
    std::vector<const Condition*> conditions;
};

void make_corpus(const CorpusOptions& options) {
    const auto sentences = load_sentences(options.sentences_path);
    const auto passages = plan_passages(sentences, options.repeats, options.seed);
    const fs::path out = options.out_dir;
    const fs::path work = out / ".work";
    fs::create_directories(work);
    talkface_bench::EspeakVoice voice;

    std::string listing;
    for (const Condition* condition : options.conditions) {
        fs::create_directories(out / condition->name);
        listing += std::string(condition->name) + "\t" + condition->description + "\n";
    }
    write_text(out / "conditions.txt", listing);

    double seconds = 0;
    for (std::size_t p = 0; p < passages.size(); ++p) {
        const Passage& passage = passages[p];
        // espeak-ng speaks each passage once per rate (fast and slow again); the sentences it
        // spoke are joined once per kind of pause between them. Joining, not speaking again, keeps
        // espeak-ng's calls, and so every other condition's files, what they were for the same seed.
        std::map<double, SpokenPassage> spoken;
        std::map<std::pair<double, bool>, Recording> joined;
        const fs::path clean_wav = work / (passage.name + "-clean.wav");
        const auto master_wav = [&](const Condition& condition) {
            return (work / (passage.name + "-x" + std::to_string(std::lround(condition.rate_factor * 100)) +
                            (condition.runs_together ? "-joined" : "") + ".wav"))
                .string();
        };
        for (std::size_t c = 0; c < options.conditions.size(); ++c) {
            const Condition& condition = *options.conditions[c];
            const auto condition_index = static_cast<std::uint64_t>(&condition - all_conditions);
            auto voice_found = spoken.find(condition.rate_factor);
            if (voice_found == spoken.end()) {
                voice_found = spoken.emplace(condition.rate_factor, speak_passage(voice, passage.transcript, passage.delivery,
                                                                                  condition.rate_factor, passage.name))
                                  .first;
            }
            const auto key = std::make_pair(condition.rate_factor, condition.runs_together);
            auto found = joined.find(key);
            if (found == joined.end()) {
                // The joints come from a stream of their own: the passage's draws stay as they were.
                const Delivery delivery = condition.runs_together
                                              ? join_sentences(passage.delivery, options.seed, p, condition_index)
                                              : passage.delivery;
                found = joined.emplace(key, join_passage(voice_found->second, delivery.gaps_s)).first;
                talkface_bench::write_wav(master_wav(condition), found->second.audio);
            }
            const Recording& recording = found->second;
            const fs::path stem = out / condition.name / passage.name;
            const std::string audio_path = stem.string() + "." + condition.extension;
            if (condition.noise == Noise::none) {
                run_sox(master_wav(condition), audio_path, condition);
            } else {
                if (!fs::exists(clean_wav)) run_sox(master_wav(condition), clean_wav.string(), all_conditions[0]);
                std::seed_seq noise_seed{options.seed, static_cast<std::uint64_t>(p), condition_index};
                std::mt19937_64 rng(noise_seed);
                talkface_bench::write_wav(audio_path, add_noise(talkface_bench::read_wav(clean_wav.string()),
                                                                recording.truth, condition.noise, condition.snr_db, rng));
            }
            write_text(stem.string() + ".txt", passage.transcript);
            write_text(stem.string() + ".json", truth_json(shifted(recording, condition.silent_ends_s), passage.delivery,
                                                           condition.rate_factor, condition.name, passage.set));
        }
        const auto normal = joined.find({1.0, false});
        seconds += normal != joined.end() ? normal->second.truth.duration_s : 0.0;
        std::cout << passage.name << " (" << p + 1 << "/" << passages.size() << ")\n" << std::flush;
    }
    fs::remove_all(work);
    std::cout << passages.size() << " passages, " << std::lround(seconds) << " s of speech per condition, "
              << options.conditions.size() << " conditions in " << out.string() << "\n";
}

struct ClipOptions {
    std::string stem;
    std::string text;
    std::uint64_t seed = 1;
    int rate_wpm = 200;
    int pitch = 50;
    double pause_s = 0.8;
};

void make_clip(const ClipOptions& options) {
    const auto timeline = talkface::read_transcript(options.text, {}, "<clip text>");
    const std::size_t count = timeline.sentences.size();
    Delivery delivery;
    delivery.rate_wpm.assign(count, options.rate_wpm);
    delivery.pitch.assign(count, options.pitch);
    delivery.gaps_s.push_back(0.3);
    for (std::size_t i = 1; i < count; ++i) delivery.gaps_s.push_back(options.pause_s);
    delivery.gaps_s.push_back(0.3);
    talkface_bench::EspeakVoice voice;
    const auto recording = join_passage(speak_passage(voice, options.text, delivery, 1.0, options.stem), delivery.gaps_s);
    const std::string master = options.stem + ".master.wav";
    talkface_bench::write_wav(master, recording.audio);
    run_sox(master, options.stem + ".wav", all_conditions[0]);
    fs::remove(master);
    write_text(options.stem + ".txt", options.text + "\n");
    write_text(options.stem + ".json", truth_json(recording, delivery, 1.0, "clip", "test"));
}

[[noreturn]] void usage(const std::string& problem) {
    std::cerr << "make_corpus: " << problem << "\n"
              << "usage: make_corpus OUT [--seed N] [--repeats N] [--sentences FILE] [--conditions A,B,...]\n"
              << "       make_corpus --clip STEM [--seed N] [--rate-wpm N] [--pitch N] [--pause-s S] TEXT\n"
              << "conditions:";
    for (const auto& condition : all_conditions) std::cerr << " " << condition.name;
    std::cerr << "\n";
    std::exit(2);
}

template <typename Number>
Number number_arg(const std::string& name, const std::string& value) {
    std::istringstream in(value);
    Number number{};
    if (!(in >> number) || !in.eof()) usage(name + " expects a number, got \"" + value + "\"");
    return number;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        CorpusOptions corpus;
        ClipOptions clip;
        bool clip_mode = false;
        std::vector<std::string> positional;
        std::string condition_list;
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            const auto value = [&]() -> std::string {
                if (i + 1 >= argc) usage(arg + " needs a value");
                return argv[++i];
            };
            if (arg == "--clip") {
                clip_mode = true;
                clip.stem = value();
            } else if (arg == "--seed") {
                corpus.seed = clip.seed = number_arg<std::uint64_t>(arg, value());
            } else if (arg == "--repeats") {
                corpus.repeats = number_arg<int>(arg, value());
            } else if (arg == "--sentences") {
                corpus.sentences_path = value();
            } else if (arg == "--conditions") {
                condition_list = value();
            } else if (arg == "--rate-wpm") {
                clip.rate_wpm = number_arg<int>(arg, value());
            } else if (arg == "--pitch") {
                clip.pitch = number_arg<int>(arg, value());
            } else if (arg == "--pause-s") {
                clip.pause_s = number_arg<double>(arg, value());
            } else if (arg == "-h" || arg == "--help") {
                usage("help");
            } else if (!arg.empty() && arg[0] == '-') {
                usage("unknown option " + arg);
            } else {
                positional.push_back(arg);
            }
        }
        if (positional.size() != 1) usage(clip_mode ? "give the clip's TEXT" : "give the output directory OUT");
        if (clip_mode) {
            clip.text = positional[0];
            make_clip(clip);
            return 0;
        }
        corpus.out_dir = positional[0];
        if (corpus.repeats < 1) usage("--repeats must be at least 1");
        std::istringstream names(condition_list);
        for (std::string name; std::getline(names, name, ',');) {
            const auto found = std::find_if(std::begin(all_conditions), std::end(all_conditions),
                                            [&](const Condition& condition) { return name == condition.name; });
            if (found == std::end(all_conditions)) usage("unknown condition \"" + name + "\"");
            corpus.conditions.push_back(found);
        }
        if (corpus.conditions.empty())
            for (const auto& condition : all_conditions) corpus.conditions.push_back(&condition);
        make_corpus(corpus);
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "make_corpus: " << error.what() << "\n";
        return 1;
    }
}
