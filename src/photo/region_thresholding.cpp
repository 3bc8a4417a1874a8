// Face from a photo, step 2: background, hair and face regions (thesis 2.2, Figure 2.1: hierarchical
// bi-level thresholding). The figure was lost in extraction; talkface splits in two levels, each a
// two-class threshold of one feature:
//   level 1: every pixel's colour distance to the skin sampled on the cheeks, thresholded by Otsu's
//            method: skin (the face) against the rest;
//   level 2: the rest, by which of two sampled colours it is nearer, the hair just above the
//            hairline or the background at the top of the frame: hair against background.
// Colour distances are taken in L*a*b* with lightness weighted down, so shading on a cheek does not
// split the face.
#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/order_statistics.hpp"
#include "photo/photo_internal.hpp"

namespace talkface::photo {

namespace {

struct ColourModel {
    cv::Vec3d median;
    cv::Vec3d spread;  // robust standard deviation per channel
};

std::vector<cv::Vec3b> collect(const cv::Mat& image, const cv::Mat& valid, const cv::Rect& area,
                               const cv::Mat& exclude = cv::Mat()) {
    std::vector<cv::Vec3b> values;
    const cv::Rect inside = area & cv::Rect(0, 0, image.cols, image.rows);
    for (int y = inside.y; y < inside.y + inside.height; ++y) {
        for (int x = inside.x; x < inside.x + inside.width; ++x) {
            if (!valid.at<std::uint8_t>(y, x)) continue;
            if (!exclude.empty() && exclude.at<std::uint8_t>(y, x)) continue;
            values.push_back(image.at<cv::Vec3b>(y, x));
        }
    }
    return values;
}

double channel_median(const std::vector<double>& values) {
    return values.empty() ? 0.0 : detail::upper_median(values);
}

ColourModel model_of(const std::vector<cv::Vec3b>& values) {
    ColourModel model;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> channel;
        channel.reserve(values.size());
        for (const cv::Vec3b& v : values) channel.push_back(v[c]);
        model.median[c] = channel_median(channel);
        for (double& v : channel) v = std::abs(v - model.median[c]);
        model.spread[c] = 1.4826 * channel_median(channel);
    }
    return model;
}

// Lightness counts a third as much as the chroma channels (shading), floors keep a flat sample from
// making every other pixel infinitely far.
double distance(const cv::Vec3b& lab, const ColourModel& model) {
    const double l = (lab[0] - model.median[0]) / (3.0 * std::max(model.spread[0], 8.0));
    const double a = (lab[1] - model.median[1]) / std::max(model.spread[1], 3.0);
    const double b = (lab[2] - model.median[2]) / std::max(model.spread[2], 3.0);
    return std::sqrt(l * l + a * a + b * b);
}

double plain_distance(const cv::Vec3d& p, const cv::Vec3d& q) {
    const cv::Vec3d diff = p - q;
    return std::sqrt(0.5 * diff[0] * diff[0] + diff[1] * diff[1] + diff[2] * diff[2]);
}

cv::Rect around(const cv::Point2d& centre, double half_width_d, double half_height_d) {
    return cv::Rect(cv::Point(static_cast<int>(centre.x - half_width_d * kFrameD),
                              static_cast<int>(centre.y - half_height_d * kFrameD)),
                    cv::Point(static_cast<int>(centre.x + half_width_d * kFrameD),
                              static_cast<int>(centre.y + half_height_d * kFrameD)));
}

// The connected region of `mask` that contains `seed`, or else the largest one overlapping `near`.
cv::Mat region_at(const cv::Mat& mask, const cv::Point& seed, const cv::Rect& near) {
    cv::Mat labels;
    const int count = cv::connectedComponents(mask, labels, 8, CV_32S);
    int chosen = labels.at<int>(seed);
    if (chosen == 0) {
        std::vector<int> votes(static_cast<std::size_t>(count), 0);
        const cv::Rect inside = near & cv::Rect(0, 0, mask.cols, mask.rows);
        for (int y = inside.y; y < inside.y + inside.height; ++y) {
            for (int x = inside.x; x < inside.x + inside.width; ++x) ++votes[static_cast<std::size_t>(labels.at<int>(y, x))];
        }
        votes[0] = 0;
        chosen = static_cast<int>(std::max_element(votes.begin(), votes.end()) - votes.begin());
    }
    if (chosen == 0) return cv::Mat::zeros(mask.size(), CV_8U);
    return labels == chosen;
}

cv::Mat fill_holes(const cv::Mat& mask) {
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    cv::Mat filled = cv::Mat::zeros(mask.size(), CV_8U);
    cv::drawContours(filled, contours, -1, cv::Scalar(255), cv::FILLED);
    return filled;
}

cv::Vec3b lab_to_bgr(const cv::Vec3d& lab) {
    cv::Mat one(1, 1, CV_8UC3, cv::Scalar(lab[0], lab[1], lab[2]));
    cv::Mat bgr;
    cv::cvtColor(one, bgr, cv::COLOR_Lab2BGR);
    return bgr.at<cv::Vec3b>(0, 0);
}

}  // namespace

