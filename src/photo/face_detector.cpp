// Face from a photo, step 1: the face and its eye pair (thesis 2.2). OpenCV's Haar cascades (Debian
// opencv-data) find face candidates; the eye pair is chosen among dark regions and Haar eye windows by
// the thesis's rules on size and position and by the symmetry of the pair.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>

#include "photo/photo_internal.hpp"
#include "talkface/errors.hpp"

namespace talkface::photo {

namespace {

// Detection runs on a copy no larger than this: Haar windows need no more, and a 24-megapixel photo
// would take seconds.
constexpr int kDetectMaxSide = 800;
// The brightest 5 % of a usable photo reach at least this (of 255); a face's mean at least this.
constexpr double kMinPhotoBrightness = 50.0;
constexpr double kMinFaceBrightness = 55.0;

std::string cascade_folder(const PhotoOptions& options) {
    if (!options.cascade_dir.empty()) return options.cascade_dir;
    if (const char* from_env = std::getenv("TALKFACE_HAARCASCADES_DIR"); from_env && *from_env) return from_env;
    for (const char* folder : {"/usr/share/opencv4/haarcascades", "/usr/share/opencv/haarcascades"}) {
        if (std::ifstream(std::string(folder) + "/haarcascade_frontalface_alt2.xml").good()) return folder;
    }
    return "/usr/share/opencv4/haarcascades";
}

// Each thread keeps its own classifiers: CascadeClassifier::detectMultiScale is not const, and
// loading one takes tens of milliseconds, too long to repeat per photo.
cv::CascadeClassifier& cascade(const PhotoOptions& options, const char* file_name) {
    thread_local std::map<std::string, std::unique_ptr<cv::CascadeClassifier>> loaded;
    const std::string path = cascade_folder(options) + "/" + file_name;
    auto found = loaded.find(path);
    if (found != loaded.end()) return *found->second;
    if (!std::ifstream(path).good()) {
        throw FileError(path, "OpenCV's Haar cascade is missing; install Debian's opencv-data or pass "
                              "the folder that holds it (PhotoOptions::cascade_dir)");
    }
    auto classifier = std::make_unique<cv::CascadeClassifier>();
    if (!classifier->load(path)) throw FileError(path, "not a Haar cascade OpenCV can read");
    return *loaded.emplace(path, std::move(classifier)).first->second;
}

std::string describe(const cv::Rect& box) {
    std::ostringstream text;
    text << "at " << box.x << "," << box.y << " size " << box.width << "x" << box.height;
    return text.str();
}

double overlap(const cv::Rect& a, const cv::Rect& b) {
    const double shared = (a & b).area();
    return shared / std::min(a.area(), b.area());
}

struct Candidate {
    cv::Rect box;
    int votes = 0;
};

std::vector<Candidate> detect(cv::CascadeClassifier& classifier, const cv::Mat& small, double scale,
                              int min_neighbours) {
    std::vector<cv::Rect> boxes;
    std::vector<int> votes;
    classifier.detectMultiScale(small, boxes, votes, 1.08, min_neighbours, 0, cv::Size(20, 20));
    std::vector<Candidate> found;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const cv::Rect& b = boxes[i];
        Candidate c{cv::Rect(static_cast<int>(std::lround(b.x * scale)), static_cast<int>(std::lround(b.y * scale)),
                             static_cast<int>(std::lround(b.width * scale)),
                             static_cast<int>(std::lround(b.height * scale))),
                    i < votes.size() ? votes[i] : min_neighbours};
        // A window inside a larger face (an eye taken for a face) is not a second face.
        bool merged = false;
        for (Candidate& kept : found) {
            if (overlap(kept.box, c.box) > 0.4) {
                if (c.votes > kept.votes) kept = c;
                merged = true;
                break;
            }
        }
        if (!merged) found.push_back(c);
    }
    return found;
}

double percentile(const cv::Mat& gray, double fraction) {
    int histogram[256] = {};
    for (int y = 0; y < gray.rows; ++y) {
        const std::uint8_t* row = gray.ptr<std::uint8_t>(y);
        for (int x = 0; x < gray.cols; ++x) ++histogram[row[x]];
    }
    const double wanted = fraction * static_cast<double>(gray.total());
    double seen = 0.0;
    for (int level = 0; level < 256; ++level) {
        seen += histogram[level];
        if (seen >= wanted) return level;
    }
    return 255.0;
}

// The share of a box's middle whose chroma is skin's (YCrCb, Chai and Ngan's ranges); 1 for a grey
// photo, where chroma tells nothing.
double skin_share(const cv::Mat& bgr, const cv::Rect& box) {
    const cv::Rect middle = cv::Rect(box.x + box.width / 4, box.y + box.height / 4, box.width / 2, box.height / 2) &
                            cv::Rect(0, 0, bgr.cols, bgr.rows);
    if (middle.area() == 0) return 0.0;
    cv::Mat ycrcb;
    cv::cvtColor(bgr(middle), ycrcb, cv::COLOR_BGR2YCrCb);
    int skin = 0, grey = 0;
    for (int y = 0; y < ycrcb.rows; ++y) {
        for (int x = 0; x < ycrcb.cols; ++x) {
            const cv::Vec3b v = ycrcb.at<cv::Vec3b>(y, x);
            if (v[1] >= 133 && v[1] <= 173 && v[2] >= 77 && v[2] <= 127) ++skin;
            if (std::abs(v[1] - 128) < 3 && std::abs(v[2] - 128) < 3) ++grey;
        }
    }
    if (grey == middle.area()) return 1.0;
    return static_cast<double>(skin) / middle.area();
}

}  // namespace

