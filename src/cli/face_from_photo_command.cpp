// `talkface face-from-photo`: a face file from a frontal photo (SPEC step 1, thesis 2.2), with the
// confidence of every located feature on stderr and, on request, the photo with its points drawn.
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <talkface/face_from_photo.hpp>
#include <talkface/talkface.hpp>

#include "commands.hpp"

namespace talkface_cli {

namespace {

struct FaceFromPhotoOptions {
    std::string photo_path;
    std::string output_path;
    std::string overlay_path;
    std::string locator = "automatic";
    int face_index = -1;
    std::string cascade_dir;
    std::string dlib_model_path;
    bool quiet = false;
};

void run_face_from_photo(const FaceFromPhotoOptions& options) {
    talkface::PhotoOptions photo_options;
    photo_options.locator = talkface::photo_locator_from_name(options.locator);
    photo_options.face_index = options.face_index;
    photo_options.cascade_dir = options.cascade_dir;
    photo_options.dlib_model_path = options.dlib_model_path;
    const talkface::PhotoFaceResult result = talkface::face_from_photo_file(options.photo_path, photo_options);
    // The overlay is written before the face, and both only after extraction has succeeded.
    if (!options.overlay_path.empty()) talkface::write_photo_overlay(options.photo_path, result, options.overlay_path);
    if (options.output_path == "-") {
        std::cout << result.face.to_xml() << std::flush;
    } else {
        result.face.save(options.output_path);
    }
    if (options.quiet) return;
    std::cerr << "locator: " << talkface::photo_locator_name(result.locator_used) << ", faces found: " << result.faces_found
              << ", d = " << std::fixed << std::setprecision(1) << result.face.fapu("d") << " px\n";
    for (const talkface::PhotoFeature& feature : result.features) {
        std::cerr << "  " << std::left << std::setw(13) << feature.name << std::right << std::setprecision(2)
                  << std::setw(5) << feature.confidence << "  " << std::left << std::setw(8) << feature.source
                  << (feature.from_prior ? "not found: drawn from the default face's proportions" : "") << std::right
                  << "\n";
    }
}

}  // namespace

void setup_face_from_photo_command(CLI::App& app) {
    auto options = std::make_shared<FaceFromPhotoOptions>();
    CLI::App* command = app.add_subcommand("face-from-photo", "Make a face file from a frontal photo of a neutral face");
    command->add_option("photo", options->photo_path, "Photo: PNG or JPEG")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", options->output_path, "Output face file (docs/face-format.md); - writes to stdout")
        ->required();
    command->add_option("--debug", options->overlay_path, "Also write the photo with the extracted points drawn (PNG)");
    command->add_option("--locator", options->locator,
                        "thesis (OpenCV only), dlib (68-point model) or automatic (dlib where installed)")
        ->check(CLI::IsMember({"thesis", "dlib", "automatic"}))
        ->capture_default_str();
    command->add_option("--face-index", options->face_index, "Which face, 0 = leftmost, when the photo shows several")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--cascades", options->cascade_dir, "Folder with OpenCV's Haar cascades (default: opencv-data's)")
        ->check(CLI::ExistingDirectory);
    command->add_option("--dlib-model", options->dlib_model_path,
                        "dlib's shape_predictor_68_face_landmarks.dat (default: libdlib-data's)")
        ->check(CLI::ExistingFile);
    command->add_flag("-q,--quiet", options->quiet, "Do not list the located features on stderr");
    command->callback([options] { run_face_from_photo(*options); });
}

}  // namespace talkface_cli
