// Face from a photo, step 4: the 72 points, the hair polygon, FAPUs and colours from what the
// locators and the region separation found (thesis 2.2, "creation of a face model"). A feature found
// with too little confidence is not used: its points come from the built-in default face's
// proportions in units of d, anchored to the nearest feature that was found, and the feature says so
// (PhotoFeature::from_prior).
#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "face/fapu_measure.hpp"
#include "photo/photo_internal.hpp"

namespace talkface::photo {

namespace {

// The default face in the frame: its eye midpoint (200, 200) and d = 65 px map onto the frame's.
cv::Point2d prior(const FaceModel& default_face, const std::string& id) {
    const Point2 p = default_face.point(id);
    return kFrameEyeMid + cv::Point2d(p.x - 200.0, p.y - 200.0) * (kFrameD / 65.0);
}

bool usable(const Located& located, const std::string& feature) {
    const PhotoFeature* found = located.feature(feature);
    return found != nullptr && found->confidence >= kUsableConfidence;
}

void mark_prior(Located& located, const std::string& feature) {
    for (PhotoFeature& f : located.features) {
        if (f.name == feature) f.from_prior = true;
    }
}

// How far the skin reaches from the face's middle along row y, towards `sign` (-1 image left), in
// frame pixels; gaps up to 2 px (a strand of hair, a shadow) are crossed.
double skin_reach(const cv::Mat& skin, int y, double sign) {
    if (y < 0 || y >= skin.rows) return 0.0;
    const int centre = static_cast<int>(kFrameEyeMid.x);
    int last = 0;
    int gap = 0;
    for (int step = 0; step < skin.cols / 2; ++step) {
        const int x = centre + static_cast<int>(sign) * step;
        if (x < 0 || x >= skin.cols) break;
        if (skin.at<std::uint8_t>(y, x)) {
            last = step;
            gap = 0;
        } else if (++gap > 2) {
            break;
        }
    }
    return last;
}

// The skin's top above `x`, searched upwards from `from_y`.
double skin_top(const cv::Mat& skin, int x, int from_y) {
    int y = from_y;
    while (y > 0 && skin.at<std::uint8_t>(y - 1, x)) --y;
    return y;
}

// Distance from `centre` along direction `angle_rad` (y up) to where `inside` stops holding, walking
// out to `max_r`; gaps shorter than `gap_px` are crossed.
template <typename Inside>
double ray_reach(const cv::Point2d& centre, double angle_rad, double max_r, double gap_px, Inside inside) {
    double last = 0.0;
    for (double r = 0.0; r <= max_r; r += 0.5) {
        const cv::Point2d p = centre + r * cv::Point2d(std::cos(angle_rad), -std::sin(angle_rad));
        if (inside(p)) {
            last = r;
        } else if (r - last > gap_px) {
            break;
        }
    }
    return last;
}

std::vector<cv::Point2d> contour_polygon(const std::map<std::string, cv::Point2d>& p) {
    std::vector<cv::Point2d> polygon;
    for (const char* id : {"11.2", "11.2a", "11.1", "11.3a", "11.3", "10.9", "2.13", "2.1", "2.14", "10.10"}) {
        polygon.push_back(p.at(id));
    }
    return polygon;
}

std::vector<cv::Point2f> to_float(const std::vector<cv::Point2d>& points) {
    std::vector<cv::Point2f> out;
    for (const auto& p : points) out.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    return out;
}

// Angles of the hair points around the eye midpoint: hair.1 just below the horizontal on the image
// left, over the crown, hair.23 mirrored; both ends below the centre so the closing edge runs under it
// and the polygon, star-shaped about the centre, is simple.
double hair_angle_rad(int k) {
    const double start_deg = 196.0, end_deg = -16.0;
    return (start_deg + (end_deg - start_deg) * k / 22.0) * CV_PI / 180.0;
}

Rgb to_rgb(const cv::Vec3b& bgr) { return Rgb{bgr[2], bgr[1], bgr[0]}; }

}  // namespace

FaceModel fit_face(const FaceFrame& frame, const Regions& regions, Located& located, const std::string& face_name) {
    const FaceModel default_face = FaceModel::default_face();
    std::map<std::string, cv::Point2d> p;
    for (const std::string& id : FaceModel::point_ids()) p[id] = prior(default_face, id);
    const double d = kFrameD;

    auto take = [&](const std::string& feature, const std::vector<const char*>& ids) {
        if (!usable(located, feature)) return false;
        for (const char* id : ids) {
            if (located.points.count(id)) p[id] = located.points[id];
        }
        return true;
    };
    // A prior feature moves with the feature it hangs from: `shift` is added to its prior points.
    auto shift_prior = [&](const std::vector<const char*>& ids, const cv::Point2d& shift) {
        for (const char* id : ids) p[id] += shift;
    };

    // Eyes: the eyeball centres always come from the eye pair (the frame is built on them).
    for (int side = 0; side < 2; ++side) {
        const bool left = side == 0;
        const std::string feature = left ? "left_eye" : "right_eye";
        const char* ball = left ? "EyeballLeft" : "EyeballRight";
        const cv::Point2d centre = located.points.count(ball) ? located.points[ball] : p[ball];
        const cv::Point2d prior_centre = p[ball];
        const std::vector<const char*> ids = left ? std::vector<const char*>{"3.2", "3.4", "3.8", "3.12"}
                                                  : std::vector<const char*>{"3.1", "3.3", "3.7", "3.11"};
        p[ball] = centre;
        if (!take(feature, ids)) {
            shift_prior(ids, centre - prior_centre);
            mark_prior(located, feature);
        }
        // A cartoon eye keeps the iris in sight: at least 0.22 d open (a real open eye is often only
        // 0.12 d, which would draw as a slit).
        const char* top = left ? "3.2" : "3.1";
        const char* bottom = left ? "3.4" : "3.3";
        const double half = std::max(0.11 * d, 0.5 * (p[bottom].y - p[top].y));
        p[top] = {centre.x, centre.y - half};
        p[bottom] = {centre.x, centre.y + half};
    }

    // Brows; a missing one mirrors the other about the face's middle, else comes from the prior.
    const char* brow_left[4] = {"4.6", "4.4a", "4.4", "4.2"};
    const char* brow_right[4] = {"4.5", "4.3a", "4.3", "4.1"};
    const bool has_left_brow = take("left_brow", {"4.6", "4.4a", "4.4", "4.2"});
    const bool has_right_brow = take("right_brow", {"4.5", "4.3a", "4.3", "4.1"});
    for (int side = 0; side < 2; ++side) {
        const bool has = side == 0 ? has_left_brow : has_right_brow;
        const bool has_other = side == 0 ? has_right_brow : has_left_brow;
        if (has) continue;
        const char* const* mine = side == 0 ? brow_left : brow_right;
        const char* const* other = side == 0 ? brow_right : brow_left;
        for (int k = 0; k < 4; ++k) {
            if (has_other) {
                p[mine[k]] = {2.0 * kFrameEyeMid.x - p[other[k]].x, p[other[k]].y};
            }
        }
        mark_prior(located, side == 0 ? "left_brow" : "right_brow");
    }
    // Brows stay above the eyes.
    for (const char* id : {"4.6", "4.4a", "4.4", "4.2", "4.5", "4.3a", "4.3", "4.1"}) {
        p[id].y = std::min(p[id].y, kFrameEyeMid.y - 0.2 * d);
    }

    // Nose; its bridge top always from the prior beside the inner eye corners.
    const cv::Point2d prior_tip = p["9.15"];
    if (!take("nose", {"9.14", "9.13", "9.2", "9.1", "9.4", "9.5", "9.15"})) mark_prior(located, "nose");
    p["9.15"].y = std::clamp(p["9.15"].y, kFrameEyeMid.y + 0.45 * d, kFrameEyeMid.y + 1.0 * d);
    const cv::Point2d nose_shift = p["9.15"] - prior_tip;

    // Mouth, closed (2.2 and 2.3 on one row): a neutral face.
    const std::vector<const char*> mouth_ids = {"8.1", "8.9", "8.10", "8.2", "8.4", "8.3", "2.2", "2.3"};
    const cv::Point2d prior_lip = p["8.2"];
    if (!take("mouth", mouth_ids)) {
        shift_prior(mouth_ids, nose_shift);
        mark_prior(located, "mouth");
    }
    {
        const double line = std::max(p["2.2"].y, p["9.15"].y + 0.15 * d);
        p["2.2"].y = p["2.3"].y = line;
        p["8.1"].y = std::min(p["8.1"].y, line - 0.04 * d);
        p["8.9"].y = std::min(p["8.9"].y, p["8.1"].y);
        p["8.10"].y = std::min(p["8.10"].y, p["8.1"].y);
        p["8.1"].y = std::max(p["8.1"].y, p["9.15"].y + 0.06 * d);
        p["8.9"].y = std::max(p["8.9"].y, p["9.15"].y + 0.04 * d);
        p["8.10"].y = std::max(p["8.10"].y, p["9.15"].y + 0.04 * d);
        p["8.2"].y = std::max(p["8.2"].y, line + 0.06 * d);
        p["8.4"].y = std::clamp(p["8.4"].y, p["8.1"].y, p["8.2"].y);
        p["8.3"].y = std::clamp(p["8.3"].y, p["8.1"].y, p["8.2"].y);
        const double mid = p["8.1"].x;
        p["8.4"].x = std::min(p["8.4"].x, mid - 0.2 * d);
        p["8.3"].x = std::max(p["8.3"].x, mid + 0.2 * d);
        p["8.9"].x = std::clamp(p["8.9"].x, p["8.4"].x + 1.0, mid - 1.0);
        p["8.10"].x = std::clamp(p["8.10"].x, mid + 1.0, p["8.3"].x - 1.0);
        p["2.2"].x = p["2.3"].x = p["8.2"].x = mid;
    }
    const cv::Point2d lip_shift = p["8.2"] - prior_lip;

    // Chin: thesis control point 2.1 = (8.2.x, 8.2.y + JawH).
    if (!take("chin", {"2.1"})) {
        p["2.1"] += lip_shift;
        mark_prior(located, "chin");
    }
    p["2.1"] = {p["8.2"].x, std::max(p["2.1"].y, p["8.2"].y + 0.3 * d)};

    // Face contour from the skin region: temples, cheeks and jaw angles at the rows the default face
    // puts them (jaw a third of the way from the lower lip to the chin).
    const double jaw_y = p["8.2"].y + 0.32 * (p["2.1"].y - p["8.2"].y);
    const double cheek_y = kFrameEyeMid.y + 0.45 * d;
    const double temple_y = kFrameEyeMid.y - 0.52 * d;
    struct Row {
        const char* left;
        const char* right;
        double y;
        double min_d, max_d, prior_d;
    };
    const Row rows[3] = {{"11.2", "11.3", temple_y, 0.75, 1.35, 1.03},
                         {"10.10", "10.9", cheek_y, 0.75, 1.4, 1.03},
                         {"2.14", "2.13", jaw_y, 0.45, 1.2, 0.72}};
    const bool jaw_from_landmarks = located.points.count("2.14") && usable(located, "face_contour");
    int plausible = 0;
    double asymmetry = 0.0;
    double reach[3][2];
    for (int r = 0; r < 3; ++r) {
        for (int side = 0; side < 2; ++side) {
            reach[r][side] = skin_reach(regions.skin, static_cast<int>(std::lround(rows[r].y)), side == 0 ? -1.0 : 1.0) / d;
            if (reach[r][side] >= rows[r].min_d && reach[r][side] <= rows[r].max_d) ++plausible;
        }
        asymmetry += std::abs(reach[r][0] - reach[r][1]) / std::max(0.1, reach[r][0] + reach[r][1]);
    }
    const double contour_confidence =
        regions.skin_confidence * (plausible / 6.0) * std::clamp(1.0 - 2.0 * asymmetry / 3.0, 0.0, 1.0);
    if (!jaw_from_landmarks) located.add_feature("face_contour", contour_confidence, "regions");
    const bool contour_ok = contour_confidence >= kUsableConfidence;
    for (int r = 0; r < 3; ++r) {
        if (jaw_from_landmarks && r > 0) {
            p[rows[r].left] = located.points[rows[r].left];
            p[rows[r].right] = located.points[rows[r].right];
            continue;
        }
        for (int side = 0; side < 2; ++side) {
            double half = rows[r].prior_d;
            if (contour_ok) half = std::clamp(reach[r][side], rows[r].min_d, rows[r].max_d);
            const double x = kFrameEyeMid.x + (side == 0 ? -half : half) * d;
            p[side == 0 ? rows[r].left : rows[r].right] = {x, rows[r].y};
        }
    }
    if (!contour_ok) mark_prior(located, "face_contour");
    // The jaw angles stay inside the cheeks, between the lips and the chin.
    for (int side = 0; side < 2; ++side) {
        const char* jaw = side == 0 ? "2.14" : "2.13";
        const char* cheek = side == 0 ? "10.10" : "10.9";
        const double sign = side == 0 ? -1.0 : 1.0;
        const double limit = p["2.1"].x + sign * (std::abs(p[cheek].x - kFrameEyeMid.x) - 0.05 * d);
        p[jaw].x = sign < 0 ? std::max(p[jaw].x, limit) : std::min(p[jaw].x, limit);
        p[jaw].y = std::clamp(p[jaw].y, p["8.2"].y, p["2.1"].y - 0.1 * d);
        p[cheek].y = std::clamp(p[cheek].y, kFrameEyeMid.y + 0.1 * d, p[jaw].y - 0.1 * d);
    }

    // Hairline: where the skin ends going up the forehead at the middle and at +-0.68 d.
    {
        const int from = static_cast<int>(kFrameEyeMid.y - 0.6 * d);
        // A fringe may come down to just above the brows.
        const double lowest = kFrameEyeMid.y - 0.45 * d, highest = kFrameEyeMid.y - 1.9 * d;
        const double top_mid = skin_top(regions.skin, static_cast<int>(kFrameEyeMid.x), from);
        const double top_left = skin_top(regions.skin, static_cast<int>(kFrameEyeMid.x - 0.68 * d), from);
        const double top_right = skin_top(regions.skin, static_cast<int>(kFrameEyeMid.x + 0.68 * d), from);
        const bool inside = top_mid <= lowest && top_mid >= highest;
        const double confidence = regions.skin_confidence * (inside ? 1.0 : 0.3);
        located.add_feature("hairline", confidence, "regions");
        if (confidence >= kUsableConfidence) {
            p["11.1"] = {kFrameEyeMid.x, top_mid};
            p["11.2a"] = {kFrameEyeMid.x - 0.68 * d, std::clamp(top_left, highest, lowest)};
            p["11.3a"] = {kFrameEyeMid.x + 0.68 * d, std::clamp(top_right, highest, lowest)};
        } else {
            mark_prior(located, "hairline");
        }
        // The hairline's sides stay between the crown and the temples.
        for (const char* id : {"11.2a", "11.3a"}) {
            p[id].y = std::clamp(p[id].y, p["11.1"].y, p["11.2"].y - 0.1 * d);
        }
        p["11.2"].y = p["11.3"].y = std::max(temple_y, std::max(p["11.2a"].y, p["11.3a"].y) + 0.1 * d);
    }

    // Brows stay below the hairline.
    for (const char* id : {"4.6", "4.4a", "4.4", "4.2", "4.5", "4.3a", "4.3", "4.1"}) {
        p[id].y = std::max(p[id].y, p["11.1"].y + 0.08 * d);
    }

    // Ears are rarely separable from the cheek and the hair in a frontal photo: placed from the
    // default face relative to the cheeks.
    {
        const cv::Point2d left_shift(p["10.10"].x - prior(default_face, "10.10").x, 0.0);
        const cv::Point2d right_shift(p["10.9"].x - prior(default_face, "10.9").x, 0.0);
        p["10.2"] = prior(default_face, "10.2") + left_shift;
        p["10.8"] = prior(default_face, "10.8") + left_shift;
        p["10.1"] = prior(default_face, "10.1") + right_shift;
        p["10.7"] = prior(default_face, "10.7") + right_shift;
        located.add_feature("ears", 0.0, "prior");
        mark_prior(located, "ears");
    }
    // The nose bridge's top beside the inner eye corners.
    p["9.6"] = prior(default_face, "9.6") + cv::Point2d(0.5 * (p["3.8"].x + p["3.11"].x) - kFrameEyeMid.x, 0.0);
    p["9.7"] = prior(default_face, "9.7") + cv::Point2d(0.5 * (p["3.8"].x + p["3.11"].x) - kFrameEyeMid.x, 0.0);

    // Hair polygon: rays from the eye midpoint over the crown to where hair or skin ends; never
    // closer than 0.2 d outside the face contour (docs/face-format.md). Without hair the default
    // face's hair, stretched to this face's contour, stands in.
    {
        const auto contour = to_float(contour_polygon(p));
        std::map<std::string, cv::Point2d> default_frame;
        for (const std::string& id : FaceModel::point_ids()) default_frame[id] = prior(default_face, id);
        const auto default_contour = to_float(contour_polygon(default_frame));
        auto inside_of = [](const std::vector<cv::Point2f>& polygon) {
            return [&polygon](const cv::Point2d& q) {
                return cv::pointPolygonTest(polygon, cv::Point2f(static_cast<float>(q.x), static_cast<float>(q.y)), false) >= 0;
            };
        };
        cv::Mat head = regions.hair | regions.skin;
        // The neck and shoulders are not hair: only rows above the mouth count.
        head.rowRange(std::min(head.rows, static_cast<int>(p["2.2"].y)), head.rows).setTo(0);
        auto in_head = [&head](const cv::Point2d& q) {
            const int x = static_cast<int>(std::lround(q.x)), y = static_cast<int>(std::lround(q.y));
            return x >= 0 && y >= 0 && x < head.cols && y < head.rows && head.at<std::uint8_t>(y, x);
        };
        const bool hair_ok = regions.hair_confidence >= kUsableConfidence;
        located.add_feature("hair", regions.hair_confidence, "regions");
        if (!hair_ok) mark_prior(located, "hair");
        std::vector<double> radii(23), minimum(23);
        for (int k = 0; k < 23; ++k) {
            const double angle = hair_angle_rad(k);
            const double face_r = ray_reach(kFrameEyeMid, angle, 4.0 * d, 0.0, inside_of(contour));
            const double up = std::max(0.0, std::sin(angle));
            minimum[static_cast<std::size_t>(k)] = face_r + (0.2 + 0.1 * up) * d;
            double r;
            if (hair_ok) {
                r = ray_reach(kFrameEyeMid, angle, 3.2 * d, 0.12 * d, in_head);
            } else {
                const std::string id = "hair." + std::to_string(k + 1);
                const cv::Point2d q = default_frame[id] - kFrameEyeMid;
                const double default_face_r = ray_reach(kFrameEyeMid, angle, 4.0 * d, 0.0, inside_of(default_contour));
                r = face_r * std::hypot(q.x, q.y) / std::max(1.0, default_face_r);
            }
            radii[static_cast<std::size_t>(k)] = r;
        }
        std::vector<double> smoothed = radii;
        for (std::size_t k = 1; k + 1 < radii.size(); ++k) {
            double trio[3] = {radii[k - 1], radii[k], radii[k + 1]};
            std::sort(trio, trio + 3);
            smoothed[k] = trio[1];
        }
        for (int k = 0; k < 23; ++k) {
            const auto i = static_cast<std::size_t>(k);
            const double r = std::max(smoothed[i], minimum[i]);
            const double angle = hair_angle_rad(k);
            p["hair." + std::to_string(k + 1)] = kFrameEyeMid + r * cv::Point2d(std::cos(angle), -std::sin(angle));
        }
    }

    // Colours: sampled where the feature was found, the default's otherwise.
    FaceColors colours;
    const bool skin_ok = regions.skin_confidence >= kUsableConfidence;
    located.add_feature("skin_colour", regions.skin_confidence, "regions");
    if (skin_ok) {
        colours.skin = to_rgb(regions.skin_bgr);
        colours.outline = Rgb{static_cast<std::uint8_t>(colours.skin.r * 0.4), static_cast<std::uint8_t>(colours.skin.g * 0.35),
                              static_cast<std::uint8_t>(colours.skin.b * 0.3)};
    } else {
        mark_prior(located, "skin_colour");
    }
    located.add_feature("hair_colour", regions.hair_confidence, "regions");
    if (regions.hair_confidence >= kUsableConfidence) {
        colours.hair = to_rgb(regions.hair_bgr);
    } else {
        mark_prior(located, "hair_colour");
    }
    const PhotoFeature* mouth = located.feature("mouth");
    located.add_feature("lip_colour", located.has_lip_colour && mouth ? mouth->confidence : 0.0,
                        mouth ? mouth->source : "thesis");
    if (located.has_lip_colour && usable(located, "mouth")) {
        colours.lips = to_rgb(located.lip_bgr);
    } else {
        mark_prior(located, "lip_colour");
    }
    if (located.has_brow_colour && (has_left_brow || has_right_brow)) colours.brows = to_rgb(located.brow_bgr);
    if (located.has_iris_colour && usable(located, "left_eye")) colours.iris = to_rgb(located.iris_bgr);

    FaceModel face = FaceModel::default_face();
    for (const auto& [id, frame_xy] : p) {
        const cv::Point2d photo_xy = apply(frame.to_photo, frame_xy);
        face.set_point(id, Point2{photo_xy.x, photo_xy.y});
    }
    for (const std::string& name : FaceModel::fapu_names()) face.set_fapu(name, detail::measured_fapu(face, name));
    face.set_colors(colours);
    face.set_name(face_name);
    return face;
}

}  // namespace talkface::photo
