// Face from a photo, step 3 (trained locator): dlib's 68-point shape predictor (Debian libdlib-data,
// trained on iBUG 300-W) places eyes, brows, nose, mouth and jaw; the hair, hairline and temples still
// come from the region separation (thesis Figure 2.1). Compiled only with TALKFACE_WITH_DLIB.
//
// The 68 points follow iBUG 300-W, numbered from the image left: jaw 0-16 (chin 8), brows 17-21 and
// 22-26, nose bridge 27-30, nose bottom 31-35 (tip 33), eyes 36-41 and 42-47 (outer corner, two upper
// lid points, inner corner, two lower lid points), outer lips 48-59 (corners 48, 54; top centre 51;
// bottom centre 57), inner lips 60-67 (upper middle 62, lower middle 66).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include <dlib/image_processing.h>
#include <dlib/image_processing/frontal_face_detector.h>
#include <opencv2/imgproc.hpp>

#include "photo/photo_internal.hpp"
#include "talkface/errors.hpp"

namespace talkface::photo {

namespace {

// The model is 95 MB and takes a second to read: read once per path, shared by every thread
// (shape_predictor's operator() is const).
std::shared_ptr<const dlib::shape_predictor> predictor(const std::string& path) {
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const dlib::shape_predictor>> loaded;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = loaded.find(path);
    if (found != loaded.end()) return found->second;
    auto model = std::make_shared<dlib::shape_predictor>();
    try {
        dlib::deserialize(path) >> *model;
    } catch (const std::exception& error) {
        throw FileError(path, std::string("not a dlib shape predictor: ") + error.what());
    }
    loaded.emplace(path, model);
    return model;
}

// dlib's predictor was trained on boxes from dlib's own HOG detector; work at a face width of
// 200 px, where that detector is reliable and fast.
constexpr double kWorkFaceWidth = 200.0;

}  // namespace

DlibShape locate_landmarks_dlib(const cv::Mat& bgr, const cv::Rect& face, const std::string& model_path) {
    const auto model = predictor(model_path);
    const double scale = kWorkFaceWidth / face.width;
    cv::Rect area(face.x - face.width / 2, face.y - face.height / 2, 2 * face.width, 2 * face.height);
    area &= cv::Rect(0, 0, bgr.cols, bgr.rows);
    cv::Mat gray;
    cv::cvtColor(bgr(area), gray, cv::COLOR_BGR2GRAY);
    cv::resize(gray, gray, cv::Size(), scale, scale, scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
    dlib::array2d<unsigned char> image(gray.rows, gray.cols);
    for (int y = 0; y < gray.rows; ++y) {
        for (int x = 0; x < gray.cols; ++x) image[y][x] = gray.at<std::uint8_t>(y, x);
    }
    thread_local dlib::frontal_face_detector detector = dlib::get_frontal_face_detector();
    const cv::Rect haar_work(static_cast<int>((face.x - area.x) * scale), static_cast<int>((face.y - area.y) * scale),
                             static_cast<int>(face.width * scale), static_cast<int>(face.height * scale));
    // The Haar box, tightened to the HOG detector's habits, when the detector finds nothing.
    dlib::rectangle box(haar_work.x + haar_work.width / 12, haar_work.y + haar_work.height / 8,
                        haar_work.x + haar_work.width * 11 / 12, haar_work.y + haar_work.height * 23 / 24);
    double confidence = 0.6;
    double best_overlap = 0.0;
    for (const dlib::rectangle& found : detector(image)) {
        const cv::Rect r(static_cast<int>(found.left()), static_cast<int>(found.top()), static_cast<int>(found.width()),
                         static_cast<int>(found.height()));
        const double overlap = static_cast<double>((r & haar_work).area()) / std::max(1, std::min(r.area(), haar_work.area()));
        if (overlap > 0.5 && overlap > best_overlap) {
            best_overlap = overlap;
            box = found;
            confidence = 0.9;
        }
    }
    const dlib::full_object_detection shape = (*model)(image, box);
    DlibShape result;
    result.confidence = confidence;
    for (unsigned long k = 0; k < shape.num_parts(); ++k) {
        result.points.emplace_back(area.x + static_cast<double>(shape.part(k).x()) / scale,
                                   area.y + static_cast<double>(shape.part(k).y()) / scale);
    }
    return result;
}

void locate_features_dlib(const DlibShape& shape, const FaceFrame& frame, Located& located) {
    std::vector<cv::Point2d> q;
    for (const cv::Point2d& point : shape.points) q.push_back(apply(frame.to_frame, point));
    auto mid = [&](int a, int b) { return 0.5 * (q[static_cast<std::size_t>(a)] + q[static_cast<std::size_t>(b)]); };
    auto at = [&](int k) { return q[static_cast<std::size_t>(k)]; };
    auto& p = located.points;

    for (int side = 0; side < 2; ++side) {
        const int base = 36 + 6 * side;
        cv::Point2d centre;
        for (int k = 0; k < 6; ++k) centre += at(base + k) / 6.0;
        const bool left = side == 0;
        p[left ? "EyeballLeft" : "EyeballRight"] = centre;
        p[left ? "3.12" : "3.11"] = at(base);
        p[left ? "3.8" : "3.7"] = at(base + 3);
        p[left ? "3.2" : "3.1"] = mid(base + 1, base + 2);
        p[left ? "3.4" : "3.3"] = mid(base + 4, base + 5);
        located.add_feature(left ? "left_eye" : "right_eye", shape.confidence, "dlib");
    }
    // Brows: dlib traces the brow's middle; the model's points are its upper edge at 4.4 and 4.4a
    // (docs/face-format.md), a brow's half thickness (about 0.05 d) higher.
    const double lift = 0.05 * kFrameD;
    p["4.6"] = at(17);
    p["4.4a"] = at(18) - cv::Point2d(0, lift);
    p["4.4"] = mid(19, 20) - cv::Point2d(0, lift);
    p["4.2"] = at(21);
    p["4.1"] = at(22);
    p["4.3"] = mid(23, 24) - cv::Point2d(0, lift);
    p["4.3a"] = at(25) - cv::Point2d(0, lift);
    p["4.5"] = at(26);
    located.add_feature("left_brow", shape.confidence, "dlib");
    located.add_feature("right_brow", shape.confidence, "dlib");

    const cv::Point2d tip = at(33);
    const double half_width = 0.5 * (at(35).x - at(31).x);
    p["9.15"] = tip;
    p["9.4"] = mid(31, 32);
    p["9.5"] = mid(34, 35);
    // The wings reach a little beyond dlib's outer nostril points (thesis Figure 2.2 proportions).
    p["9.2"] = at(31) + cv::Point2d(-0.25 * half_width, -0.1 * kFrameD);
    p["9.1"] = at(35) + cv::Point2d(0.25 * half_width, -0.1 * kFrameD);
    p["9.14"] = {tip.x - 0.52 * half_width * 1.25, tip.y - 0.26 * kFrameD};
    p["9.13"] = {tip.x + 0.52 * half_width * 1.25, tip.y - 0.26 * kFrameD};
    located.add_feature("nose", shape.confidence, "dlib");

    const cv::Point2d line = mid(62, 66);
    p["8.4"] = at(48);
    p["8.3"] = at(54);
    p["8.1"] = at(51);
    p["8.9"] = at(50);
    p["8.10"] = at(52);
    p["8.2"] = at(57);
    p["2.2"] = line;
    p["2.3"] = line;
    located.add_feature("mouth", shape.confidence, "dlib");

    p["2.1"] = at(8);
    located.add_feature("chin", shape.confidence, "dlib");
    // Jaw angles and cheeks from the jaw line; temples from the regions (face_fitting.cpp).
    p["2.14"] = mid(4, 5);
    p["2.13"] = mid(11, 12);
    p["10.10"] = mid(1, 2);
    p["10.9"] = mid(14, 15);
    located.add_feature("face_contour", shape.confidence, "dlib");
    cv::Mat lips_mask = cv::Mat::zeros(frame.bgr.size(), CV_8U);
    std::vector<cv::Point> outer;
    for (int k = 48; k < 60; ++k) outer.emplace_back(static_cast<int>(at(k).x), static_cast<int>(at(k).y));
    cv::fillPoly(lips_mask, std::vector<std::vector<cv::Point>>{outer}, cv::Scalar(255));
    std::vector<cv::Point> inner;
    for (int k = 60; k < 68; ++k) inner.emplace_back(static_cast<int>(at(k).x), static_cast<int>(at(k).y));
    cv::fillPoly(lips_mask, std::vector<std::vector<cv::Point>>{inner}, cv::Scalar(0));
    if (cv::countNonZero(lips_mask) > 10) {
        const cv::Scalar mean = cv::mean(frame.bgr, lips_mask);
        located.lip_bgr = cv::Vec3b(static_cast<std::uint8_t>(mean[0]), static_cast<std::uint8_t>(mean[1]),
                                    static_cast<std::uint8_t>(mean[2]));
        located.has_lip_colour = true;
    }
}

}  // namespace talkface::photo
