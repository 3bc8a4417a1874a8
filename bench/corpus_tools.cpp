#include "corpus_tools.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include <talkface/transcript.hpp>

namespace talkface_bench {

void CorpusUsage::fail(const std::string& problem) const {
    std::cerr << program << ": " << problem << "\n" << lines << "conditions:";
    for (const std::string& condition : conditions) std::cerr << " " << condition;
    std::cerr << "\n";
    std::exit(2);
}

CorpusCommand parse_corpus_command(int argc, char** argv, const CorpusUsage& usage,
                                   const std::string& sentences_path,
                                   const std::vector<std::pair<std::string, OwnOption>>& own) {
    CorpusCommand command;
    command.sentences_path = sentences_path;
    std::vector<std::string> positional;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            const auto value = [&]() -> std::string {
                if (i + 1 >= argc) usage.fail(arg + " needs a value");
                return argv[++i];
            };
            const auto own_option =
                std::find_if(own.begin(), own.end(), [&](const auto& o) { return o.first == arg; });
            if (arg == "--clip")
                command.clip_stem = value();
            else if (arg == "--seed")
                command.seed = parse_number<std::uint64_t>(arg, value());
            else if (arg == "--repeats")
                command.repeats = parse_number<int>(arg, value());
            else if (arg == "--sentences")
                command.sentences_path = value();
            else if (arg == "--conditions")
                command.conditions = value();
            else if (own_option != own.end())
                own_option->second(arg, value());
            else if (arg == "-h" || arg == "--help")
                usage.fail("help");
            else if (!arg.empty() && arg[0] == '-')
                usage.fail("unknown option " + arg);
            else
                positional.push_back(arg);
        }
    } catch (const std::invalid_argument& error) {
        usage.fail(error.what());
    }
    const bool is_clip = !command.clip_stem.empty();
    if (positional.size() != 1)
        usage.fail(is_clip ? "give the clip's TEXT" : "give the output directory OUT");
    (is_clip ? command.clip_text : command.out_dir) = positional[0];
    if (command.repeats < 1) usage.fail("--repeats must be at least 1");
    return command;
}

double uniform(std::mt19937_64& rng, double low, double high) {
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

void run_sox(const std::string& input, const std::string& output, const std::string& output_options,
             const std::string& effects) {
    const std::string command = "sox -R -V1 " + quoted(input) + " " + output_options + " " + quoted(output) + " " + effects;
    if (std::system(command.c_str()) != 0) throw std::runtime_error("sox failed: " + command);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    file << text;
    if (!file) throw std::runtime_error(path.string() + ": cannot write");
}

std::string read_text(const std::filesystem::path& path) {
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

void plan_passages(const std::vector<BenchSentence>& sentences, int repeats, std::mt19937_64& rng,
                   const std::function<void(const PlannedPassage&)>& on_planned) {
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
                PlannedPassage passage;
                char name[32];
                std::snprintf(name, sizeof name, "%s-%03d", set.c_str(), number++);
                passage.name = name;
                passage.set = set;
                for (std::size_t i = begin; i < end; ++i) passage.transcript += texts[i] + "\n";
                passage.sentence_count = end - begin;
                on_planned(passage);
            }
        }
    }
}

