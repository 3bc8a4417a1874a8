#include "speech/breath_edge.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "common/order_statistics.hpp"
#include "speech/held_music.hpp"
#include "speech/lifted_noise.hpp"
#include "speech/unvoiced_beat.hpp"

namespace talkface::detail {

namespace {

// The weight of cepstrum c in fundamental_rise_db: log_mel[m] = (2 / kMelFilters) (c0 / 2 +
// sum over c >= 1 of cepstrum[c] cos(c, m)) (late_reverb.cpp's to_bands), so a difference of two
// bands' means leaves c0 out. In dB, as the level columns read (log_mel is a natural log).
std::array<float, kCepstrumCount> fundamental_rise_weights() {
    std::array<float, kCepstrumCount> weights{};
    std::vector<std::size_t> fundamental, rest;
    for (std::size_t m = 0; m < static_cast<std::size_t>(kMelFilters); ++m) {
        const double centre_hz = mel_edge_hz(m + 1);
        if (centre_hz < kFundamentalTopHz)
            fundamental.push_back(m);
        else if (centre_hz < kLowBandHighHz)
            rest.push_back(m);
    }
    const auto mean_cosine = [](std::size_t c, const std::vector<std::size_t>& bands) {
        double sum = 0.0;
        for (const std::size_t m : bands) sum += mel_cepstrum_cosine(c, m);
        return sum / static_cast<double>(bands.size());
    };
    const double to_db = 10.0 / std::log(10.0) * 2.0 / kMelFilters;
    for (std::size_t c = 1; c < static_cast<std::size_t>(kCepstrumCount); ++c)
        weights[c] = static_cast<float>(to_db * (mean_cosine(c, fundamental) - mean_cosine(c, rest)));
    return weights;
}

// The share of the loud, sounding frames in [first, end) for which `holds(t)` is true; 0 where no
// frame is loud.
template <typename Holds>
double loud_share_where(const FeatureTrack& track, const std::vector<float>& activity_db, float threshold_db,
                        std::size_t first, std::size_t end, Holds holds) {
    std::size_t loud = 0, held = 0;
    for (std::size_t t = first; t < end; ++t) {
        if (!is_loud_sounding_frame(track, activity_db, threshold_db, t)) continue;
        ++loud;
        if (holds(t)) ++held;
    }
    return loud == 0 ? 0.0 : static_cast<double>(held) / static_cast<double>(loud);
}

// Whether frame t's power gathers in a harmonic's lines (a voiced frame's does; a breath's noise spreads).
bool holds_harmonic(const FeatureTrack& track, std::size_t t) {
    return track.at(t, kLineShare) >= kHarmonicLineShare;
}

// Whether [first, end) holds kVowelHarmonicFrames loud frames in a row with a harmonic.
bool holds_vowel(const FeatureTrack& track, const LoudnessProfile& loudness, const FrameSpan& stretch) {
    std::size_t run = 0;
    for (std::size_t t = stretch.first_frame; t < stretch.end_frame; ++t) {
        const bool is_harmonic =
            is_loud_sounding_frame(track, loudness.activity_db, loudness.activity_threshold_db, t) &&
            holds_harmonic(track, t);
        run = is_harmonic ? run + 1 : 0;
        if (run >= kVowelHarmonicFrames) return true;
    }
    return false;
}

// Whether the bands of `stretch` stand above their floors in the floors' shape (keeps_floor_shape on
// each band's median), as noise a gain control lifts does (lifted_noise.hpp). A breath's noise, over
// 400-3000 Hz, mostly fills the bands unevenly; through a codec's narrow band not always.
bool stretch_keeps_floor_shape(const FeatureTrack& track, const LoudnessProfile& loudness,
                               const FrameSpan& stretch) {
    std::array<std::vector<float>, 3> bands;
    for (std::size_t t = stretch.first_frame; t < stretch.end_frame; ++t) {
        const std::array<float, 3> above = bands_above_floors(track, t, loudness.low_floor_db,
                                                              loudness.mid_floor_db, loudness.high_floor_db);
        for (std::size_t b = 0; b < 3; ++b) bands[b].push_back(above[b]);
    }
    std::array<float, 3> medians{};
    for (std::size_t b = 0; b < 3; ++b) medians[b] = percentile_of(bands[b], 0.5);
    return keeps_floor_shape(medians);
}

// Whether `stretch` is noise a gain control lifted: its bands keep the floors' shape
// (stretch_keeps_floor_shape) and it reaches an edge of the recording, less than a pause from its
// start or its end. A gain starts high and climbs until the first loud syllable pulls it down
// (lifted_lead_in.hpp), and after the last sound nothing pulls it down again, so the noise it lifts
// stays up until the recording stops; a breath ends, and the noise after it falls back to the
// floors. A breath through a codec's narrow band may keep the floors' shape (bench/ short kinds
// p-breath: 5 of the 20 held-out out-breaths), but the hiss after it lasts a pause or more (the
// tuning lines' 32-63 frames), where p-fast-combo's lifted noise after its line ends 5 frames short
// of the recording's end (bench/README.md, session 32).
bool is_lifted_noise(const FeatureTrack& track, const LoudnessProfile& loudness, const FrameSpan& stretch) {
    const bool reaches_edge =
        stretch.first_frame < kMinPauseFrames || track.frame_count - stretch.end_frame < kMinPauseFrames;
    return reaches_edge && stretch_keeps_floor_shape(track, loudness, stretch);
}

}  // namespace

float fundamental_rise_db(const FeatureTrack& track, std::size_t t) {
    static const std::array<float, kCepstrumCount> weights = fundamental_rise_weights();
    float rise_db = 0.0f;
    for (std::size_t c = 1; c < static_cast<std::size_t>(kCepstrumCount); ++c)
        rise_db += weights[c] * track.at(t, kCepstrum0 + static_cast<int>(c));
    return rise_db;
}

double loud_fundamental_share(const FeatureTrack& track, const std::vector<float>& activity_db,
                              float threshold_db, std::size_t first, std::size_t end) {
    return loud_share_where(track, activity_db, threshold_db, first, end, [&](std::size_t t) {
        return fundamental_rise_db(track, t) >= kFundamentalBelowLowBandDb;
    });
}

double loud_harmonic_share(const FeatureTrack& track, const std::vector<float>& activity_db,
                           float threshold_db, std::size_t first, std::size_t end) {
    return loud_share_where(track, activity_db, threshold_db, first, end,
                            [&](std::size_t t) { return holds_harmonic(track, t); });
}

bool is_breath_beside_voice(const FeatureTrack& track, const LoudnessProfile& loudness,
                            const FrameSpan& stretch, const FrameSpan& voice, bool by_voicing_too) {
    const auto is_beside_voice = [&](auto loud_share) {
        return is_beat_beside_voice(loud_share(track, loudness.activity_db, loudness.activity_threshold_db,
                                               stretch.first_frame, stretch.end_frame),
                                    loud_share(track, loudness.activity_db, loudness.activity_threshold_db,
                                               voice.first_frame, voice.end_frame));
    };
    const bool is_long = stretch.length() >= kFewestBreathFrames;
    if (track.fundamental_share >= kNarrowbandFundamentalShare)
        return (by_voicing_too && is_beside_voice(loud_voiced_share)) ||
               (is_long && is_beside_voice(loud_fundamental_share));
    return (by_voicing_too && is_beside_voice(loud_voiced_share)) ||
           (is_long && is_beside_voice(loud_harmonic_share) && !holds_vowel(track, loudness, stretch) &&
            (by_voicing_too || !is_lifted_noise(track, loudness, stretch)));
}

std::optional<FrameSpan> find_gap_after_first_sound(const LoudnessProfile& loudness, std::size_t first,
                                                    std::size_t end) {
    std::size_t quiet = first;
    while (quiet < end && is_speech_frame(loudness, quiet)) ++quiet;
    std::size_t voice = quiet;
    while (voice < end && !is_speech_frame(loudness, voice)) ++voice;
    if (voice == end || voice - quiet < kBreathGapFrames) return std::nullopt;
    return FrameSpan{quiet, voice};
}

std::optional<FrameSpan> find_close_breath(const FeatureTrack& track, const LoudnessProfile& loudness,
                                           std::size_t first, std::size_t end) {
    const auto gap = find_gap_after_first_sound(loudness, first, end);
    if (!gap ||
        !is_breath_beside_voice(track, loudness, {first, gap->first_frame}, {gap->end_frame, end}, false))
        return std::nullopt;
    return FrameSpan{first, gap->first_frame};
}

}  // namespace talkface::detail
