#include "talkface/alignment_plot.hpp"

#include <algorithm>
#include <memory>
#include <sstream>
#include <vector>

#include "audio/audio_source.hpp"
#include "common/atomic_file.hpp"
#include "common/number_format.hpp"
#include "render/html_text.hpp"
#include "talkface/web_page.hpp"

namespace talkface {
inline namespace v0 {

namespace {

constexpr double kPixelsPerSecond = 200.0;
constexpr double kMinWidth = 600.0;
constexpr double kMaxWidth = 20000.0;
constexpr double kHeight = 260.0;
constexpr double kWaveTop = 60.0;
constexpr double kWaveHeight = 160.0;
// Thesis Figure 3.5: odd sentences blue, even ones green.
constexpr const char* kSentenceColours[2] = {"#2a6fdb", "#2e9e4f"};
constexpr const char* kOutsideColour = "#9a9a9a";
constexpr const char* kDoubtfulColour = "#d62728";

// The lowest and highest sample in each pixel column: a plot of an hour needs only this, never
// the signal itself.
struct Envelope {
    std::vector<float> low;
    std::vector<float> high;
};

Envelope read_envelope(detail::AudioSource& audio, std::size_t columns) {
    Envelope envelope{std::vector<float>(columns, 0.0f), std::vector<float>(columns, 0.0f)};
    const double frames = static_cast<double>(std::max<std::size_t>(audio.frame_count(), 1));
    std::vector<float> block(4096);
    std::size_t position = 0;
    while (const std::size_t got = audio.read(block.data(), block.size())) {
        for (std::size_t i = 0; i < got; ++i, ++position) {
            const auto column = std::min(
                columns - 1, static_cast<std::size_t>(static_cast<double>(position) / frames * static_cast<double>(columns)));
            envelope.low[column] = std::min(envelope.low[column], block[i]);
            envelope.high[column] = std::max(envelope.high[column], block[i]);
        }
    }
    return envelope;
}

std::string number(double value) { return detail::format_fixed(value, 1); }

std::string vertical_line(double x, double y1, double y2, const std::string& style) {
    return "<line x1=\"" + number(x) + "\" y1=\"" + number(y1) + "\" x2=\"" + number(x) + "\" y2=\"" + number(y2) +
           "\" " + style + "/>";
}

std::string plot_svg(detail::AudioSource& audio, const Timeline& timeline) {
    const double duration_s = std::max(timeline.duration_s, 0.01);
    const double width = std::clamp(duration_s * kPixelsPerSecond, kMinWidth, kMaxWidth);
    const auto columns = static_cast<std::size_t>(width);
    const Envelope envelope = read_envelope(audio, columns);
    float peak = 1e-6f;
    for (std::size_t i = 0; i < columns; ++i) peak = std::max({peak, envelope.high[i], -envelope.low[i]});
    const auto x_of = [&](double time_s) { return time_s / duration_s * width; };
    const auto y_of = [&](float value) {
        return kWaveTop + kWaveHeight / 2.0 - static_cast<double>(value / peak) * kWaveHeight / 2.0;
    };

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\"" << number(kHeight)
        << "\" viewBox=\"0 0 " << number(width) << ' ' << number(kHeight) << "\" font-family=\"sans-serif\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const auto& sentence = timeline.sentences[k];
        svg << "<rect x=\"" << number(x_of(sentence.start_s)) << "\" y=\"" << number(kWaveTop) << "\" width=\""
            << number(std::max(0.5, x_of(sentence.end_s) - x_of(sentence.start_s))) << "\" height=\""
            << number(kWaveHeight) << "\" fill=\"" << kSentenceColours[k % 2] << "\" fill-opacity=\"0.12\"><title>"
            << k + 1 << ": " << escape_html(sentence.text) << "</title></rect>\n";
    }
    // The waveform takes its sentence's colour, found by walking the sentences alongside the
    // columns (both are in time order).
    std::size_t sentence = 0;
    for (std::size_t i = 0; i < columns; ++i) {
        const double x = static_cast<double>(i) + 0.5;
        const double time_s = x / width * duration_s;
        while (sentence < timeline.sentences.size() && timeline.sentences[sentence].end_s <= time_s) ++sentence;
        const bool inside = sentence < timeline.sentences.size() && timeline.sentences[sentence].start_s <= time_s;
        const double top = y_of(envelope.high[i]);
        svg << vertical_line(x, top, std::max(y_of(envelope.low[i]), top + 0.5),
                             std::string("stroke=\"") + (inside ? kSentenceColours[sentence % 2] : kOutsideColour) + "\"")
            << '\n';
    }
    // Alternating label rows keep neighbouring syllables' labels apart. A syllable the aligner is
    // unsure of (issue 12) is drawn in red over a red band: where a user should look and listen.
    for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
        const auto& syllable = timeline.syllables[i];
        const double x = x_of(syllable.start_s);
        const bool is_doubtful = syllable.confidence < kLowAlignmentConfidence;
        if (is_doubtful)
            svg << "<rect x=\"" << number(x) << "\" y=\"8\" width=\"" << number(std::max(1.0, x_of(syllable.end_s) - x))
                << "\" height=\"" << number(kWaveTop + kWaveHeight - 8) << "\" fill=\"" << kDoubtfulColour
                << "\" fill-opacity=\"0.15\"><title>" << escape_html(syllable.text) << " " << escape_html(syllable.pinyin)
                << ": confidence " << detail::format_fixed(syllable.confidence, 2) << ", below "
                << detail::format_fixed(kLowAlignmentConfidence, 2)
                << ": check its place</title></rect>\n";
        svg << vertical_line(x, kWaveTop - 8, kWaveTop + kWaveHeight,
                             std::string("stroke=\"") + (is_doubtful ? kDoubtfulColour : "#333333") + "\" stroke-width=\"1\"")
            << '\n';
        if (syllable.final_start_s && *syllable.final_start_s > syllable.start_s)
            svg << vertical_line(x_of(*syllable.final_start_s), kWaveTop, kWaveTop + kWaveHeight,
                                 "stroke=\"#333333\" stroke-dasharray=\"2 3\" stroke-width=\"0.7\"")
                << '\n';
        svg << "<text x=\"" << number(x + 2) << "\" y=\"" << number(i % 2 == 0 ? 24.0 : 44.0) << "\" font-size=\"12\""
            << (is_doubtful ? std::string(" fill=\"") + kDoubtfulColour + "\"" : std::string()) << ">"
            << escape_html(syllable.text) << ' ' << escape_html(syllable.pinyin) << "</text>\n";
    }
    for (int second = 0; second <= static_cast<int>(duration_s); ++second) {
        const double x = x_of(second);
        svg << vertical_line(x, kWaveTop + kWaveHeight, kWaveTop + kWaveHeight + 6, "stroke=\"#000000\"") << "<text x=\""
            << number(x + 2) << "\" y=\"" << number(kHeight - 12) << "\" font-size=\"11\">" << second << " s</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace

std::string alignment_plot_svg(const std::string& audio_path, const Timeline& timeline) {
    const std::unique_ptr<detail::AudioSource> audio = detail::open_audio_file(audio_path);
    return plot_svg(*audio, timeline);
}

std::string alignment_plot_svg(const AudioView& audio, const Timeline& timeline) {
    const std::unique_ptr<detail::AudioSource> source = detail::open_audio_view(audio);
    return plot_svg(*source, timeline);
}

void write_alignment_plot_svg(const std::string& svg_path, const std::string& audio_path, const Timeline& timeline) {
    detail::write_file_atomically(svg_path, alignment_plot_svg(audio_path, timeline));
}

}  // namespace v0
}  // namespace talkface
