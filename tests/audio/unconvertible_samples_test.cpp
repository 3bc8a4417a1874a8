// Samples FFmpeg's resampler cannot convert are refused naming the file and the time. No decoder of
// FFmpeg 5.1 gives such a frame (swresample converts every sample format and channel layout they
// give), so this program stands in for swr_init (its own definition comes before the library's):
// the first converter is made, each one after it fails. A raw AAC whose channels go from one to two
// at 1 s makes the reader ask for a second converter there. A program of its own, as every
// converter it makes after the first fails.
#include <doctest/doctest.h>

#include <dlfcn.h>

#include <string>

extern "C" {
#include <libavutil/error.h>
#include <libswresample/swresample.h>
}

#include "audio/audio_source.hpp"
#include "common/made_by_command.hpp"
#include "talkface/errors.hpp"

using namespace talkface;

namespace {

int converters_made = 0;

// A second of a sine tone in raw AAC with `channels` channels, at 16 kHz.
std::string tone_in_aac(const std::string& name, int channels) {
    return test::made_by_command(
        name, "ffmpeg -nostdin -loglevel error -y -f lavfi -i sine=f=220:d=1:r=16000 -ac " +
                  std::to_string(channels) + " -c:a aac -f adts");
}

}  // namespace

extern "C" int swr_init(SwrContext* context) {
    using Init = int (*)(SwrContext*);
    static const auto library_init = reinterpret_cast<Init>(dlsym(RTLD_NEXT, "swr_init"));
    return ++converters_made == 1 ? library_init(context) : AVERROR(EINVAL);
}

TEST_SUITE("FFmpeg source") {
    TEST_CASE("samples the resampler cannot convert are refused naming the file and the time") {
        const std::string mono = tone_in_aac("one_channel.aac", 1);
        const std::string stereo = tone_in_aac("two_channels.aac", 2);
        const std::string joined =
            test::made_by_command("channels_change.aac", "cat '" + mono + "' '" + stereo + "' >");
        CHECK_THROWS_WITH_AS(
            {
                const auto source = detail::open_audio_file(joined);
                std::vector<float> block(4096);
                while (source->read(block.data(), block.size()) > 0) {
                }
            },
            doctest::Contains((joined + ": cannot convert its samples (fltp) at 1.").c_str()), ParseError);
        CHECK(converters_made == 2);
    }
}
