// written_forms_bench: how many written-form sentences (numbers, dates, money, phone numbers,
// acronyms, English words) the transcript stage reads as a native reader says them (issue 13).
//
//   written_forms_bench [--sentences FILE] [--tones] [--corpus-sentences OUT]
//
// FILE (bench/corpus/written_forms.txt by default) holds SET<TAB>SENTENCE<TAB>SAID lines. A sentence
// is read exactly when its toneless syllables equal those of SAID read by the same tables (tones do
// not move the lips, and polyphonic characters are not what is measured here). --tones compares the
// tones too, for a SAID written in numbered pinyin (bench/corpus/readings.txt): a tone sets a
// syllable's duration prior in the aligner, a light one shorter; it also counts the syllables read
// right, the longest common run of SAID's and the reading's. --corpus-sentences
// writes SET<TAB>SENTENCE for make_corpus --sentences, so that espeak-ng speaks the readings and
// align_bench measures the onsets on them (bench/README.md).
#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <talkface/talkface.hpp>

namespace {

struct WrittenSentence {
    std::string set;
    std::string text;
    std::string said;
    int line = 0;
};

std::vector<WrittenSentence> read_sentences(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw std::runtime_error(path + ": cannot be read");
    std::vector<WrittenSentence> sentences;
    std::string line;
    int number = 0;
    while (std::getline(file, line)) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        const auto first = line.find('\t');
        const auto second = first == std::string::npos ? first : line.find('\t', first + 1);
        if (second == std::string::npos) {
            throw std::runtime_error(path + ":" + std::to_string(number) +
                                     ": expected SET<TAB>SENTENCE<TAB>SAID");
        }
        WrittenSentence sentence{line.substr(0, first), line.substr(first + 1, second - first - 1),
                                 line.substr(second + 1), number};
        if (sentence.set != "tuning" && sentence.set != "held-out") {
            throw std::runtime_error(path + ":" + std::to_string(number) + ": set \"" + sentence.set +
                                     "\" is neither tuning nor held-out");
        }
        sentences.push_back(std::move(sentence));
    }
    return sentences;
}

// The said text's Latin words are toneless pinyin; among Chinese characters the reader takes a
// toneless word the English dictionary has (feng, pai) for English, so each gets tone 5 first.
std::string with_neutral_tones(const std::string& said) {
    std::string marked;
    for (std::size_t i = 0; i < said.size(); ++i) {
        marked += said[i];
        const bool is_letter = said[i] >= 'a' && said[i] <= 'z';
        const bool ends_word = i + 1 == said.size() || !((said[i + 1] >= 'a' && said[i + 1] <= 'z') ||
                                                         (said[i + 1] >= '0' && said[i + 1] <= '9'));
        if (is_letter && ends_word) marked += '5';
    }
    return marked;
}

std::vector<std::string> syllables(const talkface::Timeline& timeline, bool with_tones) {
    std::vector<std::string> pinyin;
    for (const auto& syllable : timeline.syllables)
        pinyin.push_back(with_tones ? syllable.pinyin
                                    : syllable.pinyin.substr(0, syllable.pinyin.size() - 1));
    return pinyin;
}

std::string joined(const std::vector<std::string>& syllables) {
    std::string text;
    for (const auto& syllable : syllables) text += (text.empty() ? "" : " ") + syllable;
    return text;
}

// The length of the longest common subsequence: syllables read right, a missing or extra one
// costing only itself.
int common_syllables(const std::vector<std::string>& got, const std::vector<std::string>& want) {
    std::vector<int> row(want.size() + 1, 0);
    for (const auto& g : got) {
        int diagonal = 0;
        for (std::size_t j = 0; j < want.size(); ++j) {
            const int above = row[j + 1];
            row[j + 1] = g == want[j] ? diagonal + 1 : std::max(row[j + 1], row[j]);
            diagonal = above;
        }
    }
    return row.back();
}

struct Tally {
    int sentences = 0;
    int exact = 0;
    int forms = 0;
    int warned = 0;
    int syllables = 0;
    int syllables_right = 0;
};

}  // namespace

