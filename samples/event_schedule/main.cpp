// Stage 5: the simulated event schedule of a minute of speech (thesis chapter 4), in both styles:
// every blink, eyebrow raise, tilt, turn and nod with its times and amount, then how many of each.
//
//   event_schedule [SEED]     seed 1 when none is given; the same seed prints the same schedule
#include <array>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include <talkface/talkface.hpp>

namespace {

constexpr double kMinuteS = 60.0;
constexpr double kSyllableS = 0.22;     // about 4.5 syllables per second, an ordinary pace
constexpr double kCommaPauseS = 0.35;   // a pause the transcript marks with ，
constexpr double kSentencePauseS = 0.8;

// A minute of speech as an aligner would give it: sentences of 8 to 14 syllables with a comma in
// the middle, the syllables cycling through a short text so that the timeline is the same every run.
talkface::Timeline minute_of_speech() {
    static const std::array<const char*, 12> kPinyin{"chang2", "qi1", "xia4", "lai2", "shang1", "hai4",
                                                     "bu4",    "duan4", "lei3", "ji1", "yin2",  "hang2"};
    talkface::Timeline timeline;
    double time_s = 0.5;
    std::size_t next = 0;
    for (std::size_t sentence = 0; time_s < kMinuteS - 4.0; ++sentence) {
        const std::size_t length = 8 + (sentence * 5) % 7;
        const double start_s = time_s;
        for (std::size_t k = 0; k < length; ++k) {
            const char* pinyin = kPinyin[next++ % kPinyin.size()];
            talkface::Syllable syllable;
            syllable.text = pinyin;
            syllable.pinyin = pinyin;
            syllable.sentence = sentence;
            syllable.start_s = time_s;
            syllable.end_s = time_s + kSyllableS;
            syllable.pause_after = k + 1 == length / 2;
            timeline.syllables.push_back(syllable);
            time_s = syllable.end_s + (syllable.pause_after ? kCommaPauseS : 0.0);
        }
        timeline.sentences.push_back({"sentence " + std::to_string(sentence + 1), start_s, time_s});
        time_s += kSentencePauseS;
    }
    timeline.duration_s = kMinuteS;
    return timeline;
}

void print_schedule(const talkface::Timeline& timeline, std::uint64_t seed, const char* style_name) {
    const talkface::ExpressionSimulator simulator(timeline, seed,
                                                  talkface::ExpressionStyle::from_name(style_name));
    std::array<int, 5> counts{};
    std::printf("\nstyle %s, seed %llu: %zu events in %.0f s\n", style_name,
                static_cast<unsigned long long>(seed), simulator.events().size(), simulator.duration_s());
    std::printf("  start s   end s  kind    amount\n");
    for (const talkface::ExpressionEvent& event : simulator.events()) {
        ++counts[static_cast<std::size_t>(event.kind)];
        const bool is_angle = event.kind != talkface::ExpressionEventKind::blink &&
                              event.kind != talkface::ExpressionEventKind::brows;
        std::printf("  %7.3f %7.3f  %-6s %7.2f%s\n", event.start_s, event.end_s,
                    talkface::expression_event_kind_name(event.kind), event.amount, is_angle ? " deg" : "");
    }
    std::printf("  per minute:");
    for (std::size_t kind = 0; kind < counts.size(); ++kind) {
        std::printf(" %s %d", talkface::expression_event_kind_name(static_cast<talkface::ExpressionEventKind>(kind)),
                    counts[kind]);
    }
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2) {
        std::cerr << "usage: event_schedule [SEED]\n";
        return 2;
    }
    try {
        const std::uint64_t seed = argc == 2 ? std::stoull(argv[1]) : 1;
        const talkface::Timeline timeline = minute_of_speech();
        std::printf("a minute of speech: %zu sentences, %zu syllables\n", timeline.sentences.size(),
                    timeline.syllables.size());
        print_schedule(timeline, seed, "normal");
        print_schedule(timeline, seed, "announcer");
    } catch (const std::exception& error) {
        std::cerr << "event_schedule: error: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
