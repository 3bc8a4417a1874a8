// `talkface align`: a speech and its transcript in, each sentence's and syllable's times out
// (SPEC "Contracts"), with an optional picture of the result (thesis Figures 3.5 and 3.8).
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "commands.hpp"
#include "error_report.hpp"
#include "timing_option.hpp"
#include "progress_bar.hpp"
#include "common/atomic_file.hpp"

namespace talkface_cli {

namespace {

struct AlignCommandOptions {
    std::string audio_path;
    TranscriptArgument transcript;
    bool json = false;
    std::string plot_path;
    std::string first_pause_text;
    double c1 = talkface::AlignOptions{}.c1;
    double c2 = talkface::AlignOptions{}.c2;
    talkface::CheckMode check = talkface::AlignOptions{}.check;
    bool lenient = false;
    std::string output_path = "-";
    bool quiet = false;
};

// "START,END" in seconds; nullopt unless it is exactly two numbers.
std::optional<std::pair<double, double>> parse_pause(const std::string& text) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double start = 0.0, end = 0.0;
    if (!(in >> start) || in.get() != ',' || !(in >> end)) return std::nullopt;
    in >> std::ws;
    if (!in.eof()) return std::nullopt;
    return std::make_pair(start, end);
}

const CLI::Validator& pause_validator() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            const auto pause = parse_pause(text);
            if (pause && pause->first >= 0.0 && pause->second > pause->first) return {};
            return "expected START,END in seconds with 0 <= START < END (e.g. 2.1,2.9), found \"" + text + "\"";
        },
        "START,END");
    return validator;
}

std::string timeline_table(const talkface::Timeline& timeline) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(3);
    // Column heads for the syllable rows below (times in seconds, confidence 0..1); each sentence's
    // row says what it is ("sentence N  START - END s  TEXT").
    out << "  text\t" << std::left << std::setw(8) << "pinyin" << std::right << " start final   end  confidence\n";
    std::size_t next = 0;
    for (std::size_t k = 0; k < timeline.sentences.size(); ++k) {
        const auto& sentence = timeline.sentences[k];
        out << "sentence " << k + 1 << "  " << sentence.start_s << " - " << sentence.end_s << " s  " << sentence.text << '\n';
        for (; next < timeline.syllables.size() && timeline.syllables[next].sentence == k; ++next) {
            const auto& syllable = timeline.syllables[next];
            out << "  " << syllable.text << '\t' << std::left << std::setw(8) << syllable.pinyin << std::right << ' '
                << syllable.start_s << ' ' << syllable.final_start_s.value_or(syllable.start_s) << ' ' << syllable.end_s
                << "  " << std::setprecision(2) << syllable.confidence << std::setprecision(3) << '\n';
        }
    }
    return out.str();
}

void run_align(const AlignCommandOptions& options) {
    talkface::AlignOptions align_options;
    align_options.c1 = options.c1;
    align_options.c2 = options.c2;
    align_options.check = options.check;
    align_options.lenient = options.lenient;
    if (!options.first_pause_text.empty()) {
        const auto pause = parse_pause(options.first_pause_text).value_or(std::make_pair(0.0, 0.0));
        align_options.sentence_cut = talkface::SentenceCutMode::first_pause;
        align_options.first_pause_start_s = pause.first;
        align_options.first_pause_end_s = pause.second;
    }
    const talkface::Timeline transcript = load_transcript_to_time(options.transcript);
    const talkface::SpeechAligner aligner(align_options);
    talkface::Timeline timeline;
    {
        const std::unique_ptr<ProgressBar> bar = make_progress_bar(options.quiet);
        timeline = aligner.align_file(options.audio_path, transcript, progress_part(bar.get(), 0.0, 1.0));
    }
    // Everything is computed before any output is written: a failure leaves no file behind.
    const std::string result = options.json ? talkface::timeline_to_json(timeline) : timeline_table(timeline);
    const std::string plot = options.plot_path.empty() ? std::string() : talkface::alignment_plot_svg(options.audio_path, timeline);
    if (!options.plot_path.empty()) talkface::detail::write_file_atomically(options.plot_path, plot);
    if (options.output_path == "-") std::cout << result << std::flush;
    else talkface::detail::write_file_atomically(options.output_path, result);
    if (!options.json)
        report_warnings(timeline);
}

}  // namespace

void setup_align_command(CLI::App& app) {
    auto options = std::make_shared<AlignCommandOptions>();
    CLI::App* align = app.add_subcommand("align", "Find when each sentence and syllable of a transcript is spoken");
    align->add_option("AUDIO", options->audio_path, kSpeechFormatsHelp)
        ->required()
        ->check(CLI::ExistingFile);
    add_transcript_argument(*align, options->transcript, kTranscriptHelp)->required();
    align->add_flag("--json", options->json,
                    "Print the timeline JSON: {\"version\":1, \"sentences\":[{text,start,end}], \"syllables\":[{text,"
                    "pinyin,start,end,sentence,final_start,confidence,pause_after}], \"duration\":s, "
                    "\"warnings\":[...]}, times in seconds (docs/timeline-format.md); a confidence below 0.5 "
                    "(talkface::kLowAlignmentConfidence) marks a syllable to check: its start may be more than "
                    "100 ms off (on the benchmark's human speech that flags at most 10% of right syllables in "
                    "every condition, 5.2% pooled, and catches 79% of those more than 100 ms off)");
    align->add_option("--plot", options->plot_path,
                      "Also draw the waveform, sentences and syllables as an SVG file (syllables to check, with a "
                      "confidence below 0.5, in red)");
    align->add_option("--first-pause", options->first_pause_text,
                      "Cut sentences by thesis Algorithm 3.1 from this pause between the first two sentences, in "
                      "seconds; default: learn the pauses from the audio")
        ->check(pause_validator());
    align->add_option("--c1", options->c1, "Algorithm 3.1: shortest pause, as a share of the first one")
        ->check(CLI::Range(0.5, 1.0))
        ->capture_default_str();
    align->add_option("--c2", options->c2, "Algorithm 3.1: loudest silence, as a multiple of the first pause's peak")
        ->check(CLI::Range(1.0, 1.5))
        ->capture_default_str();
    align->add_option("--check", options->check,
                      "What a transcript that does not match the audio does (a missing or extra sentence, the wrong "
                      "text, a text that lacks its last words): refuse (strong evidence stops the "
                      "alignment), warn (a warning, aligned anyway) or off")
        ->transform(CLI::CheckedTransformer(std::map<std::string, talkface::CheckMode>{
            {"refuse", talkface::CheckMode::refuse}, {"warn", talkface::CheckMode::warn}, {"off", talkface::CheckMode::off}}))
        ->default_str("refuse");
    add_lenient_option(*align, options->lenient);
    align->add_option("-o,--output", options->output_path, "Write the result here instead of stdout (- is stdout)");
    align->add_flag("-q,--quiet", options->quiet, "No progress bar");
    align->callback([options] { run_align(*options); });
}

}  // namespace talkface_cli
