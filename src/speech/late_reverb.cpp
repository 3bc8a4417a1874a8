#include "speech/late_reverb.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/order_statistics.hpp"
#include "speech/level_line.hpp"
#include "speech/mel_cepstrum.hpp"

namespace talkface::detail {

namespace {

// The band levels the models read besides the cepstra (observe: loudness, tilt, low band), and
// the mid band with them, as a stage that reads one reads the others.
constexpr std::array<int, 4> kBandColumns = {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb};
constexpr std::size_t kFollowedBands = kMelFilters + kBandColumns.size();

// The level a room is read on: the whole band's, as end_before_tail (sentence_chains.cpp) found
// the tails by it, and as one decay is read for every band (without_late_ringing follows each band
// at it); the tails' lines are fitted to it and the voice before a tail is weighed on it.
constexpr int kTailLevelColumn = kEnergyDb;

}  // namespace

std::optional<RoomRinging> measure_room_ringing(const FeatureTrack& track,
                                                const std::vector<SentenceChain>& chains) {
    struct Tail {
        const SentenceChain* chain;
        std::size_t first_frame;
        LevelLine line;
    };
    std::vector<Tail> tails;
    std::vector<double> decays;
    for (const SentenceChain& chain : chains) {
        if (!chain.ends_in_tail) continue;
        const std::size_t first = chain.speech.end_frame - chain.tail_frames;
        const LevelLine line = fit_level_line(track, kTailLevelColumn, first, chain.speech.end_frame);
        if (!(line.slope_db_per_frame < 0.0)) continue;
        tails.push_back({&chain, first, line});
        decays.push_back(-line.slope_db_per_frame);
    }
    if (tails.empty()) return std::nullopt;
    RoomRinging room;
    room.decay_db_per_frame = mean_median(decays);
    const double decay = db_to_power(-room.decay_db_per_frame);
    std::vector<double> shares;
    for (const Tail& tail : tails) {
        // The frames as heard, ringing and all: the share read is, if anything, a little low.
        double voice = 0.0, weight = 1.0;
        for (std::size_t t = tail.first_frame; t-- > tail.chain->speech.first_frame;) {
            voice += weight * db_to_power(track.at(t, kTailLevelColumn));
            weight *= decay;
        }
        shares.push_back(db_to_power(tail.line.start_db) / voice);
    }
    room.voice_share = mean_median(shares);
    return room;
}

FeatureTrack without_late_ringing(const FeatureTrack& track, const RoomRinging& room) {
    const double decay = db_to_power(-room.decay_db_per_frame);
    const double floor = db_to_power(-kDryFloorDb);
    const MelCepstrum transform;
    FeatureTrack dry = track;
    std::array<double, kFollowedBands> ringing{}, voice{};
    std::array<double, kMelFilters> log_mel{};
    for (std::size_t t = 0; t < track.frame_count; ++t) {
        float* row = &dry.values[t * kFeatureCount];
        transform.to_bands(row + kCepstrum0, log_mel);
        auto take_out = [&](std::size_t band, double power) {
            ringing[band] = decay * ringing[band] + room.voice_share * voice[band];
            voice[band] = std::max(power - ringing[band], floor * power);
            return voice[band];
        };
        for (std::size_t m = 0; m < kMelFilters; ++m)
            log_mel[m] = std::log(take_out(m, std::exp(log_mel[m])));
        transform.to_cepstrum(log_mel, row + kCepstrum0);
        for (std::size_t b = 0; b < kBandColumns.size(); ++b) {
            float& level_db = row[kBandColumns[b]];
            level_db = static_cast<float>(power_to_db(take_out(kMelFilters + b, db_to_power(level_db))));
        }
    }
    return dry;
}

}  // namespace talkface::detail