Regions separate_regions(const FaceFrame& frame) {
    Regions regions;
    const cv::Mat& lab = frame.lab;
    const cv::Mat& valid = frame.valid;

    // Level 1: skin. Samples from both cheeks and the nose bridge, which hair, glasses and beards
    // cover least often.
    std::vector<cv::Vec3b> skin_sample;
    for (const cv::Rect& patch : {around(in_d(-0.45, 0.55), 0.12, 0.1), around(in_d(0.45, 0.55), 0.12, 0.1),
                                  around(in_d(0.0, 0.2), 0.07, 0.1)}) {
        const auto values = collect(lab, valid, patch);
        skin_sample.insert(skin_sample.end(), values.begin(), values.end());
    }
    if (skin_sample.size() < 20) {
        regions.skin = cv::Mat::zeros(lab.size(), CV_8U);
        regions.hair = regions.skin.clone();
        regions.background = valid.clone();
        return regions;
    }
    const ColourModel skin = model_of(skin_sample);
    cv::Mat skin_distance(lab.size(), CV_8U);
    for (int y = 0; y < lab.rows; ++y) {
        for (int x = 0; x < lab.cols; ++x) {
            const double dist = valid.at<std::uint8_t>(y, x) ? distance(lab.at<cv::Vec3b>(y, x), skin) : 8.0;
            skin_distance.at<std::uint8_t>(y, x) = cv::saturate_cast<std::uint8_t>(dist * 32.0);
        }
    }
    const cv::Rect head_area = around(in_d(0.0, 0.0), 2.2, 2.4) & cv::Rect(0, 0, lab.cols, lab.rows);
    cv::Mat unused;
    const double otsu = cv::threshold(skin_distance(head_area), unused, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    // Keep Otsu's split between 1.75 and 2.75 robust deviations: a backdrop far from skin would pull
    // it out so far that fair hair next to the forehead counts as skin.
    const double limit = std::clamp(otsu, 56.0, 88.0);
    cv::Mat skin_mask = skin_distance <= limit;
    skin_mask &= valid;
    cv::morphologyEx(skin_mask, skin_mask, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
    cv::morphologyEx(skin_mask, skin_mask, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, {5, 5}));
    const cv::Point nose(in_d(0.0, 0.45));
    regions.skin = fill_holes(region_at(skin_mask, nose, around(in_d(0.0, 0.5), 0.6, 0.2)));
    regions.skin_bgr = lab_to_bgr(skin.median);
    const double cheek_cover = cv::mean(regions.skin(around(in_d(0.0, 0.45), 0.6, 0.25)))[0] / 255.0;
    regions.skin_confidence = std::clamp(cheek_cover, 0.0, 1.0);

    // Level 2: hair against background, among what is not skin.
    std::vector<cv::Vec3b> background_sample;
    for (const cv::Rect& band : {cv::Rect(0, 0, lab.cols, static_cast<int>(in_d(0, -2.75).y)),
                                 cv::Rect(0, 0, static_cast<int>(in_d(-2.3, 0).x), static_cast<int>(in_d(0, 0.3).y)),
                                 cv::Rect(static_cast<int>(in_d(2.3, 0).x), 0, lab.cols, static_cast<int>(in_d(0, 0.3).y))}) {
        const auto values = collect(lab, valid, band, regions.skin);
        background_sample.insert(background_sample.end(), values.begin(), values.end());
    }
    // The hairline is the skin's top on the centre column; hair sits just above it.
    int hairline_y = static_cast<int>(in_d(0, -0.6).y);
    while (hairline_y > 0 && regions.skin.at<std::uint8_t>(hairline_y - 1, static_cast<int>(kFrameEyeMid.x))) --hairline_y;
    const int hair_band_top = std::max(0, hairline_y - static_cast<int>(0.45 * kFrameD));
    const cv::Rect hair_patch(static_cast<int>(in_d(-0.35, 0).x), hair_band_top, static_cast<int>(0.7 * kFrameD),
                              std::max(1, hairline_y - static_cast<int>(0.06 * kFrameD) - hair_band_top));
    const auto hair_sample = collect(lab, valid, hair_patch, regions.skin);
    const ColourModel background = model_of(background_sample);
    const ColourModel hair = model_of(hair_sample);
    const double separation = plain_distance(hair.median, background.median);

    cv::Mat other = valid & ~regions.skin;
    cv::Mat hair_mask = cv::Mat::zeros(lab.size(), CV_8U);
    const int lowest_hair_row = static_cast<int>(in_d(0, 1.0).y);
    if (hair_sample.size() >= 20 && !background_sample.empty()) {
        for (int y = 0; y < std::min(lowest_hair_row, lab.rows); ++y) {
            for (int x = 0; x < lab.cols; ++x) {
                if (!other.at<std::uint8_t>(y, x)) continue;
                const cv::Vec3d p(lab.at<cv::Vec3b>(y, x));
                if (plain_distance(p, hair.median) < plain_distance(p, background.median)) {
                    hair_mask.at<std::uint8_t>(y, x) = 255;
                }
            }
        }
        cv::morphologyEx(hair_mask, hair_mask, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
        // Hair touches the head: keep the regions that reach the skin's top and sides.
        cv::Mat near_skin;
        cv::dilate(regions.skin, near_skin, cv::getStructuringElement(cv::MORPH_ELLIPSE, {9, 9}));
        cv::Mat labels;
        const int count = cv::connectedComponents(hair_mask, labels, 8, CV_32S);
        std::vector<bool> touching(static_cast<std::size_t>(count), false);
        for (int y = 0; y < labels.rows; ++y) {
            for (int x = 0; x < labels.cols; ++x) {
                const int label = labels.at<int>(y, x);
                if (label && near_skin.at<std::uint8_t>(y, x)) touching[static_cast<std::size_t>(label)] = true;
            }
        }
        for (int y = 0; y < labels.rows; ++y) {
            for (int x = 0; x < labels.cols; ++x) {
                if (!touching[static_cast<std::size_t>(labels.at<int>(y, x))]) hair_mask.at<std::uint8_t>(y, x) = 0;
            }
        }
    }
    regions.hair = hair_mask;
    regions.background = other & ~hair_mask;
    regions.hair_bgr = lab_to_bgr(hair.median);
    // Sure of the hair when its colour stands apart from the background and it covers the crown.
    const double crown_cover =
        cv::mean(hair_mask(around(in_d(0.0, -1.6), 0.5, 0.25) & cv::Rect(0, 0, lab.cols, lab.rows)))[0] / 255.0;
    regions.hair_confidence = std::clamp(std::min(separation / 30.0, 1.0) * (0.3 + 0.7 * crown_cover), 0.0, 1.0);
    if (hair_sample.size() < 20) regions.hair_confidence = 0.0;
    return regions;
}

}  // namespace talkface::photo
