#include "speech/bed_removal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "common/order_statistics.hpp"
#include "speech/late_reverb.hpp"
#include "speech/mel_cepstrum.hpp"

namespace talkface::detail {

namespace {

// The band levels the models read besides the cepstra (observe: loudness, tilt, low band), and
// the mid band with them, as a stage that reads one reads the others.
constexpr std::array<int, 4> kBandColumns = {kEnergyDb, kLowBandDb, kMidBandDb, kHighBandDb};
constexpr std::size_t kBands = kMelFilters + kBandColumns.size();
using BandPowers = std::array<double, kBands>;

// A frame's power in each mel band (as its cepstra keep them) and in each band column.
BandPowers band_powers(const FeatureTrack& track, const MelCepstrum& transform, std::size_t t) {
    std::array<double, kMelFilters> log_mel{};
    transform.to_bands(&track.values[t * kFeatureCount + kCepstrum0], log_mel);
    BandPowers powers{};
    for (std::size_t m = 0; m < kMelFilters; ++m) powers[m] = std::exp(log_mel[m]);
    for (std::size_t b = 0; b < kBandColumns.size(); ++b)
        powers[kMelFilters + b] = db_to_power(track.at(t, kBandColumns[b]));
    return powers;
}

bool is_inside(const FrameSpan& span, std::size_t first, std::size_t end) {
    return span.first_frame >= first && span.end_frame <= end;
}

// The lower median of each band's power over the pauses of `loudness` outside frames [first, end):
// the recording's own noise, where the bed is taken out; zeros where there are none.
BandPowers pause_floor(const FeatureTrack& track, const LoudnessProfile& loudness,
                       const MelCepstrum& transform, std::size_t first, std::size_t end) {
    std::vector<std::vector<double>> quiet(kBands);
    for (const FrameSpan& pause : loudness.pauses) {
        if (is_inside(pause, first, end)) continue;
        for (std::size_t t = pause.first_frame; t < pause.end_frame; ++t) {
            const BandPowers powers = band_powers(track, transform, t);
            for (std::size_t band = 0; band < kBands; ++band) quiet[band].push_back(powers[band]);
        }
    }
    BandPowers floor{};
    if (quiet.front().empty()) return floor;
    for (std::size_t band = 0; band < kBands; ++band) floor[band] = lower_median(std::move(quiet[band]));
    return floor;
}

}  // namespace

FeatureTrack without_music_bed(const FeatureTrack& track, const LoudnessProfile& loudness) {
    const std::size_t first = loudness.music_before_voice.first_frame;
    const std::size_t end = loudness.voice_under_music.end_frame;
    FeatureTrack voice = track;
    if (end <= first) return voice;
    const MelCepstrum transform;
    std::vector<BandPowers> powers(end - first);
    for (std::size_t t = first; t < end; ++t) powers[t - first] = band_powers(track, transform, t);
    const double least_share = db_to_power(-kDryFloorDb);
    const BandPowers noise = pause_floor(track, loudness, transform, first, end);
    std::array<double, kMelFilters> log_mel{};
    for (std::size_t i = loudness.voice_under_music.first_frame - first; i < powers.size(); ++i) {
        const std::size_t from = i >= kBedLevelHalfWindow ? i - kBedLevelHalfWindow : 0;
        const std::size_t to = std::min(powers.size(), i + kBedLevelHalfWindow + 1);
        BandPowers left = powers[i];
        for (std::size_t band = 0; band < kBands; ++band) {
            double bed = left[band];
            for (std::size_t j = from; j < to; ++j) bed = std::min(bed, powers[j][band]);
            left[band] = std::max(left[band] - bed,
                                  std::max(std::min(noise[band], left[band]), least_share * left[band]));
        }
        float* row = &voice.values[(first + i) * kFeatureCount];
        for (std::size_t m = 0; m < kMelFilters; ++m) log_mel[m] = std::log(left[m]);
        transform.to_cepstrum(log_mel, row + kCepstrum0);
        for (std::size_t b = 0; b < kBandColumns.size(); ++b)
            row[kBandColumns[b]] = static_cast<float>(power_to_db(left[kMelFilters + b]));
    }
    return voice;
}

}  // namespace talkface::detail