int main(int argc, char** argv) {
    try {
        std::string sentences_path = TALKFACE_BENCH_WRITTEN_FORMS;
        std::string corpus_path;
        bool with_tones = false;
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            if (arg == "--sentences" && i + 1 < argc) {
                sentences_path = argv[++i];
            } else if (arg == "--tones") {
                with_tones = true;
            } else if (arg == "--corpus-sentences" && i + 1 < argc) {
                corpus_path = argv[++i];
            } else {
                std::cerr
                    << "usage: written_forms_bench [--sentences FILE] [--tones] [--corpus-sentences OUT]\n";
                return 2;
            }
        }
        const auto sentences = read_sentences(sentences_path);
        std::map<std::string, Tally> tallies;
        std::ofstream corpus;
        if (!corpus_path.empty()) {
            corpus.open(corpus_path);
            if (!corpus) throw std::runtime_error(corpus_path + ": cannot be written");
            corpus << "# Written-form sentences from " << sentences_path << " (written_forms_bench).\n";
        }
        int left_out = 0;
        for (const auto& sentence : sentences) {
            const auto where = sentences_path + ":" + std::to_string(sentence.line);
            const auto read = talkface::read_transcript(sentence.text, {}, where);
            const auto expected =
                talkface::read_transcript(with_neutral_tones(sentence.said), {}, where + " (said)");
            auto& tally = tallies[sentence.set];
            ++tally.sentences;
            tally.forms += static_cast<int>(read.written_forms.size());
            if (!read.warnings.empty()) ++tally.warned;
            const auto got = syllables(read, with_tones);
            const auto want = syllables(expected, with_tones);
            tally.syllables += static_cast<int>(want.size());
            tally.syllables_right += common_syllables(got, want);
            if (got == want) {
                ++tally.exact;
            } else {
                std::cout << "miss (" << sentence.set << ") " << sentence.text << "\n  expected "
                          << joined(want) << "\n  got      " << joined(got) << '\n';
            }
            // make_corpus takes one sentence with no warnings (every syllable spoken and known), and
            // joins sentences into passages: one without an end mark (a chat line, 666，带带我～)
            // would run on into the next, so it gets a full stop there.
            if (corpus.is_open()) {
                if (read.warnings.empty() && read.sentences.size() == 1) {
                    const bool runs_on =
                        talkface::read_transcript(sentence.text + "好。").sentences.size() == 1;
                    corpus << sentence.set << '\t' << sentence.text << (runs_on ? "。" : "") << '\n';
                } else {
                    ++left_out;
                }
            }
        }
        const auto percent = [](int part, int whole) { return (100 * part + whole / 2) / whole; };
        if (with_tones) {
            std::cout << "\n| set | sentences | read exactly, tones too | share | syllables | read right | "
                         "share |\n"
                      << "|---|---|---|---|---|---|---|\n";
        } else {
            std::cout << "\n| set | sentences | written forms | read exactly | share | with a warning |\n"
                      << "|---|---|---|---|---|---|\n";
        }
        for (const auto* set : {"tuning", "held-out"}) {
            const auto& tally = tallies[set];
            if (tally.sentences == 0) continue;
            std::cout << "| " << set << " | " << tally.sentences << " | ";
            if (with_tones) {
                std::cout << tally.exact << " | " << percent(tally.exact, tally.sentences) << "% | "
                          << tally.syllables << " | " << tally.syllables_right << " | "
                          << percent(tally.syllables_right, tally.syllables) << "% |\n";
            } else {
                std::cout << tally.forms << " | " << tally.exact << " | "
                          << percent(tally.exact, tally.sentences) << "% | " << tally.warned << " |\n";
            }
        }
        if (corpus.is_open())
            std::cout << "\ncorpus sentences written to " << corpus_path << " (" << left_out
                      << " left out: a warning or more than one sentence)\n";
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "written_forms_bench: error: " << error.what() << '\n';
        return 1;
    }
}
