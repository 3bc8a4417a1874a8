// Where a sentence's voice ends before a room's tail (end_before_tail, issue 12: a quiet last
// syllable is speech, not a tail), and before the tail's ringing (end_before_ringing); where the
// last syllable ends (place_syllables: a quiet end is a tail only where the recording rings).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "common/level_track.hpp"
#include "speech/hsmm.hpp"
#include "speech/sentence_chains.hpp"
#include "speech/sentence_cutter.hpp"
#include "speech/syllable_placement.hpp"
#include "talkface/timeline.hpp"

using namespace talkface;
using namespace talkface::detail;
using talkface::test::track_of;

namespace {

// A transcript of `sentences` sentences of three syllables each.
Timeline transcript_of(std::size_t sentences) {
    Timeline transcript;
    for (std::size_t k = 0; k < sentences; ++k) {
        transcript.sentences.emplace_back();
        for (const char* pinyin : {"ta1", "men5", "shan1"}) {
            Syllable syllable;
            syllable.pinyin = pinyin;
            syllable.sentence = k;
            transcript.syllables.push_back(syllable);
        }
    }
    return transcript;
}

struct Recording {
    FeatureTrack track;
    SentenceCut cut;
};

// Sentences of 40 frames of voice, 20 of them a loud vowel, between pauses of 50 frames at the
// floor; each sentence's end after the vowel is `ends[k]`'s levels, the cutter's span holding it.
Recording recording_of(const std::vector<std::vector<float>>& ends) {
    std::vector<float> levels(50, -70.0f);
    SentenceCut cut;
    for (const std::vector<float>& end : ends) {
        const std::size_t first = levels.size();
        levels.insert(levels.end(), 20, -30.0f);
        levels.insert(levels.end(), 20, -20.0f);
        levels.insert(levels.end(), end.begin(), end.end());
        cut.spans.push_back({first, levels.size()});
        cut.runs_on.push_back(false);
        levels.insert(levels.end(), 50, -70.0f);
    }
    return {track_of(levels), cut};
}

// Where place_syllables ends the last syllable of `chain` (frames of the track) on a path that holds
// its first state until the sentence's speech starts, its last one (the pause after) for
// `pause_frames` at the search's end, and every state between but the optional ones (pauses) in
// turn, the last to the pause; `result` (the transcript's syllables) holds the placement.
std::size_t last_end_frame(const SentenceChain& chain, const FeatureTrack& track, Timeline& result,
                           std::size_t pause_frames = 1) {
    const std::size_t length = chain.searched.length() + 1 - pause_frames;
    const std::size_t speech_first = chain.speech.first_frame - chain.searched.first_frame;
    std::vector<std::size_t> middle;
    for (std::size_t s = 1; s + 1 < chain.states.size(); ++s)
        if (!chain.states[s].is_optional) middle.push_back(s);
    std::vector<StateSegment> path = {{0, 0, speech_first}};
    const std::size_t each = (length - 1 - speech_first) / middle.size();
    for (std::size_t m = 0; m < middle.size(); ++m) {
        const std::size_t first = speech_first + m * each;
        path.push_back({middle[m], first, m + 1 == middle.size() ? length - 1 : first + each});
    }
    path.push_back({chain.states.size() - 1, length - 1, chain.searched.length()});
    EmissionScores scores;
    scores.frame_count = chain.searched.length();
    scores.values.assign(scores.frame_count * kPhoneClassCount, -1.0f);
    std::vector<SyllableEvidence> evidence(result.syllables.size());
    place_syllables(chain, 0, path, {}, scores, track, result, evidence);
    return static_cast<std::size_t>(
        std::lround(result.syllables[chain.syllable_indices.back()].end_s / kFrameStepS));
}

std::size_t last_end_frame(const SentenceChain& chain, const FeatureTrack& track,
                           const Timeline& transcript) {
    Timeline result = transcript;
    return last_end_frame(chain, track, result);
}

// `recording` with a coder's comfort noise (Opus at 6 kbit/s) in place of its frames at -70 dB: swinging
// between -61 and -72 dB from frame to frame, crossing zero on `noise_crossings` of its samples; the
// voice's frames cross on 0.08 of theirs, as its vowels do.
FeatureTrack with_comfort_noise(const FeatureTrack& recording, float noise_crossings) {
    FeatureTrack track = recording;
    for (std::size_t t = 0; t < track.frame_count; ++t) {
        float* row = &track.values[t * kFeatureCount];
        const bool is_noise = row[kEnergyDb] == -70.0f;
        if (is_noise) row[kEnergyDb] = t % 2 == 0 ? -61.0f : -72.0f;
        row[kZeroCrossings] = is_noise ? noise_crossings : 0.08f;
    }
    return track;
}

// The loudness profile of a recording whose pauses are its runs of frames at or under `noise_db`
// (the noise alone), at least 12 frames long.
LoudnessProfile pauses_at(const FeatureTrack& track, float noise_db) {
    LoudnessProfile loudness;
    std::size_t first = 0;
    for (std::size_t t = 0; t <= track.frame_count; ++t) {
        if (t < track.frame_count && track.at(t, kEnergyDb) <= noise_db) continue;
        if (t >= first + 12) loudness.pauses.push_back({first, t});
        first = t + 1;
    }
    return loudness;
}

// 休息's end through a telephone band: 5 frames of murmur 24 dB under the vowel, the x the band took
// away (`dip_frames` at the noise, -70 dB), then the neutral-tone i, `back_frames` at `back_db`.
std::vector<float> dipped_end(std::size_t dip_frames, std::size_t back_frames, float back_db) {
    std::vector<float> end(5, -44.0f);
    end.insert(end.end(), dip_frames, -70.0f);
    end.insert(end.end(), back_frames, back_db);
    return end;
}

// The chains of `transcript` on `cut`, their search spans set on `track` whose pauses are its frames
// at or under `noise_db` (pauses_at).
std::vector<SentenceChain> searched_chains(const Timeline& transcript, const SentenceCut& cut,
                                           const FeatureTrack& track, float noise_db) {
    std::vector<SentenceChain> chains = group_chains(transcript, cut, cut.spans);
    set_search_spans(track, pauses_at(track, noise_db), chains);
    return chains;
}

}  // namespace

