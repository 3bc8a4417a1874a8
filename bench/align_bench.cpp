// align_bench: aligns every passage of a corpus made by make_corpus and prints, per recording
// condition and per sentence set, how close the syllable starts and sentence boundaries come to
// the truth and how fast it ran, beside the naive baseline and the targets of issue #4.
//
//   align_bench CORPUS [--conditions clean,white10,...] [--dump SYLLABLES.tsv] [--warnings WARNINGS.tsv]
//                                                         (every syllable's error, confidence; every
//                                                         passage's warnings)
//   align_bench --file AUDIO TRANSCRIPT [--truth LIST]   (one file, for memory_bench.sh)
//   align_bench --mismatch CORPUS [--conditions ...]      (wrong transcripts: detected, and false alarms;
//                                                          texts that lack a sentence or a sentence's end
//                                                          too)
//   align_bench --lenient CORPUS [--conditions ...] [--dump SYLLABLES.tsv]   (--lenient: changed words found,
//                                                          right syllables marked)
//
// LIST names the truths of the passages joined into AUDIO, one "OFFSET_S<TAB>TRUTH.json" a line:
// the onsets are then scored against them (the transcript may have lost its punctuation, so only
// the syllables, in order, are compared).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <sndfile.h>
#include <talkface/talkface.hpp>

namespace fs = std::filesystem;

namespace {

constexpr double boundary_tolerance_s = 0.150;
constexpr double target_speed = 500.0;
const char* const sets[] = {"tuning", "held-out"};

// Adds a count of another group of passages to one's own; appends its per-syllable figures.
template <class T>
void accumulate(T& sum, const T& other) {
    sum += other;
}
template <class T>
void accumulate(std::vector<T>& sum, const std::vector<T>& other) {
    sum.insert(sum.end(), other.begin(), other.end());
}
// Each of `fields` of `other` accumulated into `sum`'s: the tallies' add().
template <class Tally, class... Fields>
void add_fields(Tally& sum, const Tally& other, Fields... fields) {
    (accumulate(sum.*fields, other.*fields), ...);
}

/// What one method (the aligner or the baseline) got right on a group of passages.
struct Score {
    int passages = 0;
    int failed = 0;                 ///< passages the aligner threw on; their onsets count as missed
    std::vector<double> errors_s;   ///< |onset error| per syllable; infinity when its passage failed
    std::vector<double> confidences;      ///< per syllable of the passages aligned
    std::vector<double> aligned_errors_s; ///< their errors, beside confidences
    int boundaries = 0;
    int boundaries_found = 0;
    double audio_s = 0;
    double cpu_s = 0;

    void add(const Score& other) {
        add_fields(*this, other, &Score::passages, &Score::failed, &Score::errors_s, &Score::confidences,
                   &Score::aligned_errors_s, &Score::boundaries, &Score::boundaries_found, &Score::audio_s,
                   &Score::cpu_s);
    }

    double median_ms() const {
        if (errors_s.empty()) return std::numeric_limits<double>::quiet_NaN();
        std::vector<double> sorted = errors_s;
        std::sort(sorted.begin(), sorted.end());
        const std::size_t n = sorted.size();
        return 1000.0 * (n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]));
    }

    double within_percent(double tolerance_s) const {
        if (errors_s.empty()) return std::numeric_limits<double>::quiet_NaN();
        const auto hits = std::count_if(errors_s.begin(), errors_s.end(), [&](double e) { return e <= tolerance_s; });
        return 100.0 * static_cast<double>(hits) / static_cast<double>(errors_s.size());
    }
};

struct Truth {
    talkface::Timeline timeline;  ///< true times
    std::string set;
};

std::string read_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error(path.string() + ": cannot read");
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

Truth load_truth(const fs::path& path) {
    const auto document = nlohmann::json::parse(read_text(path));
    Truth truth;
    truth.set = document.at("set").get<std::string>();
    truth.timeline.duration_s = document.at("duration").get<double>();
    for (const auto& item : document.at("sentences")) {
        talkface::Sentence sentence;
        sentence.text = item.at("text").get<std::string>();
        sentence.start_s = item.at("start").get<double>();
        sentence.end_s = item.at("end").get<double>();
        truth.timeline.sentences.push_back(sentence);
    }
    for (const auto& item : document.at("syllables")) {
        talkface::Syllable syllable;
        syllable.text = item.at("text").get<std::string>();
        syllable.pinyin = item.at("pinyin").get<std::string>();
        syllable.sentence = item.at("sentence").get<std::size_t>();
        syllable.start_s = item.at("start").get<double>();
        syllable.end_s = item.at("end").get<double>();
        truth.timeline.syllables.push_back(syllable);
    }
    return truth;
}

// The naive baseline: each true sentence span divided evenly among its syllables.
talkface::Timeline even_split(const talkface::Timeline& truth) {
    talkface::Timeline result = truth;
    for (std::size_t k = 0; k < result.sentences.size(); ++k) {
        std::vector<talkface::Syllable*> members;
        for (auto& syllable : result.syllables)
            if (syllable.sentence == k) members.push_back(&syllable);
        const double start = result.sentences[k].start_s;
        const double step = (result.sentences[k].end_s - start) / static_cast<double>(std::max<std::size_t>(members.size(), 1));
        for (std::size_t i = 0; i < members.size(); ++i) {
            members[i]->start_s = start + step * static_cast<double>(i);
            members[i]->end_s = members[i]->start_s + step;
        }
    }
    return result;
}

void score_timeline(const talkface::Timeline& aligned, const talkface::Timeline& truth, const std::string& where,
                    Score& score) {
    if (aligned.syllables.size() != truth.syllables.size() || aligned.sentences.size() != truth.sentences.size()) {
        throw std::runtime_error(where + ": the aligner returned " + std::to_string(aligned.sentences.size()) +
                                 " sentences and " + std::to_string(aligned.syllables.size()) + " syllables, the truth has " +
                                 std::to_string(truth.sentences.size()) + " and " + std::to_string(truth.syllables.size()));
    }
    for (std::size_t i = 0; i < truth.syllables.size(); ++i) {
        const double error = std::fabs(aligned.syllables[i].start_s - truth.syllables[i].start_s);
        score.errors_s.push_back(error);
        score.aligned_errors_s.push_back(error);
        score.confidences.push_back(aligned.syllables[i].confidence);
    }
    for (std::size_t k = 0; k < truth.sentences.size(); ++k) {
        score.boundaries += 2;
        score.boundaries_found += std::fabs(aligned.sentences[k].start_s - truth.sentences[k].start_s) <= boundary_tolerance_s;
        score.boundaries_found += std::fabs(aligned.sentences[k].end_s - truth.sentences[k].end_s) <= boundary_tolerance_s;
    }
}

