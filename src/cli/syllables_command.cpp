// `talkface syllables`: the sentences of a transcript and each character's reading, so a user
// can check them (and fix one in place, 行{hang2}) before aligning.
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "commands.hpp"

namespace talkface_cli {

namespace {

struct SyllablesOptions {
    std::string transcript_path;
    bool json = false;
    bool no_pinyin_input = false;
};

void print_plain(const talkface::Timeline& timeline) {
    std::size_t next = 0;
    for (std::size_t index = 0; index < timeline.sentences.size(); ++index) {
        std::cout << "sentence " << index + 1 << ": " << timeline.sentences[index].text << '\n';
        for (; next < timeline.syllables.size() && timeline.syllables[next].sentence == index; ++next) {
            const auto& syllable = timeline.syllables[next];
            std::cout << "  " << syllable.text << '\t' << syllable.pinyin
                      << (syllable.pause_after ? "\t(pause)" : "") << '\n';
        }
    }
}

void run_syllables(const SyllablesOptions& options) {
    talkface::TranscriptOptions transcript_options;
    transcript_options.read_pinyin = !options.no_pinyin_input;
    const auto timeline = talkface::load_transcript(options.transcript_path, transcript_options);
    if (options.json) {
        talkface::TimelineJsonOptions json_options;
        json_options.with_times = false;
        std::cout << talkface::timeline_to_json(timeline, json_options);
        return;
    }
    print_plain(timeline);
    for (const auto& warning : timeline.warnings) std::cerr << "talkface: warning: " << warning << '\n';
}

}  // namespace

void setup_syllables_command(CLI::App& app) {
    auto options = std::make_shared<SyllablesOptions>();
    CLI::App* syllables = app.add_subcommand(
        "syllables", "Show a transcript's sentences and each character's reading, to check before aligning");
    syllables
        ->add_option(
            "TRANSCRIPT", options->transcript_path,
            "UTF-8 text, Traditional or Simplified, or numbered pinyin; fix a reading in place: 行{hang2}")
        ->required()
        ->check(CLI::ExistingFile);
    syllables->add_flag("--json", options->json,
                        "Print the timeline JSON without times: {\"version\":1, \"sentences\":[{text}], "
                        "\"syllables\":[{text,pinyin,sentence,pause_after}], \"warnings\":[...]}");
    syllables->add_flag("--no-pinyin-input", options->no_pinyin_input,
                        "Report Latin letters as unreadable instead of reading them as pinyin");
    syllables->callback([options] { run_syllables(*options); });
}

}  // namespace talkface_cli
