// Sample: a talking-face model from a photo (SPEC step 1, thesis 2.2). Extracts the face with the
// chosen locator, lists each feature's confidence, and writes the face file, the photo with its
// points, and the cartoon drawn from them.
//
//   face_from_photo PHOTO [OUTPUT_PREFIX] [thesis|dlib|automatic]
#include <iomanip>
#include <iostream>
#include <string>

#include <talkface/face_from_photo.hpp>
#include <talkface/talkface.hpp>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 4) {
        std::cerr << "usage: face_from_photo PHOTO [OUTPUT_PREFIX] [thesis|dlib|automatic]\n";
        return 2;
    }
    const std::string photo = argv[1];
    const std::string prefix = argc >= 3 ? argv[2] : "photo-face";
    try {
        talkface::PhotoOptions options;
        if (argc == 4) options.locator = talkface::photo_locator_from_name(argv[3]);
        const talkface::PhotoFaceResult result = talkface::face_from_photo_file(photo, options);
        std::cout << "locator " << talkface::photo_locator_name(result.locator_used) << ", d = " << std::fixed
                  << std::setprecision(1) << result.face.fapu("d") << " px\n";
        for (const talkface::PhotoFeature& feature : result.features) {
            std::cout << "  " << std::left << std::setw(13) << feature.name << std::right << std::setprecision(2)
                      << feature.confidence << (feature.from_prior ? "  (not found: default proportions)" : "")
                      << "\n";
        }
        result.face.save(prefix + ".xml");
        talkface::write_photo_overlay(photo, result, prefix + "-points.png");
        talkface::SvgAnimator(result.face).write_svg(prefix + "-cartoon.svg", talkface::FaceState{});
        std::cout << "wrote " << prefix << ".xml, " << prefix << "-points.png, " << prefix << "-cartoon.svg\n";
    } catch (const talkface::Error& error) {
        std::cerr << "face_from_photo: " << talkface::full_message(error) << "\n";
        return 1;
    }
    return 0;
}
