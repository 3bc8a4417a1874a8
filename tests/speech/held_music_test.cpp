// Music that holds its notes under the voice (issue 13): the changing part of the spectrum
// (changing_spectrum.hpp) is small for held notes (their partials beating), half for noise, most of a gliding
// voice; and the pauses between sentences under struck chords and a piano's decaying notes, as loud as the
// quieter speech, are found; a piano before the voice and after it, as loud as the voice (a
// podcast's intro and outro), is given no syllable; nor is a piano that plays on under the first
// words (a bed).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/decoded_audio.hpp"
#include "common/six_sentences.hpp"
#include "common/speech_clips.hpp"
#include "speech/frame_features.hpp"
#include "speech/held_music.hpp"
#include "speech/sentence_cutter.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/timeline.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

constexpr double kPi = 3.14159265358979323846;

detail::FeatureTrack features_of(const std::vector<float>& samples, int rate_hz) {
    const auto source = detail::open_audio_view(AudioView{samples.data(), samples.size(), 1, rate_hz});
    return detail::analyze_audio(*source, {});
}

// The share of the change band's power that changes over frames [first, end).
double changing_share(const detail::FeatureTrack& track, std::size_t first, std::size_t end) {
    double band = 0.0, changing = 0.0;
    for (std::size_t t = first; t < end; ++t) {
        band += std::pow(10.0, track.at(t, detail::kChangeBandDb) / 10.0);
        changing += std::pow(10.0, track.at(t, detail::kChangingDb) / 10.0);
    }
    return changing / band;
}

// A note of six harmonics (amplitudes 1/k) from `start_s`, struck (5 ms attack) and decaying at
// `decay_per_s`, added to `out`.
void add_note(std::vector<float>& out, int rate_hz, double start_s, double length_s, double frequency_hz, double amplitude,
              double decay_per_s) {
    const auto first = static_cast<std::size_t>(start_s * rate_hz);
    const auto length = static_cast<std::size_t>(length_s * rate_hz);
    for (std::size_t j = 0; j < length && first + j < out.size(); ++j) {
        const double since = static_cast<double>(j) / rate_hz;
        const double envelope = std::min(1.0, since / 0.005) * std::exp(-since * decay_per_s) * std::min(1.0, (length_s - since) / 0.01);
        double value = 0.0;
        for (int k = 1; k <= 6; ++k) value += std::sin(2 * kPi * k * frequency_hz * since) / k;
        out[first + j] += static_cast<float>(amplitude * envelope * value);
    }
}

// A piano under a voice, of mean power 1: a chord of three notes struck every 1.6 s and left to
// ring, and a melody note every 0.4 s that decays over it. Nothing of it falls silent.
std::vector<float> piano(std::size_t count, int rate_hz) {
    std::vector<float> music(count, 0.0f);
    const double roots[] = {220.0, 174.6, 196.0, 164.8};
    const double melody[] = {440.0, 523.3, 587.3, 659.3, 587.3, 523.3, 493.9};
    const double duration_s = static_cast<double>(count) / rate_hz;
    for (std::size_t bar = 0; 1.6 * static_cast<double>(bar) < duration_s; ++bar)
        for (const double ratio : {1.0, 1.26, 1.5})
            add_note(music, rate_hz, 1.6 * static_cast<double>(bar), 1.6, roots[bar % 4] * ratio, 0.5, 0.5);
    for (std::size_t n = 0; 0.4 * static_cast<double>(n) < duration_s; ++n)
        add_note(music, rate_hz, 0.4 * static_cast<double>(n), 0.8, melody[n % 7], 0.6, 2.5);
    double power = 0.0;
    for (const float v : music) power += static_cast<double>(v) * v;
    const double gain = 1.0 / std::sqrt(power / static_cast<double>(count));
    for (float& v : music) v = static_cast<float>(v * gain);
    return music;
}

}  // namespace

