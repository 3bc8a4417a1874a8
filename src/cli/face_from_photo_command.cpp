// `talkface face-from-photo`: the options, and the module that does the work (face_from_photo.hpp),
// opened when the command runs.
#include <dlfcn.h>

#include <filesystem>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <talkface/errors.hpp>

#include "commands.hpp"
#include "face_from_photo.hpp"

namespace talkface_cli {

namespace {

// The module's path: where CMake puts it, relative to this executable, in the build tree as in an
// install (src/cli/CMakeLists.txt).
std::filesystem::path module_path() {
    return std::filesystem::canonical("/proc/self/exe").parent_path() / TALKFACE_CLI_PHOTO_MODULE;
}

// The module's entry point; the module stays loaded. \throws talkface::FileError naming the module
// if it is missing or a library it needs (the photo stage's) cannot be loaded, with the packages.
decltype(&talkface_cli_face_from_photo) load_face_from_photo() {
    const std::string path = module_path().lexically_normal().string();
    if (!std::filesystem::exists(path)) {
        throw talkface::FileError(path, "face-from-photo's module is missing; install talkface whole (cmake --install "
                                        "puts it in LIBDIR/talkface/, beside the libraries)");
    }
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    void* entry = module != nullptr ? dlsym(module, "talkface_cli_face_from_photo") : nullptr;
    if (entry == nullptr) {
        const char* reason = dlerror();
        throw talkface::FileError(
            path,
            "face-from-photo needs the photo stage, which could not be loaded (" +
                std::string(reason != nullptr ? reason : "no entry point") +
                "); install the libraries it links (Debian 12: libopencv-objdetect406, libopencv-imgproc406, "
                "libpng16-16, libjpeg62-turbo and, built with dlib, libdlib19.1)");
    }
    return reinterpret_cast<decltype(&talkface_cli_face_from_photo)>(entry);
}

}  // namespace

void setup_face_from_photo_command(CLI::App& app) {
    auto options = std::make_shared<FaceFromPhotoOptions>();
    CLI::App* command =
        app.add_subcommand("face-from-photo", "Make a face file from a frontal photo of a neutral face");
    command->add_option("photo", options->photo_path, "Photo: PNG or JPEG")
        ->required()
        ->check(CLI::ExistingFile);
    command
        ->add_option("-o,--output", options->output_path,
                     "Output face file (docs/face-format.md); - writes to stdout")
        ->required();
    command->add_option("--debug", options->overlay_path,
                        "Also write the photo with the extracted points drawn (PNG)");
    command
        ->add_option("--locator", options->locator,
                     "thesis (OpenCV only), dlib (68-point model) or automatic (dlib where installed)")
        ->check(CLI::IsMember({"thesis", "dlib", "automatic"}))
        ->capture_default_str();
    command
        ->add_option("--face-index", options->face_index,
                     "Which face, 0 = leftmost, when the photo shows several")
        ->check(CLI::NonNegativeNumber);
    command
        ->add_option("--cascades", options->cascade_dir,
                     "Folder with OpenCV's Haar cascades (default: opencv-data's)")
        ->check(CLI::ExistingDirectory);
    command
        ->add_option("--dlib-model", options->dlib_model_path,
                     "dlib's shape_predictor_68_face_landmarks.dat (default: libdlib-data's)")
        ->check(CLI::ExistingFile);
    command
        ->add_option("--min-face-width", options->min_face_width_px,
                     "The smallest face accepted, its width in the photo's pixels (at least 16)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_flag("-q,--quiet", options->quiet, "Do not list the located features on stderr");
    command->callback([options] { load_face_from_photo()(*options); });
}

}  // namespace talkface_cli