namespace {

std::vector<float> make_random_noise(Noise colour, std::size_t count, std::mt19937_64& rng) {
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
        const std::vector<float> pink = kind == Noise::tone_pink ? make_random_noise(Noise::pink, count, rng) : std::vector<float>();
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
        const std::vector<float> pink = make_random_noise(Noise::pink, count, rng);
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

// `signal` scaled to a mean power of 1 (left as it is if silent).
void normalise_power(std::vector<float>& signal) {
    double power = 0;
    for (float v : signal) power += double(v) * v;
    power /= static_cast<double>(std::max<std::size_t>(signal.size(), 1));
    if (power <= 0) return;
    const double gain = 1.0 / std::sqrt(power);
    for (auto& v : signal) v = static_cast<float>(v * gain);
}

// A note of `frequency_hz` (harmonics with amplitudes 1/k) added to `out` from sample `first`: a
// linear attack, then an exponential decay at `decay_per_s`, cut off after `length_s`. A vibrato of
// 5 Hz and `vibrato` (a share of the frequency) gives a sung or bowed melody its life.
void add_note(std::vector<float>& out, std::size_t first, double length_s, int rate_hz, double frequency_hz, int harmonic_count,
              double amplitude, double attack_s, double decay_per_s, double vibrato = 0.0) {
    const auto length = static_cast<std::size_t>(length_s * rate_hz);
    double phase = 0;
    for (std::size_t j = 0; j < length && first + j < out.size(); ++j) {
        const double since = static_cast<double>(j) / rate_hz;
        phase += 2 * kPi * frequency_hz * (1.0 + vibrato * std::sin(2 * kPi * 5.0 * since)) / rate_hz;
        // The last 10 ms fade out, so that a note cut short does not click.
        const double release = std::min(1.0, (length_s - since) / 0.01);
        const double envelope = std::min(1.0, since / attack_s) * std::exp(-since * decay_per_s) * release;
        double value = 0;
        for (int k = 1; k <= harmonic_count; ++k) value += std::sin(k * phase) / k;
        out[first + j] += static_cast<float>(amplitude * envelope * value);
    }
}

// A tune as a radio plays one under a voice: a bar of four beats at 85-135 beats a minute, chords
// I-V-vi-IV of a drawn key held through each bar, a bass on beats 1 and 3, a melody of the key's
// pentatonic scale in eighth notes with rests, and a drum kit (a kick on 1 and 3, a snare on 2 and
// 4, a hi-hat on every eighth): onsets of every kind, as often as syllables, tonal and noisy.
std::vector<float> make_song(std::size_t count, int rate_hz, std::mt19937_64& rng) {
    std::vector<float> music(count, 0.0f), drums(count, 0.0f);
    const double beat_s = 60.0 / uniform(rng, 85.0, 135.0);
    const double key_hz = 220.0 * std::pow(2.0, uniform_int(rng, -5, 6) / 12.0);
    const auto semitones = [&](double semitone) { return key_hz * std::pow(2.0, semitone / 12.0); };
    // Each chord as its root and two more tones, in semitones above the key.
    const int chords[4][3] = {{0, 4, 7}, {7, 11, 14}, {9, 12, 16}, {5, 9, 12}};
    const int pentatonic[] = {0, 2, 4, 7, 9, 12, 14, 16};
    const auto at = [&](double seconds) { return static_cast<std::size_t>(seconds * rate_hz); };
    for (std::size_t bar = 0; at(static_cast<double>(bar) * 4 * beat_s) < count; ++bar) {
        const double bar_s = static_cast<double>(bar) * 4 * beat_s;
        const auto& chord = chords[bar % 4];
        for (int tone : chord) add_note(music, at(bar_s), 4 * beat_s, rate_hz, semitones(tone), 5, 0.25, 0.05, 0.4);
        for (int beat : {0, 2}) add_note(music, at(bar_s + beat * beat_s), 2 * beat_s, rate_hz, semitones(chord[0]) / 4, 4, 0.6, 0.01, 3.0);
        for (int eighth = 0; eighth < 8; ++eighth) {
            const double start_s = bar_s + eighth * beat_s / 2;
            if (uniform(rng, 0, 1) < 0.7) {
                const int degree = pentatonic[uniform_int(rng, 0, 7)];
                const double length_s = (uniform(rng, 0, 1) < 0.3 ? 2 : 1) * beat_s / 2;
                add_note(music, at(start_s), length_s, rate_hz, 2 * semitones(degree), 4, 0.4, 0.01, 2.0, 0.004);
            }
            // Drums: a falling sine for the kick, noise and a 185 Hz body for the snare, a click of
            // high noise (the difference of white samples) for the hi-hat.
            const bool is_kick = eighth == 0 || eighth == 4, is_snare = eighth == 2 || eighth == 6;
            double phase = 0, last_white = 0;
            for (std::size_t j = 0; j < at(0.25) && at(start_s) + j < count; ++j) {
                const double since = static_cast<double>(j) / rate_hz;
                const double white = gaussian(rng);
                double value = 0.15 * (white - last_white) * std::exp(-since / 0.02);
                last_white = white;
                if (is_kick) {
                    phase += 2 * kPi * (50.0 + 70.0 * std::exp(-since / 0.03)) / rate_hz;
                    value += std::sin(phase) * std::exp(-since / 0.12);
                }
                if (is_snare) value += (0.4 * white + 0.3 * std::sin(2 * kPi * 185.0 * since)) * std::exp(-since / 0.08);
                drums[at(start_s) + j] += static_cast<float>(value);
            }
        }
    }
    normalise_power(music);
    normalise_power(drums);
    for (std::size_t i = 0; i < count; ++i) music[i] += 0.6f * drums[i];
    return music;
}

// Mains hum and a fan: 50 or 60 Hz with harmonics up to 13 (the second, a transformer's
// magnetostriction, the strongest; odd ones a rectifier's buzz), each at a drawn phase; and the
// fan's air (pink noise under one pole near 1 kHz) with its blade tone (5-7 blades at 15-25
// turns a second, three harmonics) swelling by a fifth at 0.3 Hz. Hum and fan of equal power.
std::vector<float> make_mains_fan(std::size_t count, int rate_hz, std::mt19937_64& rng) {
    const double mains_hz = uniform(rng, 0, 1) < 0.5 ? 50.0 : 60.0;
    const double amplitudes[] = {0.6, 1.0, 0.5, 0.3, 0.35, 0.15, 0.2, 0.1, 0.12, 0.05, 0.08, 0.03, 0.05};
    std::vector<double> phases;
    for (std::size_t k = 0; k < std::size(amplitudes); ++k) phases.push_back(uniform(rng, 0, 2 * kPi));
    const double blade_hz = uniform_int(rng, 5, 7) * uniform(rng, 15.0, 25.0);
    std::vector<float> hum(count), blade(count), air = make_random_noise(Noise::pink, count, rng);
    const double pole = 1.0 - std::exp(-2 * kPi * 1000.0 / rate_hz);
    double low = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const double t = static_cast<double>(i) / rate_hz;
        double value = 0;
        for (std::size_t k = 0; k < std::size(amplitudes); ++k)
            if (static_cast<double>(k + 1) * mains_hz < rate_hz / 2.0)
                value += amplitudes[k] * std::sin(2 * kPi * static_cast<double>(k + 1) * mains_hz * t + phases[k]);
        hum[i] = static_cast<float>(value);
        low += pole * (air[i] - low);
        air[i] = static_cast<float>(low);
        blade[i] = static_cast<float>((1.0 + 0.2 * std::sin(2 * kPi * 0.3 * t)) * harmonics(blade_hz, 3, t));
    }
    normalise_power(hum);
    normalise_power(air);
    normalise_power(blade);
    // The fan: its blade tone 6 dB under its air; together as loud as the hum.
    const float fan_gain = static_cast<float>(1.0 / std::sqrt(1.25));
    for (std::size_t i = 0; i < count; ++i) hum[i] += fan_gain * (air[i] + 0.5f * blade[i]);
    return hum;
}

}  // namespace

