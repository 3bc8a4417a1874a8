#include "corpus_tools.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <talkface/transcript.hpp>

namespace talkface_bench {

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
    const auto noise = make_noise(colour, clean.samples.size(), rng);
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
