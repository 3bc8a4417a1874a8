// Face from a photo, step 3 (thesis locator): each feature's region and points by knowledge-based
// edge detection (thesis 2.2). Knowledge: in the face frame the eyes are fixed, so each feature is
// searched only in the window where a frontal face keeps it, in units of d; inside the window a
// bi-level threshold or an intensity / edge profile finds it. Each feature's confidence is the
// contrast that found it, scaled so that a clear photo gives about 1.
#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/order_statistics.hpp"
#include "photo/photo_internal.hpp"

namespace talkface::photo {

namespace {

int row_of(double y_d) { return static_cast<int>(std::lround(in_d(0, y_d).y)); }
int col_of(double x_d) { return static_cast<int>(std::lround(in_d(x_d, 0).x)); }

cv::Rect clip(const cv::Rect& r, const cv::Mat& image) { return r & cv::Rect(0, 0, image.cols, image.rows); }

cv::Rect window(const cv::Point2d& centre, double half_width_d, double half_height_d) {
    return cv::Rect(cv::Point(static_cast<int>(std::lround(centre.x - half_width_d * kFrameD)),
                              static_cast<int>(std::lround(centre.y - half_height_d * kFrameD))),
                    cv::Point(static_cast<int>(std::lround(centre.x + half_width_d * kFrameD)),
                              static_cast<int>(std::lround(centre.y + half_height_d * kFrameD))));
}

double median_of(const cv::Mat& gray, const cv::Mat& mask) {
    std::vector<std::uint8_t> values;
    for (int y = 0; y < gray.rows; ++y) {
        for (int x = 0; x < gray.cols; ++x) {
            if (mask.empty() || mask.at<std::uint8_t>(y, x)) values.push_back(gray.at<std::uint8_t>(y, x));
        }
    }
    return values.empty() ? 0.0 : detail::upper_median(std::move(values));
}

cv::Vec3b median_colour(const cv::Mat& bgr, const cv::Mat& mask) {
    std::vector<cv::Mat> channels;
    cv::split(bgr, channels);
    return cv::Vec3b(static_cast<std::uint8_t>(median_of(channels[0], mask)),
                     static_cast<std::uint8_t>(median_of(channels[1], mask)),
                     static_cast<std::uint8_t>(median_of(channels[2], mask)));
}

// The skin's grey level beside the nose, the reference every darkness below is measured against.
double skin_gray(const FaceFrame& frame) {
    cv::Mat cheeks;
    cv::hconcat(frame.gray(clip(window(in_d(-0.45, 0.55), 0.12, 0.1), frame.gray)),
                frame.gray(clip(window(in_d(0.45, 0.55), 0.12, 0.1), frame.gray)), cheeks);
    return median_of(cheeks, cv::Mat());
}

// A row (or column) profile smoothed over `radius` samples.
std::vector<double> smooth(const std::vector<double>& values, int radius) {
    std::vector<double> out(values.size(), 0.0);
    for (std::size_t i = 0; i < values.size(); ++i) {
        double sum = 0.0;
        int count = 0;
        for (int k = -radius; k <= radius; ++k) {
            const auto j = static_cast<std::ptrdiff_t>(i) + k;
            if (j < 0 || j >= static_cast<std::ptrdiff_t>(values.size())) continue;
            sum += values[static_cast<std::size_t>(j)];
            ++count;
        }
        out[i] = sum / std::max(count, 1);
    }
    return out;
}

std::size_t argmax(const std::vector<double>& values) {
    return static_cast<std::size_t>(std::max_element(values.begin(), values.end()) - values.begin());
}

// Darkness below the skin, averaged along each row of `area`.
std::vector<double> row_darkness(const cv::Mat& gray, const cv::Rect& area, double skin) {
    std::vector<double> rows;
    for (int y = area.y; y < area.y + area.height; ++y) {
        double sum = 0.0;
        for (int x = area.x; x < area.x + area.width; ++x) sum += std::max(0.0, skin - gray.at<std::uint8_t>(y, x));
        rows.push_back(sum / std::max(area.width, 1));
    }
    return rows;
}

// The connected region of a mask that holds the most mask pixels near `centre` (within `reach`).
cv::Mat largest_near(const cv::Mat& mask, const cv::Point2d& centre, double reach_px) {
    cv::Mat labels, stats, centroids;
    const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
    int best = 0;
    double best_score = 0.0;
    for (int label = 1; label < count; ++label) {
        const cv::Point2d c(centroids.at<double>(label, 0), centroids.at<double>(label, 1));
        const double distance = cv::norm(c - centre);
        if (distance > reach_px) continue;
        const double score = stats.at<int>(label, cv::CC_STAT_AREA) * (1.0 - distance / reach_px);
        if (score > best_score) {
            best_score = score;
            best = label;
        }
    }
    if (best == 0) return cv::Mat::zeros(mask.size(), CV_8U);
    return labels == best;
}

// Top and bottom mask rows in column x (frame coordinates), or false.
bool column_extent(const cv::Mat& mask, int x, int& top, int& bottom) {
    top = -1;
    bottom = -1;
    if (x < 0 || x >= mask.cols) return false;
    for (int y = 0; y < mask.rows; ++y) {
        if (mask.at<std::uint8_t>(y, x)) {
            if (top < 0) top = y;
            bottom = y;
        }
    }
    return top >= 0;
}

void locate_eye(const FaceFrame& frame, const cv::Point2d& centre, bool image_left, double skin, Located& located) {
    const char* top_id = image_left ? "3.2" : "3.1";
    const char* bottom_id = image_left ? "3.4" : "3.3";
    const char* outer_id = image_left ? "3.12" : "3.7";
    const char* inner_id = image_left ? "3.8" : "3.11";
    const double outward = image_left ? -1.0 : 1.0;
    const cv::Rect area = clip(window(centre, 0.42, 0.16), frame.gray);
    cv::Mat patch;
    cv::GaussianBlur(frame.gray(area), patch, cv::Size(3, 3), 0.0);
    cv::Mat dark;
    cv::threshold(patch, dark, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
    const cv::Point2d local_centre = centre - cv::Point2d(area.tl());
    const cv::Mat eye = largest_near(dark, local_centre, 0.25 * kFrameD);
    const double iris = median_of(patch, eye);
    const double contrast = skin - iris;

    // Corners: the dark region's ends along the eye's row band (lashes and corner shadows).
    int left_end = -1, right_end = -1;
    double left_y = local_centre.y, right_y = local_centre.y;
    const int band = static_cast<int>(0.09 * kFrameD);
    for (int x = 0; x < eye.cols; ++x) {
        for (int y = std::max(0, static_cast<int>(local_centre.y) - band);
             y <= std::min(eye.rows - 1, static_cast<int>(local_centre.y) + band); ++y) {
            if (!eye.at<std::uint8_t>(y, x)) continue;
            if (left_end < 0) {
                left_end = x;
                left_y = y;
            }
            if (x >= right_end) {
                right_end = x;
                right_y = y;
            }
        }
    }
    double half_left = left_end >= 0 ? local_centre.x - left_end : 0.25 * kFrameD;
    double half_right = right_end >= 0 ? right_end - local_centre.x : 0.25 * kFrameD;
    // An eye is about half d wide (thesis Figure 2.2's proportions): clamp each half to 0.16..0.34 d.
    half_left = std::clamp(half_left, 0.16 * kFrameD, 0.34 * kFrameD);
    half_right = std::clamp(half_right, 0.16 * kFrameD, 0.34 * kFrameD);
    int top = 0, bottom = 0;
    double half_height = 0.08 * kFrameD;
    if (column_extent(eye, static_cast<int>(local_centre.x), top, bottom)) {
        half_height = std::clamp(0.5 * (bottom - top), 0.05 * kFrameD, 0.16 * kFrameD);
    }
    const cv::Point2d origin(area.tl());
    const cv::Point2d left_corner = origin + cv::Point2d(local_centre.x - half_left, left_y);
    const cv::Point2d right_corner = origin + cv::Point2d(local_centre.x + half_right, right_y);
    located.points[outer_id] = outward < 0 ? left_corner : right_corner;
    located.points[inner_id] = outward < 0 ? right_corner : left_corner;
    located.points[top_id] = centre - cv::Point2d(0, half_height);
    located.points[bottom_id] = centre + cv::Point2d(0, half_height);
    located.points[image_left ? "EyeballLeft" : "EyeballRight"] = centre;
    if (!eye.empty() && cv::countNonZero(eye) > 0) {
        located.iris_bgr = median_colour(frame.bgr(area), eye);
        located.has_iris_colour = true;
    }
    located.add_feature(image_left ? "left_eye" : "right_eye", std::clamp(contrast / 60.0, 0.0, 1.0), "thesis");
}

void locate_brow(const FaceFrame& frame, const cv::Point2d& eye, bool image_left, double skin, Located& located) {
    const double outward = image_left ? -1.0 : 1.0;
    // Knowledge: a brow lies 0.18 to 0.75 d above its eye and spans about the eye's width.
    const cv::Rect area = clip(cv::Rect(cv::Point(static_cast<int>(eye.x - 0.5 * kFrameD), static_cast<int>(eye.y - 0.75 * kFrameD)),
                                        cv::Point(static_cast<int>(eye.x + 0.5 * kFrameD), static_cast<int>(eye.y - 0.18 * kFrameD))),
                               frame.gray);
    cv::Mat patch;
    cv::GaussianBlur(frame.gray(area), patch, cv::Size(5, 5), 0.0);
    const std::vector<double> rows = smooth(row_darkness(patch, cv::Rect(0, 0, patch.cols, patch.rows), skin), 2);
    // Knowledge: the brow is the first dark band above the eye; a fringe of hair higher up may be
    // darker still. Going up from the eye, take the first peak that reaches 30 % of the window's darkest.
    const double darkest_row = *std::max_element(rows.begin(), rows.end());
    std::size_t peak = argmax(rows);
    for (std::size_t r = rows.size() - 2; r >= 1; --r) {
        if (rows[r] >= 0.3 * darkest_row && rows[r] >= rows[r - 1] && rows[r] >= rows[r + 1]) {
            peak = r;
            break;
        }
    }
    const int brow_row = static_cast<int>(peak);
    cv::Mat dark;
    cv::threshold(patch, dark, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
    // Only the brow's rows: the threshold also takes fringe and lashes above and below it.
    const int half_band = static_cast<int>(0.12 * kFrameD);
    dark.rowRange(0, std::max(0, brow_row - half_band)).setTo(0);
    dark.rowRange(std::min(dark.rows, brow_row + half_band), dark.rows).setTo(0);
    const cv::Mat brow = largest_near(dark, cv::Point2d(0.5 * patch.cols, brow_row), 0.45 * kFrameD);
    const cv::Point2d origin(area.tl());
    std::vector<cv::Point> pixels;
    cv::findNonZero(brow, pixels);
    const char* ids_outer_to_inner[4] = {image_left ? "4.6" : "4.5", image_left ? "4.4a" : "4.3a",
                                         image_left ? "4.4" : "4.3", image_left ? "4.2" : "4.1"};
    if (pixels.size() < 10) {
        located.add_feature(image_left ? "left_brow" : "right_brow", 0.0, "thesis");
        return;
    }
    const cv::Rect box = cv::boundingRect(pixels);
    const double span = box.width;
    const double outer_x = outward < 0 ? box.x : box.x + box.width - 1;
    const double inner_x = outward < 0 ? box.x + box.width - 1 : box.x;
    // Thesis Figure 2.2 / the default face: 4.4a at 15 % and 4.4 at 57 % of the way from the outer end.
    const double fractions[4] = {0.0, 0.15, 0.57, 1.0};
    for (int k = 0; k < 4; ++k) {
        const int x = static_cast<int>(std::lround(outer_x + (inner_x - outer_x) * fractions[k]));
        int top = 0, bottom = 0;
        double y = brow_row;
        if (column_extent(brow, std::clamp(x, 0, brow.cols - 1), top, bottom)) {
            // The ends are drawn at the brow's middle, the inner points on its upper edge.
            y = (k == 0 || k == 3) ? 0.5 * (top + bottom) : top;
        }
        located.points[ids_outer_to_inner[k]] = origin + cv::Point2d(x, y);
    }
    const double darkness = skin - median_of(patch, brow);
    const double shape = (span > 0.35 * kFrameD && span < 1.0 * kFrameD) ? 1.0 : 0.3;
    located.brow_bgr = median_colour(frame.bgr(area), brow);
    located.has_brow_colour = true;
    located.add_feature(image_left ? "left_brow" : "right_brow", std::clamp(darkness / 45.0, 0.0, 1.0) * shape, "thesis");
}

// The nose: nostrils are the first dark row below the eyes (0.45 to 0.9 d); the wings are the strongest
// vertical edges beside them.
void locate_nose(const FaceFrame& frame, double skin, Located& located) {
    const cv::Rect area = clip(cv::Rect(cv::Point(col_of(-0.3), row_of(0.45)), cv::Point(col_of(0.3), row_of(0.9))), frame.gray);
    cv::Mat patch;
    cv::GaussianBlur(frame.gray(area), patch, cv::Size(5, 5), 0.0);
    const std::vector<double> rows = smooth(row_darkness(patch, cv::Rect(0, 0, patch.cols, patch.rows), skin), 1);
    // Going down from the eyes the nostrils come before the lips, which may be darker: the first
    // peak that reaches half the window's darkest row.
    const double darkest_row = *std::max_element(rows.begin(), rows.end());
    std::size_t peak = argmax(rows);
    for (std::size_t r = 1; r + 1 < rows.size(); ++r) {
        if (rows[r] >= 0.5 * darkest_row && rows[r] >= rows[r - 1] && rows[r] >= rows[r + 1]) {
            peak = r;
            break;
        }
    }
    const int nostril_row = area.y + static_cast<int>(peak);
    // Nostril centres: the darkest columns on each side in that row band.
    const int band = static_cast<int>(0.05 * kFrameD);
    double nostril_x[2] = {in_d(-0.12, 0).x, in_d(0.12, 0).x};
    double nostril_dark[2] = {0.0, 0.0};
    for (int side = 0; side < 2; ++side) {
        const int from = side == 0 ? col_of(-0.32) : col_of(0.04);
        const int to = side == 0 ? col_of(-0.04) : col_of(0.32);
        for (int x = from; x <= to; ++x) {
            double dark = 0.0;
            for (int y = nostril_row - band; y <= nostril_row + band; ++y) dark += std::max(0.0, skin - frame.gray.at<std::uint8_t>(y, x));
            if (dark > nostril_dark[side]) {
                nostril_dark[side] = dark;
                nostril_x[side] = x;
            }
        }
        nostril_dark[side] /= (2 * band + 1);
    }
    const double mid_x = 0.5 * (nostril_x[0] + nostril_x[1]);
    // Wings: the strongest |d/dx| in the 0.25 d above the nostrils, 0.12 to 0.45 d out from the middle.
    cv::Mat gradient;
    cv::Sobel(frame.gray, gradient, CV_32F, 1, 0, 3);
    double wing_x[2] = {mid_x - 0.21 * kFrameD, mid_x + 0.21 * kFrameD};
    double wing_edge[2] = {0.0, 0.0};
    for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? -1.0 : 1.0;
        for (double offset = 0.14 * kFrameD; offset <= 0.42 * kFrameD; offset += 1.0) {
            const int x = static_cast<int>(std::lround(mid_x + sign * offset));
            double edge = 0.0;
            for (int y = nostril_row - static_cast<int>(0.22 * kFrameD); y <= nostril_row; ++y) {
                edge += std::abs(gradient.at<float>(y, x));
            }
            if (edge > wing_edge[side]) {
                wing_edge[side] = edge;
                wing_x[side] = x;
            }
        }
    }
    const double half_width = 0.5 * (wing_x[1] - wing_x[0]);
    const double tip_y = nostril_row + 0.03 * kFrameD;
    located.points["9.15"] = {mid_x, tip_y};
    located.points["9.4"] = {nostril_x[0], nostril_row + 0.0};
    located.points["9.5"] = {nostril_x[1], nostril_row + 0.0};
    located.points["9.2"] = {wing_x[0], tip_y - 0.12 * kFrameD};
    located.points["9.1"] = {wing_x[1], tip_y - 0.12 * kFrameD};
    // Thesis Figure 2.2 proportions: the lower nose sides sit half-way in, 0.26 d above the tip.
    located.points["9.14"] = {mid_x - 0.52 * half_width, tip_y - 0.26 * kFrameD};
    located.points["9.13"] = {mid_x + 0.52 * half_width, tip_y - 0.26 * kFrameD};
    const double contrast = std::min(nostril_dark[0], nostril_dark[1]);
    const double centred = 1.0 - std::min(1.0, std::abs(mid_x - kFrameEyeMid.x) / (0.2 * kFrameD));
    located.add_feature("nose", std::clamp(contrast / 30.0, 0.0, 1.0) * (0.5 + 0.5 * centred), "thesis");
}

// The mouth: the lips are redder than the skin (L*a*b* a*); Otsu's threshold on a* in the window
// below the nose gives the lip region, the darkest row inside it the line where the lips meet.
void locate_mouth(const FaceFrame& frame, Located& located) {
    const double nose_y = located.points.count("9.15") ? located.points["9.15"].y : in_d(0, 0.8).y;
    const cv::Rect area = clip(cv::Rect(cv::Point(col_of(-0.7), static_cast<int>(nose_y + 0.12 * kFrameD)),
                                        cv::Point(col_of(0.7), static_cast<int>(nose_y + 0.8 * kFrameD))),
                               frame.gray);
    std::vector<cv::Mat> lab;
    cv::split(frame.lab(area), lab);
    cv::Mat redness;
    cv::GaussianBlur(lab[1], redness, cv::Size(5, 5), 0.0);
    cv::Mat lips_mask;
    cv::threshold(redness, lips_mask, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    cv::morphologyEx(lips_mask, lips_mask, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
    // An open or smiling mouth splits the lips at the teeth: keep every sizeable region near the middle.
    cv::Mat labels, stats, centroids;
    const int count = cv::connectedComponentsWithStats(lips_mask, labels, stats, centroids, 8);
    int largest = 0;
    for (int label = 1; label < count; ++label) largest = std::max(largest, stats.at<int>(label, cv::CC_STAT_AREA));
    cv::Mat lips = cv::Mat::zeros(lips_mask.size(), CV_8U);
    for (int label = 1; label < count; ++label) {
        const double cx = centroids.at<double>(label, 0) + area.x;
        if (stats.at<int>(label, cv::CC_STAT_AREA) < 0.15 * largest) continue;
        if (std::abs(cx - kFrameEyeMid.x) > 0.35 * kFrameD) continue;
        lips |= labels == label;
    }
    std::vector<cv::Point> pixels;
    cv::findNonZero(lips, pixels);
    const cv::Point2d origin(area.tl());
    if (pixels.size() < 20) {
        located.add_feature("mouth", 0.0, "thesis");
        return;
    }
    const cv::Rect box = cv::boundingRect(pixels);
    auto mean_y_at = [&](int x) {
        int top = 0, bottom = 0;
        column_extent(lips, x, top, bottom);
        return 0.5 * (top + bottom);
    };
    const cv::Point2d left_corner = origin + cv::Point2d(box.x, mean_y_at(box.x));
    const cv::Point2d right_corner = origin + cv::Point2d(box.x + box.width - 1, mean_y_at(box.x + box.width - 1));
    const int centre_x = static_cast<int>(std::lround(0.5 * (left_corner.x + right_corner.x))) - area.x;
    int top = 0, bottom = 0;
    if (!column_extent(lips, centre_x, top, bottom)) {
        top = box.y;
        bottom = box.y + box.height - 1;
    }
    // The lips meet on the darkest row between the lip's top and bottom at the middle.
    double darkest = 1e9;
    int line = (top + bottom) / 2;
    for (int y = top + 1; y < bottom; ++y) {
        double sum = 0.0;
        for (int x = centre_x - 3; x <= centre_x + 3; ++x) sum += frame.gray.at<std::uint8_t>(area.y + y, area.x + std::clamp(x, 0, area.width - 1));
        if (sum < darkest) {
            darkest = sum;
            line = y;
        }
    }
    const double half_width = 0.5 * (right_corner.x - left_corner.x);
    int peak_top = top, peak_bottom = bottom;
    const int peak_dx = static_cast<int>(std::lround(0.3 * half_width));
    int left_peak = top, right_peak = top;
    if (column_extent(lips, centre_x - peak_dx, peak_top, peak_bottom)) left_peak = peak_top;
    if (column_extent(lips, centre_x + peak_dx, peak_top, peak_bottom)) right_peak = peak_top;
    const double mid_x = origin.x + centre_x;
    located.points["8.4"] = left_corner;
    located.points["8.3"] = right_corner;
    located.points["8.1"] = {mid_x, origin.y + top};
    located.points["8.9"] = {mid_x - peak_dx, origin.y + std::min(left_peak, top)};
    located.points["8.10"] = {mid_x + peak_dx, origin.y + std::min(right_peak, top)};
    located.points["8.2"] = {mid_x, origin.y + bottom};
    located.points["2.2"] = {mid_x, origin.y + line};
    located.points["2.3"] = {mid_x, origin.y + line};
    const double lip_a = median_of(lab[1], lips);
    const double skin_a = median_of(lab[1], ~lips);
    const double width_d = (right_corner.x - left_corner.x) / kFrameD;
    const double plausible = (width_d > 0.45 && width_d < 1.35) ? 1.0 : 0.3;
    located.lip_bgr = median_colour(frame.bgr(area), lips);
    located.has_lip_colour = true;
    located.add_feature("mouth", std::clamp((lip_a - skin_a) / 10.0, 0.0, 1.0) * plausible, "thesis");
}

// The chin: the strongest step from bright skin to darker (shadow, neck, collar) going down the middle,
// 0.25 to 1.1 d below the lower lip.
void locate_chin(const FaceFrame& frame, const Regions& regions, Located& located) {
    const double lip_y = located.points.count("8.2") ? located.points["8.2"].y : in_d(0, 1.2).y;
    const int from = static_cast<int>(lip_y + 0.25 * kFrameD);
    const int to = std::min(frame.gray.rows - 4, static_cast<int>(lip_y + 1.1 * kFrameD));
    cv::Mat blurred;
    cv::GaussianBlur(frame.gray, blurred, cv::Size(5, 5), 0.0);
    const int x0 = col_of(-0.15), x1 = col_of(0.15);
    double best = 0.0;
    int chin_y = static_cast<int>(lip_y + 0.58 * kFrameD);
    for (int y = from; y < to; ++y) {
        double step = 0.0;
        for (int x = x0; x <= x1; ++x) step += blurred.at<std::uint8_t>(y - 2, x) - blurred.at<std::uint8_t>(y + 2, x);
        step /= (x1 - x0 + 1);
        // Knowledge: the skin region ends at the chin; an edge where the skin mask ends counts double.
        const bool skin_ends = regions.skin.at<std::uint8_t>(y - 3, kFrameEyeMid.x > 0 ? static_cast<int>(kFrameEyeMid.x) : 0) &&
                               !regions.skin.at<std::uint8_t>(std::min(y + 3, frame.gray.rows - 1), static_cast<int>(kFrameEyeMid.x));
        const double score = step * (skin_ends ? 2.0 : 1.0);
        if (score > best) {
            best = score;
            chin_y = y;
        }
    }
    located.points["2.1"] = {kFrameEyeMid.x, static_cast<double>(chin_y)};
    located.add_feature("chin", std::clamp(best / 40.0, 0.0, 1.0), "thesis");
}

}  // namespace

EyePair refine_eye_centres(const FaceFrame& frame, double half_width_d) {
    EyePair eyes;
    double contrast[2] = {0.0, 0.0};
    const double skin = skin_gray(frame);
    for (int side = 0; side < 2; ++side) {
        const cv::Point2d guess = in_d(side == 0 ? -0.5 : 0.5, 0.0);
        const cv::Rect area = clip(window(guess, half_width_d, 0.7 * half_width_d), frame.gray);
        cv::Mat patch;
        cv::GaussianBlur(frame.gray(area), patch, cv::Size(5, 5), 0.0);
        // The iris: the darkest 12 % of the window, the region nearest the guess.
        cv::Mat sorted = patch.reshape(1, 1).clone();
        cv::sort(sorted, sorted, cv::SORT_ASCENDING);
        const double cut = sorted.at<std::uint8_t>(0, static_cast<int>(0.12 * (sorted.cols - 1)));
        const cv::Mat dark = patch <= cut;
        const cv::Mat iris = largest_near(dark, guess - cv::Point2d(area.tl()), 0.3 * kFrameD);
        const cv::Moments m = cv::moments(iris, true);
        const cv::Point2d found = m.m00 > 0 ? cv::Point2d(m.m10 / m.m00, m.m01 / m.m00) + cv::Point2d(area.tl()) : guess;
        (side == 0 ? eyes.left : eyes.right) = found;
        contrast[side] = skin - median_of(patch, iris);
    }
    eyes.confidence = std::clamp(std::min(contrast[0], contrast[1]) / 60.0, 0.0, 1.0);
    return eyes;
}

void locate_features_thesis(const FaceFrame& frame, const Regions& regions, Located& located) {
    const double skin = skin_gray(frame);
    locate_eye(frame, in_d(-0.5, 0.0), true, skin, located);
    locate_eye(frame, in_d(0.5, 0.0), false, skin, located);
    locate_brow(frame, in_d(-0.5, 0.0), true, skin, located);
    locate_brow(frame, in_d(0.5, 0.0), false, skin, located);
    locate_nose(frame, skin, located);
    locate_mouth(frame, located);
    locate_chin(frame, regions, located);
}

}  // namespace talkface::photo
