// What the two corpus generators share (make_corpus: espeak-ng's voice; make_human_corpus: a
// person's recorded syllables): seeded draws that repeat on every standard library, the sentence
// list, the noise of the recording conditions, sox, and the truth files align_bench reads.
#ifndef TALKFACE_BENCH_CORPUS_TOOLS_HPP
#define TALKFACE_BENCH_CORPUS_TOOLS_HPP

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iterator>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <talkface/timeline.hpp>

#include "wav_file.hpp"

namespace talkface_bench {

/// `value` read whole as a Number.
/// \throws std::invalid_argument naming the option `name` if it is not one.
template <typename Number>
Number parse_number(const std::string& name, const std::string& value) {
    std::istringstream in(value);
    Number number{};
    if (!(in >> number) || !in.eof()) throw std::invalid_argument(name + " expects a number, got \"" + value + "\"");
    return number;
}

/// The conditions (each with a `name`) that `list` names, comma-separated, or all of them if it is empty.
/// \throws std::invalid_argument naming an unknown one.
template <typename Condition, std::size_t N>
std::vector<const Condition*> select_conditions(const Condition (&all)[N], const std::string& list) {
    std::vector<const Condition*> selected;
    std::istringstream names(list);
    for (std::string name; std::getline(names, name, ',');) {
        const auto found = std::find_if(std::begin(all), std::end(all),
                                        [&](const Condition& condition) { return name == condition.name; });
        if (found == std::end(all)) throw std::invalid_argument("unknown condition \"" + name + "\"");
        selected.push_back(found);
    }
    if (selected.empty())
        for (const auto& condition : all) selected.push_back(&condition);
    return selected;
}

/// What both generators' command lines say:
///   PROGRAM OUT [--seed N] [--repeats N] [--sentences FILE] [--conditions A,B,...] [own options]
///   PROGRAM --clip STEM [--seed N] [own options] TEXT
struct CorpusCommand {
    std::string out_dir;    ///< OUT; empty with --clip
    std::string clip_stem;  ///< STEM; empty for a corpus
    std::string clip_text;  ///< TEXT
    std::uint64_t seed = 1;
    int repeats = 3;  ///< at least 1
    std::string sentences_path;
    std::string conditions;  ///< comma-separated names; empty: all
};

/// How a generator is used, for its messages.
struct CorpusUsage {
    std::string program;                  ///< "make_corpus"
    std::string lines;                    ///< the usage lines, each ending in "\n"
    std::vector<std::string> conditions;  ///< every condition's name
    /// Prints "PROGRAM: PROBLEM", the usage and the conditions to stderr; exits with status 2.
    [[noreturn]] void fail(const std::string& problem) const;
};

/// A generator's own option (--rate-wpm, --voice ...): given its value.
/// \throws std::invalid_argument for a bad value (parse_number's).
using OwnOption = std::function<void(const std::string& name, const std::string& value)>;

/// Reads the command line, handing each of `own`'s options to it. `sentences_path` is the default
/// sentence list. A bad command line (an unknown option, a missing value or argument, a number that
/// is not one, --repeats below 1) or -h / --help ends in usage.fail().
CorpusCommand parse_corpus_command(int argc, char** argv, const CorpusUsage& usage,
                                   const std::string& sentences_path,
                                   const std::vector<std::pair<std::string, OwnOption>>& own);

/// Uniform in [low, high). Not std::uniform_real_distribution, whose output differs between
/// standard libraries.
double uniform(std::mt19937_64& rng, double low, double high);
/// Uniform in low..high, both included.
int uniform_int(std::mt19937_64& rng, int low, int high);
/// Standard normal (Box-Muller).
double gaussian(std::mt19937_64& rng);

/// `text` in single quotes for a POSIX shell.
std::string quoted(const std::string& text);
/// Runs `sox -R -V1 INPUT OUTPUT_OPTIONS OUTPUT EFFECTS` (-R: sox's dither repeats from run to run).
/// \throws std::runtime_error with the command if sox fails.
void run_sox(const std::string& input, const std::string& output, const std::string& output_options,
             const std::string& effects);

void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);

struct BenchSentence {
    std::string text;  ///< as written in sentences.txt, reading fixes kept
    std::string set;   ///< "tuning" or "held-out"
};

/// `SET<TAB>SENTENCE` lines, each one sentence of characters with readings.
/// \throws std::runtime_error naming the file and line of a bad one.
std::vector<BenchSentence> load_sentences(const std::string& path);

/// A passage of about five sentences of one set.
struct PlannedPassage {
    std::string name;        ///< SET-NNN
    std::string set;
    std::string transcript;  ///< one sentence a line
    std::size_t sentence_count = 0;
};

/// Each repeat shuffles each set and cuts it into passages of about five sentences, so that a
/// sentence is heard beside different neighbours. `on_planned` is called on each passage as soon
/// as it is chosen, so that the caller draws its delivery from the same `rng` in the same order.
void plan_passages(const std::vector<BenchSentence>& sentences, int repeats, std::mt19937_64& rng,
                   const std::function<void(const PlannedPassage&)>& on_planned);

/// The noises under the voice. Issue #13 adds the steady and the musical ones, which must not be
/// blamed on the transcript either: hum is mains hum (50 Hz and its harmonics), tone_pink a steady
/// 440 Hz tone under pink noise, music a synthetic tune (chords of harmonic notes over a bass,
/// changing every 0.2-0.6 s), room a ventilated room (low-passed pink noise with a 120 Hz motor line).
/// song is a tune as a radio plays one under a voice: chords that change with the bar, a bass, a
/// melody and a drum kit's beat; mains_fan mains hum at 50 or 60 Hz (drawn) with its harmonics
/// and a fan's broadband air and blade tone.
enum class Noise { none, white, pink, brown, hum, tone_pink, music, room, song, mains_fan };

/// Noise of `colour` at `rate_hz`: Paul Kellet's pink filter (within 0.05 dB of -3 dB/octave above
/// 10 Hz at these rates), a leaky integrator for brown (-6 dB/octave), and the tonal kinds above.
std::vector<float> make_noise(Noise colour, std::size_t count, int rate_hz, std::mt19937_64& rng);

/// `clean` with noise added at `snr_db` against the speech's active level: the mean power inside
/// the sentences of `truth`, pauses left out. Speech and noise are scaled together below clipping.
MonoAudio add_noise(const MonoAudio& clean, const talkface::Timeline& truth, Noise colour, double snr_db,
                    std::mt19937_64& rng);

/// Seconds rounded to 10 us, as the truth files write them.
double rounded(double seconds);

/// The truth file's document: the shape of `talkface align --json` plus `after_pause` per syllable.
/// Callers add what they drew per sentence (`document["sentences"][k]["rate_wpm"]`) before dumping.
nlohmann::ordered_json truth_document(const std::string& generator, const std::string& condition,
                                      const std::string& set, const talkface::Timeline& truth,
                                      const std::vector<bool>& after_pause);

}  // namespace talkface_bench

#endif
