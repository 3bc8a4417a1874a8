// Stage 4, thesis 3.2: a speech cut into sentence utterances, automatically (the default) or by
// Algorithm 3.1 from the pause between the first two sentences, printed as a table.
//
//   segment_sentences AUDIO TRANSCRIPT [FIRST_PAUSE_START_S FIRST_PAUSE_END_S]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>

#include <talkface/talkface.hpp>

int main(int argc, char** argv) {
    if (argc != 3 && argc != 5) {
        std::cerr << "usage: segment_sentences AUDIO TRANSCRIPT [FIRST_PAUSE_START_S FIRST_PAUSE_END_S]\n";
        return 2;
    }
    try {
        talkface::AlignOptions options;
        if (argc == 5) {
            options.sentence_cut = talkface::SentenceCutMode::first_pause;
            options.first_pause_start_s = std::strtod(argv[3], nullptr);
            options.first_pause_end_s = std::strtod(argv[4], nullptr);
        }
        const talkface::Timeline transcript = talkface::load_transcript(argv[2]);
        const talkface::Timeline timeline = talkface::SpeechAligner(options).align_file(argv[1], transcript);
        std::printf("%-4s %8s %8s %8s  %s\n", "#", "start_s", "end_s", "length_s", "text");
        for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
            const auto& sentence = timeline.sentences[k];
            std::printf("%-4zu %8.3f %8.3f %8.3f  %s\n", k + 1, sentence.start_s, sentence.end_s,
                        sentence.end_s - sentence.start_s, sentence.text.c_str());
        }
        std::printf("audio: %.3f s, %s\n", timeline.duration_s,
                    argc == 5 ? "cut by Algorithm 3.1 (c1 0.95, c2 1.45)" : "cut automatically");
    } catch (const std::exception& error) {
        std::cerr << "segment_sentences: " << talkface::full_message(error) << '\n';
        return 1;
    }
    return 0;
}
