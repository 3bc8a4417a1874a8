// Background pictures read through FFmpeg (src/video/image_decoder).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "talkface/errors.hpp"
#include "talkface/video_writer.hpp"
#include "test_pattern.hpp"
#include "video/image_decoder.hpp"

namespace {

const std::string kOutputDir = TALKFACE_TEST_OUTPUT_DIR;

}  // namespace

TEST_SUITE("image decoder") {

TEST_CASE("a PNG comes back as the RGBA it was made of") {
    const std::string folder = kOutputDir + "/image_decoder";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    talkface::VideoOptions options;
    options.width_px = 45;
    options.height_px = 31;
    options.transparent = true;
    const std::vector<std::uint8_t> pixels = talkface_test::test_pattern(2, 45, 31, true);
    {
        talkface::VideoWriter writer(folder + "/still.png", options);
        writer.write_frame(pixels.data(), 45 * 4);
        writer.finish();
    }
    const talkface::detail::RgbaImage image = talkface::detail::decode_image_file(folder + "/still-000000.png");
    CHECK(image.width == 45);
    CHECK(image.height == 31);
    CHECK(image.pixels == pixels);
}

TEST_CASE("a file that is not a picture is a FileError naming it") {
    const std::string path = kOutputDir + "/image_decoder_not_a_picture.png";
    { std::ofstream(path) << "this is text, not a picture"; }
    CHECK_THROWS_WITH_AS(talkface::detail::decode_image_file(path), doctest::Contains("not_a_picture.png: "),
                         talkface::FileError);
    CHECK_THROWS_WITH_AS(talkface::detail::decode_image_file(kOutputDir + "/no_such_picture.jpg"),
                         doctest::Contains("no_such_picture.jpg: cannot open the image"), talkface::FileError);
}

}  // TEST_SUITE