// Issue #4: clean and SNR 30 dB are held to the strict target, SNR 10 dB and every distorted
// condition (white noise at 20 dB among them) to the loose one, and all to every boundary; issue
// 12 raises SNR 10 dB to 85%. Issue 12's human speech (h-*, and r-* run together), onsets only: at SNR 25 dB or better,
// tempo up to 1.5, median <= 20 ms, 90% within 50 ms and 97% within 100 ms; at 15-20 dB (and in a
// room) 80% and 95%. (Its sentence ends are printed but not held to a target: a weak last syllable's
// decay, which the truth counts to -35 dB of its peak, sinks under the noise.)
struct Target {
    bool applies = false;
    double max_median_ms = 0;  ///< 0: no median target
    double min_in_50 = 0;
    double min_in_100 = 0;     ///< 0: no 100 ms target
    bool all_boundaries = true;

    std::string text() const {
        std::string text;
        if (max_median_ms > 0) text += "median<=" + std::to_string(static_cast<int>(max_median_ms)) + "ms, ";
        text += ">=" + std::to_string(static_cast<int>(min_in_50)) + "% in 50ms";
        if (min_in_100 > 0) text += ", >=" + std::to_string(static_cast<int>(min_in_100)) + "% in 100ms";
        return all_boundaries ? text + ", all boundaries" : text;
    }
    bool met(const Score& score) const {
        if (all_boundaries && score.boundaries_found != score.boundaries) return false;
        if (max_median_ms > 0 && !(score.median_ms() <= max_median_ms)) return false;
        if (min_in_100 > 0 && !(score.within_percent(0.100) >= min_in_100)) return false;
        return score.within_percent(0.050) >= min_in_50;
    }
};

Target target_for(const std::string& condition) {
    // v-: another voice made of speaker 3's, w-: another person (make_human_corpus), held to the same
    // targets; w-breathy and w-lenis are at SNR 30 dB, tempo up to 1.5.
    const bool is_human = condition.rfind("h-", 0) == 0 || condition.rfind("r-", 0) == 0 ||
                          condition.rfind("v-", 0) == 0 || condition.rfind("w-", 0) == 0;
    const std::string kind = is_human ? condition.substr(2) : "";
    if (kind == "clean" || kind == "white30" || kind == "pink25" || kind == "fast" || kind == "breathy" || kind == "lenis")
        return {true, 20.0, 90.0, 97.0, false};
    if (is_human) return {true, 0.0, 80.0, 95.0, false};
    if (condition == "clean" || condition == "white30") return {true, 20.0, 90.0, 0.0, true};
    if (condition == "white10") return {true, 0.0, 85.0, 0.0, true};
    return {true, 0.0, 80.0, 0.0, true};
}

// Issue 12: a syllable more than 100 ms off should come out with a low confidence. Of the
// syllables of `score`, how many of those more than 100 ms off fall under `threshold`, and how
// many of the others do (a false alarm); and the confidence under which a tenth of the others fall.
// Returns the share of the others flagged.
double print_confidence(const std::string& condition, const Score& score, double threshold) {
    std::size_t bad = 0, bad_flagged = 0, good = 0, good_flagged = 0;
    std::vector<double> good_confidences;
    for (std::size_t i = 0; i < score.confidences.size(); ++i) {
        const bool is_low = score.confidences[i] < threshold;
        if (score.aligned_errors_s[i] > 0.100) {
            ++bad;
            bad_flagged += is_low;
        } else {
            ++good;
            good_flagged += is_low;
            good_confidences.push_back(score.confidences[i]);
        }
    }
    std::sort(good_confidences.begin(), good_confidences.end());
    const double tenth = good_confidences.empty() ? 0.0 : good_confidences[good_confidences.size() / 10];
    std::printf("%-10s %6zu of %-6zu %6.1f%%   %6zu of %-6zu %6.1f%%   %.3f\n", condition.c_str(), bad_flagged, bad,
                bad ? 100.0 * static_cast<double>(bad_flagged) / static_cast<double>(bad) : 0.0, good_flagged, good,
                good ? 100.0 * static_cast<double>(good_flagged) / static_cast<double>(good) : 0.0, tenth);
    return good ? static_cast<double>(good_flagged) / static_cast<double>(good) : 0.0;
}