TEST_SUITE("speech") {
    TEST_CASE("held notes hardly change, noise changes half its power, a gliding voice most of it") {
        const int rate = detail::kAnalysisRateHz;
        const std::size_t count = rate;  // 1 s of each
        std::vector<float> chord(count, 0.0f), noise(count), glide(count);
        for (const double hz : {220.0, 277.2, 329.6}) add_note(chord, rate, 0.0, 1.0, hz, 0.1, 0.5);
        std::uint32_t state = 99;
        for (float& v : noise) v = 0.1f * (static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 8388608.0f - 1.0f);
        // A voice's pitch falling and rising by a fifth twice a second (tones), harmonics to 4 kHz.
        double phase = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
            const double t = static_cast<double>(i) / rate;
            phase += 2 * kPi * 150.0 * std::pow(1.5, std::sin(2 * kPi * 2.0 * t)) / rate;
            double value = 0.0;
            for (int k = 1; k <= 20; ++k) value += std::sin(k * phase) / k;
            glide[i] = static_cast<float>(0.1 * value);
        }
        // Frames 10-90: the chord's attack and the ends of the recording left out.
        CHECK(changing_share(features_of(chord, rate), 10, 90) < detail::kHeldMusicChangeShare);
        const double noise_share = changing_share(features_of(noise, rate), 10, 90);
        CHECK(noise_share > 0.4);
        CHECK(noise_share < 0.6);
        CHECK(changing_share(features_of(glide, rate), 10, 90) > 0.6);
    }

    TEST_CASE("the pauses between sentences under a piano's ringing chords are found whole") {
        // tests/data/speech/two_sentences.wav three times over, a piano under it at SNR 15 dB
        // against the speech's active level: six sentences, 0.9 s of music inside each copy and
        // 0.6 s between copies. Its struck chords ring through the pauses as loud as the quieter
        // speech.
        const test::SixSentences six = test::six_sentences();
        const std::vector<float> mixed = test::mixed_at_snr(six.samples, piano(six.samples.size(), six.rate_hz), six.rate_hz, 15.0);
        REQUIRE(!mixed.empty());

        const detail::LoudnessProfile loudness = detail::measure_loudness(features_of(mixed, six.rate_hz));
        for (const auto& [start_s, end_s] : six.gaps) {
            CAPTURE(start_s);
            // One pause over most of the gap: by loudness alone the music's notes cut it in pieces
            // (4.17-4.42 and 4.45-4.77 s), or shorten it by a third (6.15-6.81 s of 6.14-7.04 s).
            CHECK(test::is_found_whole(loudness.pauses, start_s, end_s, 0.8));
        }
    }

    TEST_CASE("a piano before the voice and after it, as loud as the voice, is given no syllable") {
        // A podcast's intro: 8 s of piano, 3 dB under the speech's active level, fading out over
        // 0.5 s, then the six sentences, then 4 s of the piano again. On main the first syllable
        // was stretched over the intro and the recording refused ("the syllable ... would last").
        const test::SixSentences six = test::six_sentences();
        const int rate = six.rate_hz;
        const std::size_t intro = static_cast<std::size_t>(8 * rate),
                          outro = static_cast<std::size_t>(4 * rate);
        const std::size_t fade = static_cast<std::size_t>(rate / 2);
        std::vector<float> speech(intro, 0.0f);
        speech.insert(speech.end(), six.samples.begin(), six.samples.end());
        speech.insert(speech.end(), outro, 0.0f);
        std::vector<float> music = piano(speech.size(), rate);
        for (std::size_t i = 0; i < music.size(); ++i) {
            if (i >= intro && i < intro + six.samples.size())
                music[i] = 0.0f;
            else if (i + fade >= intro && i < intro)
                music[i] *= static_cast<float>(intro - i) / static_cast<float>(fade);
        }
        const std::vector<float> mixed = test::mixed_at_snr(speech, music, rate, 3.0);
        REQUIRE(!mixed.empty());

        const Timeline two = load_transcript(test::clip_path("two_sentences.txt"));
        const std::string sentences = two.sentences[0].text + "\n" + two.sentences[1].text + "\n";
        const Timeline transcript = read_transcript(sentences + sentences + sentences);
        const std::vector<double> truth_once = test::true_starts("two_sentences");
        const double copy_s = static_cast<double>(six.samples.size()) / (3.0 * rate);
        AudioView audio;
        audio.samples = mixed.data();
        audio.frame_count = mixed.size();
        audio.sample_rate_hz = rate;
        const Timeline aligned = SpeechAligner().align(audio, transcript);
        REQUIRE(aligned.syllables.size() == 3 * truth_once.size());
        std::size_t within = 0;
        for (std::size_t i = 0; i < aligned.syllables.size(); ++i) {
            const double truth =
                8.0 + copy_s * static_cast<double>(i / truth_once.size()) + truth_once[i % truth_once.size()];
            within += std::fabs(aligned.syllables[i].start_s - truth) <= 0.05;
        }
        CHECK(std::fabs(aligned.syllables.front().start_s - (8.0 + truth_once.front())) <= 0.05);
        CHECK(aligned.syllables.back().end_s <= 8.0 + 3.0 * copy_s + 0.2);
        CHECK(static_cast<double>(within) >= 0.9 * static_cast<double>(aligned.syllables.size()));
    }

    TEST_CASE("a piano that plays on under the first words, with no pause before them, is no speech") {
        // A podcast's bed: 8 s of piano 3 dB under the speech's active level that plays on under
        // the first 3 s of the six sentences, fading out, with no pause between the two. Without
        // music_bed.hpp the speech was found to start 4.46 s from the first syllable.
        const test::SixSentences six = test::six_sentences();
        const int rate = six.rate_hz;
        const std::vector<float> speech = test::with_silent_edges(six, 8.0, 0.0);
        const auto intro = static_cast<std::size_t>(8 * rate), under = static_cast<std::size_t>(3 * rate);
        std::vector<float> music = piano(speech.size(), rate);
        for (std::size_t i = intro; i < music.size(); ++i)
            music[i] *= static_cast<float>(i < intro + under ? static_cast<double>(intro + under - i) /
                                                                   static_cast<double>(under)
                                                             : 0.0);
        const std::vector<float> mixed = test::mixed_at_snr(speech, music, rate, 3.0);
        REQUIRE(!mixed.empty());
        CHECK(test::start_error_s(detail::measure_loudness(features_of(mixed, rate)), 8.0) <= 0.1);
    }
}
