// SpeechAligner: audio -> features (streamed) -> sentence utterances -> per-sentence HSMM
// alignment, re-estimated on the recording (thesis chapter 3, SPEC "Alignment").
#include "talkface/speech_aligner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/joined_copy.hpp"
#include "common/number_format.hpp"
#include "speech/alignment_checks.hpp"
#include "speech/alignment_progress.hpp"
#include "speech/bed_removal.hpp"
#include "speech/chain_measures.hpp"
#include "speech/cut_alignment.hpp"
#include "speech/dropout_concealment.hpp"
#include "speech/frame_features.hpp"
#include "speech/given_spans_alignment.hpp"
#include "speech/latin_only_text.hpp"
#include "speech/line_among_voices.hpp"
#include "speech/own_reading_bound.hpp"
#include "speech/run_together.hpp"
#include "speech/sentence_cutter.hpp"
#include "speech/silenced_words.hpp"
#include "speech/skipped_time.hpp"
#include "speech/tone_witness.hpp"
#include "speech/weak_evidence.hpp"
#include "talkface/errors.hpp"
#include "text/unread_transcript.hpp"

namespace talkface {
inline namespace v0 {

namespace {

using namespace detail;

// The features of `source` (analyze_audio, after the samples `read_first` already read from it),
// its reading reported as the job's first kReadingShare.
FeatureTrack read_features(AudioSource& source, ProgressReporter& progress, bool with_pitch,
                           std::size_t skipped_samples, const std::vector<float>& read_first = {}) {
    return analyze_audio(
        source, [&](double fraction) { progress.report(kReadingShare * fraction, "reading"); }, with_pitch,
        skipped_samples, read_first);
}

void validate_transcript(const Timeline& transcript) {
    if (transcript.syllables.empty())
        throw InvalidArgument("transcript", "no syllables to align (" + detail::describe_unread_transcript(transcript) + ")");
    std::size_t previous = 0;
    for (std::size_t i = 0; i < transcript.syllables.size(); ++i) {
        const std::size_t sentence = transcript.syllables[i].sentence;
        if (sentence >= transcript.sentences.size() || sentence < previous)
            throw InvalidArgument("transcript", "syllable " + std::to_string(i) + " (\"" + transcript.syllables[i].text +
                                                    "\") names sentence " + std::to_string(sentence) + " of " +
                                                    std::to_string(transcript.sentences.size()) + " out of order");
        previous = sentence;
    }
}

// A line's own reading: after the noise a gain lifted before the first words
// (loudness_after_lifted_lead_in), or the line among quieter voices (line_cut_among_voices) of
// `cut`. Nothing where it has none, or where the checks (when `is_checked`) refuse it there.
std::optional<AlignedTimelines> align_own_reading(const FeatureTrack& track, const LoudnessProfile& loudness,
                                                  const Timeline& transcript, const SentenceCut& cut,
                                                  const std::vector<bool>& is_spoken,
                                                  const AlignOptions& options, ProgressReporter& progress,
                                                  bool is_checked) {
    try {
        if (const auto lifted = loudness_after_lifted_lead_in(track, loudness))
            return align_confirmed(track, track, *lifted, transcript,
                                   cut_sentences(track, *lifted, transcript, options), is_spoken, progress,
                                   is_checked, options.lenient);
        if (const auto line = line_cut_among_voices(track, loudness, transcript, cut))
            return align_cut(track, track, loudness, transcript, *line, progress, is_checked,
                             options.lenient);
    } catch (const AlignmentError&) {
        // Refused there: the cut's reading stands.
    }
    return std::nullopt;
}

// `given_spans` empty: the sentences cut as options.sentence_cut says; else where they say.
// `loudness` is the track's (conceal_dropouts).
Timeline align_track(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                     const AlignOptions& options, const std::vector<GivenSpan>& given_spans,
                     ProgressReporter& progress, bool is_checked) {
    if (loudness.speech_end_frame <= loudness.speech_first_frame)
        throw AlignmentError("no speech found in the " + format_fixed(track.duration_s, 2) +
                             " s of audio: nothing rises above its noise floor");
    const bool is_given = !given_spans.empty();
    const SentenceCut cut = is_given ? given_sentence_cut(track, loudness, transcript, given_spans)
                                     : cut_sentences(track, loudness, transcript, options);
    progress.report(kReadingShare + kCuttingShare, "sentences");
    // Music played on under the first words is no sound of the voice's: the syllables are placed and
    // judged with it taken out (bed_removal.hpp), the cut having been found on the recording as heard
    // and the voiced peaks counted there (align_cut).
    const std::optional<FeatureTrack> without_bed =
        has_music_bed(loudness) ? std::optional<FeatureTrack>(without_music_bed(track, loudness))
                                : std::nullopt;
    const FeatureTrack& voice = without_bed ? *without_bed : track;
    const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
    const auto spoken_sentences = static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(), true));
    const std::size_t stretches = loudness.pauses.size() + 1;
    const bool is_own_reading_sought =
        !is_given && !options.lenient && options.sentence_cut == SentenceCutMode::automatic;
    AlignedTimelines result;
    try {
        result = align_confirmed(voice, track, loudness, transcript, cut, is_spoken, progress, is_checked,
                                 options.lenient);
    } catch (const AlignmentError& error) {
        // A line refused for its path's shape on its cut, whose span holds the noise around its
        // voice, is judged on its own reading too: the path there keeps its syllables on the voice,
        // and the text is aligned there where every check passes it and its order margin vouches
        // for it (PathShapeRefusal, kMinVouchingOrderMargin). Else it is judged again on its cut
        // with its syllables kept to the voice its own reading finds, the noise left to the edge
        // pauses (cut_bounded_by_own_reading), and aligned there where every check passes it.
        if (is_checked && is_own_reading_sought && is_one_spoken_line(transcript) &&
            dynamic_cast<const PathShapeRefusal*>(&error) != nullptr) {
            auto own =
                align_own_reading(track, loudness, transcript, cut, is_spoken, options, progress, true);
            if (own && own->is_vouched_by_order)
                return own->in_room ? std::move(*own->in_room) : std::move(own->checked);
            if (const auto bounded = cut_bounded_by_own_reading(track, loudness, transcript, cut, options)) {
                try {
                    AlignedTimelines kept = align_confirmed(voice, track, loudness, transcript, *bounded,
                                                            is_spoken, progress, true, options.lenient);
                    return kept.in_room ? std::move(*kept.in_room) : std::move(kept.checked);
                } catch (const AlignmentError&) {
                    // Refused with its syllables on the voice as well: the cut's refusal stands.
                }
            }
        }
        // Fewer stretches of speech than sentences: either sentences run together or the
        // transcript has one the audio lacks; the first is tried, and the message tells of both.
        if (!is_given && options.sentence_cut == SentenceCutMode::automatic && stretches < spoken_sentences)
            throw AlignmentError("the transcript has " + std::to_string(spoken_sentences) +
                                 " spoken sentences but the audio has only " + std::to_string(stretches) +
                                 " stretches of speech between pauses, and run together they do not fit it either: " +
                                 error.what());
        // A sentence end cut at a pause inside a sentence (speech run together, whose only pauses
        // are a comma's) squeezes one sentence and stretches the next until a check refuses them.
        // Aligned as one block, the syllables find the ends; a transcript that does not match the
        // audio fails there too, and the first, sentence-by-sentence, account of it is kept. Where
        // the pauses do single the sentence ends out (and in the caller's own cut, Algorithm 3.1),
        // the cut stands and so does the refusal, as it does for given spans.
        if (!cut.is_in_doubt || block_count(cut, transcript) == 1) throw;
        SentenceCut block = cut;
        std::fill(block.runs_on.begin(), block.runs_on.end(), true);
        try {
            result =
                align_cut(voice, track, loudness, transcript, block, progress, is_checked, options.lenient);
        } catch (const AlignmentError&) {
            throw error;
        }
        // Syllables that end every sentence in the pause it was cut at confirm the cut, and a
        // sentence end moved off a pause the text does not account for is a wrong text's doing:
        // either way it was the text, not the cut, that the checks refused. A cut pause the
        // syllables pass over for a longer one of their own was no pause (is_cut_pause_passed_over).
        bool has_moved_end = false;
        for (const auto& [k, next] : spoken_neighbours(is_spoken)) {
            if (!moves_sentence_end(cut, result.checked, k, next)) continue;
            if (!is_cut_pause_in_text(cut, result.checked, k, next) &&
                !is_cut_pause_passed_over(cut, result.checked, k, next))
                throw error;
            has_moved_end = true;
        }
        if (!has_moved_end) throw error;
    }
    // Noise a gain lifted before the first words, or a line among quieter voices, its text passed
    // on the speech the profile finds: its syllables placed after the noise or on the line alone,
    // where the checks pass it there too (else the placement the checks passed stands).
    if (is_own_reading_sought)
        if (auto own =
                align_own_reading(track, loudness, transcript, cut, is_spoken, options, progress, is_checked))
            result = std::move(*own);
    return result.in_room ? std::move(*result.in_room) : std::move(result.checked);
}

// AlignOptions::check: refuse, as the checks find; warn, the alignment the checks refused made
// again without them, and their finding kept in its warnings; off, no checks at all. Lenient
// alignment reports what does not match in place of the checks.
Timeline align_checked(const FeatureTrack& track, const LoudnessProfile& loudness, const Timeline& transcript,
                       const AlignOptions& options, const std::vector<GivenSpan>& given_spans,
                       ProgressReporter& progress) {
    if (options.lenient)
        return align_track(track, loudness, transcript, options, given_spans, progress, false);
    if (options.check != CheckMode::warn)
        return align_track(track, loudness, transcript, options, given_spans, progress,
                           options.check == CheckMode::refuse);
    try {
        return align_track(track, loudness, transcript, options, given_spans, progress, true);
    } catch (const AlignmentError& error) {
        Timeline result = align_track(track, loudness, transcript, options, given_spans, progress, false);
        result.warnings.push_back(std::string("the transcript may not match the audio (aligned anyway, check mode warn): ") +
                                  error.what());
        return result;
    }
}

// How much sound a damaged file must have lost before a refusal names the damage first: about a
// syllable. A refusal after a smaller loss (a damaged AAC packet, 20-60 ms) is the transcript's
// own, and the loss is said after it.
constexpr double kLostAudioNamedFirstS = 0.2;

// The aligner's refusal `error` with what the file's reader found: the sound it lost (`lost`, described;
// "" where none) named first where it is about a syllable or more (lost_s), after the refusal where it is
// less, and its `notes` (" (the file: ...)", or "") at the end.
AlignmentError refusal_of_file(const AlignmentError& error, const std::string& lost, double lost_s,
                               const std::string& notes) {
    if (lost.empty()) return AlignmentError(error.what() + notes);
    if (lost_s < kLostAudioNamedFirstS)
        return AlignmentError(std::string(error.what()) + " (the file is also damaged: " + lost + ")" + notes);
    return AlignmentError("the file is damaged: " + lost +
                          " (read as silence: the speech there is lost), and the rest cannot be aligned "
                          "without it; --lenient (AlignOptions::lenient) aligns what it can and reports "
                          "the rest. The aligner found: " + error.what() + notes);
}

// The transcript aligned with `track` (of `loudness`), read from `open` with its first
// `skipped_samples` of the analysis stream left out (align_checked); where a room's sentence is to
// be refused and its pitch may witness for its text (ToneWitnessWanted), the recording is read
// again with the pitch and aligned again.
Timeline align_witnessed(const std::function<std::unique_ptr<AudioSource>()>& open, FeatureTrack& track,
                         const LoudnessProfile& loudness, std::size_t skipped_samples,
                         const Timeline& transcript, const AlignOptions& options,
                         const std::vector<GivenSpan>& given_spans, ProgressReporter& progress) {
    try {
        return align_checked(track, loudness, transcript, options, given_spans, progress);
    } catch (const ToneWitnessWanted&) {
        std::unique_ptr<AudioSource> source = open();
        track = read_features(*source, progress, true, skipped_samples);
        const LoudnessProfile again = conceal_dropouts(track);
        return align_checked(track, again, transcript, options, given_spans, progress);
    }
}

// Where the other readings of a recording start, in samples of the analysis stream: a
// quarter of a frame later and a quarter earlier (three quarters later), the two phases nearest
// the first reading's on either side.
constexpr std::size_t kOtherPhaseSkips[] = {kHopSamples / 4, 3 * kHopSamples / 4};

// Aligns the whole of the recording `open` gives. A file its reader found damaged (sound it could
// not decode, read as silence in its place: LostAudio) gets a warning naming where, and a refusal
// says first that the sound there is lost, for the text is not what is wrong. What else the reader
// says of how it read the file (AudioSource::notes: a stale WAV header) is a warning too, and
// closes a refusal. A warning begins with the source's name() (only a file loses sound); a refusal
// does not, its callers name the audio as they name it. A transcript the checks cannot weigh
// (latin_only_text.hpp) is aligned with a warning that says so (in every check mode but off: no
// evidence against a text is no reason to refuse it, and a game's "OK!" is such a text); a silent
// recording is refused after its samples alone are read (read_first_sound), with no features.
//
// The voice's pitch is measured as the audio is read only for lenient alignment and for a line of
// one spoken sentence (line_among_voices.hpp: where its start lies among other voices); where a
// room's sentence is to be refused and its pitch may witness for its text (ToneWitnessWanted), the
// recording is read again, from `open`, with the pitch, and aligned again: that costs a second
// reading only there (the pitch costs 9% more instructions on every recording, bench/README.md
// Session 19). The second reading is work done again on the bar (ProgressReporter).
//
// A file's bytes are searched for a second recording joined to it (describe_joined_copy, which reads
// the whole file) only where the text's fit is not vouched for: where it is refused, and in a mode
// that aligns a text that does not fit (warn, off, lenient, and a short line refuse mode aligns on
// weak evidence). A text aligned in refuse mode otherwise fits the speech, joined or not, and a good
// file is read once.
//
// A refusal is a majority of three phases. Where the samples fall against the 10 ms frames moves
// a check's figures by up to 0.2 per frame and a path by a syllable, so a text near a check's
// limit was refused at one phase and aligned at the next, right and wrong alike (bench/README.md
// Session 21). With check mode refuse, a recording is also read a quarter of a frame later and a
// quarter earlier (kOtherPhaseSkips), until two of the three readings agree: a file of one or two
// spoken sentences always, and a longer one only where the first reading refuses, for a passage
// read three times would take three times as long. A refusal gives the first refusing reading's
// message (the phase-shifted readings name times up to 7.5 ms early); an alignment gives the
// first reading's timeline, or, where that refused, the first other one that aligned, its times
// moved onto the recording's (its warnings' words keep that reading's); the other readings are work
// done again on the bar (ProgressReporter). Refusing only where two phases refuse, never where one
// aligns, would pick the kinder of two draws and let wrong texts through (Session 20). A short line
// the vote refuses on weak evidence (weak_evidence.hpp) is aligned instead, as CheckMode::warn
// aligns it, and the finding kept as a warning.
Timeline align_source(const std::function<std::unique_ptr<AudioSource>()>& open, const std::string& file_path,
                      const Timeline& transcript, const AlignOptions& given,
                      const std::vector<GivenSpan>& given_spans, const ProgressCallback& callback) {
    validate_transcript(transcript);
    const std::optional<std::string> unconfirmable = describe_latin_only_text(transcript);
    // A text the checks cannot weigh is never refused by them: their evidence is reported as warnings
    // (session 35: a guess's syllables moved, and "The quick brown fox" was refused where it had passed).
    AlignOptions options = given;
    if (unconfirmable && options.check == CheckMode::refuse) options.check = CheckMode::warn;
    ProgressReporter progress(callback);
    progress.report(0.0, "reading");
    std::unique_ptr<AudioSource> source = open();
    const FirstSound first = read_first_sound(*source);
    const std::size_t silence_skipped = silence_to_skip(first, source->sample_rate_hz());
    const double silence_skipped_s = static_cast<double>(silence_skipped) / kAnalysisRateHz;
    if (first.held.empty()) {
        // The reading that is kept seeks past the silence this one read: it notes the samples
        // that are not numbers, and the stretches lost to damage, this one found there. This one
        // is let go first: an MP4's index is held once.
        AudioSource::FirstReading found = source->first_reading();
        source.reset();
        source = open();
        source->take_first_reading(std::move(found));
    }
    FeatureTrack track = read_features(
        *source, progress, options.lenient || (given_spans.empty() && is_one_spoken_line(transcript)),
        silence_skipped, first.held);
    const LoudnessProfile loudness = conceal_dropouts(track);
    const std::string lost = describe_lost_audio(source->lost_audio());
    std::string notes;
    for (const std::string& note : source->notes()) notes += " (the file: " + note + ")";
    const bool is_voted = options.check == CheckMode::refuse && !options.lenient;
    const auto joined_copy = [&] {
        return file_path.empty() ? std::nullopt : describe_joined_copy(file_path);
    };
    Timeline result;
    std::optional<std::string> weak_finding;
    try {
        std::optional<AlignmentError> first_refusal;
        std::optional<std::string> first_weak_finding;
        try {
            result = align_witnessed(open, track, loudness, silence_skipped, transcript,
                                     options_after_skip(options, silence_skipped_s),
                                     spans_after_skip(given_spans, silence_skipped_s), progress);
            move_onto_recording(result, silence_skipped_s);
        } catch (const AlignmentError& refusal) {
            if (!is_voted) throw;
            first_refusal = refusal;
            first_weak_finding = describe_weak_evidence(refusal, transcript);
        }
        const std::vector<bool> is_spoken = spoken_sentences_of(transcript);
        const bool is_short = static_cast<std::size_t>(std::count(is_spoken.begin(), is_spoken.end(),
                                                                  true)) <= kMaxHeldOutCheckSentences;
        if (is_voted && (first_refusal || is_short)) {
            std::size_t refusals = first_refusal ? 1 : 0;
            std::size_t alignments = first_refusal ? 0 : 1;
            std::optional<AlignmentError> other_refusal;
            std::optional<std::string> other_weak_finding;
            std::optional<Timeline> other_alignment;
            for (const std::size_t phase_skipped : kOtherPhaseSkips) {
                if (refusals >= 2 || alignments >= 2) break;
                const std::size_t skipped = silence_skipped + phase_skipped;
                const double skipped_s = static_cast<double>(skipped) / kAnalysisRateHz;
                std::unique_ptr<AudioSource> again = open();
                FeatureTrack other = read_features(*again, progress, !track.pitch.empty(), skipped);
                const LoudnessProfile other_loudness = conceal_dropouts(other);
                try {
                    Timeline found = align_witnessed(open, other, other_loudness, skipped, transcript,
                                                     options_after_skip(options, skipped_s),
                                                     spans_after_skip(given_spans, skipped_s), progress);
                    ++alignments;
                    if (!other_alignment) {
                        move_onto_recording(found, skipped_s);
                        other_alignment = std::move(found);
                    }
                } catch (const AlignmentError& refusal) {
                    ++refusals;
                    if (!other_refusal) {
                        other_refusal = refusal;
                        other_weak_finding = describe_weak_evidence(refusal, transcript);
                    }
                }
            }
            if (refusals >= 2) {
                // A short line refused on weak evidence is aligned as CheckMode::warn aligns it:
                // the first reading's alignment, made without the checks where they refused it.
                weak_finding = first_refusal ? first_weak_finding : other_weak_finding;
                if (!weak_finding) throw first_refusal ? *first_refusal : *other_refusal;
                if (first_refusal) {
                    AlignOptions unchecked = options;
                    unchecked.check = CheckMode::off;
                    result = align_witnessed(open, track, loudness, silence_skipped, transcript,
                                             options_after_skip(unchecked, silence_skipped_s),
                                             spans_after_skip(given_spans, silence_skipped_s), progress);
                    move_onto_recording(result, silence_skipped_s);
                }
                result.warnings.push_back(*weak_finding);
            } else if (first_refusal) {
                result = std::move(*other_alignment);
            }
        }
    } catch (const AlignmentError& error) {
        const auto joined = joined_copy();
        if (joined) notes.insert(0, " (the file: " + joined->description + ")");
        if (const auto zeros = describe_zeros_in_refused_sentence(
                track, silence_skipped_s, transcript, error.what(), source->lost_audio(),
                source->cuts_to_zeros(), joined ? joined->second_starts_s : std::nullopt))
            notes += " (" + *zeros + ")";
        if (silence_skipped > 0)
            notes += " (its times count from " + format_fixed(silence_skipped_s, 3) +
                     " s: the digital silence before the recording's first sound was left out)";
        if (lost.empty() && notes.empty()) throw;
        throw refusal_of_file(error, lost, lost_seconds(source->lost_audio()), notes);
    }
    if (!lost.empty())
        result.warnings.push_back(source->name() + ": the file is damaged: " + lost +
                                  "; read as silence there, the syllables after it keep their times");
    // A text vouched for by the checks may still have been stretched over a second recording joined
    // to its own: the join told from the headers alone (an MP3's frames', an Ogg file's pages', a Matroska
    // file's Segment's) is asked of every file.
    const auto joined = is_voted && !weak_finding
                            ? (file_path.empty() ? std::nullopt : describe_second_stream(file_path))
                            : joined_copy();
    if (joined) result.warnings.push_back(source->name() + ": " + joined->description);
    for (const std::string& note : source->notes()) result.warnings.push_back(source->name() + ": " + note);
    for (const std::string& silenced :
         describe_silenced_words(track, silence_skipped_s, result, source->lost_audio(),
                                 source->cuts_to_zeros(), joined ? joined->second_starts_s : std::nullopt))
        result.warnings.push_back(source->name() + ": " + silenced);
    if (unconfirmable && options.check != CheckMode::off)
        result.warnings.push_back("the transcript cannot be checked against the audio: " + *unconfirmable);
    if (silence_skipped > 0) round_to_microseconds(result);
    progress.report_done();
    return result;
}

}  // namespace