std::string format_fixed(double value, int decimals) {
    if (std::isnan(value)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

void print_header() {
    std::printf("%-10s %-9s %14s %9s %9s %8s %8s %11s %10s  %s\n", "condition", "method", "passages", "syllables",
                "median_ms", "in_50ms", "in_100ms", "boundaries", "x_realtime", "target");
}

void print_row(const std::string& condition, const std::string& method, const Score& score, const Target& target,
               bool timed) {
    const std::string passages =
        std::to_string(score.passages) + (score.failed ? " (" + std::to_string(score.failed) + " failed)" : "");
    const std::string boundaries = std::to_string(score.boundaries_found) + "/" + std::to_string(score.boundaries);
    const std::string speed = timed && score.cpu_s > 0 ? format_fixed(score.audio_s / score.cpu_s, 0) + "x" : "-";
    std::string verdict = target.applies ? target.text() + ": " + (target.met(score) ? "met" : "NOT MET") : "";
    std::printf("%-10s %-9s %14s %9zu %9s %7s%% %7s%% %11s %10s  %s\n", condition.c_str(), method.c_str(),
                passages.c_str(), score.errors_s.size(), format_fixed(score.median_ms(), 1).c_str(),
                format_fixed(score.within_percent(0.050), 1).c_str(), format_fixed(score.within_percent(0.100), 1).c_str(),
                boundaries.c_str(), speed.c_str(), verdict.c_str());
}

std::vector<std::string> corpus_conditions(const fs::path& corpus, const std::string& only) {
    std::istringstream lines(read_text(corpus / "conditions.txt"));
    std::vector<std::string> names;
    for (std::string line; std::getline(lines, line);) {
        const std::string name = line.substr(0, line.find('\t'));
        if (!name.empty() && (only.empty() || ("," + only + ",").find("," + name + ",") != std::string::npos))
            names.push_back(name);
    }
    if (names.empty()) throw std::runtime_error((corpus / "conditions.txt").string() + ": no condition selected");
    return names;
}

// The truths of one condition's passages, in order.
std::vector<fs::path> truth_files(const fs::path& directory) {
    std::vector<fs::path> truths;
    for (const auto& entry : fs::directory_iterator(directory))
        if (entry.path().extension() == ".json") truths.push_back(entry.path());
    std::sort(truths.begin(), truths.end());
    return truths;
}

fs::path transcript_beside(const fs::path& truth_path) {
    fs::path transcript_path = truth_path;
    return transcript_path.replace_extension(".txt");
}

fs::path audio_beside(const fs::path& truth_path) {
    for (const char* extension : {".wav", ".ogg", ".flac"}) {
        fs::path candidate = truth_path;
        candidate.replace_extension(extension);
        if (fs::exists(candidate)) return candidate;
    }
    throw std::runtime_error(truth_path.string() + ": no audio beside it");
}

int run_corpus(const fs::path& corpus, const std::string& only, const std::string& dump_path,
               const std::string& warnings_path) {
    std::ofstream dump;
    std::ofstream warnings;
    if (!warnings_path.empty()) {
        warnings.open(warnings_path);
        if (!warnings) throw std::runtime_error(warnings_path + ": cannot write");
    }
    if (!dump_path.empty()) {
        dump.open(dump_path);
        if (!dump) throw std::runtime_error(dump_path + ": cannot write");
        dump << "condition\tpassage\tsyllable\tpinyin\ttrue_start\tstart\terror_ms\tconfidence\n";
    }
    const auto conditions = corpus_conditions(corpus, only);
    const talkface::SpeechAligner aligner;
    // scores[set][condition] for the aligner and the baseline.
    std::map<std::string, std::map<std::string, Score>> aligner_scores, baseline_scores;
    for (const auto& condition : conditions) {
        for (const auto& truth_path : truth_files(corpus / condition)) {
            const Truth truth = load_truth(truth_path);
            const fs::path audio_path = audio_beside(truth_path);
            const auto transcript = talkface::load_transcript(transcript_beside(truth_path).string());

            Score& mine = aligner_scores[truth.set][condition];
            ++mine.passages;
            mine.audio_s += truth.timeline.duration_s;
            const std::clock_t begin = std::clock();
            try {
                const auto aligned = aligner.align_file(audio_path.string(), transcript);
                mine.cpu_s += static_cast<double>(std::clock() - begin) / CLOCKS_PER_SEC;
                score_timeline(aligned, truth.timeline, audio_path.string(), mine);
                for (const std::string& warning : aligned.warnings)
                    if (warnings)
                        warnings << condition << "\t" << truth_path.stem().string() << "\t" << warning
                                 << "\n";
                for (std::size_t i = 0; dump && i < aligned.syllables.size(); ++i) {
                    const auto& syllable = aligned.syllables[i];
                    const double truth_s = truth.timeline.syllables[i].start_s;
                    dump << condition << "\t" << truth_path.stem().string() << "\t" << i << "\t" << syllable.pinyin << "\t"
                         << truth_s << "\t" << syllable.start_s << "\t" << 1000.0 * (syllable.start_s - truth_s) << "\t"
                         << syllable.confidence << "\n";
                }
            } catch (const talkface::Error& error) {
                mine.cpu_s += static_cast<double>(std::clock() - begin) / CLOCKS_PER_SEC;
                ++mine.failed;
                mine.errors_s.insert(mine.errors_s.end(), truth.timeline.syllables.size(),
                                     std::numeric_limits<double>::infinity());
                mine.boundaries += 2 * static_cast<int>(truth.timeline.sentences.size());
                std::cerr << "align_bench: " << error.what() << "\n";
            }
            Score& naive = baseline_scores[truth.set][condition];
            ++naive.passages;
            score_timeline(even_split(truth.timeline), truth.timeline, audio_path.string(), naive);
        }
        std::cerr << "align_bench: " << condition << " done\n";
    }

    std::printf("talkface aligner benchmark on %s\n", corpus.string().c_str());
    std::printf("onset error: |aligned start - true start| of every syllable (SPEC \"Alignment\"); failed passages count\n"
                "  as missed. boundaries: a sentence start or end counts as found within %.0f ms of the truth.\n"
                "  x_realtime: seconds of audio per second of process CPU time (std::clock, reading and decoding\n"
                "  included), i.e. one core's worth. baseline: each TRUE sentence span divided evenly among its\n"
                "  syllables (its boundaries are the truth's, so they are always found).\n",
                1000.0 * boundary_tolerance_s);
    Score aligner_all, baseline_all;
    int targets = 0, targets_met = 0;
    for (const char* set : sets) {
        if (aligner_scores.find(set) == aligner_scores.end()) continue;
        std::printf("\n%s sentences\n", set);
        print_header();
        for (const auto& condition : conditions) {
            const Score& mine = aligner_scores[set][condition];
            const Score& naive = baseline_scores[set][condition];
            if (mine.passages == 0) continue;
            const Target target = target_for(condition);
            ++targets;
            targets_met += target.met(mine);
            print_row(condition, "aligner", mine, target, true);
            print_row("", "baseline", naive, Target{}, false);
            aligner_all.add(mine);
            baseline_all.add(naive);
        }
    }
    std::printf("\nconfidence (issue 12): syllables more than 100 ms off, and the others, under talkface's documented\n"
                "  threshold for a low confidence (%.2f); good_p10: the confidence under which 10%% of the others fall\n",
                talkface::kLowAlignmentConfidence);
    for (const char* set : sets) {
        if (aligner_scores.find(set) == aligner_scores.end()) continue;
        std::printf("%s sentences\n%-10s %-24s %-24s %s\n", set, "condition", "off >100ms: flagged", "others: flagged",
                    "good_p10");
        Score pooled;
        // The threshold must hold in every condition (a voice or a room the benchmark lacks is
        // another condition), not only pooled: the condition that flags most, beside the pool.
        double most_flagged = -1.0;
        std::string most_flagged_condition;
        for (const auto& condition : conditions) {
            const Score& mine = aligner_scores[set][condition];
            if (mine.passages == 0) continue;
            const double flagged = print_confidence(condition, mine, talkface::kLowAlignmentConfidence);
            if (flagged > most_flagged) {
                most_flagged = flagged;
                most_flagged_condition = condition;
            }
            pooled.add(mine);
        }
        print_confidence("all", pooled, talkface::kLowAlignmentConfidence);
        std::printf("%-10s %-24s %6.1f%%   (%s)\n", "most", "", 100.0 * most_flagged, most_flagged_condition.c_str());
    }
    std::printf("\nall\n");
    print_header();
    print_row("all", "aligner", aligner_all, Target{}, true);
    print_row("", "baseline", baseline_all, Target{}, false);
    const double speed = aligner_all.cpu_s > 0 ? aligner_all.audio_s / aligner_all.cpu_s : 0.0;
    ++targets;
    targets_met += speed >= target_speed;
    std::printf("\nspeed: %.0f s of audio in %.2f s of CPU = %.0fx real time (target >= %.0fx: %s)\n", aligner_all.audio_s,
                aligner_all.cpu_s, speed, target_speed, speed >= target_speed ? "met" : "NOT MET");
    std::printf("peak memory for an hour of speech (target < 200 MB): run bench/memory_bench.sh\n");
    std::printf("targets met: %d of %d\n", targets_met, targets);
    return 0;
}

// The syllables of joined passages, each truth moved to where its passage starts in the audio.
std::vector<talkface::Syllable> joined_truth(const std::string& list_path) {
    std::istringstream lines(read_text(list_path));
    std::vector<talkface::Syllable> syllables;
    for (std::string line; std::getline(lines, line);) {
        const auto tab = line.find('\t');
        if (tab == std::string::npos) throw std::runtime_error(list_path + ": expected OFFSET_S<TAB>TRUTH.json, found " + line);
        const double offset_s = std::stod(line.substr(0, tab));
        for (auto syllable : load_truth(line.substr(tab + 1)).timeline.syllables) {
            syllable.start_s += offset_s;
            syllable.end_s += offset_s;
            syllables.push_back(syllable);
        }
    }
    return syllables;
}

int run_file(const std::string& audio_path, const std::string& transcript_path, const std::string& truth_list) {
    const auto transcript = talkface::load_transcript(transcript_path);
    const talkface::SpeechAligner aligner;
    const std::clock_t begin = std::clock();
    const auto aligned = aligner.align_file(audio_path, transcript);
    const double cpu_s = static_cast<double>(std::clock() - begin) / CLOCKS_PER_SEC;
    std::printf("%s: %.1f s of audio, %zu sentences, %zu syllables aligned in %.2f s of CPU = %.0fx real time\n",
                audio_path.c_str(), aligned.duration_s, aligned.sentences.size(), aligned.syllables.size(), cpu_s,
                cpu_s > 0 ? aligned.duration_s / cpu_s : 0.0);
    if (truth_list.empty()) return 0;
    const auto truth = joined_truth(truth_list);
    if (truth.size() != aligned.syllables.size())
        throw std::runtime_error(truth_list + ": " + std::to_string(truth.size()) + " syllables, the transcript has " +
                                 std::to_string(aligned.syllables.size()));
    Score score;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (truth[i].pinyin != aligned.syllables[i].pinyin)
            throw std::runtime_error(truth_list + ": syllable " + std::to_string(i) + " is " + truth[i].pinyin +
                                     ", the transcript's is " + aligned.syllables[i].pinyin);
        score.errors_s.push_back(std::fabs(aligned.syllables[i].start_s - truth[i].start_s));
    }
    std::printf("onsets: median %s ms, %s%% within 50 ms, %s%% within 100 ms\n", format_fixed(score.median_ms(), 1).c_str(),
                format_fixed(score.within_percent(0.050), 1).c_str(), format_fixed(score.within_percent(0.100), 1).c_str());
    return 0;
}

// --mismatch: how often a wrong transcript is reported (AlignmentError) and how often a right one
// is refused, on clips of one and two sentences cut from each passage at the middle of the pauses
// around them, and on whole passages. Wrong texts: another sentence of the passage of the nearest
// syllable count in place of one, or two sentences swapped; and texts that lack what was said
// (issue 13): a whole sentence of the passage left out, or the last 1-3 syllables of a sentence.
struct Audio {
    std::vector<float> samples;  ///< interleaved
    int channels = 1;
    int rate_hz = 0;
};

Audio read_audio(const fs::path& path) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.string().c_str(), SFM_READ, &info);
    if (!file) throw std::runtime_error(path.string() + ": " + sf_strerror(nullptr));
    Audio audio;
    audio.channels = info.channels;
    audio.rate_hz = info.samplerate;
    audio.samples.resize(static_cast<std::size_t>(info.frames * info.channels));
    sf_readf_float(file, audio.samples.data(), info.frames);
    sf_close(file);
    return audio;
}

