// The work of `talkface face-from-photo` (SPEC step 1, thesis 2.2), the command's module that links
// the photo stage (face_from_photo.hpp says why): a face file from a frontal photo, the confidence
// of every located feature on stderr and, on request, the photo with its points drawn.
#include <iomanip>
#include <iostream>

#include <talkface/face_from_photo.hpp>
#include <talkface/talkface.hpp>

#include "face_from_photo.hpp"

extern "C" __attribute__((visibility("default"))) void talkface_cli_face_from_photo(
    const talkface_cli::FaceFromPhotoOptions& options) {
    talkface::PhotoOptions photo_options;
    photo_options.locator = talkface::photo_locator_from_name(options.locator);
    photo_options.face_index = options.face_index;
    photo_options.cascade_dir = options.cascade_dir;
    photo_options.dlib_model_path = options.dlib_model_path;
    photo_options.min_face_width_px = options.min_face_width_px;
    const talkface::PhotoFaceResult result =
        talkface::face_from_photo_file(options.photo_path, photo_options);
    // The overlay is written before the face, and both only after extraction has succeeded.
    if (!options.overlay_path.empty())
        talkface::write_photo_overlay(options.photo_path, result, options.overlay_path);
    if (options.output_path == "-") {
        std::cout << result.face.to_xml() << std::flush;
    } else {
        result.face.save(options.output_path);
    }
    if (options.quiet) return;
    std::cerr << "locator: " << talkface::photo_locator_name(result.locator_used)
              << ", faces found: " << result.faces_found << ", d = " << std::fixed << std::setprecision(1)
              << result.face.fapu("d") << " px\n";
    for (const talkface::PhotoFeature& feature : result.features) {
        std::cerr << "  " << std::left << std::setw(13) << feature.name << std::right << std::setprecision(2)
                  << std::setw(5) << feature.confidence << "  " << std::left << std::setw(8) << feature.source
                  << (feature.from_prior ? "not found: drawn from the default face's proportions" : "")
                  << std::right << "\n";
    }
}
