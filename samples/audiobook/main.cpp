// Chapter 7.3: an audio book page. The title, the text with the sentence being spoken highlighted,
// links under it, and the talking face beside them reading the bundled speech.
//
//   audiobook OUT.html
#include <exception>
#include <iostream>
#include <string>

#include <talkface/talkface.hpp>

namespace {

const std::string kSpeechFolder = TALKFACE_SAMPLE_SPEECH_DIR;

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: audiobook OUT.html\n";
        return 2;
    }
    try {
        const talkface::FaceModel face = talkface::FaceModel::default_face();
        const std::string audio = kSpeechFolder + "/demo.ogg";
        const talkface::Timeline timeline =
            talkface::SpeechAligner().align_file(audio, talkface::load_transcript(kSpeechFolder + "/demo.txt"));
        const talkface::ExpressionSimulator simulator(timeline, 3);
        const talkface::Animation animation = talkface::animate(face, timeline, simulator);

        talkface::WebPageOptions page;
        page.app = talkface::WebPageApp::audiobook;
        page.title = "第一課：公園散步";
        page.links = {{"下一課", "lesson-2.html"}, {"talkface", "https://example.org/talkface"}};
        talkface::write_web_page(argv[1], talkface::SvgAnimator(face), animation, timeline, audio, page);
        std::cout << "wrote " << argv[1] << ": " << timeline.sentences.size() << " sentences, "
                  << animation.frames.size() << " frames\n";
    } catch (const std::exception& error) {
        std::cerr << "audiobook: " << talkface::full_message(error) << '\n';
        return 1;
    }
    return 0;
}