struct MismatchCount {
    int right = 0, refused = 0;    ///< right transcripts, and those the aligner threw on
    int wrong = 0, detected = 0;   ///< wrong transcripts, and those it threw on
    void add(const MismatchCount& other) {
        add_fields(*this, other, &MismatchCount::right, &MismatchCount::refused, &MismatchCount::wrong,
                   &MismatchCount::detected);
    }
};

bool throws_alignment_error(const talkface::SpeechAligner& aligner, const Audio& audio, std::size_t first_frame,
                            std::size_t end_frame, const talkface::Timeline& transcript, const std::string& where,
                            bool is_right, bool report_missed) {
    const talkface::AudioView view{audio.samples.data() + first_frame * static_cast<std::size_t>(audio.channels),
                                   end_frame - first_frame, audio.channels, audio.rate_hz};
    try {
        aligner.align(view, transcript);
        if (!is_right && report_missed) std::cerr << "align_bench: missed: " << where << "\n";
        return false;
    } catch (const talkface::AlignmentError& error) {
        if (is_right) std::cerr << "align_bench: false alarm: " << where << ": " << error.what() << "\n";
        return true;
    }
}

// `transcript` without the last `count` syllables of its sentence `sentence` (which keeps at least
// one); the written forms after them move up, those among them are left out.
talkface::Timeline without_tail(const talkface::Timeline& transcript, std::size_t sentence, std::size_t count) {
    talkface::Timeline result = transcript;
    std::size_t end = 0, members = 0;
    for (std::size_t i = 0; i < result.syllables.size(); ++i) {
        if (result.syllables[i].sentence != sentence) continue;
        end = i + 1;
        ++members;
    }
    count = std::min(count, members > 0 ? members - 1 : 0);
    const std::size_t first = end - count;
    result.syllables.erase(result.syllables.begin() + static_cast<std::ptrdiff_t>(first),
                           result.syllables.begin() + static_cast<std::ptrdiff_t>(end));
    std::vector<talkface::WrittenForm> forms;
    for (auto form : result.written_forms) {
        if (form.first_syllable + form.syllable_count <= first) {
            forms.push_back(form);
        } else if (form.first_syllable >= end) {
            form.first_syllable -= count;
            forms.push_back(form);
        }
    }
    result.written_forms = forms;
    return result;
}

// Lines `lines` joined as a transcript, one sentence a line.
std::string joined_lines(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& line : lines) text += line + "\n";
    return text;
}