struct SpeechAligner::Impl {
    AlignOptions options;
};

SpeechAligner::SpeechAligner(AlignOptions options) : impl_(std::make_unique<Impl>()) {
    if (!(options.c1 >= 0.5 && options.c1 <= 1.0))
        throw InvalidArgument("c1", "expected 0.5..1 (Algorithm 3.1 step 3), found " + format_shortest(options.c1));
    if (!(options.c2 >= 1.0 && options.c2 <= 1.5))
        throw InvalidArgument("c2", "expected 1..1.5 (Algorithm 3.1 step 4), found " + format_shortest(options.c2));
    if (options.check != CheckMode::refuse && options.check != CheckMode::warn && options.check != CheckMode::off)
        throw InvalidArgument("check", "unknown mode " + std::to_string(static_cast<int>(options.check)));
    if (options.sentence_cut != SentenceCutMode::automatic && options.sentence_cut != SentenceCutMode::first_pause)
        throw InvalidArgument("sentence_cut", "unknown mode " + std::to_string(static_cast<int>(options.sentence_cut)));
    if (options.sentence_cut == SentenceCutMode::first_pause &&
        !(std::isfinite(options.first_pause_start_s) && std::isfinite(options.first_pause_end_s) &&
          options.first_pause_start_s >= 0.0 && options.first_pause_end_s > options.first_pause_start_s))
        throw InvalidArgument("first_pause", "expected 0 <= start < end in seconds, found " +
                                                 format_shortest(options.first_pause_start_s) + ".." +
                                                 format_shortest(options.first_pause_end_s));
    impl_->options = options;
}