DetectedFace detect_face(const cv::Mat& bgr, const cv::Mat& gray, const PhotoOptions& options,
                         const std::string& source) {
    const double bright = percentile(gray, 0.95);
    if (bright < kMinPhotoBrightness) {
        fail(source, "too dark: the brightest 5% of the pixels reach only " + std::to_string(static_cast<int>(bright)) +
                         " of 255 (at least " + std::to_string(static_cast<int>(kMinPhotoBrightness)) +
                         " needed); light the face evenly or brighten the photo");
    }
    const double scale = std::max(1.0, std::max(gray.cols, gray.rows) / static_cast<double>(kDetectMaxSide));
    cv::Mat small;
    if (scale > 1.0) {
        cv::resize(gray, small, cv::Size(), 1.0 / scale, 1.0 / scale, cv::INTER_AREA);
    } else {
        small = gray;
    }
    cv::equalizeHist(small, small);

    std::vector<Candidate> faces = detect(cascade(options, "haarcascade_frontalface_alt2.xml"), small, scale, 3);
    if (faces.empty()) faces = detect(cascade(options, "haarcascade_frontalface_default.xml"), small, scale, 6);
    if (faces.empty()) {
        cv::Mat flipped;
        cv::flip(small, flipped, 1);
        auto& profile = cascade(options, "haarcascade_profileface.xml");
        if (!detect(profile, small, scale, 5).empty() || !detect(profile, flipped, scale, 5).empty()) {
            fail(source, "face not frontal enough: only a face seen from the side was found; use a photo "
                         "that looks straight into the camera");
        }
        fail(source, "no face found; use a frontal photo of one face, lit evenly, at least " +
                         std::to_string(options.min_face_width_px) + " px wide");
    }
    // Thesis 2.2 looks for the face among skin-coloured regions: a window with hardly any skin in
    // its middle (a badge, a pattern) or with far fewer detector votes than the best is not a face.
    int most_votes = 0;
    for (const Candidate& c : faces) most_votes = std::max(most_votes, c.votes);
    faces.erase(std::remove_if(faces.begin(), faces.end(),
                               [&](const Candidate& c) {
                                   return skin_share(bgr, c.box) < 0.25 || c.votes * 4 < most_votes;
                               }),
                faces.end());
    if (faces.empty()) {
        fail(source, "no face found: the face-like windows hold no skin colour; use a frontal colour photo of one face, lit evenly");
    }
    std::sort(faces.begin(), faces.end(), [](const Candidate& a, const Candidate& b) { return a.box.x < b.box.x; });

    const int count = static_cast<int>(faces.size());
    int index = options.face_index;
    if (index < 0) {
        if (count > 1) {
            std::string where;
            for (int i = 0; i < count; ++i) {
                where += (i ? "; " : "") + std::to_string(i) + " " + describe(faces[static_cast<std::size_t>(i)].box);
            }
            fail(source, std::to_string(count) + " faces found (" + where + "); pass face_index 0.." +
                             std::to_string(count - 1) + " to choose one (0 is the leftmost)");
        }
        index = 0;
    } else if (index >= count) {
        throw InvalidArgument("face_index", source + ": " + std::to_string(count) + " face" +
                                                (count == 1 ? "" : "s") + " found, so face_index must be 0.." +
                                                std::to_string(count - 1) + ", found " + std::to_string(index));
    }
    const Candidate& chosen = faces[static_cast<std::size_t>(index)];
    if (chosen.box.width < options.min_face_width_px) {
        fail(source, "face too small: " + std::to_string(chosen.box.width) + " px wide " + describe(chosen.box) +
                         ", at least " + std::to_string(options.min_face_width_px) +
                         " px needed; use a closer or larger photo");
    }
    const cv::Rect inside = chosen.box & cv::Rect(0, 0, gray.cols, gray.rows);
    const double face_mean = cv::mean(gray(inside))[0];
    if (face_mean < kMinFaceBrightness) {
        fail(source, "face too dark: its mean brightness is " + std::to_string(static_cast<int>(face_mean)) +
                         " of 255 (at least " + std::to_string(static_cast<int>(kMinFaceBrightness)) +
                         " needed); light the face evenly");
    }
    // alt2 with 3 neighbours: a face seen clearly collects 10 to 40 windows.
    return DetectedFace{chosen.box, count, std::min(1.0, 0.4 + chosen.votes / 25.0)};
}