// With `clips_only` (--clips), the clips of one and two sentences alone: the lines dialogue users
// bring (issue 13), whose checks a change moves first, in a fraction of the passages' time.
int run_mismatch(const fs::path& corpus, const std::string& only, bool clips_only) {
    const auto conditions = corpus_conditions(corpus, only);
    const talkface::SpeechAligner aligner;
    // The first three are cut by another sentence's text; the others lack what was said, and their
    // right texts are those of the clips they were cut from (counted again beside them).
    const char* const groups[] = {"1 sentence", "2 sentences", "passage", "1 tail-",
                                  "passage tail-", "2 one left", "passage one left"};
    // counts[set][condition][group]
    std::map<std::string, std::map<std::string, std::map<std::string, MismatchCount>>> counts;
    for (const auto& condition : conditions) {
        for (const auto& truth_path : truth_files(corpus / condition)) {
            const Truth truth = load_truth(truth_path);
            const fs::path audio_path = audio_beside(truth_path);
            const fs::path transcript_path = transcript_beside(truth_path);
            const Audio audio = read_audio(audio_path);
            std::vector<std::string> lines;
            {
                std::istringstream text(read_text(transcript_path));
                for (std::string line; std::getline(text, line);)
                    if (!line.empty()) lines.push_back(line);
            }
            const auto& sentences = truth.timeline.sentences;
            const std::size_t n = sentences.size();
            if (lines.size() != n) throw std::runtime_error(transcript_path.string() + ": not one sentence a line");
            std::vector<std::size_t> syllable_counts(n, 0);
            for (const auto& syllable : truth.timeline.syllables) ++syllable_counts[syllable.sentence];
            const auto total_frames = audio.samples.size() / static_cast<std::size_t>(audio.channels);
            auto frame_at = [&](double seconds) {
                return std::min(total_frames, static_cast<std::size_t>(std::max(0.0, seconds) * audio.rate_hz));
            };
            // Clip k..last: from the middle of the pause before sentence k to the middle of the one after.
            auto clip_first = [&](std::size_t k) { return frame_at(k == 0 ? 0.0 : 0.5 * (sentences[k - 1].end_s + sentences[k].start_s)); };
            auto clip_end = [&](std::size_t k) {
                return k + 1 == n ? total_frames : frame_at(0.5 * (sentences[k].end_s + sentences[k + 1].start_s));
            };
            // Another sentence of the passage, outside [first, last], of the nearest syllable count.
            auto replacement = [&](std::size_t k, std::size_t first, std::size_t last) {
                std::size_t best = n;
                for (std::size_t j = 0; j < n; ++j) {
                    if ((j >= first && j <= last) || lines[j] == lines[k]) continue;
                    const auto difference = [&](std::size_t i) {
                        return std::abs(static_cast<long>(syllable_counts[i]) - static_cast<long>(syllable_counts[k]));
                    };
                    if (best == n || difference(j) < difference(best)) best = j;
                }
                return best;
            };
            auto& by_group = counts[truth.set][condition];
            const std::string name = audio_path.string();
            auto run_transcript = [&](const char* group, std::size_t first, std::size_t end,
                                      const talkface::Timeline& transcript, bool is_right, const std::string& what) {
                MismatchCount& count = by_group[group];
                // A text that lacks what was said is named when it passes: the cases issue 13 is about.
                const bool report_missed = std::string(group).find('-') != std::string::npos ||
                                           std::string(group).find("left") != std::string::npos;
                const bool thrown =
                    throws_alignment_error(aligner, audio, first, end, transcript, name + " " + what, is_right, report_missed);
                if (is_right) {
                    ++count.right;
                    count.refused += thrown;
                } else {
                    ++count.wrong;
                    count.detected += thrown;
                }
                return thrown;
            };
            auto run = [&](const char* group, std::size_t first, std::size_t end, const std::string& text, bool is_right,
                           const std::string& what) {
                return run_transcript(group, first, end, talkface::read_transcript(text), is_right, what);
            };
            // The right text's refusal counted again in a group of texts cut from it.
            auto count_right = [&](const char* group, bool thrown) {
                MismatchCount& count = by_group[group];
                ++count.right;
                count.refused += thrown;
            };
            for (std::size_t k = 0; k < n; ++k) {
                const std::string what = "sentence " + std::to_string(k + 1);
                const bool right_thrown = run("1 sentence", clip_first(k), clip_end(k), lines[k], true, what);
                const std::size_t other = replacement(k, k, k);
                if (other < n) run("1 sentence", clip_first(k), clip_end(k), lines[other], false, what);
                // 1, 2 or 3 syllables, in turn.
                const std::size_t tail = 1 + k % 3;
                if (syllable_counts[k] > tail) {
                    count_right("1 tail-", right_thrown);
                    run_transcript("1 tail-", clip_first(k), clip_end(k), without_tail(talkface::read_transcript(lines[k]), 0, tail),
                                   false, what + " less " + std::to_string(tail) + " syllables");
                }
            }
            for (std::size_t k = 0; k + 1 < n; ++k) {
                const std::string what = "sentences " + std::to_string(k + 1) + "-" + std::to_string(k + 2);
                const bool right_thrown = run("2 sentences", clip_first(k), clip_end(k + 1), lines[k] + "\n" + lines[k + 1], true, what);
                run("2 sentences", clip_first(k), clip_end(k + 1), lines[k + 1] + "\n" + lines[k], false, what);
                const std::size_t other = replacement(k + 1, k, k + 1);
                if (other < n) run("2 sentences", clip_first(k), clip_end(k + 1), lines[k] + "\n" + lines[other], false, what);
                // The first or the second left out, in turn.
                const std::size_t left = k % 2 == 0 ? k : k + 1;
                count_right("2 one left", right_thrown);
                run("2 one left", clip_first(k), clip_end(k + 1), lines[left == k ? k + 1 : k], false,
                    what + " without sentence " + std::to_string(left + 1));
            }
            if (clips_only) continue;
            std::vector<std::string> swapped = lines, replaced = lines;
            const std::size_t middle = n / 2;
            const std::size_t other = replacement(middle, middle, middle);
            if (n >= 2) std::swap(swapped[0], swapped[1]);
            if (other < n) replaced[middle] = lines[other];
            const bool right_thrown = run("passage", 0, total_frames, joined_lines(lines), true, "passage");
            if (n >= 2) run("passage", 0, total_frames, joined_lines(swapped), false, "passage swapped");
            if (other < n) run("passage", 0, total_frames, joined_lines(replaced), false, "passage replaced");
            if (n >= 3) {
                // The first, the middle and the last sentence left out.
                for (const std::size_t left : {std::size_t{0}, middle, n - 1}) {
                    std::vector<std::string> kept = lines;
                    kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(left));
                    count_right("passage one left", right_thrown);
                    run("passage one left", 0, total_frames, joined_lines(kept), false,
                        "passage without sentence " + std::to_string(left + 1));
                }
                // The tail of the middle sentence, and of the one before the last.
                const talkface::Timeline whole = talkface::read_transcript(joined_lines(lines));
                for (const std::size_t k : {middle, n - 2}) {
                    const std::size_t tail = k == middle ? 2 : 1;
                    if (syllable_counts[k] <= tail) continue;
                    count_right("passage tail-", right_thrown);
                    run_transcript("passage tail-", 0, total_frames, without_tail(whole, k, tail), false,
                                   "passage, sentence " + std::to_string(k + 1) + " less " + std::to_string(tail) + " syllables");
                }
            }
        }
        std::cerr << "align_bench: " << condition << " done\n";
    }

    std::printf("wrong transcripts on %s: detected = the aligner threw AlignmentError on a wrong text (another\n"
                "sentence of the passage, of the nearest syllable count, in place of one; or two sentences swapped;\n"
                "\"tail-\": the last 1-3 syllables of a sentence left out; \"one left\": a whole sentence left out);\n"
                "false alarm = it threw on the right text. Clips are cut at the middle of the pauses around them.\n",
                corpus.string().c_str());
    for (const char* set : sets) {
        if (counts.find(set) == counts.end()) continue;
        std::printf("\n%s sentences\n%-10s %-16s %16s %16s\n", set, "condition", "clip", "detected", "false alarms");
        std::map<std::string, MismatchCount> totals;
        for (const auto& condition : conditions) {
            for (const char* group : groups) {
                const MismatchCount& count = counts[set][condition][group];
                if (count.right == 0 && count.wrong == 0) continue;
                totals[group].add(count);
                std::printf("%-10s %-16s %9d/%-6d %9d/%-6d\n", condition.c_str(), group, count.detected, count.wrong,
                            count.refused, count.right);
            }
        }
        for (const char* group : groups) {
            const MismatchCount& count = totals[group];
            if (count.right == 0 && count.wrong == 0) continue;
            std::printf("%-10s %-16s %9d/%-6d %9d/%-6d  (%s%% detected, %s%% false alarms)\n", "all", group, count.detected,
                        count.wrong, count.refused, count.right,
                        format_fixed(100.0 * count.detected / std::max(count.wrong, 1), 1).c_str(),
                        format_fixed(100.0 * count.refused / std::max(count.right, 1), 1).c_str());
        }
    }
    return 0;
}

