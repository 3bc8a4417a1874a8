#include "speech/bed_free_models.hpp"

#include <algorithm>

namespace talkface::detail {

std::vector<bool> chains_clear_of_bed(const std::vector<SentenceChain>& chains,
                                      const LoudnessProfile& loudness) {
    const FrameSpan& bed = loudness.voice_under_music;
    if (bed.length() == 0) return {};
    std::vector<bool> is_clear(chains.size());
    for (std::size_t w = 0; w < chains.size(); ++w)
        is_clear[w] = chains[w].searched.end_frame <= bed.first_frame ||
                      chains[w].searched.first_frame >= bed.end_frame;
    const auto clear = std::count(is_clear.begin(), is_clear.end(), true);
    if (clear == 0 || static_cast<std::size_t>(clear) == chains.size()) return {};
    return is_clear;
}

}  // namespace talkface::detail