SpeechAligner::~SpeechAligner() = default;
SpeechAligner::SpeechAligner(SpeechAligner&&) noexcept = default;
SpeechAligner& SpeechAligner::operator=(SpeechAligner&&) noexcept = default;

const AlignOptions& SpeechAligner::options() const { return impl_->options; }

Timeline SpeechAligner::align(const AudioView& audio, const Timeline& transcript, const ProgressCallback& progress) const {
    return align_source([&] { return open_audio_view(audio); }, "", transcript, impl_->options, {}, progress);
}

Timeline SpeechAligner::align_file(const std::string& audio_path, const Timeline& transcript,
                                   const ProgressCallback& progress) const {
    validate_transcript(transcript);
    std::unique_ptr<AudioSource> first = open_audio_file(audio_path);
    try {
        return align_source([&] { return first ? std::move(first) : open_audio_file(audio_path); },
                            audio_path, transcript, impl_->options, {}, progress);
    } catch (const AlignmentError& error) {
        // Name the audio: the times in the message are in this file.
        throw AlignmentError(audio_path + ": " + error.what());
    }
}

}  // namespace v0
}  // namespace talkface

namespace talkface::detail {

Timeline align_in_given_spans(const std::string& audio_path, const Timeline& transcript,
                              const std::vector<GivenSpan>& sentence_spans_s, const AlignOptions& options,
                              const ProgressCallback& progress) {
    validate_transcript(transcript);
    std::unique_ptr<AudioSource> first = open_audio_file(audio_path);
    const std::string name = first->name();
    try {
        return align_source([&] { return first ? std::move(first) : open_audio_file(audio_path); },
                            audio_path, transcript, options, sentence_spans_s, progress);
    } catch (const AlignmentError& error) {
        throw AlignmentError(name + ": " + error.what());
    }
}

}  // namespace talkface::detail
