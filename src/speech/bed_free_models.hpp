// The models a recording with a music bed (music_bed.hpp) judges its other sentences on. The
// models re-estimated on the recording learn from every sentence's path; under the bed those
// frames are the voice and the music together, or what bed_removal.hpp leaves of the voice, and
// either way they widen the voice's classes, so that a wrong text on a clean sentence fits its
// speech nearly as well as free sounds do (bench/README.md, session 35: a replaced sentence 0.37
// per frame worse than free sounds with the bed as heard, 0.15 with it taken out). The sentences
// clear of the bed are placed and judged on models learned from them alone, as they would be in
// the same speech without a bed; those under it keep the models learned from every sentence,
// which their own frames shaped (on the clean sentences' models alone a right text under the bed
// fits 0.1-0.2 per frame worse, and is refused). Learned from three or four sentences, those
// models fit a wrong text among them as a file of one or two's do: its sentences are judged by
// their order margin and held-out halves too (chain_measures.hpp, is_judged_by_order_margin).
#ifndef TALKFACE_SPEECH_BED_FREE_MODELS_HPP
#define TALKFACE_SPEECH_BED_FREE_MODELS_HPP

#include <vector>

#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"

namespace talkface::detail {

// Which of `chains` are searched clear of the bed of `loudness` (LoudnessProfile::voice_under_music):
// empty where there is no bed, or where every chain or none lies under it (one set of models then).
std::vector<bool> chains_clear_of_bed(const std::vector<SentenceChain>& chains,
                                      const LoudnessProfile& loudness);

}  // namespace talkface::detail

#endif
