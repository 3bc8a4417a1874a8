#include "speech/room_closures.hpp"

#include "common/order_statistics.hpp"

namespace talkface::detail {

bool is_room(const std::vector<SentenceChain>& chains) {
    if (chains.empty()) return false;
    std::vector<double> tails;
    tails.reserve(chains.size());
    for (const SentenceChain& chain : chains) tails.push_back(static_cast<double>(chain.tail_frames));
    return mean_median(tails) >= kRoomMedianTailFrames;
}

void let_closures_ring(std::vector<PhoneState>& states) {
    for (PhoneState& state : states) {
        if (state.role != StateRole::closure) continue;
        state.phone_class = kGenericSpeech;
        state.frame_log_penalty = kRoomClosureFrameLogPenalty;
    }
}

}  // namespace talkface::detail
