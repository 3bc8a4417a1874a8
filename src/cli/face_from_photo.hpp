// `talkface face-from-photo`'s two halves. The command (face_from_photo_command.cpp) parses its
// options; the work, which needs the photo stage (libtalkface_photo: OpenCV, dlib, libpng,
// libjpeg), is a module of its own (face_from_photo_module.cpp), opened with dlopen() only when the
// command runs: linked into the command, the photo stage cost every `talkface` start some 50 M
// instructions of dynamic linking, a quarter of a `talkface syllables` (bench/README.md, "Session 14").
#ifndef TALKFACE_CLI_FACE_FROM_PHOTO_HPP
#define TALKFACE_CLI_FACE_FROM_PHOTO_HPP

#include <string>

#include <talkface/face_from_photo.hpp>

namespace talkface_cli {

struct FaceFromPhotoOptions {
    std::string photo_path;
    std::string output_path;
    std::string overlay_path;
    std::string locator = "automatic";
    int face_index = -1;
    std::string cascade_dir;
    std::string dlib_model_path;
    int min_face_width_px = talkface::PhotoOptions{}.min_face_width_px;
    bool quiet = false;
};

}  // namespace talkface_cli

// The module's one entry point, found by this name: writes the face (and the overlay), lists the
// features on stderr. Throws talkface's errors as the library does; the command reports them.
extern "C" void talkface_cli_face_from_photo(const talkface_cli::FaceFromPhotoOptions& options);

#endif
