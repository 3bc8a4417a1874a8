#include "audio/repeated_sound.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include "audio/audio_source.hpp"
#include "talkface/errors.hpp"

namespace talkface::detail {

namespace {

// Frames read at a time.
constexpr std::size_t kBlockFrames = std::size_t{1} << 16;

// Frames a second copy may decode otherwise than the first from its start: the decoder's state the
// first copy's end left reaches two of the longest frames a codec here decodes at once (Vorbis's
// 2048; MP3's are 1152, AAC's 1024).
constexpr std::size_t kDecoderReachFrames = 2 * 2048;

// The sound found again lasts a tenth of a second: no two stretches of a voice or of a
// microphone's noise are the same samples for that long.
constexpr int kReferencesPerSecond = 10;

// Reads `frames` frames of `source` into `into`, fewer only at its end; how many.
std::size_t read_block(AudioSource& source, std::vector<float>& into, std::size_t frames) {
    into.resize(frames);
    std::size_t held = 0;
    while (held < frames) {
        const std::size_t got = source.read(into.data() + held, frames - held);
        if (got == 0) break;
        held += got;
    }
    into.resize(held);
    return held;
}

// The first samples of sound past the decoder's reach, and where they start.
struct Reference {
    std::size_t frame = 0;
    std::vector<float> samples;
    std::vector<float> after;  // the samples read past them
};

std::optional<Reference> read_reference(AudioSource& source, std::size_t frames) {
    Reference reference;
    std::optional<std::size_t> start;
    std::size_t read = 0;
    std::vector<float> block;
    while (reference.samples.size() < frames) {
        if (read_block(source, block, kBlockFrames) == 0) return std::nullopt;
        std::size_t k = 0;
        if (!start) {
            k = read < kDecoderReachFrames ? std::min(kDecoderReachFrames - read, block.size()) : 0;
            while (k < block.size() && block[k] == 0.0f) ++k;
            if (k < block.size()) start = read + k;
        }
        if (start) {
            const std::size_t take = std::min(block.size() - k, frames - reference.samples.size());
            reference.samples.insert(reference.samples.end(), block.begin() + static_cast<std::ptrdiff_t>(k),
                                     block.begin() + static_cast<std::ptrdiff_t>(k + take));
            reference.after.assign(block.begin() + static_cast<std::ptrdiff_t>(k + take), block.end());
        }
        read += block.size();
    }
    reference.frame = *start;
    return reference;
}

std::optional<RepeatedSound> find_repeat(const std::string& path) {
    const std::unique_ptr<AudioSource> source = open_audio_file(path);
    const int rate_hz = source->sample_rate_hz();
    const auto length = static_cast<std::size_t>(rate_hz / kReferencesPerSecond);
    std::optional<Reference> reference = read_reference(*source, length);
    if (!reference) return std::nullopt;
    const std::vector<float>& sound = reference->samples;
    // The frames read past the reference, from held_start on, searched for it; a block's last
    // length - 1 are searched again with the next.
    std::vector<float> held = std::move(reference->after);
    std::size_t held_start = reference->frame + length;
    std::vector<float> block;
    std::size_t found = 0;
    while (true) {
        bool is_found = false;
        for (std::size_t k = 0; k + length <= held.size(); ++k) {
            if (held[k] == sound[0] &&
                std::equal(sound.begin(), sound.end(), held.begin() + static_cast<std::ptrdiff_t>(k))) {
                found = k;
                is_found = true;
                break;
            }
        }
        if (is_found) break;
        if (held.size() >= length) {
            const std::size_t searched = held.size() - length + 1;
            held.erase(held.begin(), held.begin() + static_cast<std::ptrdiff_t>(searched));
            held_start += searched;
        }
        if (read_block(*source, block, kBlockFrames) == 0) return std::nullopt;
        held.insert(held.end(), block.begin(), block.end());
    }
    const std::size_t repeat = held_start + found;
    const std::size_t distance = repeat - reference->frame;
    // The repeat compared to the end of the file with the sound it repeats, read again.
    const std::unique_ptr<AudioSource> original = open_audio_file(path);
    for (std::size_t passed = 0; passed < reference->frame;) {
        const std::size_t got =
            read_block(*original, block, std::min(kBlockFrames, reference->frame - passed));
        if (got == 0) return std::nullopt;
        passed += got;
    }
    std::vector<float> again(held.begin() + static_cast<std::ptrdiff_t>(found), held.end());
    std::size_t compared = 0;
    while (!again.empty() || read_block(*source, again, kBlockFrames) > 0) {
        if (compared + again.size() > distance) return std::nullopt;
        if (read_block(*original, block, again.size()) < again.size() || block != again) return std::nullopt;
        compared += again.size();
        again.clear();
    }
    return RepeatedSound{rate_hz, reference->frame, repeat};
}

}  // namespace

std::optional<RepeatedSound> repeated_sound(const std::string& path) {
    // A file that cannot be read to its end says so where it is read for the alignment; here that
    // only means no repeat is found.
    try {
        return find_repeat(path);
    } catch (const Error&) {
        return std::nullopt;
    }
}

}  // namespace talkface::detail
