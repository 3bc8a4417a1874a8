// Chapter 7.2: a virtual announcer. The talking face stands on a stage in front of a background
// (a colour, or an image file), with its clothes, placed and scaled by where its neck O stands and
// how far apart its eyes are (d), and reads the bundled speech.
//
//   announcer OUT.html [BACKGROUND]     (BACKGROUND: #rrggbb or an image file; default #1d3b5c)
#include <exception>
#include <iostream>
#include <string>

#include <talkface/talkface.hpp>

namespace {

// The bundled speech (samples/speech/), found through the source tree this sample was built from.
const std::string kSpeechFolder = TALKFACE_SAMPLE_SPEECH_DIR;

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::cerr << "usage: announcer OUT.html [BACKGROUND]\n";
        return 2;
    }
    try {
        const talkface::FaceModel face = talkface::FaceModel::default_face();
        const std::string audio = kSpeechFolder + "/demo.ogg";
        const talkface::Timeline timeline =
            talkface::SpeechAligner().align_file(audio, talkface::load_transcript(kSpeechFolder + "/demo.txt"));
        // An announcer turns and nods faster than a person at ease (thesis Table 4.12).
        const talkface::ExpressionSimulator simulator(timeline, 7, talkface::ExpressionStyle::announcer());
        const talkface::Animation animation = talkface::animate(face, timeline, simulator);

        talkface::SvgOptions look;
        look.clothes = talkface::Rgb{0x3a, 0x3a, 0x48};  // a dark suit; the stage replaces the face's background

        talkface::WebPageOptions page;
        page.app = talkface::WebPageApp::announcer;
        page.title = "晚間新聞";
        page.stage_width_px = 960;
        page.stage_height_px = 540;
        const std::string background = argc == 3 ? argv[2] : "#1d3b5c";
        if (background.front() == '#') {
            page.stage_colour = talkface::rgb_from_hex(background, "BACKGROUND");
        } else {
            page.background_image_path = background;
        }
        // The neck right of the caption, the shoulders on the stage's bottom edge; eyes 60 px apart.
        page.face_origin_px = talkface::Point2{720.0, 426.0};
        page.face_d_px = 60.0;
        talkface::write_web_page(argv[1], talkface::SvgAnimator(face, look), animation, timeline, audio, page);
        std::cout << "wrote " << argv[1] << ": " << animation.frames.size() << " frames, "
                  << timeline.sentences.size() << " sentences\n";
    } catch (const std::exception& error) {
        std::cerr << "announcer: " << talkface::full_message(error) << '\n';
        return 1;
    }
    return 0;
}