// --lenient (issue 13): texts a word off aligned with AlignOptions::lenient. Each passage is
// aligned with its right text (every syllable a mismatch names there is a false mark) and, once
// for each of its sentences, with two neighbouring characters near that sentence's middle changed
// into another word (a changed word: found whole where mismatches name both its syllables, in
// part where they name one or a mark overlaps its true span naming neither, else missed; the
// other syllables a mismatch names are false marks too).
// Words put in place of the one said: two syllables whose sounds differ from most (as lenient_bench.py).
const char* const substitutes[] = {"电脑", "火车", "足球", "沙发"};

struct LenientCount {
    int right_syllables = 0, right_marked = 0;  ///< right texts' syllables, and those a mismatch names
    int right_generic = 0;                      ///< "speech the transcript lacks" marks on right texts
    int words = 0, whole = 0, in_part = 0;      ///< changed words, and those found
    int exact = 0;                              ///< words found whole whose marks name no other syllable
    int other_syllables = 0, other_marked = 0;  ///< the changed texts' other syllables, and those named
    int other_generic = 0;                      ///< marks on changed texts that neither name nor overlap the word
    std::vector<double> start_errors_s, end_errors_s;  ///< of the marks over a word found
    int lacking = 0, lacking_found = 0;              ///< texts that lack the word, and those a mark overlaps it in
    int lacking_syllables = 0, lacking_marked = 0;   ///< their syllables (all right), and those a mismatch names
    int lacking_generic = 0;                         ///< their marks of speech lacking elsewhere
    std::vector<double> lacking_start_errors_s, lacking_end_errors_s;
    void add(const LenientCount& other) {
        using C = LenientCount;
        add_fields(*this, other, &C::right_syllables, &C::right_marked, &C::right_generic, &C::words, &C::whole,
                   &C::in_part, &C::exact, &C::other_syllables, &C::other_marked, &C::other_generic, &C::start_errors_s,
                   &C::end_errors_s, &C::lacking, &C::lacking_found, &C::lacking_syllables, &C::lacking_marked,
                   &C::lacking_generic, &C::lacking_start_errors_s, &C::lacking_end_errors_s);
    }
};

// Byte offsets in `line` of its CJK ideographs (U+4E00-U+9FFF, three bytes in UTF-8) that carry
// no reading fixed in place ("行{hang2}").
std::vector<std::size_t> plain_han_offsets(const std::string& line) {
    std::vector<std::size_t> offsets;
    for (std::size_t i = 0; i < line.size();) {
        const auto lead = static_cast<unsigned char>(line[i]);
        const std::size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        if (length == 3 && i + 3 <= line.size()) {
            const unsigned code = ((lead & 0x0Fu) << 12) | ((static_cast<unsigned char>(line[i + 1]) & 0x3Fu) << 6) |
                                  (static_cast<unsigned char>(line[i + 2]) & 0x3Fu);
            const bool is_fixed = i + 3 < line.size() && line[i + 3] == '{';
            if (code >= 0x4E00 && code <= 0x9FFF && !is_fixed) offsets.push_back(i);
        }
        i += length;
    }
    return offsets;
}

// Byte offset in `line` of two neighbouring ideographs nearest its middle (not its first one, nor
// among its last three) that are not `word`; npos where it has no such pair.
std::size_t middle_word_offset(const std::string& line, const std::string& word) {
    const std::vector<std::size_t> han = plain_han_offsets(line);
    if (han.size() < 5) return std::string::npos;
    std::vector<std::size_t> order;
    for (std::size_t k = 1; k + 4 <= han.size(); ++k) order.push_back(k);
    const auto middle = static_cast<long>(han.size() / 2);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return std::labs(static_cast<long>(a) - middle) < std::labs(static_cast<long>(b) - middle);
    });
    for (const std::size_t k : order)
        if (han[k + 1] == han[k] + 3 && line.compare(han[k], 6, word) != 0) return han[k];
    return std::string::npos;
}

