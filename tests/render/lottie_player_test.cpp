// The Lottie document as a player draws it: rlottie (Debian's librlottie, the renderer of Telegram
// and of many Android apps, standing in for the phone players here) loads the document and renders
// its frames; the mouth opens at a vowel and rests in a pause, and a frame matches the raster
// renderer's picture of the same state.
#include <doctest/doctest.h>
#include <rlottie.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/json.hpp"
#include "talkface/animation.hpp"
#include "talkface/expression_simulator.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/frame_renderer.hpp"
#include "talkface/svg_animator.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

struct Picture {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // 3 bytes a pixel
    int at(int x, int y, int channel) const { return rgb[3 * (static_cast<std::size_t>(y) * width + x) + channel]; }
};

Picture render_with_rlottie(rlottie::Animation& player, std::size_t frame, int width, int height) {
    std::vector<std::uint32_t> buffer(static_cast<std::size_t>(width) * height);
    player.renderSync(frame, rlottie::Surface(buffer.data(), width, height, 4 * static_cast<std::size_t>(width)));
    Picture picture{width, height, {}};
    for (const std::uint32_t pixel : buffer) {
        // ARGB32, premultiplied; the background is opaque, so alpha is 255.
        picture.rgb.push_back(static_cast<std::uint8_t>(pixel >> 16));
        picture.rgb.push_back(static_cast<std::uint8_t>(pixel >> 8));
        picture.rgb.push_back(static_cast<std::uint8_t>(pixel));
    }
    return picture;
}

Picture render_with_cairo(FrameRenderer& renderer, const FaceState& state) {
    const std::vector<std::uint8_t> rgba = renderer.render_frame_rgba(state);
    Picture picture{renderer.width_px(), renderer.height_px(), {}};
    for (std::size_t k = 0; k < rgba.size(); k += 4) picture.rgb.insert(picture.rgb.end(), {rgba[k], rgba[k + 1], rgba[k + 2]});
    return picture;
}

// Mean absolute difference per channel inside [x0, x1) x [y0, y1).
double mean_difference(const Picture& a, const Picture& b, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    std::size_t count = 0;
    for (int y = std::max(0, y0); y < std::min(a.height, y1); ++y) {
        for (int x = std::max(0, x0); x < std::min(a.width, x1); ++x) {
            for (int c = 0; c < 3; ++c) sum += std::abs(a.at(x, y, c) - b.at(x, y, c));
            count += 3;
        }
    }
    return count == 0 ? 0.0 : sum / static_cast<double>(count);
}

}  // namespace

TEST_CASE("rlottie plays the Lottie document: the mouth opens at a vowel, and a frame is the raster renderer's") {
    Timeline timeline = read_transcript("八。");
    timeline.syllables[0].start_s = 0.4;
    timeline.syllables[0].end_s = 0.9;
    timeline.sentences[0].start_s = 0.4;
    timeline.sentences[0].end_s = 0.9;
    timeline.duration_s = 1.4;
    const FaceModel face = FaceModel::default_face();
    const Animation animation = animate(face, timeline, ExpressionSimulator(timeline, 2));
    const SvgAnimator animator(face);
    const std::string json = animator.render_animation_lottie(animation);

    const std::unique_ptr<rlottie::Animation> player = rlottie::Animation::loadFromData(json, "talkface", "", false);
    REQUIRE(player != nullptr);
    std::size_t width = 0, height = 0;
    player->size(width, height);
    CHECK(player->totalFrame() == animation.frames.size());
    CHECK(player->frameRate() == doctest::Approx(animation.fps));

    // Where the canvas starts in the face's image pixels and the mouth there.
    talkface::detail::JsonReader reader(json, "<lottie>");
    const talkface::detail::JsonValue document = reader.read_document();
    // The background is the bottom layer; its anchor is the canvas's corner.
    const talkface::detail::JsonValue& anchor = *document.find("layers")->items.back().find("ks")->find("a")->find("k");
    const double origin_x = anchor.items[0].number, origin_y = anchor.items[1].number;
    std::size_t vowel = 0;
    for (const MouthKeyFrame& key : animation.mouth_key_frames) {
        if (key.shape == MouthShape::a) vowel = static_cast<std::size_t>(std::lround(key.time_s * animation.fps));
    }
    REQUIRE(vowel > 0);
    const ProjectedFace open = project_face(face, animation.frames[vowel]);
    const int mouth_x0 = static_cast<int>(open.point("8.4").x - origin_x) - 4;
    const int mouth_x1 = static_cast<int>(open.point("8.3").x - origin_x) + 4;
    const int mouth_y0 = static_cast<int>(open.point("8.1").y - origin_y) - 4;
    const int mouth_y1 = static_cast<int>(open.point("2.1").y - origin_y) + 4;
    const int w = static_cast<int>(width), h = static_cast<int>(height);
    const Picture at_vowel = render_with_rlottie(*player, vowel, w, h);
    const Picture in_pause = render_with_rlottie(*player, 0, w, h);
    const double mouth_change = mean_difference(at_vowel, in_pause, mouth_x0, mouth_y0, mouth_x1, mouth_y1);
    MESSAGE("mouth region, vowel against pause: mean difference " << mouth_change << " per channel");
    CHECK(mouth_change > 20.0);

    // The same state drawn by cairo on the same canvas (the face layout at the canvas's size).
    FrameOptions options;
    options.width_px = w;
    options.height_px = h;
    options.layout = FrameLayout::face;
    options.background = SvgOptions{}.background;
    FrameRenderer renderer(face, options);
    for (const std::size_t frame : {std::size_t{0}, vowel}) {
        const Picture cairo = render_with_cairo(renderer, animation.frames[frame]);
        const Picture lottie = frame == 0 ? in_pause : at_vowel;
        const double whole = mean_difference(lottie, cairo, 0, 0, w, h);
        const double mouth = mean_difference(lottie, cairo, mouth_x0, mouth_y0, mouth_x1, mouth_y1);
        MESSAGE("frame " << frame << ", rlottie against cairo: mean difference " << whole << " (mouth " << mouth
                         << ") per channel");
        // Antialiasing and the key frames' 0.3 px: a shape out of place by a pixel would show
        // several times this over the mouth.
        CHECK(whole < 1.5);
        CHECK(mouth < 6.0);
    }
}
