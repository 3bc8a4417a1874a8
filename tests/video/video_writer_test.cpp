// VideoWriter on a moving test pattern: each format read back with libavformat/libavcodec.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "media_probe.hpp"
#include "talkface/errors.hpp"
#include "talkface/video_writer.hpp"
#include "test_pattern.hpp"

using talkface::VideoFormat;
using talkface::VideoOptions;
using talkface::VideoWriter;

namespace {

const std::string kOutputDir = TALKFACE_TEST_OUTPUT_DIR;

std::string fresh_folder(const std::string& name) {
    const std::string folder = kOutputDir + "/video_writer_" + name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

std::vector<float> speech_like(int rate_hz, double seconds) {
    std::vector<float> samples(static_cast<std::size_t>(std::lround(seconds * rate_hz)));
    for (std::size_t i = 0; i < samples.size(); ++i) {
        samples[i] = static_cast<float>(0.3 * std::sin(2.0 * M_PI * 180.0 * static_cast<double>(i) / rate_hz));
    }
    return samples;
}

VideoOptions small(int width = 320, int height = 240, double fps = 30.0) {
    VideoOptions options;
    options.width_px = width;
    options.height_px = height;
    options.fps = fps;
    return options;
}

void write_pattern(VideoWriter& writer, long frames, bool alpha = false) {
    const VideoOptions& options = writer.options();
    for (long k = 0; k < frames; ++k) {
        const std::vector<std::uint8_t> frame = talkface_test::test_pattern(k, options.width_px, options.height_px, alpha);
        writer.write_frame(frame.data(), options.width_px * 4);
    }
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Close enough for a lossy codec on a flat colour, away from edges.
bool is_near(talkface_test::Rgba found, talkface_test::Rgba expected, int tolerance) {
    return std::abs(found.r - expected.r) <= tolerance && std::abs(found.g - expected.g) <= tolerance &&
           std::abs(found.b - expected.b) <= tolerance;
}

}  // namespace

TEST_SUITE("VideoWriter") {

TEST_CASE("the format comes from the extension, in either case") {
    CHECK(talkface::video_format_from_path("a/talk.mp4") == VideoFormat::mp4);
    CHECK(talkface::video_format_from_path("TALK.MP4") == VideoFormat::mp4);
    CHECK(talkface::video_format_from_path("x.webm") == VideoFormat::webm);
    CHECK(talkface::video_format_from_path("x.WebP") == VideoFormat::webp);
    CHECK(talkface::video_format_from_path("frames/face.png") == VideoFormat::png_sequence);
    CHECK(talkface::video_format_from_path("chat.GIF") == VideoFormat::gif);
    CHECK(std::string(talkface::video_format_name(VideoFormat::gif)) == "gif");
    CHECK(std::string(talkface::video_format_name(VideoFormat::png_sequence)) == "png");
}

TEST_CASE("MP4: H.264 yuv420p and AAC that start together and last as long as the speech") {
    const std::string folder = fresh_folder("mp4");
    const std::string path = folder + "/talk.mp4";
    const std::vector<float> samples = speech_like(16000, 1.5);
    {
        VideoWriter writer(path, small());
        writer.add_audio({samples.data(), samples.size(), 1, 16000});
        write_pattern(writer, 45);  // 1.5 s at 30 fps
        CHECK_FALSE(std::filesystem::exists(path));  // only the temporary file so far
        writer.finish();
    }
    const talkface_test::MediaInfo info = talkface_test::probe_media(path);
    REQUIRE(info.video() != nullptr);
    REQUIRE(info.audio() != nullptr);
    CHECK(info.video()->codec == "h264");
    CHECK(info.video()->pixel_format == "yuv420p");
    CHECK(info.video()->width == 320);
    CHECK(info.video()->height == 240);
    CHECK(info.video()->frame_count == 45);
    CHECK(info.audio()->codec == "aac");
    CHECK(std::abs(info.video()->start_s) < 1e-9);
    CHECK(std::abs(info.audio()->start_s) < 1e-9);
    CHECK(info.duration_s == doctest::Approx(1.5).epsilon(1.0 / 30.0 / 1.5));
    CHECK(info.audio()->duration_s == doctest::Approx(1.5).epsilon(1.0 / 30.0 / 1.5));
    // faststart: the index is in front, so a browser plays it while it downloads.
    const std::string bytes = read_bytes(path);
    CHECK(bytes.find("moov") < bytes.find("mdat"));
    // Nothing else is left in the folder.
    CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("MP4: a decoded frame shows the pattern of its own index") {
    const std::string path = fresh_folder("mp4_frames") + "/pattern.mp4";
    {
        VideoWriter writer(path, small());
        write_pattern(writer, 30);
        writer.finish();
    }
    for (const long index : {0L, 7L, 29L}) {
        CAPTURE(index);
        int width = 0, height = 0;
        const std::vector<std::uint8_t> rgba = talkface_test::decode_video_frame_rgba(path, index, &width, &height);
        REQUIRE(width == 320);
        const int centre_x = talkface_test::square_left(index, 320) + talkface_test::kSquarePx / 2;
        CHECK(is_near(talkface_test::pixel_at(rgba, width, centre_x, 120), {220, 30, 40, 255}, 12));
        // A step of the square to either side is background.
        CHECK_FALSE(is_near(talkface_test::pixel_at(rgba, width, centre_x + talkface_test::kSquarePx, 120),
                            {220, 30, 40, 255}, 40));
        CHECK(is_near(talkface_test::pixel_at(rgba, width, 4, 4), {40, 60, 160, 255}, 12));
    }
}

TEST_CASE("MP4: the same frames and sound give the same bytes") {
    const std::string folder = fresh_folder("mp4_same");
    const std::vector<float> samples = speech_like(22050, 0.5);
    // Between the two, the heap is left holding other bytes (x264's AVX-512 code gave different
    // bytes then: video_stream_encoder.cpp).
    std::vector<std::vector<std::uint8_t>> clutter;
    for (const char* name : {"/a.mp4", "/b.mp4"}) {
        for (int k = 0; k < 8; ++k) clutter.emplace_back(static_cast<std::size_t>(37000 * (k + 1)), std::uint8_t(0xA5));
        VideoWriter writer(folder + name, small());
        writer.add_audio({samples.data(), samples.size(), 1, 22050});
        write_pattern(writer, 15);
        writer.finish();
    }
    CHECK(read_bytes(folder + "/a.mp4") == read_bytes(folder + "/b.mp4"));
}

TEST_CASE("WebM: VP9 and Opus, transparent keeps the alpha channel") {
    const std::string folder = fresh_folder("webm");
    const std::vector<float> samples = speech_like(48000, 1.0);
    VideoOptions options = small();
    options.transparent = true;
    {
        VideoWriter writer(folder + "/alpha.webm", options);
        writer.add_audio({samples.data(), samples.size(), 1, 48000});
        write_pattern(writer, 30, true);
        writer.finish();
    }
    const talkface_test::MediaInfo info = talkface_test::probe_media(folder + "/alpha.webm");
    REQUIRE(info.video() != nullptr);
    REQUIRE(info.audio() != nullptr);
    CHECK(info.video()->codec == "vp9");
    CHECK(info.audio()->codec == "opus");
    CHECK(info.duration_s == doctest::Approx(1.0).epsilon(1.0 / 30.0));
    // Sound and picture start together: the first sound after Opus's pre-skip, the first frame at 0.
    CHECK(std::abs(info.video()->start_s) < 1e-9);
    CHECK(std::abs(info.audio()->start_s + info.audio()->priming_s) < 0.001);
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgba = talkface_test::decode_video_frame_rgba(folder + "/alpha.webm", 10, &width,
                                                                                  &height);
    const int centre_x = talkface_test::square_left(10, 320) + talkface_test::kSquarePx / 2;
    CHECK(talkface_test::pixel_at(rgba, width, centre_x, 120).a > 240);  // the square: opaque
    CHECK(talkface_test::pixel_at(rgba, width, 4, 4).a < 16);             // the rest: transparent
}

TEST_CASE("WebP: an animated image that loops, no sound") {
    const std::string path = fresh_folder("webp") + "/chat.webp";
    const std::vector<float> samples = speech_like(16000, 0.5);
    {
        VideoWriter writer(path, small(200, 150, 10.0));
        writer.add_audio({samples.data(), samples.size(), 1, 16000});  // ignored: WebP has no sound
        write_pattern(writer, 5);
        writer.finish();
    }
    const std::string bytes = read_bytes(path);
    CHECK(bytes.substr(0, 4) == "RIFF");
    CHECK(bytes.substr(8, 4) == "WEBP");
    const std::size_t anim = bytes.find("ANIM");
    REQUIRE(anim != std::string::npos);
    CHECK(bytes[anim + 12] == 0);  // loop count 0: forever
    CHECK(bytes[anim + 13] == 0);
    std::size_t frames = 0;
    for (std::size_t at = bytes.find("ANMF"); at != std::string::npos; at = bytes.find("ANMF", at + 4)) ++frames;
    CHECK(frames == 5);
}

TEST_CASE("GIF: one palette for all the frames, looping, as long as its frames, no sound") {
    const std::string folder = fresh_folder("gif");
    const std::vector<float> samples = speech_like(16000, 0.5);
    {
        VideoWriter writer(folder + "/chat.gif", small(200, 150, 10.0));
        writer.add_audio({samples.data(), samples.size(), 1, 16000});  // ignored: GIF has no sound
        write_pattern(writer, 12);
        writer.finish();
    }
    const talkface_test::MediaInfo info = talkface_test::probe_media(folder + "/chat.gif");
    REQUIRE(info.video() != nullptr);
    CHECK(info.audio() == nullptr);
    CHECK(info.video()->codec == "gif");
    CHECK(info.video()->frame_count == 12);
    CHECK(info.duration_s == doctest::Approx(1.2).epsilon(0.1 / 1.2));
    const std::string bytes = read_bytes(folder + "/chat.gif");
    CHECK(bytes.substr(0, 6) == "GIF89a");
    CHECK((static_cast<unsigned char>(bytes[10]) & 0x80) != 0);  // a global colour table
    const std::size_t loop = bytes.find("NETSCAPE2.0");
    REQUIRE(loop != std::string::npos);
    CHECK(bytes[loop + 13] == 0);  // loop count 0: forever
    CHECK(bytes[loop + 14] == 0);
    // The pattern has fewer colours than the palette holds: every frame comes back exact, the
    // first whole and the others as the rectangle that changed over the frame before.
    for (const long index : {0L, 5L, 11L}) {
        CAPTURE(index);
        int width = 0, height = 0;
        const std::vector<std::uint8_t> rgba = talkface_test::decode_video_frame_rgba(folder + "/chat.gif", index,
                                                                                      &width, &height);
        CHECK(rgba == talkface_test::test_pattern(index, 200, 150));
    }
    CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("GIF: frames past the palette's sample are mapped as they come, each exact") {
    // Noise of 16 colours deflates poorly (900 KB a frame at 1280x720): the palette's sample (the
    // first 32 MB of kept frames) ends within some 36 frames, and the rest are mapped to its
    // palette as they are written.
    const std::string path = fresh_folder("gif_long") + "/long.gif";
    const int width = 1280, height = 720;
    const long frame_count = 60;
    const auto noise = [&](long index) {
        std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
        std::uint32_t state = 2654435761u * static_cast<std::uint32_t>(index + 1);
        for (std::size_t pixel = 0; pixel < rgba.size(); pixel += 4) {
            state = state * 1664525u + 1013904223u;
            const std::uint32_t colour = state >> 28;  // 0..15
            rgba[pixel] = static_cast<std::uint8_t>(colour * 17);
            rgba[pixel + 1] = static_cast<std::uint8_t>(255 - colour * 13);
            rgba[pixel + 2] = static_cast<std::uint8_t>((colour * 97) % 256);
            rgba[pixel + 3] = 255;
        }
        return rgba;
    };
    {
        VideoWriter writer(path, small(width, height, 25.0));
        for (long index = 0; index < frame_count; ++index) writer.write_frame(noise(index).data(), width * 4);
        writer.finish();
    }
    const talkface_test::MediaInfo info = talkface_test::probe_media(path);
    REQUIRE(info.video() != nullptr);
    CHECK(info.video()->frame_count == frame_count);
    for (const long index : {0L, 45L, frame_count - 1}) {
        CAPTURE(index);
        int decoded_width = 0, decoded_height = 0;
        const std::vector<std::uint8_t> rgba = talkface_test::decode_video_frame_rgba(path, index, &decoded_width,
                                                                                      &decoded_height);
        CHECK(rgba == noise(index));
    }
}

TEST_CASE("GIF: transparent keeps what has no alpha transparent") {
    const std::string path = fresh_folder("gif_alpha") + "/sticker.gif";
    VideoOptions options = small(120, 90, 25.0);
    options.transparent = true;
    {
        VideoWriter writer(path, options);
        write_pattern(writer, 4, true);
        writer.finish();
    }
    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgba = talkface_test::decode_video_frame_rgba(path, 3, &width, &height);
    const int centre_x = talkface_test::square_left(3, 120) + talkface_test::kSquarePx / 2;
    CHECK(is_near(talkface_test::pixel_at(rgba, width, centre_x, 45), {220, 30, 40, 255}, 0));
    CHECK(talkface_test::pixel_at(rgba, width, centre_x, 45).a == 255);
    CHECK(talkface_test::pixel_at(rgba, width, 4, 4).a == 0);
}

TEST_CASE("PNG sequence: numbered files, exact pixels, transparent if asked") {
    const std::string folder = fresh_folder("png");
    VideoOptions options = small(63, 41);  // any size, odd sides too
    options.transparent = true;
    {
        VideoWriter writer(folder + "/face.png", options);
        write_pattern(writer, 3, true);
        writer.finish();
        // Only the frames, while the writer still exists.
        CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 3);
    }
    for (long index = 0; index < 3; ++index) {
        CAPTURE(index);
        const std::string frame_path = folder + "/face-00000" + std::to_string(index) + ".png";
        REQUIRE(std::filesystem::exists(frame_path));
        int width = 0, height = 0;
        const std::vector<std::uint8_t> rgba = talkface_test::decode_video_frame_rgba(frame_path, 0, &width, &height);
        CHECK(rgba == talkface_test::test_pattern(index, 63, 41, true));
    }
    CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 3);
}

TEST_CASE("a writer dropped before finish leaves no file, not even a temporary one") {
    for (const char* name : {"/a.mp4", "/a.webm", "/a.webp", "/a.png", "/a.gif"}) {
        CAPTURE(name);
        const std::string folder = fresh_folder("dropped");
        {
            VideoWriter writer(folder + name, small());
            write_pattern(writer, 3);
        }
        CHECK(std::filesystem::is_empty(folder));
    }
}

TEST_CASE("an existing file is replaced only when the new one is whole") {
    const std::string folder = fresh_folder("replace");
    const std::string path = folder + "/talk.mp4";
    { std::ofstream(path) << "old"; }
    {
        VideoWriter writer(path, small());
        write_pattern(writer, 2);
    }
    CHECK(read_bytes(path) == "old");
    VideoWriter writer(path, small());
    write_pattern(writer, 2);
    writer.finish();
    CHECK(read_bytes(path) != "old");
}

TEST_CASE("bad options are refused by name before any file is made") {
    const std::string folder = fresh_folder("refused");
    struct Case {
        const char* name;
        VideoOptions options;
        const char* message;
    };
    VideoOptions odd = small(321, 240);
    VideoOptions odd_height = small(320, 241);
    VideoOptions too_wide = small(7682, 720);
    VideoOptions too_tall = small(4400, 4400);
    VideoOptions slow = small(320, 240, 0.5);
    VideoOptions fast = small(320, 240, 121.0);
    VideoOptions fast_gif = small(320, 240, 60.0);
    VideoOptions crf = small();
    crf.crf = 52;
    VideoOptions transparent = small();
    transparent.transparent = true;
    const std::vector<Case> cases = {
        {"/talk.avi", small(), "unknown extension \".avi\"; expected .mp4"},
        {"/talk", small(), "no extension"},
        {"/talk.mp4", odd, "width_px: a size of 321x240: H.264 in .mp4 needs an even width and height"},
        {"/talk.webm", odd_height, "height_px: a size of 320x241: VP9 in .webm needs an even width and height"},
        {"/talk.mp4", too_wide, "over the largest, 7680x4320"},
        {"/talk.png", too_tall, "over the largest, 7680x4320"},
        {"/talk.mp4", slow, "fps: expected 1..120 frames per second, found 0.5"},
        {"/talk.mp4", fast, "fps: expected 1..120 frames per second, found 121"},
        {"/talk.gif", fast_gif, "fps: expected 1..50 frames per second for .gif"},
        {"/talk.gif", too_wide, "over the largest, 7680x4320"},
        {"/talk.mp4", crf, "crf: expected 0..51"},
        {"/talk.mp4", transparent, "transparent: H.264 in .mp4 has no alpha channel"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.name);
        CAPTURE(c.message);
        CHECK_THROWS_WITH_AS(VideoWriter(folder + c.name, c.options), doctest::Contains(c.message),
                             talkface::InvalidArgument);
        CHECK_THROWS_AS(talkface::check_video_options(folder + c.name, c.options), talkface::InvalidArgument);
    }
    CHECK(std::filesystem::is_empty(folder));
    // 8K portrait is within the limit, and WebP and GIF take odd sides.
    CHECK_NOTHROW(talkface::check_video_options("a.mp4", small(4320, 7680)));
    CHECK_NOTHROW(talkface::check_video_options("a.webp", small(321, 241)));
    CHECK_NOTHROW(talkface::check_video_options("a.gif", small(321, 241, 50.0)));
}

TEST_CASE("frames and sound in the wrong order are refused") {
    const std::string folder = fresh_folder("order");
    const std::vector<float> samples = speech_like(16000, 0.2);
    VideoWriter writer(folder + "/a.mp4", small());
    CHECK_THROWS_WITH_AS(writer.finish(), doctest::Contains("no frame was written"), talkface::InvalidArgument);
    CHECK_THROWS_WITH_AS(writer.write_frame(nullptr, 1280), doctest::Contains("rgba"), talkface::InvalidArgument);
    const std::vector<std::uint8_t> frame = talkface_test::test_pattern(0, 320, 240);
    CHECK_THROWS_WITH_AS(writer.write_frame(frame.data(), 320), doctest::Contains("stride_bytes: expected at least"),
                         talkface::InvalidArgument);
    writer.write_frame(frame.data(), 320 * 4);
    CHECK_THROWS_WITH_AS(writer.add_audio({samples.data(), samples.size(), 1, 16000}),
                         doctest::Contains("before the first frame"), talkface::InvalidArgument);
    writer.finish();
    CHECK_THROWS_AS(writer.finish(), talkface::InvalidArgument);
}

TEST_CASE("a missing audio file is a FileError naming it") {
    const std::string folder = fresh_folder("no_audio");
    VideoWriter writer(folder + "/a.mp4", small());
    CHECK_THROWS_WITH_AS(writer.add_audio_file(folder + "/missing.wav"), doctest::Contains("missing.wav"),
                         talkface::FileError);
}

}  // TEST_SUITE