void print_lenient_row(const std::string& condition, const LenientCount& count) {
    auto share = [](int part, int whole) { return format_fixed(100.0 * part / std::max(whole, 1), 1) + "%"; };
    auto median_ms = [](std::vector<double> values) {
        if (values.empty()) return std::string("-");
        std::sort(values.begin(), values.end());
        return format_fixed(1000.0 * values[values.size() / 2], 0);
    };
    std::printf("%-16s %5d/%-5d %6s %4d | %4d/%-4d %4d %4d %5d  %5d/%-5d %6s %4d  %5s %5s | %4d/%-4d %5d/%-5d %4d  %5s %5s\n",
                condition.c_str(), count.right_marked, count.right_syllables,
                share(count.right_marked, count.right_syllables).c_str(), count.right_generic, count.whole, count.words,
                count.in_part, count.words - count.whole - count.in_part, count.exact, count.other_marked, count.other_syllables,
                share(count.other_marked, count.other_syllables).c_str(), count.other_generic,
                median_ms(count.start_errors_s).c_str(), median_ms(count.end_errors_s).c_str(), count.lacking_found,
                count.lacking, count.lacking_marked, count.lacking_syllables, count.lacking_generic,
                median_ms(count.lacking_start_errors_s).c_str(), median_ms(count.lacking_end_errors_s).c_str());
}

int run_lenient(const fs::path& corpus, const std::string& only, const std::string& dump_path) {
    const auto conditions = corpus_conditions(corpus, only);
    std::ofstream dump;
    if (!dump_path.empty()) {
        dump.open(dump_path);
        if (!dump) throw std::runtime_error(dump_path + ": cannot write");
        dump << "condition\tset\tpassage\tcase\tsyllable\tchanged\tmarked\tconfidence\terror_s\n";
    }
    // One row a syllable of `result`: `word` is the changed word's first syllable (none: max).
    auto dump_rows = [&](const std::string& condition, const std::string& set, const std::string& passage,
                         const std::string& what, const talkface::Timeline& result, const talkface::Timeline& truth,
                         std::size_t word) {
        if (!dump) return;
        std::vector<bool> marked(result.syllables.size());
        for (const auto& mismatch : result.mismatches)
            for (std::size_t i = mismatch.first_syllable; i < mismatch.first_syllable + mismatch.syllable_count; ++i) marked[i] = true;
        for (std::size_t i = 0; i < result.syllables.size(); ++i)
            dump << condition << '\t' << set << '\t' << passage << '\t' << what << '\t' << i << '\t'
                 << (i == word || i == word + 1) << '\t' << marked[i] << '\t' << result.syllables[i].confidence << '\t'
                 << std::fabs(result.syllables[i].start_s - truth.syllables[i].start_s) << '\n';
    };
    talkface::AlignOptions options;
    options.lenient = true;
    const talkface::SpeechAligner aligner(options);
    std::map<std::string, std::map<std::string, LenientCount>> counts;  // counts[set][condition]
    for (const auto& condition : conditions) {
        std::size_t substitute = 0;
        for (const auto& truth_path : truth_files(corpus / condition)) {
            const Truth truth = load_truth(truth_path);
            const fs::path audio_path = audio_beside(truth_path);
            const std::string text = read_text(transcript_beside(truth_path));
            std::vector<std::string> lines;
            {
                std::istringstream stream(text);
                for (std::string line; std::getline(stream, line);)
                    if (!line.empty()) lines.push_back(line);
            }
            LenientCount& count = counts[truth.set][condition];
            const talkface::Timeline right_text = talkface::read_transcript(text);
            const auto& truth_syllables = truth.timeline.syllables;
            if (right_text.syllables.size() != truth_syllables.size())
                throw std::runtime_error(audio_path.string() + ": its text and its truth differ in syllables");
            const talkface::Timeline right = aligner.align_file(audio_path.string(), right_text);
            const std::string passage = truth_path.stem().string();
            dump_rows(condition, truth.set, passage, "right", right, truth.timeline, std::numeric_limits<std::size_t>::max());
            count.right_syllables += static_cast<int>(right.syllables.size());
            for (const auto& mismatch : right.mismatches) {
                count.right_marked += static_cast<int>(mismatch.syllable_count);
                count.right_generic += mismatch.syllable_count == 0;
            }
            for (std::size_t k = 0; k < lines.size(); ++k) {
                const std::string substitute_word = substitutes[substitute++ % std::size(substitutes)];
                const std::size_t at = middle_word_offset(lines[k], substitute_word);
                if (at == std::string::npos) continue;
                std::vector<std::string> changed_lines = lines, lacking_lines = lines;
                changed_lines[k] = lines[k].substr(0, at) + substitute_word + lines[k].substr(at + 6);
                lacking_lines[k] = lines[k].substr(0, at) + lines[k].substr(at + 6);
                const talkface::Timeline changed_text = talkface::read_transcript(joined_lines(changed_lines));
                // The word's two syllables: where the texts differ (a pair, or the case is left out).
                std::vector<std::size_t> differ;
                if (changed_text.syllables.size() == right_text.syllables.size())
                    for (std::size_t i = 0; i < right_text.syllables.size(); ++i)
                        if (changed_text.syllables[i].text != right_text.syllables[i].text) differ.push_back(i);
                if (differ.size() != 2 || differ[1] != differ[0] + 1) continue;
                const std::size_t word = differ[0];
                const double word_start = truth_syllables[word].start_s, word_end = truth_syllables[word + 1].end_s;
                const talkface::Timeline result = aligner.align_file(audio_path.string(), changed_text);
                dump_rows(condition, truth.set, passage, "changed " + std::to_string(k + 1), result, truth.timeline, word);
                ++count.words;
                count.other_syllables += static_cast<int>(result.syllables.size()) - 2;
                bool names[2] = {false, false};
                bool names_beside = false;  // a mismatch that names the word names another syllable too
                double first_s = std::numeric_limits<double>::infinity(), last_s = -first_s;
                bool is_hit = false;
                for (const auto& mismatch : result.mismatches) {
                    const std::size_t end = mismatch.first_syllable + mismatch.syllable_count;
                    const bool covers = mismatch.syllable_count > 0 && mismatch.first_syllable <= word + 1 && end > word;
                    const bool overlaps = mismatch.start_s < word_end && mismatch.end_s > word_start;
                    for (std::size_t i = mismatch.first_syllable; i < end; ++i) {
                        if (i == word || i == word + 1) names[i - word] = true;
                        else ++count.other_marked;
                    }
                    if (covers && (mismatch.first_syllable < word || end > word + 2)) names_beside = true;
                    if (covers || overlaps) {
                        is_hit = true;
                        first_s = std::min(first_s, mismatch.start_s);
                        last_s = std::max(last_s, mismatch.end_s);
                    } else if (mismatch.syllable_count == 0) {
                        ++count.other_generic;
                    }
                }
                if (names[0] && names[1]) ++count.whole;
                else if (is_hit) ++count.in_part;
                if (names[0] && names[1] && !names_beside) ++count.exact;
                // Every word not found whole is named, with the marks made, to read them.
                if (!(names[0] && names[1])) {
                    std::cerr << "align_bench: " << (is_hit ? "in part" : "missed") << ": " << audio_path.string() << " sentence "
                              << k + 1 << " " << right_text.syllables[word].text << right_text.syllables[word + 1].text << " -> "
                              << changed_text.syllables[word].text << changed_text.syllables[word + 1].text << " at "
                              << format_fixed(word_start, 2) << "-" << format_fixed(word_end, 2) << " s; marks:";
                    for (const auto& mismatch : result.mismatches)
                        std::cerr << " [" << format_fixed(mismatch.start_s, 2) << "-" << format_fixed(mismatch.end_s, 2) << " \""
                                  << mismatch.expected_text << "\"]";
                    std::cerr << "\n";
                }
                if (is_hit) {
                    count.start_errors_s.push_back(std::fabs(first_s - word_start));
                    count.end_errors_s.push_back(std::fabs(last_s - word_end));
                }
                // The same word left out of the text: found where a mark overlaps its true span; every
                // syllable a mismatch names is a right one.
                const talkface::Timeline lacking_text = talkface::read_transcript(joined_lines(lacking_lines));
                if (lacking_text.syllables.size() + 2 != right_text.syllables.size()) continue;
                const talkface::Timeline lacking = aligner.align_file(audio_path.string(), lacking_text);
                ++count.lacking;
                count.lacking_syllables += static_cast<int>(lacking.syllables.size());
                bool is_found = false;
                first_s = std::numeric_limits<double>::infinity();
                last_s = -first_s;
                for (const auto& mismatch : lacking.mismatches) {
                    count.lacking_marked += static_cast<int>(mismatch.syllable_count);
                    if (mismatch.start_s < word_end && mismatch.end_s > word_start) {
                        is_found = true;
                        first_s = std::min(first_s, mismatch.start_s);
                        last_s = std::max(last_s, mismatch.end_s);
                    } else if (mismatch.syllable_count == 0) {
                        ++count.lacking_generic;
                    }
                }
                count.lacking_found += is_found;
                if (is_found) {
                    count.lacking_start_errors_s.push_back(std::fabs(first_s - word_start));
                    count.lacking_end_errors_s.push_back(std::fabs(last_s - word_end));
                }
            }
        }
        std::cerr << "align_bench: " << condition << " done\n";
    }
    std::printf("lenient alignment on %s (issue 13): each passage with its right text, and once per sentence with\n"
                "two neighbouring characters near its middle changed into another word (%s, %s, %s, %s in turn).\n"
                "right: syllables a mismatch names on the right texts (false marks), and marks of speech the\n"
                "transcript lacks; changed words found whole (both syllables named), in part (one named, or a mark\n"
                "over the word's true span naming neither) or missed, and exact: whole, its mismatch naming no other\n"
                "syllable; the changed texts' other syllables named (false marks) and their marks elsewhere; the\n"
                "median start and end error (ms) of the marks found.\n"
                "lacking: the same word left out of the text, found where a mark overlaps its true span; the\n"
                "syllables a mismatch names there (all right ones), marks elsewhere, errors of the marks found.\n",
                corpus.string().c_str(), substitutes[0], substitutes[1], substitutes[2], substitutes[3]);
    for (const char* set : sets) {
        if (counts.find(set) == counts.end()) continue;
        std::printf("\n%s\n%-16s %11s %6s %4s | %9s %4s %4s %5s  %11s %6s %4s  %5s %5s | %9s %11s %4s  %5s %5s\n", set,
                    "condition", "right named", "", "lack", "changed", "part", "miss", "exact", "others named", "", "else", "start",
                    "end", "lacking", "named", "else", "start", "end");
        LenientCount total;
        for (const auto& condition : conditions) {
            const auto found = counts[set].find(condition);
            if (found == counts[set].end()) continue;
            total.add(found->second);
            print_lenient_row(condition, found->second);
        }
        print_lenient_row("all", total);
    }
    return 0;
}

