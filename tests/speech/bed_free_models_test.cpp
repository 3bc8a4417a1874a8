// The sentences clear of a music bed judged on models learned from them alone (bed_free_models.hpp,
// issue 13).
#include <doctest/doctest.h>

#include "speech/bed_free_models.hpp"

using namespace talkface::detail;

namespace {

// Chains searched over [first, end) frames, one for each pair.
std::vector<SentenceChain> chains_over(const std::vector<FrameSpan>& searched) {
    std::vector<SentenceChain> chains(searched.size());
    for (std::size_t w = 0; w < searched.size(); ++w) chains[w].searched = searched[w];
    return chains;
}

}  // namespace

TEST_CASE("the sentences searched clear of a bed are told from those under it") {
    LoudnessProfile loudness;
    loudness.music_before_voice = {0, 300};
    loudness.voice_under_music = {300, 620};
    // The second sentence's search reaches back into the bed's fading end: it is under the bed too.
    const auto chains = chains_over({{290, 500}, {560, 800}, {850, 1000}, {1050, 1300}});
    CHECK(chains_clear_of_bed(chains, loudness) == std::vector<bool>{false, false, true, true});
}

TEST_CASE("one set of models where there is no bed, or no sentence clear of it") {
    LoudnessProfile loudness;
    const auto chains = chains_over({{0, 200}, {250, 400}});
    CHECK(chains_clear_of_bed(chains, loudness).empty());
    loudness.voice_under_music = {0, 450};
    CHECK(chains_clear_of_bed(chains, loudness).empty());
}
