// Stage 4, thesis 3.3: every syllable of a transcript found in its speech (start, where the final
// starts, end, confidence), printed as a table.
//
//   align_syllables AUDIO TRANSCRIPT
#include <cstdio>
#include <exception>
#include <iostream>

#include <talkface/talkface.hpp>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: align_syllables AUDIO TRANSCRIPT\n";
        return 2;
    }
    try {
        const talkface::Timeline transcript = talkface::load_transcript(argv[2]);
        const talkface::Timeline timeline = talkface::SpeechAligner().align_file(argv[1], transcript);
        std::printf("%-4s %-4s %-3s %-8s %8s %8s %8s %5s\n", "#", "sent", "chr", "pinyin", "start_s", "final_s", "end_s",
                    "conf");
        for (std::size_t i = 0; i < timeline.syllables.size(); ++i) {
            const auto& syllable = timeline.syllables[i];
            std::printf("%-4zu %-4zu %s  %-8s %8.3f %8.3f %8.3f %5.2f\n", i + 1, syllable.sentence + 1,
                        syllable.text.c_str(), syllable.pinyin.c_str(), syllable.start_s,
                        syllable.final_start_s.value_or(syllable.start_s), syllable.end_s, syllable.confidence);
        }
        for (const auto& warning : timeline.warnings) std::cerr << "warning: " << warning << '\n';
    } catch (const std::exception& error) {
        std::cerr << "align_syllables: " << talkface::full_message(error) << '\n';
        return 1;
    }
    return 0;
}