[[noreturn]] void usage(const std::string& problem) {
    std::cerr << "align_bench: " << problem << "\n"
              << "usage: align_bench CORPUS [--conditions A,B,...] [--dump SYLLABLES.tsv] [--warnings "
                 "WARNINGS.tsv]\n"
              << "       align_bench --file AUDIO TRANSCRIPT [--truth LIST]\n"
              << "       align_bench --mismatch CORPUS [--conditions A,B,...] [--clips]\n"
              << "       align_bench --lenient CORPUS [--conditions A,B,...] [--dump SYLLABLES.tsv]\n";
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        std::vector<std::string> positional;
        std::string only;
        std::string truth_list;
        std::string dump_path;
        std::string warnings_path;
        bool file_mode = false;
        bool mismatch_mode = false;
        bool lenient_mode = false;
        bool clips_only = false;
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            // The option's value, the next argument.
            const auto value = [&]() -> std::string {
                if (i + 1 >= argc) usage(arg + " needs a value");
                return argv[++i];
            };
            if (arg == "--conditions") {
                only = value();
            } else if (arg == "--truth") {
                truth_list = value();
            } else if (arg == "--dump") {
                dump_path = value();
            } else if (arg == "--warnings") {
                warnings_path = value();
            } else if (arg == "--mismatch") {
                mismatch_mode = true;
            } else if (arg == "--clips") {
                clips_only = true;
            } else if (arg == "--lenient") {
                lenient_mode = true;
            } else if (arg == "--file") {
                file_mode = true;
            } else if (arg == "-h" || arg == "--help") {
                usage("help");
            } else if (!arg.empty() && arg[0] == '-') {
                usage("unknown option " + arg);
            } else {
                positional.push_back(arg);
            }
        }
        if (file_mode) {
            if (positional.size() != 2) usage("--file takes AUDIO and TRANSCRIPT");
            return run_file(positional[0], positional[1], truth_list);
        }
        if (!truth_list.empty()) usage("--truth goes with --file");
        if (clips_only && !mismatch_mode) usage("--clips goes with --mismatch");
        if (positional.size() != 1) usage("give the corpus directory that make_corpus wrote");
        if (lenient_mode) return run_lenient(positional[0], only, dump_path);
        return mismatch_mode ? run_mismatch(positional[0], only, clips_only)
                             : run_corpus(positional[0], only, dump_path, warnings_path);
    } catch (const std::exception& error) {
        std::cerr << "align_bench: " << error.what() << "\n";
        return 1;
    }
}
