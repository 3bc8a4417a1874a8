#include "alignment_plot.hpp"

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include <talkface/errors.hpp>

namespace talkface_cli {

namespace {

constexpr double kPixelsPerSecond = 200.0;
constexpr double kMinWidth = 600.0;
constexpr double kMaxWidth = 20000.0;
constexpr double kHeight = 260.0;
constexpr double kWaveTop = 60.0;
constexpr double kWaveHeight = 160.0;
// Thesis Figure 3.5: odd sentences blue, even ones green.
constexpr const char* kSentenceColours[2] = {"#2a6fdb", "#2e9e4f"};

struct Envelope {
    std::vector<float> low;
    std::vector<float> high;
    double duration_s = 0.0;
};

Envelope read_envelope(const std::string& path, std::size_t columns) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    if (file == nullptr) throw talkface::ParseError(path, 0, 0, "", std::string("cannot read the audio: ") + sf_strerror(nullptr));
    Envelope envelope;
    envelope.low.assign(columns, 0.0f);
    envelope.high.assign(columns, 0.0f);
    const auto frames = static_cast<double>(std::max<sf_count_t>(info.frames, 1));
    envelope.duration_s = frames / info.samplerate;
    const auto channels = static_cast<std::size_t>(info.channels);
    std::vector<float> block(4096 * channels);
    std::size_t position = 0;
    sf_count_t got = 0;
    while ((got = sf_readf_float(file, block.data(), 4096)) > 0) {
        for (std::size_t i = 0; i < static_cast<std::size_t>(got); ++i, ++position) {
            float sum = 0.0f;
            for (std::size_t c = 0; c < channels; ++c) sum += block[i * channels + c];
            const float value = sum / static_cast<float>(channels);
            const auto column = std::min(columns - 1, static_cast<std::size_t>(static_cast<double>(position) / frames * static_cast<double>(columns)));
            envelope.low[column] = std::min(envelope.low[column], value);
            envelope.high[column] = std::max(envelope.high[column], value);
        }
    }
    sf_close(file);
    return envelope;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

std::string escape(const std::string& text) {
    std::string result;
    for (char c : text) {
        switch (c) {
            case '&': result += "&amp;"; break;
            case '<': result += "&lt;"; break;
            case '>': result += "&gt;"; break;
            case '"': result += "&quot;"; break;
            default: result += c;
        }
    }
    return result;
}

}  // namespace

std::string alignment_plot_svg(const std::string& audio_path, const talkface::Timeline& timeline) {
    const double duration_s = std::max(timeline.duration_s, 0.01);
    const double width = std::clamp(duration_s * kPixelsPerSecond, kMinWidth, kMaxWidth);
    const auto columns = static_cast<std::size_t>(width);
    const Envelope envelope = read_envelope(audio_path, columns);
    float peak = 1e-6f;
    for (std::size_t i = 0; i < columns; ++i) peak = std::max({peak, envelope.high[i], -envelope.low[i]});
    auto x_of = [&](double time_s) { return time_s / duration_s * width; };
    auto y_of = [&](float value) { return kWaveTop + kWaveHeight / 2.0 - static_cast<double>(value / peak) * kWaveHeight / 2.0; };

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\"" << number(kHeight)
        << "\" viewBox=\"0 0 " << number(width) << ' ' << number(kHeight) << "\" font-family=\"sans-serif\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    // Sentences: a tinted band and the waveform inside it in the sentence's colour.
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const auto& sentence = timeline.sentences[k];
        svg << "<rect x=\"" << number(x_of(sentence.start_s)) << "\" y=\"" << number(kWaveTop) << "\" width=\""
            << number(std::max(0.5, x_of(sentence.end_s) - x_of(sentence.start_s))) << "\" height=\"" << number(kWaveHeight)
            << "\" fill=\"" << kSentenceColours[k % 2] << "\" fill-opacity=\"0.12\"><title>" << k + 1 << ": "
            << escape(sentence.text) << "</title></rect>\n";
    }
    auto colour_at = [&](double time_s) -> const char* {
        for (std::size_t k = 0; k < timeline.sentences.size(); ++k)
            if (time_s >= timeline.sentences[k].start_s && time_s < timeline.sentences[k].end_s) return kSentenceColours[k % 2];
        return "#9a9a9a";
    };
    for (std::size_t i = 0; i < columns; ++i) {
        const double x = static_cast<double>(i) + 0.5;
        svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(y_of(envelope.high[i])) << "\" x2=\"" << number(x)
            << "\" y2=\"" << number(std::max(y_of(envelope.low[i]), y_of(envelope.high[i]) + 0.5)) << "\" stroke=\""
            << colour_at((static_cast<double>(i) + 0.5) / width * duration_s) << "\"/>\n";
    }
    // Syllables: a line at each start, a dotted one where its final starts, the pinyin above,
    // alternating rows so that neighbours do not overlap.
    for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
        const auto& syllable = timeline.syllables[i];
        const double x = x_of(syllable.start_s);
        svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(kWaveTop - 8) << "\" x2=\"" << number(x) << "\" y2=\""
            << number(kWaveTop + kWaveHeight) << "\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
        if (syllable.final_start_s && *syllable.final_start_s > syllable.start_s) {
            const double xf = x_of(*syllable.final_start_s);
            svg << "<line x1=\"" << number(xf) << "\" y1=\"" << number(kWaveTop) << "\" x2=\"" << number(xf) << "\" y2=\""
                << number(kWaveTop + kWaveHeight) << "\" stroke=\"#333333\" stroke-dasharray=\"2 3\" stroke-width=\"0.7\"/>\n";
        }
        svg << "<text x=\"" << number(x + 2) << "\" y=\"" << number(i % 2 == 0 ? 24.0 : 44.0) << "\" font-size=\"12\">"
            << escape(syllable.text) << ' ' << escape(syllable.pinyin) << "</text>\n";
    }
    for (int second = 0; second <= static_cast<int>(duration_s); ++second) {
        const double x = x_of(second);
        svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(kWaveTop + kWaveHeight) << "\" x2=\"" << number(x)
            << "\" y2=\"" << number(kWaveTop + kWaveHeight + 6) << "\" stroke=\"#000000\"/>"
            << "<text x=\"" << number(x + 2) << "\" y=\"" << number(kHeight - 12) << "\" font-size=\"11\">" << second
            << " s</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace talkface_cli
