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

#include "corpus_tools.hpp"
#include "espeak_speech.hpp"
#include "wav_file.hpp"

namespace fs = std::filesystem;
using talkface_bench::BenchSentence;
using talkface_bench::MonoAudio;
using talkface_bench::Noise;
using talkface_bench::add_noise;
using talkface_bench::load_sentences;
using talkface_bench::read_text;
using talkface_bench::uniform;
using talkface_bench::uniform_int;
using talkface_bench::write_text;

namespace {

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

// Every output is 16-bit PCM except OGG and GSM; resampling is sox's linear-phase "rate -v", which keeps times.
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
    // Issue 13, recordings as people have them: a tune with drums and a melody, mains hum with a
    // fan, and a phone's voice mail (the telephone band at 8 kHz, GSM 06.10 in WAV, read by libsndfile).
    {"song15", "a tune (chords, bass, melody, drums), SNR 15 dB", 1.0, Noise::song, 15, "", "", "wav", false},
    {"mainsfan15", "mains hum (50 or 60 Hz and harmonics) and a fan, SNR 15 dB", 1.0, Noise::mains_fan, 15, "", "", "wav",
     false},
    {"gsm", "300-3400 Hz band, 8 kHz, GSM 06.10 in WAV", 1.0, Noise::none, 0, "sinc 300-3400 rate -v 8k",
     "-e gsm-full-rate", "wav", false},
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

void run_sox(const std::string& input, const std::string& output, const Condition& condition) {
    talkface_bench::run_sox(input, output, condition.sox_output_options, condition.sox_effects);
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

// The passages of talkface_bench::plan_passages, each with its delivery drawn from the same stream
// as soon as its sentences are chosen.
std::vector<Passage> plan_passages(const std::vector<BenchSentence>& sentences, int repeats, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Passage> passages;
    talkface_bench::plan_passages(sentences, repeats, rng, [&](const talkface_bench::PlannedPassage& planned) {
        passages.push_back({planned.name, planned.set, planned.transcript, draw_delivery(planned.sentence_count, rng)});
    });
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
    auto document = talkface_bench::truth_document("talkface bench/make_corpus, espeak-ng voice cmn-latn-pinyin", condition,
                                                   set, recording.truth, recording.after_pause);
    for (std::size_t k = 0; k < recording.truth.sentences.size(); ++k) {
        document["sentences"][k]["rate_wpm"] = std::lround(delivery.rate_wpm[k] * rate_factor);
        document["sentences"][k]["pitch"] = delivery.pitch[k];
    }
    return document.dump(1) + "\n";
}

struct CorpusOptions {
    std::string out_dir;
    std::uint64_t seed = 1;
    int repeats = 3;
    std::string sentences_path;
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

}  // namespace

int main(int argc, char** argv) {
    talkface_bench::CorpusUsage usage{
        "make_corpus",
        "usage: make_corpus OUT [--seed N] [--repeats N] [--sentences FILE] [--conditions A,B,...]\n"
        "       make_corpus --clip STEM [--seed N] [--rate-wpm N] [--pitch N] [--pause-s S] TEXT\n",
        {}};
    for (const auto& condition : all_conditions) usage.conditions.push_back(condition.name);
    try {
        ClipOptions clip;
        const talkface_bench::CorpusCommand command = talkface_bench::parse_corpus_command(
            argc, argv, usage, TALKFACE_BENCH_SENTENCES,
            {{"--rate-wpm",
              [&](auto& name, auto& value) {
                  clip.rate_wpm = talkface_bench::parse_number<int>(name, value);
              }},
             {"--pitch",
              [&](auto& name, auto& value) { clip.pitch = talkface_bench::parse_number<int>(name, value); }},
             {"--pause-s", [&](auto& name, auto& value) {
                  clip.pause_s = talkface_bench::parse_number<double>(name, value);
              }}});
        if (!command.clip_stem.empty()) {
            clip.stem = command.clip_stem;
            clip.text = command.clip_text;
            clip.seed = command.seed;
            make_clip(clip);
            return 0;
        }
        CorpusOptions corpus{command.out_dir, command.seed, command.repeats, command.sentences_path, {}};
        corpus.conditions = talkface_bench::select_conditions(all_conditions, command.conditions);
        make_corpus(corpus);
        return 0;
    } catch (const std::invalid_argument& error) {
        usage.fail(error.what());
    } catch (const std::exception& error) {
        std::cerr << "make_corpus: " << error.what() << "\n";
        return 1;
    }
}
