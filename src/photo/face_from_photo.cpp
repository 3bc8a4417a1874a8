// Face from a photo (SPEC step 1; thesis 2.2, Chen and Tsai's three steps): the public entry points.
//   1. face and eye pair            face_detector.cpp
//   2. background / hair / face     region_thresholding.cpp
//   3. feature regions and points   feature_locator_thesis.cpp or feature_locator_dlib.cpp
//   4. the face model               face_fitting.cpp
#include "talkface/face_from_photo.hpp"

#include <cmath>
#include <fstream>

#include <opencv2/imgproc.hpp>

#include "common/atomic_file.hpp"
#include "photo/photo_internal.hpp"
#include "talkface/errors.hpp"

namespace talkface::photo {

void fail(const std::string& source, const std::string& problem) {
    throw InvalidArgument(source, problem);
}

cv::Mat to_bgr(const ImageView& view, const std::string& source) {
    int channels = 0;
    int conversion = -1;
    switch (view.format) {
        case PixelFormat::gray8: channels = 1; conversion = cv::COLOR_GRAY2BGR; break;
        case PixelFormat::rgb8: channels = 3; conversion = cv::COLOR_RGB2BGR; break;
        case PixelFormat::bgr8: channels = 3; break;
        case PixelFormat::rgba8: channels = 4; conversion = cv::COLOR_RGBA2BGR; break;
        default: fail(source, "unknown PixelFormat " + std::to_string(static_cast<int>(view.format)));
    }
    if (view.pixels == nullptr) fail(source, "the image view has no pixels (pixels is null)");
    if (view.width <= 0 || view.height <= 0) {
        fail(source, "the image is " + std::to_string(view.width) + " x " + std::to_string(view.height) +
                         " pixels; both sides must be positive");
    }
    if (view.stride_bytes < view.width * channels) {
        fail(source, "stride_bytes " + std::to_string(view.stride_bytes) + " is less than width x channels = " +
                         std::to_string(view.width * channels));
    }
    const cv::Mat wrapped(view.height, view.width, CV_8UC(channels), const_cast<std::uint8_t*>(view.pixels),
                          static_cast<std::size_t>(view.stride_bytes));
    cv::Mat bgr;
    if (conversion < 0) {
        bgr = wrapped.clone();
    } else {
        cv::cvtColor(wrapped, bgr, conversion);
    }
    return bgr;
}

cv::Point2d apply(const cv::Matx23d& a, const cv::Point2d& q) {
    return {a(0, 0) * q.x + a(0, 1) * q.y + a(0, 2), a(1, 0) * q.x + a(1, 1) * q.y + a(1, 2)};
}

FaceFrame make_frame(const cv::Mat& bgr, const cv::Point2d& eye_left, const cv::Point2d& eye_right) {
    FaceFrame frame;
    const cv::Point2d delta = eye_right - eye_left;
    frame.photo_px_per_d = std::hypot(delta.x, delta.y);
    const double scale = kFrameD / frame.photo_px_per_d;
    const double angle = std::atan2(delta.y, delta.x);
    const double c = std::cos(angle) * scale, s = std::sin(angle) * scale;
    const cv::Point2d mid = 0.5 * (eye_left + eye_right);
    // photo -> frame: rotate by -angle, scale, move the eye midpoint to kFrameEyeMid.
    frame.to_frame = cv::Matx23d(c, s, kFrameEyeMid.x - (c * mid.x + s * mid.y),
                                 -s, c, kFrameEyeMid.y - (-s * mid.x + c * mid.y));
    cv::invertAffineTransform(frame.to_frame, frame.to_photo);
    const int interpolation = scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR;
    cv::warpAffine(bgr, frame.bgr, frame.to_frame, kFrameSize, interpolation, cv::BORDER_REPLICATE);
    cv::warpAffine(cv::Mat(bgr.size(), CV_8U, cv::Scalar(255)), frame.valid, frame.to_frame, kFrameSize,
                   cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::cvtColor(frame.bgr, frame.gray, cv::COLOR_BGR2GRAY);
    cv::cvtColor(frame.bgr, frame.lab, cv::COLOR_BGR2Lab);
    return frame;
}

void Located::add_feature(const std::string& name, double confidence, const std::string& source) {
    for (PhotoFeature& existing : features) {
        if (existing.name == name) {
            existing = PhotoFeature{name, confidence, false, source};
            return;
        }
    }
    features.push_back(PhotoFeature{name, confidence, false, source});
}

const PhotoFeature* Located::feature(const std::string& name) const {
    for (const PhotoFeature& f : features) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

std::string default_dlib_model_path() {
    for (const char* path : {"/usr/share/dlib/shape_predictor_68_face_landmarks.dat"}) {
        if (std::ifstream(path).good()) return path;
    }
    return "";
}

}  // namespace talkface::photo

namespace talkface {
inline namespace v0 {

namespace {

PhotoLocator choose_locator(const PhotoOptions& options, std::string& model_path) {
    model_path = options.dlib_model_path.empty() ? photo::default_dlib_model_path() : options.dlib_model_path;
    switch (options.locator) {
        case PhotoLocator::thesis:
            return PhotoLocator::thesis;
        case PhotoLocator::dlib:
            if (!has_dlib_locator()) {
                throw InvalidArgument("locator", "this talkface was built without dlib (TALKFACE_WITH_DLIB=OFF); "
                                                 "use the thesis locator or rebuild with libdlib-dev installed");
            }
            if (model_path.empty() || !std::ifstream(model_path).good()) {
                throw FileError(model_path.empty() ? "/usr/share/dlib/shape_predictor_68_face_landmarks.dat" : model_path,
                                "dlib's 68-point shape predictor is missing; install Debian's libdlib-data or "
                                "pass PhotoOptions::dlib_model_path");
            }
            return PhotoLocator::dlib;
        case PhotoLocator::automatic:
            return has_dlib_locator() && !model_path.empty() && std::ifstream(model_path).good() ? PhotoLocator::dlib
                                                                                              : PhotoLocator::thesis;
    }
    throw InvalidArgument("locator", "expected thesis, dlib or automatic, found " +
                                         std::to_string(static_cast<int>(options.locator)));
}

// A turned head shows one cheek wider than the other beside the eye pair.
void check_cheeks_frontal(const photo::Regions& regions, const std::string& source) {
    if (regions.skin_confidence < photo::kUsableConfidence) return;
    const int y = static_cast<int>(photo::in_d(0, 0.45).y);
    int reach[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
        const int sign = side == 0 ? -1 : 1;
        for (int step = 0; step < regions.skin.cols / 2; ++step) {
            const int x = static_cast<int>(photo::kFrameEyeMid.x) + sign * step;
            if (x < 0 || x >= regions.skin.cols || !regions.skin.at<std::uint8_t>(y, x)) break;
            reach[side] = step;
        }
    }
    const double total = reach[0] + reach[1];
    if (total > 0.0 && std::abs(reach[0] - reach[1]) / total > 0.3) {
        photo::fail(source, "face not frontal enough: the cheek beside the image-" +
                                std::string(reach[0] < reach[1] ? "left" : "right") +
                                " eye shows much narrower than the other (the head is turned); use a photo "
                                "that looks straight into the camera");
    }
}

// Steps 1-4 on the photo as 8-bit BGR; source_name names it in errors.
PhotoFaceResult extract_face(const cv::Mat& bgr, const PhotoOptions& options) {
    const std::string& source = options.source_name;
    if (options.face_index < -1) {
        throw InvalidArgument("face_index", "expected -1 (one face only) or a face's index, found " +
                                                std::to_string(options.face_index));
    }
    if (options.min_face_width_px < 16) {
        throw InvalidArgument("min_face_width_px", "expected at least 16, found " + std::to_string(options.min_face_width_px));
    }
    std::string model_path;
    const PhotoLocator locator = choose_locator(options, model_path);
    cv::Mat gray;
    cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);

    const photo::DetectedFace detected = photo::detect_face(bgr, gray, options, source);
    photo::Located located;
    photo::EyePair eyes;
#ifdef TALKFACE_WITH_DLIB
    photo::DlibShape shape;
#endif
    if (locator == PhotoLocator::dlib) {
#ifdef TALKFACE_WITH_DLIB
        shape = photo::locate_landmarks_dlib(bgr, detected.box, model_path);
        cv::Point2d centre[2];
        for (int side = 0; side < 2; ++side) {
            for (int k = 0; k < 6; ++k) centre[side] += shape.points[static_cast<std::size_t>(36 + 6 * side + k)] / 6.0;
        }
        eyes = photo::EyePair{centre[0], centre[1], shape.confidence};
#endif
    } else {
        eyes = photo::find_eye_pair(gray, detected.box, options);
    }
    photo::check_frontal(eyes, detected.box, source);
    photo::FaceFrame frame = photo::make_frame(bgr, eyes.left, eyes.right);
    if (locator == PhotoLocator::thesis) {
        // Thesis 2.2 finds the pair from regions; the iris centres inside them fix the frame.
        // Twice, the second time in a narrower window: the first pass may start from a brow or a
        // lash line beside the iris, and dark outer corners pull a wide window's centre outwards.
        double refined_confidence = 0.0;
        for (int pass = 0; pass < 2; ++pass) {
            const photo::EyePair refined = photo::refine_eye_centres(frame, pass == 0 ? 0.28 : 0.17);
            const double moved = std::max(cv::norm(refined.left - photo::in_d(-0.5, 0)),
                                          cv::norm(refined.right - photo::in_d(0.5, 0)));
            refined_confidence = refined.confidence;
            if (refined.confidence < photo::kUsableConfidence || moved > 0.2 * photo::kFrameD) break;
            eyes.left = photo::apply(frame.to_photo, refined.left);
            eyes.right = photo::apply(frame.to_photo, refined.right);
            frame = photo::make_frame(bgr, eyes.left, eyes.right);
        }
        eyes.confidence = 0.5 * (eyes.confidence + refined_confidence);
    }
    located.add_feature("face", detected.confidence, "haar");
    located.add_feature("eye_pair", eyes.confidence, locator == PhotoLocator::dlib ? "dlib" : "thesis");

    const photo::Regions regions = photo::separate_regions(frame);
    check_cheeks_frontal(regions, source);
    if (locator == PhotoLocator::dlib) {
#ifdef TALKFACE_WITH_DLIB
        photo::locate_features_dlib(shape, frame, located);
#endif
    } else {
        photo::locate_features_thesis(frame, regions, located);
    }

    PhotoFaceResult result;
    result.face = photo::fit_face(frame, regions, located, options.face_name);
    result.features = located.features;
    result.locator_used = locator;
    result.face_box = PhotoBox{detected.box.x, detected.box.y, detected.box.width, detected.box.height};
    result.faces_found = detected.faces_found;
    return result;
}

void write_overlay(cv::Mat bgr, const PhotoFaceResult& result, const std::string& output_png_path) {
    photo::draw_overlay(bgr, result);
    detail::write_file_atomically(output_png_path, photo::encode_png(bgr));
}

}  // namespace

const char* photo_locator_name(PhotoLocator locator) {
    switch (locator) {
        case PhotoLocator::thesis: return "thesis";
        case PhotoLocator::dlib: return "dlib";
        case PhotoLocator::automatic: return "automatic";
    }
    return "unknown";
}

PhotoLocator photo_locator_from_name(std::string_view name) {
    for (PhotoLocator locator : {PhotoLocator::thesis, PhotoLocator::dlib, PhotoLocator::automatic}) {
        if (name == photo_locator_name(locator)) return locator;
    }
    throw InvalidArgument("locator", "expected thesis, dlib or automatic, found \"" + std::string(name) + "\"");
}

bool has_dlib_locator() {
#ifdef TALKFACE_WITH_DLIB
    return true;
#else
    return false;
#endif
}

double PhotoFaceResult::confidence(std::string_view feature_name) const {
    for (const PhotoFeature& feature : features) {
        if (feature.name == feature_name) return feature.confidence;
    }
    throw InvalidArgument("feature_name", "no feature \"" + std::string(feature_name) +
                                              "\"; see PhotoFeature::name for the list");
}

PhotoFaceResult face_from_photo(const ImageView& view, const PhotoOptions& options) {
    return extract_face(photo::to_bgr(view, options.source_name), options);
}

PhotoFaceResult face_from_photo_file(const std::string& path, const PhotoOptions& options) {
    PhotoOptions named = options;
    named.source_name = path;
    return extract_face(photo::read_photo_file(path), named);
}

void write_photo_overlay(const ImageView& view, const PhotoFaceResult& result, const std::string& output_png_path) {
    write_overlay(photo::to_bgr(view, "photo"), result, output_png_path);
}

void write_photo_overlay(const std::string& photo_path, const PhotoFaceResult& result, const std::string& output_png_path) {
    write_overlay(photo::read_photo_file(photo_path), result, output_png_path);
}

}  // namespace v0
}  // namespace talkface