EyePair find_eye_pair(const cv::Mat& gray, const cv::Rect& face, const PhotoOptions& options) {
    const double w = face.width;
    const double h = face.height;
    // Knowledge (thesis 2.2): the eyes lie in the upper half of a frontal face's box.
    cv::Rect band(face.x, face.y + static_cast<int>(0.18 * h), face.width, static_cast<int>(0.42 * h));
    band &= cv::Rect(0, 0, gray.cols, gray.rows);
    // Work at a fixed face width of 160 px so that the rules below hold for any photo size.
    const double to_work = 160.0 / w;
    cv::Mat roi;
    cv::resize(gray(band), roi, cv::Size(), to_work, to_work, cv::INTER_AREA);
    cv::GaussianBlur(roi, roi, cv::Size(3, 3), 0.0);

    struct Eye {
        cv::Point2d centre;  // work pixels inside the band
        double area = 0.0;
        double darkness = 0.0;
        bool from_cascade = false;
    };
    std::vector<Eye> candidates;

    // Bi-level thresholding of the band: the darker class holds brows, eyes and shadows.
    cv::Mat dark;
    cv::threshold(roi, dark, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
    cv::Mat labels, stats, centroids;
    const int count = cv::connectedComponentsWithStats(dark, labels, stats, centroids, 8);
    const double band_mean = cv::mean(roi)[0];
    for (int label = 1; label < count; ++label) {
        const int bw = stats.at<int>(label, cv::CC_STAT_WIDTH);
        const int bh = stats.at<int>(label, cv::CC_STAT_HEIGHT);
        const int area = stats.at<int>(label, cv::CC_STAT_AREA);
        // Rules on the region (thesis 2.2): an eye is a few pixels to a fifth of the face wide, wider
        // than tall but not a brow-like streak.
        if (area < 12 || bw > 50 || bh > 32 || bw < 4) continue;
        const double aspect = static_cast<double>(bw) / bh;
        if (aspect < 0.6 || aspect > 5.0) continue;
        const cv::Mat mask = labels == label;
        // The iris is the darkest part: weight the centre by darkness below the band's mean.
        double sx = 0, sy = 0, sw = 0;
        const int x0 = stats.at<int>(label, cv::CC_STAT_LEFT), y0 = stats.at<int>(label, cv::CC_STAT_TOP);
        for (int y = y0; y < y0 + bh; ++y) {
            for (int x = x0; x < x0 + bw; ++x) {
                if (!mask.at<std::uint8_t>(y, x)) continue;
                const double weight = std::pow(std::max(0.0, band_mean - roi.at<std::uint8_t>(y, x)), 2.0);
                sx += weight * x;
                sy += weight * y;
                sw += weight;
            }
        }
        if (sw <= 0) continue;
        const double mean_inside = cv::mean(roi, mask)[0];
        candidates.push_back({{sx / sw, sy / sw}, static_cast<double>(area), band_mean - mean_inside, false});
    }
    std::vector<cv::Rect> haar_eyes;
    cascade(options, "haarcascade_eye.xml").detectMultiScale(roi, haar_eyes, 1.08, 3, 0, cv::Size(12, 12));
    for (const cv::Rect& e : haar_eyes) {
        candidates.push_back({{e.x + 0.5 * e.width, e.y + 0.55 * e.height}, 0.05 * e.area(), 0.0, true});
    }

    // Pair rules and symmetry score, in the 160-px-wide work frame.
    const double work_h = roi.rows;
    const double centre_x = 80.0;
    EyePair best;
    double best_score = 0.0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        for (std::size_t j = 0; j < candidates.size(); ++j) {
            const Eye& a = candidates[i];
            const Eye& b = candidates[j];
            const double dx = b.centre.x - a.centre.x;
            const double dy = b.centre.y - a.centre.y;
            if (dx < 0.26 * 160 || dx > 0.62 * 160 || std::abs(dy) > 0.25 * dx) continue;
            const double mid_x = 0.5 * (a.centre.x + b.centre.x);
            if (std::abs(mid_x - centre_x) > 0.15 * 160) continue;
            const double symmetry = 1.0 - std::abs(mid_x - centre_x) / (0.15 * 160);
            const double level = 1.0 - std::abs(dy) / (0.25 * dx);
            const double spacing = 1.0 - std::min(1.0, std::abs(dx - 0.42 * 160) / (0.2 * 160));
            double likeness = 0.5;
            if (!a.from_cascade && !b.from_cascade) {
                likeness = std::min(a.area, b.area) / std::max(a.area, b.area) *
                           std::min(a.darkness, b.darkness) / std::max(1.0, std::max(a.darkness, b.darkness));
            }
            // Eyes sit below the brows: among stacked candidates prefer the lower pair a little.
            const double lowness = 0.5 + 0.5 * std::min(a.centre.y, b.centre.y) / work_h;
            const double cascade_bonus = 0.15 * (a.from_cascade + b.from_cascade);
            const double score = (0.3 * symmetry + 0.2 * level + 0.2 * spacing + 0.3 * likeness) * lowness +
                                 cascade_bonus;
            if (score > best_score) {
                best_score = score;
                const cv::Point2d origin(band.x, band.y);
                best.left = origin + a.centre / to_work;
                best.right = origin + b.centre / to_work;
            }
        }
    }
    if (best_score <= 0.0) {
        // No pair passed the rules: a frontal face's usual eye places in its Haar box.
        best.left = {face.x + 0.3 * w, face.y + 0.4 * h};
        best.right = {face.x + 0.7 * w, face.y + 0.4 * h};
        best.confidence = 0.1;
        return best;
    }
    best.confidence = std::clamp(best_score, 0.0, 1.0);
    return best;
}

void check_frontal(const EyePair& eyes, const cv::Rect& face, const std::string& source) {
    const cv::Point2d mid = 0.5 * (eyes.left + eyes.right);
    const double off_centre = (mid.x - (face.x + 0.5 * face.width)) / face.width;
    if (std::abs(off_centre) > 0.12) {
        fail(source, "face not frontal enough: its eyes sit " + std::to_string(static_cast<int>(std::lround(std::abs(off_centre) * 100))) +
                         "% of the face's width off its centre (the head is turned); use a photo that "
                         "looks straight into the camera");
    }
    const double roll_deg = std::atan2(eyes.right.y - eyes.left.y, eyes.right.x - eyes.left.x) * 180.0 / CV_PI;
    if (std::abs(roll_deg) > 20.0) {
        fail(source, "face not frontal enough: the head is tilted by " +
                         std::to_string(static_cast<int>(std::lround(roll_deg))) +
                         " degrees (at most 20 accepted); straighten the photo");
    }
}

}  // namespace talkface::photo
