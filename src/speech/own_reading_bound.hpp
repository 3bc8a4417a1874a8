// A short line's syllables kept on its cut to the voice its own reading finds (issue 13). Where a
// short line's cut holds the noise a phone's gain lifted before its voice, the path there lays an
// edge syllable on the noise and squeezes its neighbours, and the checks refuse that path's shape
// (PathShapeRefusal), the text's or not; the line's own reading (the speech after the lifted lead-in)
// leaves that noise out, but judged on the line alone a wrong text passes as often as the right one
// (bench/README.md, sessions 29 and 39). On the cut with its syllables held to the own reading's
// span, the noise stays in what the models learn and the checks read, as the edge pauses', and a
// wrong text's path is held to the same span (sessions 40 (short8) and 41 (short9)).
#ifndef TALKFACE_SPEECH_OWN_READING_BOUND_HPP
#define TALKFACE_SPEECH_OWN_READING_BOUND_HPP

#include <cstddef>
#include <optional>

#include "speech/frame_features.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/timeline.hpp"

namespace talkface::detail {

// Whether a line of `syllables` syllables whose own reading finds its voice in `own` is held there
// on its cut: a line under kMinEndClauseSyllables whose own reading holds at most
// kMaxNucleiPerSyllable voiced peaks (count_nuclei) a syllable. From 8 syllables on a line holds
// enough of its own speech for the checks on its cut to stand: align_bench --mismatch's sentences of
// 9-17 syllables (p-agc, p-babble), held to their own readings, gave one right sentence back and let
// 13 wrong texts through. An own reading with more voiced peaks than a line alone has holds speech
// its text lacks: 7 of the 13 were clips of two sentences given the text of one, the other voices
// around the two left out (1.7-2.0 peaks a syllable; the short lines freed hold 0.86-1.57).
bool is_held_to_own_reading(const FeatureTrack& track, const LoudnessProfile& loudness, const FrameSpan& own,
                            std::size_t syllables);

// `cut` (cut_sentences' of `loudness`) with the syllables of `transcript`'s only spoken sentence
// bounded (SentenceCut::syllable_bounds) by its span cut on the profile after a gain's lifted
// lead-in (loudness_after_lifted_lead_in), where is_held_to_own_reading says so. Nothing where the
// transcript has several spoken sentences or no gain lifted noise before the line: the line among
// quieter voices (line_cut_among_voices) is not bounded so, for what its reading leaves out is
// speech, and a wrong text held off it passes as the right one does (short_kinds_bench: 5 right
// lines freed there, 3 wrong texts let through, and a freed line misplaced by 0.2-0.46 s; bench/
// README.md, session 41 (short9)).
std::optional<SentenceCut> cut_bounded_by_own_reading(const FeatureTrack& track,
                                                      const LoudnessProfile& loudness,
                                                      const Timeline& transcript, const SentenceCut& cut,
                                                      const AlignOptions& options);

}  // namespace talkface::detail

#endif
