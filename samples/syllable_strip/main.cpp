// Stage 6 + 7: the frames of a spoken word as a strip, like thesis Figures 5.11 (願望 yuan4 wang4)
// and 5.12 (波濤 bo1 tao1): each frame zoomed on the lower face, labelled with its time and with the
// mouth shape whose key frame falls on it.
//
//   syllable_strip OUT.svg [WORD ...]     words 願望 and 波濤 when none are given
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <talkface/talkface.hpp>

#include "common/mouth_zoom.hpp"
#include "common/nested_svg.hpp"

namespace {

constexpr double kFps = 25.0;
constexpr double kSyllableS = 0.32;  // a carefully spoken word, as in the thesis's recordings
constexpr double kLeadS = 0.12;      // frames shown before the word and after it
constexpr int kColumns = 9;
constexpr double kCellWidth = 150.0;
constexpr double kLabelHeight = 36.0;
constexpr double kTitleHeight = 34.0;
constexpr double kGap = 6.0;

// The word read as a transcript, its syllables spoken one after another from kLeadS.
talkface::Timeline spoken_word(const std::string& word) {
    talkface::Timeline timeline = talkface::read_transcript(word);
    if (timeline.syllables.empty()) throw std::runtime_error("\"" + word + "\" has no Mandarin syllables");
    double time_s = kLeadS;
    for (talkface::Syllable& syllable : timeline.syllables) {
        syllable.start_s = time_s;
        syllable.end_s = time_s + kSyllableS;
        time_s = syllable.end_s;
    }
    timeline.sentences.front().start_s = kLeadS;
    timeline.sentences.front().end_s = time_s;
    timeline.duration_s = time_s + kLeadS;
    return timeline;
}

std::string text_element(double x, double y, int size, const std::string& anchor, const std::string& text) {
    return "<text x=\"" + talkface_samples::svg_number(x) + "\" y=\"" + talkface_samples::svg_number(y) +
           "\" text-anchor=\"" + anchor + "\" font-family=\"sans-serif\" font-size=\"" + std::to_string(size) +
           "\" fill=\"#222222\">" + talkface_samples::escape_xml(text) + "</text>\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: syllable_strip OUT.svg [WORD ...]\n";
        return 2;
    }
    try {
        std::vector<std::string> words(argv + 2, argv + argc);
        if (words.empty()) words = {"願望", "波濤"};
        const talkface::FaceModel face = talkface::FaceModel::default_face();
        const talkface_samples::MouthZoom zoom = talkface_samples::mouth_zoom(face);
        const double cell_height = kCellWidth * zoom.height / zoom.width;
        const double row_height = cell_height + kLabelHeight + kGap;

        talkface::LipSyncOptions options;
        options.fps = kFps;
        const talkface::SvgAnimator animator(face);
        std::string body;
        double y = kGap;
        int cell_index = 0;
        for (const std::string& word : words) {
            const talkface::Timeline timeline = spoken_word(word);
            const auto key_frames = talkface::mouth_key_frames(timeline, options);
            const auto frame_count = static_cast<std::size_t>(std::floor(timeline.duration_s * kFps + 1e-9)) + 1;
            const auto mouths = talkface::mouth_frames(face, key_frames, frame_count, options);

            std::string pinyin;
            for (const talkface::Syllable& syllable : timeline.syllables) {
                pinyin += (pinyin.empty() ? "" : " ") + syllable.pinyin;
            }
            const std::string title = pinyin + (word == pinyin ? "" : "  " + word) + "   (" +
                                      std::to_string(static_cast<int>(kFps)) + " frames per second)";
            body += text_element(kGap, y + 24, 22, "start", title);
            y += kTitleHeight;
            for (std::size_t frame = 0; frame < frame_count; ++frame) {
                const double x = kGap + static_cast<double>(frame % kColumns) * (kCellWidth + kGap);
                if (frame > 0 && frame % kColumns == 0) y += row_height;
                talkface::FaceState state;
                state.mouth = mouths[frame];
                const talkface_samples::Cell cell{x, y, kCellWidth, cell_height, zoom.view_box};
                body += talkface_samples::nest_svg(animator.render_svg(state), cell,
                                                   "f" + std::to_string(cell_index++) + "-");
                const double time_s = static_cast<double>(frame) / kFps;
                std::string label = std::to_string(static_cast<int>(std::lround(time_s * 1000))) + " ms";
                for (const talkface::MouthKeyFrame& key : key_frames) {
                    if (std::lround(key.time_s * kFps) == static_cast<long>(frame) && key.syllable) {
                        label += "  " + std::string(talkface::mouth_shape_name(key.shape));
                    }
                }
                body += text_element(x + kCellWidth / 2, y + cell_height + 24, 17, "middle", label);
            }
            y += row_height + kGap;
        }

        const double width = kColumns * (kCellWidth + kGap) + kGap;
        std::string sheet = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
                            "<svg xmlns=\"http://www.w3.org/2000/svg\" "
                            "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"" +
                            talkface_samples::svg_number(width) + "\" height=\"" + talkface_samples::svg_number(y) +
                            "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n" + body + "</svg>\n";
        std::ofstream out(argv[1], std::ios::binary);
        out << sheet;
        if (!out.flush()) throw std::runtime_error(std::string("cannot write ") + argv[1]);
        std::printf("wrote %s: %d frames of %zu words\n", argv[1], cell_index, words.size());
    } catch (const std::exception& error) {
        std::cerr << "syllable_strip: error: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
