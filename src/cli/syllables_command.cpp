// `talkface syllables`: the sentences of a transcript and each character's reading, so a user
// can check them (and fix one in place, 行{hang2}) before aligning.
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "commands.hpp"
#include "error_report.hpp"
#include "transcript_option.hpp"

namespace talkface_cli {

namespace {

struct SyllablesOptions {
    TranscriptArgument transcript;
    bool json = false;
};

// One line per character, and one per written form read by rule, with what it became:
//   2026年 -> 二零二六年 er4 ling2 er4 liu4 nian2
void print_plain(const talkface::Timeline& timeline) {
    std::size_t next = 0;
    std::size_t next_form = 0;
    for (std::size_t index = 0; index < timeline.sentences.size(); ++index) {
        std::cout << "sentence " << index + 1 << ": " << timeline.sentences[index].text << '\n';
        while (next < timeline.syllables.size() && timeline.syllables[next].sentence == index) {
            const talkface::WrittenForm* form =
                next_form < timeline.written_forms.size() && timeline.written_forms[next_form].first_syllable == next
                    ? &timeline.written_forms[next_form]
                    : nullptr;
            const std::size_t count = form != nullptr ? form->syllable_count : 1;
            std::string said;
            std::string readings;
            for (std::size_t k = next; k < next + count && k < timeline.syllables.size(); ++k) {
                // Characters run together (二零二六年), Latin syllables get a space (ai feng).
                const bool is_wide = (static_cast<unsigned char>(timeline.syllables[k].text.front()) & 0x80U) != 0;
                if (!said.empty() && !is_wide) said += ' ';
                said += timeline.syllables[k].text;
                readings += (readings.empty() ? "" : " ") + timeline.syllables[k].pinyin;
            }
            const std::size_t end = std::min(next + count, timeline.syllables.size());
            const bool pause = timeline.syllables[end - 1].pause_after;
            std::size_t generic = 0;
            for (std::size_t k = next; k < end; ++k) generic += timeline.syllables[k].generic_speech ? 1 : 0;
            if (form != nullptr) {
                std::cout << "  " << form->text << " -> " << said << '\t' << readings;
                ++next_form;
            } else {
                std::cout << "  " << said << '\t' << readings;
            }
            if (generic > 0)
                std::cout << "\t(unknown word: " << generic << (generic == 1 ? " syllable" : " syllables")
                          << " of generic speech)";
            std::cout << (pause ? "\t(pause)" : "") << '\n';
            next += count;
        }
    }
}

void run_syllables(const SyllablesOptions& options) {
    const auto timeline = talkface::load_transcript(options.transcript.path, options.transcript.options);
    if (options.json) {
        talkface::TimelineJsonOptions json_options;
        json_options.with_times = false;
        std::cout << talkface::timeline_to_json(timeline, json_options);
        return;
    }
    print_plain(timeline);
    report_warnings(timeline);
    // An empty listing alone left a user to guess whether anything was read at all.
    if (timeline.sentences.empty())
        std::cerr
            << "talkface: warning: " << options.transcript.path
            << ": no sentence to show: the transcript holds no text with a reading (align refuses it)\n";
}

}  // namespace

void setup_syllables_command(CLI::App& app) {
    auto options = std::make_shared<SyllablesOptions>();
    CLI::App* syllables = app.add_subcommand(
        "syllables", "Show a transcript's sentences and each character's reading, to check before aligning");
    add_transcript_argument(*syllables, options->transcript, kTranscriptHelp)->required();
    syllables->add_flag("--json", options->json,
                        "Print the timeline JSON without times: {\"version\":1, \"sentences\":[{text}], "
                        "\"syllables\":[{text,pinyin,sentence,pause_after,generic_speech (only when true)}], "
                        "\"warnings\":[...]}");
    syllables->callback([options] { run_syllables(*options); });
}

}  // namespace talkface_cli
