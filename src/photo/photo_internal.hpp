// Face from a photo (SPEC step 1, thesis 2.2): the pieces shared by the steps in this folder. Only
// src/photo/*.cpp include this header, so OpenCV's headers stay out of every other file.
#ifndef TALKFACE_FACE_PHOTO_PHOTO_INTERNAL_HPP
#define TALKFACE_FACE_PHOTO_PHOTO_INTERNAL_HPP

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "talkface/face_from_photo.hpp"
#include "talkface/face_model.hpp"

namespace talkface::photo {

// Throws InvalidArgument(source, problem), "<source>: <problem>": every photo error names the photo
// (its path, or PhotoOptions::source_name, "photo" by default) first, and only once.
[[noreturn]] void fail(const std::string& source, const std::string& problem);

// The caller's view copied into an 8-bit BGR image. Throws for a malformed view.
cv::Mat to_bgr(const ImageView& photo, const std::string& source);

// --- image_file.cpp -----------------------------------------------------------------------------

// The largest photo read from a file. A 24-megapixel camera's photo is 6000 x 4000; a larger one
// finds no better face and would make the decoder allocate gigabytes.
inline constexpr std::uint64_t kMaxPhotoPixels = 100'000'000;

// A PNG or JPEG file (EXIF orientation applied, transparency on white) as 8-bit BGR. Throws FileError
// naming the path and what is wrong: unreadable, empty, another format, broken or truncated, larger
// than kMaxPhotoPixels.
cv::Mat read_photo_file(const std::string& path);

// An 8-bit BGR image as the bytes of a PNG file.
std::string encode_png(const cv::Mat& bgr);

// --- face_detector.cpp ------------------------------------------------------------------------

struct DetectedFace {
    cv::Rect box;             // photo pixels
    int faces_found = 0;      // frontal faces in the photo
    double confidence = 0.0;  // how many detector windows agreed, 0..1
};

// The Haar frontal face the caller asked for. Throws (InvalidArgument, "photo") for no face, too
// many faces without face_index, a face too small, a photo or face too dark, a profile face.
DetectedFace detect_face(const cv::Mat& bgr, const cv::Mat& gray, const PhotoOptions& options,
                         const std::string& source);

struct EyePair {
    cv::Point2d left;   // image-left eye centre, photo pixels
    cv::Point2d right;  // image-right eye centre
    double confidence = 0.0;
};

// Thesis 2.2: candidate eye regions inside the face (dark blobs of a bi-level threshold and Haar eye
// windows), paired by rules on size and position and ranked by the symmetry of the two regions.
EyePair find_eye_pair(const cv::Mat& gray, const cv::Rect& face, const PhotoOptions& options);

// Throws unless the eye pair sits like a frontal, upright face's in its box.
void check_frontal(const EyePair& eyes, const cv::Rect& face, const std::string& source);

// --- the normalised face frame ------------------------------------------------------------------

// Every step after the eye pair works in a frame where the eyeball centres are horizontal, kFrameD
// pixels apart and centred at kFrameEyeMid, so the knowledge-based windows of thesis 2.2 are fixed
// rectangles in units of d whatever the photo's size or roll.
inline constexpr double kFrameD = 64.0;
inline const cv::Point2d kFrameEyeMid{192.0, 208.0};
inline const cv::Size kFrameSize{384, 448};  // 6 d wide; 3.25 d above the eyes, 3.75 d below

struct FaceFrame {
    cv::Mat bgr;               // CV_8UC3
    cv::Mat gray;              // CV_8U
    cv::Mat lab;               // CV_8UC3, OpenCV's 8-bit L*a*b*
    cv::Mat valid;             // CV_8U, 255 where the frame shows the photo (not outside it)
    cv::Matx23d to_frame;      // photo -> frame
    cv::Matx23d to_photo;      // frame -> photo
    double photo_px_per_d = 0; // d in photo pixels
};

FaceFrame make_frame(const cv::Mat& bgr, const cv::Point2d& eye_left, const cv::Point2d& eye_right);
cv::Point2d apply(const cv::Matx23d& affine, const cv::Point2d& point);
// Frame coordinates from offsets in units of d from the eye midpoint (x right, y down).
inline cv::Point2d in_d(double x_d, double y_d) {
    return {kFrameEyeMid.x + x_d * kFrameD, kFrameEyeMid.y + y_d * kFrameD};
}

// --- region_thresholding.cpp --------------------------------------------------------------------

// Thesis Figure 2.1: background, hair and face regions by hierarchical bi-level thresholding.
struct Regions {
    cv::Mat skin;        // CV_8U 0/255: the face's skin (one connected region through the nose)
    cv::Mat hair;        // CV_8U 0/255: hair touching the head
    cv::Mat background;  // CV_8U 0/255
    cv::Vec3b skin_bgr;  // median colours
    cv::Vec3b hair_bgr;
    double skin_confidence = 0.0;
    double hair_confidence = 0.0;
};

Regions separate_regions(const FaceFrame& frame);

// --- the locators --------------------------------------------------------------------------------

// What a locator found: model point ids -> frame coordinates, plus one PhotoFeature per feature.
struct Located {
    std::map<std::string, cv::Point2d> points;
    std::vector<PhotoFeature> features;
    cv::Vec3b lip_bgr{0x5a, 0x5a, 0xc8};
    cv::Vec3b brow_bgr{0x18, 0x20, 0x2e};
    cv::Vec3b iris_bgr{0x22, 0x32, 0x4a};
    bool has_lip_colour = false;
    bool has_brow_colour = false;
    bool has_iris_colour = false;

    void add_feature(const std::string& name, double confidence, const std::string& source);
    const PhotoFeature* feature(const std::string& name) const;
};

// A feature below this confidence is not used: its points come from the priors (face_fitting.cpp).
inline constexpr double kUsableConfidence = 0.35;

// feature_locator_thesis.cpp: eyes, brows, nose, mouth, chin by knowledge-based edge detection in
// windows placed from the eye pair (thesis 2.2).
void locate_features_thesis(const FaceFrame& frame, const Regions& regions, Located& located);

// Refines the eyeball centres: the darkest blob (the iris) within half_width_d of each eye's place
// in the frame. Frame coordinates.
EyePair refine_eye_centres(const FaceFrame& frame, double half_width_d);

#ifdef TALKFACE_WITH_DLIB
// feature_locator_dlib.cpp: dlib's 68 landmarks in the photo, the eye centres they imply.
struct DlibShape {
    std::vector<cv::Point2d> points;  // 68, photo pixels, iBUG 300-W order
    double confidence = 0.0;
};
DlibShape locate_landmarks_dlib(const cv::Mat& bgr, const cv::Rect& face, const std::string& model_path);
// Maps the 68 landmarks (photo pixels) onto the model's eye, brow, nose, mouth and jaw points.
void locate_features_dlib(const DlibShape& shape, const FaceFrame& frame, Located& located);
#endif
// Where libdlib-data puts the model, or "" when it is not installed.
std::string default_dlib_model_path();

// --- face_fitting.cpp ----------------------------------------------------------------------------

// All 72 points, the hair polygon, FAPUs and colours from what was located; weak features come from
// the default face's proportions in units of d. Marks those features from_prior.
FaceModel fit_face(const FaceFrame& frame, const Regions& regions, Located& located,
                   const std::string& face_name);

// --- debug_overlay.cpp ---------------------------------------------------------------------------

void draw_overlay(cv::Mat& bgr, const PhotoFaceResult& result);

}  // namespace talkface::photo

#endif