TEST_SUITE("sentence chains") {
    TEST_CASE("a room's tail, falling from the last vowel, is cut off") {
        std::vector<float> levels(30, -20.0f);  // the voice
        for (int k = 1; k <= 30; ++k) levels.push_back(-20.0f - 1.5f * static_cast<float>(k));  // the tail
        const FeatureTrack track = track_of(levels);
        // The voice ends after the last frame within 18 dB of its loudest: 12 frames into the fall.
        CHECK(end_before_tail(track, 0, levels.size()) == 42);
    }

    TEST_CASE("a large room's slow ringing is followed back to where the voice stopped") {
        std::vector<float> levels(30, -20.0f);  // the voice
        // The ringing, 12 dB under the voice where it stops, falls 0.3 dB a frame with a 1 dB ripple:
        // it passes 18 dB under the voice 23 frames after the voice stopped.
        for (int k = 0; k < 40; ++k)
            levels.push_back(-32.0f - 0.3f * static_cast<float>(k) + (k % 2 == 0 ? 1.0f : -1.0f));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        CHECK(mark == 53);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == 30);
    }

    TEST_CASE("a ringing longer than the reference window is measured from the last vowel's peak") {
        std::vector<float> levels(30, -20.0f);  // the last vowel
        // The ringing of a large room, 6 dB under the vowel where the voice stops, falls 0.35 dB a
        // frame with a 1 dB ripple for 0.7 s: the last 0.6 s hold none of the vowel, and their
        // loudest frame, their first, is already ringing.
        for (int k = 0; k < 70; ++k)
            levels.push_back(-26.0f - 0.35f * static_cast<float>(k) + (k % 2 == 0 ? 1.0f : -1.0f));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        // 18 dB under the vowel, not under the ringing's first frame in the window (91).
        CHECK(mark == 67);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == 30);
    }

    TEST_CASE("a large room's ringing is followed back past the dips between its reflections") {
        std::vector<float> levels(30, -20.0f);  // the voice
        // The ringing of the slow room above, where every seventh frame one reflection has died and
        // the next not come: the level dips 6 dB under the line for a frame.
        for (int k = 0; k < 40; ++k)
            levels.push_back(-32.0f - 0.3f * static_cast<float>(k) + (k % 7 == 3 ? -6.0f : 0.0f));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        REQUIRE(mark > 45);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == 30);
    }

    TEST_CASE("a voice that stops at its loudest frame is found by its fall into the ringing") {
        // The last vowel rises to its loudest frame and stops there (a rising tone cut by the
        // sentence's end): the walk back along the line reaches that frame without leaving the line,
        // and the voice's fall of 12 dB onto the slow ringing of the room above tells where it stopped.
        std::vector<float> levels;
        for (int k = 0; k < 30; ++k) levels.push_back(-26.0f + 0.2f * static_cast<float>(k));
        for (int k = 0; k < 40; ++k)
            levels.push_back(-32.0f - 0.3f * static_cast<float>(k) + (k % 2 == 0 ? 1.0f : -1.0f));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        REQUIRE(mark > 45);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == 30);
    }

    TEST_CASE("a fade that passes under the ringing's line drawn back keeps the mark") {
        // The last vowel fades 1 dB a frame to 20 dB under the voice, while what the louder frames
        // before it left rings on over it, falling 0.3 dB a frame: followed back, the level leaves the
        // line under it, and where in the fade the voice stopped cannot be told.
        std::vector<float> levels(30, -20.0f);
        for (int k = 1; k <= 20; ++k) levels.push_back(-20.0f - 1.0f * static_cast<float>(k));
        for (int k = 0; k < 40; ++k) levels.push_back(-34.0f - 0.3f * static_cast<float>(k));
        const FeatureTrack track = track_of(levels);
        const std::size_t mark = end_before_tail(track, 0, levels.size());
        REQUIRE(mark > 50);
        CHECK(end_before_ringing(track, 0, mark, levels.size()) == mark);
    }

    TEST_CASE("a quiet last syllable after a closure is kept, though far under the one before") {
        std::vector<float> levels(30, -20.0f);                      // a loud syllable
        levels.insert(levels.end(), 5, -70.0f);                      // a stop's closure
        levels.insert(levels.end(), 20, -42.0f);                     // a quiet third tone, 22 dB under
        const FeatureTrack track = track_of(levels);
        CHECK(end_before_tail(track, 0, levels.size()) == levels.size());
    }

    TEST_CASE("a quiet end is the last syllable's where the recording's other sentences stop dry") {
        // A nasal coda whose murmur a telephone band takes away: 24 dB under the vowel for 15 frames.
        const std::vector<float> murmur(15, -44.0f);
        const Recording dry = recording_of({murmur, {}, {}});
        const Timeline transcript = transcript_of(3);
        std::vector<SentenceChain> chains = group_chains(transcript, dry.cut, dry.cut.spans);
        set_search_spans(dry.track, LoudnessProfile(), chains);
        REQUIRE(chains[0].tail_frames == 15);
        // The path gives the last syllable every frame searched after the vowel.
        CHECK(last_end_frame(chains[0], dry.track, transcript) == chains[0].searched.end_frame - 1);

        // Where every sentence rings on, the tail is the room's: the voice ends before it.
        std::vector<float> tail;
        for (int k = 1; k <= 30; ++k) tail.push_back(-20.0f - 1.0f * static_cast<float>(k));
        const Recording room = recording_of({tail, tail, tail});
        chains = group_chains(transcript, room.cut, room.cut.spans);
        set_search_spans(room.track, LoudnessProfile(), chains);
        REQUIRE(chains[0].tail_frames >= 9);
        CHECK(last_end_frame(chains[0], room.track, transcript) ==
              chains[0].speech.end_frame - chains[0].tail_frames);
    }

    TEST_CASE("a quiet end outside a room runs on to where it falls into the noise") {
        // A nasal coda's murmur through a telephone band: 15 frames 24 dB under the vowel, then 10
        // fading 36 dB under it, over a steady noise at -70 dB; the cutter's span ends before the fade.
        std::vector<float> murmur(15, -44.0f);
        murmur.insert(murmur.end(), 10, -56.0f);
        Recording phone = recording_of({murmur, {}, {}});
        phone.cut.spans[0].end_frame -= 10;
        const Timeline transcript = transcript_of(3);
        std::vector<SentenceChain> chains = group_chains(transcript, phone.cut, phone.cut.spans);
        set_search_spans(phone.track, pauses_at(phone.track, -60.0f), chains);
        const std::size_t voice_end = chains[0].speech.first_frame + 40;
        REQUIRE(chains[0].speech.end_frame - chains[0].tail_frames == voice_end);
        // The search still ends 5 frames past the vowel; the last syllable keeps the whole murmur.
        CHECK(chains[0].searched.end_frame == voice_end + 5);
        CHECK(last_end_frame(chains[0], phone.track, transcript) == voice_end + 25);

        // In a noise that swings by 16 dB between frames, what lies under its reach says nothing of
        // the voice: the last syllable ends where the path ends it.
        FeatureTrack swinging = phone.track;
        for (std::size_t t = 0; t < swinging.frame_count; t += 2)
            if (swinging.at(t, kEnergyDb) == -70.0f) swinging.values[t * kFeatureCount + kEnergyDb] = -54.0f;
        chains = group_chains(transcript, phone.cut, phone.cut.spans);
        set_search_spans(swinging, pauses_at(swinging, -54.0f), chains);
        CHECK(last_end_frame(chains[0], swinging, transcript) == voice_end + 4);
    }

    TEST_CASE("a quiet end that dips into the noise and comes back ends where it falls again") {
        // 休息 through a telephone band: the murmur 24 dB under the vowel, then the x the band took
        // away (12 frames at the noise, -70 dB), then the neutral-tone i 8 dB over the noise for 8
        // frames; the cutter's span ends in the dip.
        Recording phone = recording_of({dipped_end(12, 8, -62.0f), {}, {}});
        phone.cut.spans[0].end_frame -= 15;
        const Timeline transcript = transcript_of(3);
        std::vector<SentenceChain> chains = group_chains(transcript, phone.cut, phone.cut.spans);
        set_search_spans(phone.track, pauses_at(phone.track, -65.0f), chains);
        const std::size_t voice_end = chains[0].speech.first_frame + 40;
        REQUIRE(chains[0].speech.end_frame - chains[0].tail_frames == voice_end);
        CHECK(chains[0].quiet_end == voice_end + 25);
        CHECK(last_end_frame(chains[0], phone.track, transcript) == voice_end + 25);

        // A swell of 3 frames is the noise's, not a vowel's; a sound that comes back and runs on
        // past where the voice's end is looked for is not the voice's: the end stays where it
        // first fell into the noise.
        Recording swelling = phone;
        for (std::size_t t = voice_end + 20; t < voice_end + 25; ++t)
            swelling.track.values[t * kFeatureCount + kEnergyDb] = -70.0f;
        chains = group_chains(transcript, swelling.cut, swelling.cut.spans);
        set_search_spans(swelling.track, pauses_at(swelling.track, -65.0f), chains);
        CHECK(chains[0].quiet_end == voice_end + 5);
        Recording running_on = phone;
        for (std::size_t t = voice_end + 17; t < voice_end + 45; ++t)
            running_on.track.values[t * kFeatureCount + kEnergyDb] = -62.0f;
        chains = group_chains(transcript, running_on.cut, running_on.cut.spans);
        set_search_spans(running_on.track, pauses_at(running_on.track, -65.0f), chains);
        CHECK(chains[0].quiet_end == voice_end + 5);
    }

    TEST_CASE(
        "a quiet end in a noise too unsteady for a reach ends where its voicing stops, after the checks "
        "where the path ends before it") {
        // A vowel's voiced tail through Opus at 6 kbit/s: 5 frames of murmur 24 dB under the vowel, then
        // 15 at -57 dB, inside the comfort noise's swing, which crosses zero on 0.2 of its samples; the
        // cutter's span ends 10 frames into the tail.
        std::vector<float> end(5, -44.0f);
        end.insert(end.end(), 15, -57.0f);
        Recording phone = recording_of({end, {}, {}});
        phone.cut.spans[0].end_frame -= 10;
        const FeatureTrack opus = with_comfort_noise(phone.track, 0.2f);
        const Timeline transcript = transcript_of(3);
        std::vector<SentenceChain> chains = group_chains(transcript, phone.cut, phone.cut.spans);
        set_search_spans(opus, pauses_at(opus, -60.0f), chains);
        const std::size_t voice_end = chains[0].speech.first_frame + 40;
        REQUIRE(chains[0].speech.end_frame - chains[0].tail_frames == voice_end);
        CHECK(chains[0].quiet_end == voice_end + 20);
        Timeline result = transcript;
        CHECK(last_end_frame(chains[0], opus, result) == voice_end + 20);
        CHECK_FALSE(voiced_end_past_path(chains[0], opus, result).has_value());

        // Where the path ends the last syllable before end_before_tail's mark (it gave the tail to
        // the pause), the checks read its end on the path, and the voice's is given out after them.
        result = transcript;
        CHECK(last_end_frame(chains[0], opus, result, 8) == voice_end - 3);
        const auto voiced = voiced_end_past_path(chains[0], opus, result);
        REQUIRE(voiced.has_value());
        CHECK(voiced->syllable == chains[0].syllable_indices.back());
        CHECK(std::lround(voiced->end_s / kFrameStepS) == static_cast<long>(voice_end + 20));

        // A noise that crosses zero as seldom as the vowels (music's notes) says nothing by its
        // voicing: the last syllable ends where the path ends it.
        const FeatureTrack music = with_comfort_noise(phone.track, 0.08f);
        chains = group_chains(transcript, phone.cut, phone.cut.spans);
        set_search_spans(music, pauses_at(music, -60.0f), chains);
        CHECK(last_end_frame(chains[0], music, transcript) == voice_end + 4);
        result = transcript;
        CHECK(last_end_frame(chains[0], music, result, 8) == voice_end - 3);
        CHECK_FALSE(voiced_end_past_path(chains[0], music, result).has_value());
    }

    TEST_CASE("a voice read back by its voicing in a comfort noise holds 4 frames") {
        // 休息 through Opus at 6 kbit/s: the murmur 24 dB under the vowel, the x the band took away
        // (10 frames that cross zero as the comfort noise does), then the i's voiced 4 frames at
        // -57 dB; the cutter's span ends 2 frames into the x.
        Recording phone = recording_of({dipped_end(10, 4, -57.0f), {}, {}});
        phone.cut.spans[0].end_frame -= 12;
        const FeatureTrack opus = with_comfort_noise(phone.track, 0.2f);
        const Timeline transcript = transcript_of(3);
        std::vector<SentenceChain> chains = searched_chains(transcript, phone.cut, opus, -60.0f);
        const std::size_t voice_end = chains[0].speech.first_frame + 40;
        REQUIRE(chains[0].speech.end_frame - chains[0].tail_frames == voice_end + 7);
        CHECK(chains[0].quiet_end == voice_end + 19);

        // 3 frames are as long as the noise's own voiced runs: the end stays where it fell, at the
        // span's end.
        FeatureTrack shorter = opus;
        shorter.values[(voice_end + 15) * kFeatureCount + kEnergyDb] = -72.0f;
        shorter.values[(voice_end + 15) * kFeatureCount + kZeroCrossings] = 0.2f;
        chains = searched_chains(transcript, phone.cut, shorter, -60.0f);
        CHECK(chains[0].quiet_end == voice_end + 7);
    }

    TEST_CASE("a span run on into a noise is no voiced tail, though the noise past it reads voiced") {
        // A street's noise through an AGC and Opus: 10 frames at -30 dB after the vowel that cross
        // zero on 0.2 of their samples, in the cutter's span, then 8 frames as loud that cross as
        // seldom as a vowel, then the comfort noise.
        Recording phone = recording_of({std::vector<float>(10, -30.0f), {}, {}});
        FeatureTrack street = with_comfort_noise(phone.track, 0.2f);
        const std::size_t voice_end = phone.cut.spans[0].first_frame + 40;
        for (std::size_t t = voice_end; t < voice_end + 18; ++t) {
            street.values[t * kFeatureCount + kEnergyDb] = -30.0f;
            street.values[t * kFeatureCount + kZeroCrossings] = t < voice_end + 10 ? 0.2f : 0.08f;
        }
        const Timeline transcript = transcript_of(3);
        const std::vector<SentenceChain> chains = searched_chains(transcript, phone.cut, street, -60.0f);
        REQUIRE(chains[0].speech.end_frame - chains[0].tail_frames == voice_end + 10);
        REQUIRE(chains[0].quiet_end == voice_end + 18);
        // The voice fell into the noise before the mark: what the voicing reads past it is not the
        // voice's, and a last syllable the path ends at the vowel keeps its end.
        CHECK_FALSE(chains[0].voiced_past_end);
        Timeline result = transcript;
        const std::size_t pause_frames = chains[0].searched.end_frame - (voice_end + 5);
        CHECK(last_end_frame(chains[0], street, result, pause_frames) == voice_end + 5);
        CHECK_FALSE(voiced_end_past_path(chains[0], street, result).has_value());
    }
}
