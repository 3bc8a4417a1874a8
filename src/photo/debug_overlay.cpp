// Face from a photo: the debug overlay, the photo with every extracted point drawn on it so a person
// can judge the extraction. Each feature has its colour; points that came from priors (a feature
// found with too little confidence) are drawn red, so a guess never passes for a measurement.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "photo/photo_internal.hpp"

namespace talkface::photo {

namespace {

struct Group {
    const char* feature;
    std::vector<const char*> ids;
    cv::Scalar bgr;
    bool closed;
};

const std::vector<Group>& groups() {
    static const std::vector<Group> all = {
        {"hairline", {"11.2", "11.2a", "11.1", "11.3a", "11.3"}, {60, 200, 255}, false},
        {"face_contour", {"11.3", "10.9", "2.13", "2.1", "2.14", "10.10", "11.2"}, {0, 220, 255}, false},
        {"ears", {"10.8", "10.2"}, {200, 200, 200}, false},
        {"ears", {"10.7", "10.1"}, {200, 200, 200}, false},
        {"left_eye", {"3.12", "3.2", "3.8", "3.4"}, {255, 200, 0}, true},
        {"right_eye", {"3.7", "3.1", "3.11", "3.3"}, {255, 200, 0}, true},
        {"left_brow", {"4.6", "4.4a", "4.4", "4.2"}, {255, 0, 200}, false},
        {"right_brow", {"4.5", "4.3a", "4.3", "4.1"}, {255, 0, 200}, false},
        {"nose", {"9.6", "9.14", "9.2", "9.4", "9.15", "9.5", "9.1", "9.13", "9.7"}, {0, 255, 0}, false},
        {"mouth", {"8.4", "8.9", "8.1", "8.10", "8.3", "8.2"}, {255, 120, 255}, true},
        {"chin", {"2.1"}, {0, 220, 255}, false},
    };
    return all;
}

bool is_prior(const PhotoFaceResult& result, const std::string& feature) {
    for (const PhotoFeature& f : result.features) {
        if (f.name == feature) return f.from_prior;
    }
    return false;
}

cv::Point at(const FaceModel& face, const std::string& id, double scale) {
    const Point2 p = face.point(id);
    return {static_cast<int>(std::lround(p.x * scale)), static_cast<int>(std::lround(p.y * scale))};
}

}  // namespace

void draw_overlay(cv::Mat& bgr, const PhotoFaceResult& result) {
    // Small photos are enlarged so that the marks stay readable.
    const double scale = std::max(1.0, 480.0 / std::max(bgr.cols, bgr.rows));
    if (scale > 1.0) cv::resize(bgr, bgr, cv::Size(), scale, scale, cv::INTER_CUBIC);
    const int thickness = std::max(1, static_cast<int>(std::lround(std::max(bgr.cols, bgr.rows) / 500.0)));
    const int radius = thickness + 1;
    const cv::Scalar red(0, 0, 255);
    const FaceModel& face = result.face;

    std::vector<cv::Point> hair;
    for (int k = 1; k <= 23; ++k) hair.push_back(at(face, "hair." + std::to_string(k), scale));
    const cv::Scalar hair_colour = is_prior(result, "hair") ? red : cv::Scalar(255, 120, 60);
    cv::polylines(bgr, hair, true, hair_colour, thickness, cv::LINE_AA);
    for (const cv::Point& q : hair) cv::circle(bgr, q, radius, hair_colour, cv::FILLED, cv::LINE_AA);

    for (const Group& group : groups()) {
        const cv::Scalar colour = is_prior(result, group.feature) ? red : group.bgr;
        std::vector<cv::Point> line;
        for (const char* id : group.ids) line.push_back(at(face, id, scale));
        if (line.size() > 1) cv::polylines(bgr, line, group.closed, colour, thickness, cv::LINE_AA);
        for (const cv::Point& q : line) cv::circle(bgr, q, radius, colour, cv::FILLED, cv::LINE_AA);
    }
    for (const char* id : {"EyeballLeft", "EyeballRight"}) {
        const cv::Point centre = at(face, id, scale);
        cv::drawMarker(bgr, centre, cv::Scalar(0, 255, 255), cv::MARKER_CROSS, 4 * radius, thickness, cv::LINE_AA);
    }
    const PhotoBox& box = result.face_box;
    cv::rectangle(bgr, cv::Rect(static_cast<int>(box.x * scale), static_cast<int>(box.y * scale),
                                static_cast<int>(box.width * scale), static_cast<int>(box.height * scale)),
                  cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
}

}  // namespace talkface::photo