std::vector<float> make_noise(Noise colour, std::size_t count, int rate_hz, std::mt19937_64& rng) {
    if (colour == Noise::song) return make_song(count, rate_hz, rng);
    if (colour == Noise::mains_fan) return make_mains_fan(count, rate_hz, rng);
    const bool is_tonal = colour == Noise::hum || colour == Noise::tone_pink || colour == Noise::music || colour == Noise::room;
    return is_tonal ? make_tonal_noise(colour, count, rate_hz, rng) : make_random_noise(colour, count, rng);
}

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
    const auto noise = make_noise(colour, clean.samples.size(), clean.sample_rate_hz, rng);
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
    if (peak > 0.98f)
        for (auto& sample : mixed.samples) sample *= 0.98f / peak;
    return mixed;
}

double rounded(double seconds) { return std::round(seconds * 1e5) / 1e5; }

nlohmann::ordered_json truth_document(const std::string& generator, const std::string& condition,
                                      const std::string& set, const talkface::Timeline& truth,
                                      const std::vector<bool>& after_pause) {
    nlohmann::ordered_json document;
    document["generator"] = generator;
    document["condition"] = condition;
    document["set"] = set;
    document["duration"] = rounded(truth.duration_s);
    document["sentences"] = nlohmann::ordered_json::array();
    for (const auto& sentence : truth.sentences)
        document["sentences"].push_back(
            {{"text", sentence.text}, {"start", rounded(sentence.start_s)}, {"end", rounded(sentence.end_s)}});
    document["syllables"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < truth.syllables.size(); ++i) {
        const auto& syllable = truth.syllables[i];
        document["syllables"].push_back({{"text", syllable.text},
                                         {"pinyin", syllable.pinyin},
                                         {"start", rounded(syllable.start_s)},
                                         {"end", rounded(syllable.end_s)},
                                         {"sentence", syllable.sentence},
                                         {"after_pause", static_cast<bool>(after_pause[i])}});
    }
    return document;
}

}  // namespace talkface_bench
