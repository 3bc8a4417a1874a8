// talkface: a FaceModel from a frontal photo of a neutral face (SPEC pipeline step 1; thesis 2.2,
// Chen and Tsai's method).
//
//   talkface::PhotoFaceResult result = talkface::face_from_photo_file("me.jpg");
//   for (const auto& feature : result.features)                 // nothing is guessed silently
//       if (feature.from_prior) std::cerr << feature.name << " was not found; drawn from priors\n";
//   result.face.save("me.xml");
//   talkface::write_photo_overlay("me.jpg", result, "me-points.png");
//
// Two locators find the features: the thesis's own (Haar face and eye candidates, hierarchical
// bi-level thresholding into background, hair and face, knowledge-based edge detection per feature),
// and, where talkface was built with dlib and libdlib-data is installed, dlib's 68-point shape
// predictor for eyes, brows, nose, mouth and jaw (hair and forehead still come from the regions).
// Thread safety: every function here may be called from several threads at once.
#ifndef TALKFACE_FACE_FROM_PHOTO_HPP
#define TALKFACE_FACE_FROM_PHOTO_HPP

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "talkface/photo_export.h"
#include "talkface/face_model.hpp"
#include "talkface/types.hpp"

namespace talkface {
inline namespace v0 {

/// How the bytes of one pixel are laid out (8 bits per channel, sRGB).
enum class PixelFormat : int {
    gray8 = 0,  ///< one byte per pixel
    rgb8 = 1,   ///< R, G, B
    bgr8 = 2,   ///< B, G, R (OpenCV's order)
    rgba8 = 3,  ///< R, G, B, A; alpha is ignored
};

/// A photo the caller owns: a non-owning view (like OpenColorIO's PackedImageDesc). Row y starts at
/// pixels + y * stride_bytes; the pixels must stay valid for the duration of the call.
struct ImageView {
    const std::uint8_t* pixels = nullptr;  ///< first byte of the top row
    int width = 0;                         ///< pixels per row, > 0
    int height = 0;                        ///< rows, > 0
    int stride_bytes = 0;                  ///< bytes from one row to the next, >= width * channels
    PixelFormat format = PixelFormat::rgb8;
};

/// Which locator finds the eyes, brows, nose, mouth and jaw.
enum class PhotoLocator : int {
    thesis = 0,     ///< Chen and Tsai's knowledge-based edge detection, OpenCV only
    dlib = 1,       ///< dlib's 68-point shape predictor; throws if talkface was built without it
    automatic = 2,  ///< dlib where it is built in and its model is installed, else thesis
};

/// "thesis", "dlib" or "automatic".
TALKFACE_PHOTO_API const char* photo_locator_name(PhotoLocator locator);
/// Parses a name as photo_locator_name() writes it. \throws talkface::InvalidArgument listing them.
TALKFACE_PHOTO_API PhotoLocator photo_locator_from_name(std::string_view name);
/// Whether this build of talkface has the dlib locator (TALKFACE_WITH_DLIB).
TALKFACE_PHOTO_API bool has_dlib_locator();

/// How a photo is read.
struct PhotoOptions {
    PhotoLocator locator = PhotoLocator::automatic;
    /// Which face to use when the photo shows several, 0-based from the image left; -1 refuses a
    /// photo with more than one face (the error says how many there are).
    int face_index = -1;
    /// Folder with OpenCV's Haar cascades; empty: opencv-data's /usr/share/opencv4/haarcascades
    /// (or $TALKFACE_HAARCASCADES_DIR when set).
    std::string cascade_dir;
    /// dlib's shape_predictor_68_face_landmarks.dat; empty: libdlib-data's /usr/share/dlib copy.
    std::string dlib_model_path;
    /// The smallest face accepted, as its detected width in pixels; smaller faces throw.
    int min_face_width_px = 64;
    /// Stands for the photo in error messages ("photo.jpg: no face found").
    std::string source_name = "photo";
    /// The FaceModel's name().
    std::string face_name = "photo";
};

/// One located feature and how sure the locator is of it.
struct PhotoFeature {
    /// "face", "eye_pair", "left_eye", "right_eye", "left_brow", "right_brow", "nose", "mouth",
    /// "chin", "face_contour", "hairline", "hair", "ears", "skin_colour", "hair_colour", "lip_colour"
    /// ("left" = image left).
    std::string name;
    /// 0 (not found) .. 1 (certain): the contrast or agreement the locator measured.
    double confidence = 0.0;
    /// True when confidence was too low to use what was found and the points come from the default
    /// face's proportions in units of d instead.
    bool from_prior = false;
    /// Which locator placed it: "haar", "thesis", "dlib", "regions" or "prior".
    std::string source;
};

/// A rectangle in photo pixels.
struct PhotoBox {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};

/// What face_from_photo() found.
struct PhotoFaceResult {
    /// All 72 points, FAPUs and colours, in the photo's pixel coordinates (y down). It passes the
    /// checks of a loaded face file: save() and load() give it back unchanged.
    FaceModel face;
    std::vector<PhotoFeature> features;  ///< one entry per feature listed in PhotoFeature::name
    PhotoLocator locator_used = PhotoLocator::thesis;  ///< never automatic
    PhotoBox face_box;                   ///< the detected face
    int faces_found = 0;                 ///< faces detected in the photo
    /// The confidence of the named feature. \throws talkface::InvalidArgument for an unknown name.
    TALKFACE_PHOTO_API double confidence(std::string_view feature_name) const;
};

/// Extracts a face model from a frontal photo of a neutral face.
/// \throws talkface::InvalidArgument (parameter "photo", message starting with options.source_name)
///         when the view is malformed, or: no face found; several faces and face_index is -1 (the
///         message says how many and how to choose); face_index out of range; the face too small;
///         the photo or face too dark; the face not frontal enough (turned, tilted or a profile).
///         Also for PhotoLocator::dlib without dlib support, and for bad options.
/// \throws talkface::FileError if a Haar cascade or the dlib model cannot be found or read.
TALKFACE_PHOTO_API PhotoFaceResult face_from_photo(const ImageView& photo, const PhotoOptions& options = {});

/// Reads a PNG (any bit depth; transparency shown on white) or JPEG (RGB or greyscale, EXIF
/// orientation applied) of at most 100 megapixels and calls face_from_photo(); error messages name
/// the path (options.source_name is ignored).
/// \throws talkface::FileError naming the path and what is wrong if the file cannot be opened, is
///         empty, is not a PNG or JPEG (other formats are named), is broken or truncated, is a CMYK
///         JPEG, or is larger than 100 megapixels; otherwise as face_from_photo().
TALKFACE_PHOTO_API PhotoFaceResult face_from_photo_file(const std::string& path, const PhotoOptions& options = {});

/// The photo with the extracted points drawn on it (points coloured by feature, the hair polygon,
/// the face contour, weak features in red), written as a PNG through a temporary file and a rename.
/// \throws talkface::InvalidArgument for a malformed view; talkface::FileError if it cannot write.
TALKFACE_PHOTO_API void write_photo_overlay(const ImageView& photo, const PhotoFaceResult& result,
                                      const std::string& output_png_path);
/// As above, reading the photo (PNG or JPEG) from a file. \throws talkface::FileError if it cannot be
/// read, as face_from_photo_file() says.
TALKFACE_PHOTO_API void write_photo_overlay(const std::string& photo_path, const PhotoFaceResult& result,
                                      const std::string& output_png_path);

}  // namespace v0
}  // namespace talkface

#endif
