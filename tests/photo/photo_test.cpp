// Face from a photo (thesis 2.2): both locators against hand-marked landmarks of real photos, a
// closed loop (render a known face, extract it, compare), photo files good and broken, and every
// error a caller can meet.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <zlib.h>

#include "common/test_paths.hpp"
#include "photo/photo_internal.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_from_photo.hpp"
#include "talkface/svg_animator.hpp"

using namespace talkface;

namespace {

// Debian python3-skimage: NASA portrait of astronaut Eileen Collins (public domain, a work of the US
// government). Read from the package at test time; cmake/install-deps.sh test installs it.
const std::string kAstronaut = "/usr/lib/python3/dist-packages/skimage/data/astronaut.png";
// Debian python-matplotlib-data: the US Navy's 1984 portrait of Commodore Grace Hopper (public
// domain, a work of the US government), a JPEG; glasses and a cap make it harder than astronaut.png.
const std::string kHopper = "/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg";

bool exists(const std::string& path) { return std::ifstream(path).good(); }

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string write_bytes(const std::string& name, const std::string& bytes) {
    const std::string path = test::output_path(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

cv::Mat read_photo(const std::string& path) { return photo::read_photo_file(path); }

// Landmarks marked by hand on an 8x enlargement of astronaut.png (image pixels, +-1 px).
const std::map<std::string, Point2> kAstronautMarks = {
    {"EyeballLeft", {204, 100}}, {"EyeballRight", {246, 102}},  // iris centres
    {"8.4", {203, 140}},         {"8.3", {243, 141}},           // mouth corners
    {"9.15", {223, 131}},                                       // nose tip, bottom centre
    {"2.1", {222, 178}},                                        // chin
};

// Landmarks marked by hand on 9x to 16x enlargements of grace_hopper.jpg (image pixels, +-1.5 px).
const std::map<std::string, Point2> kHopperMarks = {
    {"EyeballLeft", {222, 190}}, {"EyeballRight", {305, 187}},  // iris centres, behind the glasses
    {"8.4", {229, 281}},         {"8.3", {301, 277}},           // where the lips end
    {"9.15", {266, 251}},                                       // nose tip, bottom centre
    {"2.1", {265, 326}},                                        // chin
};

double distance_in_d(Point2 a, Point2 b, double d) { return std::hypot(a.x - b.x, a.y - b.y) / d; }

bool segments_cross(Point2 a, Point2 b, Point2 c, Point2 e) {
    auto side = [](Point2 p, Point2 q, Point2 r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    return side(a, b, c) * side(a, b, e) < 0 && side(c, e, a) * side(c, e, b) < 0;
}

bool hair_is_simple(const FaceModel& face) {
    std::vector<Point2> hair;
    for (int k = 1; k <= 23; ++k) hair.push_back(face.point("hair." + std::to_string(k)));
    for (std::size_t i = 0; i < hair.size(); ++i) {
        for (std::size_t j = i + 2; j < hair.size(); ++j) {
            if (i == 0 && j + 1 == hair.size()) continue;  // neighbours through the closing edge
            if (segments_cross(hair[i], hair[(i + 1) % hair.size()], hair[j], hair[(j + 1) % hair.size()])) return false;
        }
    }
    return true;
}

// What every extracted face must satisfy: a valid face file, a closed mouth, a simple hair polygon
// above the forehead, features with confidences in 0..1.
void check_valid(const PhotoFaceResult& result) {
    const FaceModel& face = result.face;
    const std::string path = test::output_path("photo_round_trip.xml");
    face.save(path);
    CHECK(FaceModel::load(path) == face);
    CHECK(face.point("2.2") == face.point("2.3"));
    CHECK(hair_is_simple(face));
    CHECK(face.point("hair.12").y < face.point("11.1").y);
    CHECK(face.point("8.4").x < face.point("8.3").x);
    CHECK(face.point("9.15").y < face.point("2.2").y);
    CHECK(result.features.size() >= 16);
    for (const PhotoFeature& feature : result.features) {
        CAPTURE(feature.name);
        CHECK(feature.confidence >= 0.0);
        CHECK(feature.confidence <= 1.0);
    }
}

std::vector<PhotoLocator> locators() {
    std::vector<PhotoLocator> all{PhotoLocator::thesis};
    if (has_dlib_locator() && exists("/usr/share/dlib/shape_predictor_68_face_landmarks.dat")) {
        all.push_back(PhotoLocator::dlib);
    }
    return all;
}

PhotoFaceResult from_mat(const cv::Mat& bgr, PhotoOptions options = {}) {
    options.locator = PhotoLocator::thesis;
    options.source_name = "test.png";
    return face_from_photo(ImageView{bgr.data, bgr.cols, bgr.rows, static_cast<int>(bgr.step[0]), PixelFormat::bgr8},
                           options);
}

// The face drawn by talkface, as a PNG through rsvg-convert (Debian librsvg2-bin); the SVG's viewBox
// origin is returned, as the PNG's pixel (0, 0) stands there. Empty when rsvg-convert is missing.
std::string render_png(const FaceModel& face, const std::string& name, Point2& view_origin,
                       const FaceState& state = {}) {
    if (std::system("command -v rsvg-convert > /dev/null 2>&1") != 0) return "";
    const std::string svg = SvgAnimator(face).render_svg(state);
    const auto at = svg.find("viewBox=\"");
    REQUIRE(at != std::string::npos);
    view_origin.x = std::atof(svg.c_str() + at + 9);
    view_origin.y = std::atof(svg.c_str() + svg.find(' ', at + 9) + 1);
    const std::string svg_path = test::output_path(name + ".svg");
    const std::string png_path = test::output_path(name + ".png");
    std::ofstream(svg_path) << svg;
    REQUIRE(std::system(("rsvg-convert '" + svg_path + "' -o '" + png_path + "'").c_str()) == 0);
    return png_path;
}

}  // namespace

TEST_SUITE("face_from_photo") {

TEST_CASE("both locators find the hand-marked landmarks of real photos within a tolerance in d") {
    struct Photo {
        std::string path;
        const std::map<std::string, Point2>* marks;
        std::string package;
        // Tolerances in units of d per locator: the eye centres are sharp, mouth corners and nose
        // tip less so, the chin's edge is soft. On grace_hopper.jpg the thesis locator takes the
        // smile creases beside the lips for the mouth's ends (measured 0.21 d; docs/photo.md).
        std::map<std::string, double> thesis_tolerance_d;
        std::map<std::string, double> dlib_tolerance_d;
    };
    const std::map<std::string, double> usual = {{"EyeballLeft", 0.1}, {"EyeballRight", 0.1}, {"8.4", 0.15},
                                                 {"8.3", 0.15},        {"9.15", 0.15},        {"2.1", 0.15}};
    std::map<std::string, double> wide_mouth = usual;
    wide_mouth["8.4"] = wide_mouth["8.3"] = 0.25;
    const std::vector<Photo> photos = {{kAstronaut, &kAstronautMarks, "python3-skimage", usual, usual},
                                       {kHopper, &kHopperMarks, "python-matplotlib-data", wide_mouth, usual}};
    for (const Photo& real : photos) {
        CAPTURE(real.path);
        if (!exists(real.path)) {
            MESSAGE("skipped: " << real.path << " is missing; install Debian's " << real.package);
            continue;
        }
        const Point2 left = real.marks->at("EyeballLeft"), right = real.marks->at("EyeballRight");
        const double d = std::hypot(right.x - left.x, right.y - left.y);
        for (PhotoLocator locator : locators()) {
            CAPTURE(photo_locator_name(locator));
            PhotoOptions options;
            options.locator = locator;
            const PhotoFaceResult result = face_from_photo_file(real.path, options);
            CHECK(result.locator_used == locator);
            CHECK(result.faces_found == 1);
            const auto& tolerance_d = locator == PhotoLocator::thesis ? real.thesis_tolerance_d : real.dlib_tolerance_d;
            for (const auto& [id, mark] : *real.marks) {
                CAPTURE(id);
                const double error = distance_in_d(result.face.point(id), mark, d);
                CAPTURE(error);
                CHECK(error <= tolerance_d.at(id));
            }
            CHECK(result.confidence("eye_pair") > 0.5);
            CHECK(result.confidence("mouth") > 0.5);
            CHECK(result.confidence("hair") > 0.35);
            check_valid(result);
        }
    }
}

TEST_CASE("an extracted face samples skin, hair and lip colours from the photo") {
    if (!exists(kAstronaut)) return;
    PhotoOptions options;
    options.locator = PhotoLocator::thesis;
    const FaceColors colours = face_from_photo_file(kAstronaut, options).face.colors();
    // Fair skin, brown hair, pinkish lips: reddest channel first in each.
    CHECK(colours.skin.r > colours.skin.b);
    CHECK(colours.skin.r > 150);
    CHECK(colours.hair.r > colours.hair.b);
    CHECK(colours.hair.r < colours.skin.r);
    CHECK(colours.lips.r > colours.lips.g);
}

TEST_CASE("closed loop: rendered faces come back with their points within a tolerance in d") {
    struct Case {
        std::string name;
        FaceModel face;
    };
    const std::vector<Case> cases = {{"default", FaceModel::default_face()},
                                     {"male", FaceModel::load(test::source_path("samples/faces/male.xml"))},
                                     {"female", FaceModel::load(test::source_path("samples/faces/female.xml"))}};
    const std::map<std::string, std::vector<std::string>> groups = {
        {"eyes", {"EyeballLeft", "EyeballRight", "3.12", "3.8", "3.11", "3.7"}},
        {"mouth", {"8.4", "8.3", "8.1", "8.2", "2.2"}},
        {"nose", {"9.15"}},
        {"jaw", {"2.1"}},
        {"cheeks", {"10.10", "10.9"}}};
    // Tolerances in d: the thesis locator's windows were tuned on photos, not drawings (see
    // docs/photo.md for the measured errors of both locators). The cheeks are the skin's reach at
    // cheek height, which takes in an ear beside the cheek: the drawn ears show there (issue 17),
    // 0.37 d beyond the default face's cheek, 0.34 d beyond the male's.
    const std::map<std::string, double> tolerance_d = {
        {"eyes", 0.1}, {"mouth", 0.15}, {"nose", 0.25}, {"jaw", 0.25}, {"cheeks", 0.4}};
    for (const Case& c : cases) {
        CAPTURE(c.name);
        Point2 origin;
        const std::string png = render_png(c.face, "photo_loop_" + c.name, origin);
        if (png.empty()) {
            MESSAGE("skipped: rsvg-convert is missing; install Debian's librsvg2-bin");
            return;
        }
        for (PhotoLocator locator : {PhotoLocator::thesis}) {
            PhotoOptions options;
            options.locator = locator;
            const PhotoFaceResult result = face_from_photo_file(png, options);
            const double d = c.face.fapu("d");
            for (const auto& [group, ids] : groups) {
                for (const std::string& id : ids) {
                    CAPTURE(group);
                    CAPTURE(id);
                    const Point2 found = result.face.point(id);
                    const double error = distance_in_d({found.x + origin.x, found.y + origin.y}, c.face.point(id), d);
                    CAPTURE(error);
                    CHECK(error <= tolerance_d.at(group));
                }
            }
            check_valid(result);
        }
    }
}

TEST_CASE("a blank image has no face") {
    const cv::Mat blank(300, 300, CV_8UC3, cv::Scalar(180, 180, 180));
    const auto message_of = [](auto call) {
        try {
            call();
        } catch (const InvalidArgument& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    CHECK(message_of([&] { from_mat(blank); }).rfind("test.png: no face found", 0) == 0);
    // The default source name stands for the photo once: "photo: no face found", not "photo: photo: ...".
    const ImageView view{blank.data, blank.cols, blank.rows, static_cast<int>(blank.step[0]),
                         PixelFormat::bgr8};
    PhotoOptions unnamed;
    unnamed.locator = PhotoLocator::thesis;
    const std::string message = message_of([&] { face_from_photo(view, unnamed); });
    CAPTURE(message);
    CHECK(message.rfind("photo: no face found", 0) == 0);
}

TEST_CASE("a dark photo is refused as too dark") {
    if (!exists(kAstronaut)) return;
    const cv::Mat dark = read_photo(kAstronaut) * 0.12;
    CHECK_THROWS_WITH_AS(from_mat(dark), doctest::Contains("too dark"), InvalidArgument);
}

TEST_CASE("a tiny face is refused as too small") {
    if (!exists(kAstronaut)) return;
    cv::Mat small;
    cv::resize(read_photo(kAstronaut), small, cv::Size(), 0.45, 0.45, cv::INTER_AREA);
    CHECK_THROWS_WITH_AS(from_mat(small), doctest::Contains("face too small"), InvalidArgument);
}

TEST_CASE("two faces side by side: refused until face_index picks one") {
    if (!exists(kAstronaut)) return;
    const cv::Mat one = read_photo(kAstronaut);
    cv::Mat two;
    cv::hconcat(one, one, two);
    CHECK_THROWS_WITH_AS(from_mat(two), doctest::Contains("2 faces found"), InvalidArgument);
    CHECK_THROWS_WITH_AS(from_mat(two), doctest::Contains("pass face_index 0..1"), InvalidArgument);
    PhotoOptions options;
    options.face_index = 1;
    const PhotoFaceResult right = from_mat(two, options);
    CHECK(right.faces_found == 2);
    CHECK(right.face.point("EyeballLeft").x == doctest::Approx(512 + 204).epsilon(0.01));
    options.face_index = 2;
    CHECK_THROWS_WITH_AS(from_mat(two, options), doctest::Contains("face_index must be 0..1"), InvalidArgument);
}

TEST_CASE("closed loop: a face seen turned far to one side is refused as not frontal enough") {
    // talkface's renderer turns a head by at most 15 degrees, and at 15 degrees the cues the method
    // has (the eye pair's place in the face box, the skin's reach beside each eye) differ from a
    // frontal face's no more than real frontal photos do: the reach differs by 13 % between the two
    // sides of the rendered face, by 11 % on astronaut.png (docs/photo.md). So such a photo is
    // accepted. A farther turn is drawn here as the renderer's 15 degrees with the receding cheek,
    // jaw and ear pulled in by a further 0.28 d. The window is narrow and moves with the drawing:
    // with the thesis's drawing 0.35 d was refused and 0.3 d accepted; with issue 17's (rounded ears
    // under the hair, the new nose, teeth) 0.24 d and 0.28 d are refused, and from 0.32 d Haar's
    // frontal cascade no longer finds the face ("no face found").
    FaceModel face = FaceModel::default_face();
    const double d = face.fapu("d");
    for (const char* id : {"11.2", "10.10", "2.14", "10.2", "10.8"}) {
        const Point2 at = face.point(id);
        face.set_point(id, {at.x + 0.28 * d, at.y});
    }
    FaceState state;
    state.pose.beta_deg = 15.0;
    Point2 origin;
    const std::string png = render_png(face, "photo_turned", origin, state);
    if (png.empty()) {
        MESSAGE("skipped: rsvg-convert is missing; install Debian's librsvg2-bin");
        return;
    }
    PhotoOptions options;
    options.locator = PhotoLocator::thesis;
    CHECK_THROWS_WITH_AS(face_from_photo_file(png, options), doctest::Contains("face not frontal enough"),
                         InvalidArgument);
}

TEST_CASE("a feature painted over gets a low confidence and comes from the priors") {
    if (!exists(kAstronaut)) return;
    PhotoOptions options;
    options.locator = PhotoLocator::thesis;
    const PhotoFaceResult seen = face_from_photo_file(kAstronaut, options);
    // The lips (hand-marked corners (203, 140) and (243, 141)) covered with the chin's skin colour,
    // as a hand or a scarf would hide them.
    cv::Mat covered = read_photo(kAstronaut);
    const cv::Scalar chin_skin = cv::mean(covered(cv::Rect(210, 162, 25, 8)));
    cv::rectangle(covered, cv::Rect(194, 130, 60, 30), chin_skin, cv::FILLED);
    const PhotoFaceResult hidden = from_mat(covered, options);
    CHECK(seen.confidence("mouth") > 0.5);
    CHECK(hidden.confidence("mouth") < photo::kUsableConfidence);
    for (const PhotoFeature& feature : hidden.features) {
        CAPTURE(feature.name);
        if (feature.name == "mouth") CHECK(feature.from_prior);
        if (feature.name == "left_eye" || feature.name == "right_eye") CHECK(feature.confidence > 0.5);
    }
}

TEST_CASE("PNG and JPEG photo files decode as the viewers show them, EXIF orientation applied") {
    if (!exists(kAstronaut) || !exists(kHopper)) return;
    const cv::Mat png = read_photo(kAstronaut);
    REQUIRE(png.size() == cv::Size(512, 512));
    // RGB (42, 29, 17) and (154, 147, 151) as python3-skimage reads them, stored B, G, R.
    CHECK(png.at<cv::Vec3b>(100, 204) == cv::Vec3b(17, 29, 42));
    CHECK(png.at<cv::Vec3b>(0, 0) == cv::Vec3b(151, 147, 154));
    const cv::Mat jpeg = read_photo(kHopper);
    REQUIRE(jpeg.size() == cv::Size(512, 600));
    // RGB (216, 136, 103) as python3-skimage reads it (the same libjpeg-turbo, so exactly).
    CHECK(jpeg.at<cv::Vec3b>(300, 256) == cv::Vec3b(103, 136, 216));

    // An EXIF APP1 segment saying "orientation 6" (stored turned; show rotated 90 degrees
    // clockwise), put right after the JPEG's start-of-image marker.
    const std::string exif_tiff("MM\0*\0\0\0\x08\0\x01\x01\x12\0\x03\0\0\0\x01\0\x06\0\0\0\0\0\0", 26);
    const std::string payload = std::string("Exif\0\0", 6) + exif_tiff;
    const std::size_t length = payload.size() + 2;
    const std::string app1 = std::string("\xFF\xE1", 2) + static_cast<char>(length >> 8) +
                             static_cast<char>(length & 0xFF) + payload;
    std::string bytes = read_bytes(kHopper);
    bytes.insert(2, app1);
    const cv::Mat turned = read_photo(write_bytes("photo_exif_6.jpg", bytes));
    REQUIRE(turned.size() == cv::Size(600, 512));
    for (const cv::Point at : {cv::Point(0, 0), cv::Point(10, 200), cv::Point(599, 511), cv::Point(300, 256)}) {
        CAPTURE(at);
        CHECK(turned.at<cv::Vec3b>(at) == jpeg.at<cv::Vec3b>(jpeg.rows - 1 - at.x, at.y));
    }
}

TEST_CASE("a broken photo file is a FileError naming the file and what is wrong") {
    const auto check_refused = [](const std::string& path, const char* problem) {
        CAPTURE(path);
        CHECK_THROWS_WITH_AS(face_from_photo_file(path), doctest::Contains(path.c_str()), FileError);
        CHECK_THROWS_WITH_AS(face_from_photo_file(path), doctest::Contains(problem), FileError);
    };
    check_refused("/nonexistent/me.jpg", "No such file or directory");
    check_refused(write_bytes("photo_empty.jpg", ""), "the file is empty");
    check_refused(write_bytes("photo_text.png", "hello, not a photo\n"), "not a PNG or JPEG photo");
    check_refused(write_bytes("photo.bmp", std::string("BM\x36\0\0\0\0\0", 8)), "a BMP image; talkface reads PNG and JPEG");
    if (!exists(kAstronaut) || !exists(kHopper)) return;

    const std::string png = read_bytes(kAstronaut);
    check_refused(write_bytes("photo_truncated.png", png.substr(0, png.size() / 2)), "broken PNG: the file ends");
    std::string corrupt_png = png;
    for (std::size_t k = png.size() / 2; k < png.size() / 2 + 64; ++k) corrupt_png[k] = static_cast<char>(~png[k]);
    check_refused(write_bytes("photo_corrupt.png", corrupt_png), "broken PNG");

    const std::string jpeg = read_bytes(kHopper);
    check_refused(write_bytes("photo_truncated.jpg", jpeg.substr(0, jpeg.size() / 2)),
                  "broken JPEG: the file ends before the image does (truncated)");
    // JPEG has no checksum: corruption is caught where libjpeg can tell, as a marker in the middle
    // of the compressed data or a header that does not add up.
    std::string corrupt_jpeg = jpeg;
    corrupt_jpeg.replace(jpeg.size() / 2, 2, "\xFF\xD9");
    check_refused(write_bytes("photo_corrupt.jpg", corrupt_jpeg), "broken JPEG: Corrupt JPEG data");
    // Headers that claim 20000 x 20000 pixels are refused before any pixel is decoded.
    std::string huge_png = png;
    for (int k = 0; k < 8; ++k) huge_png[16 + k] = "\0\0\x4e\x20\0\0\x4e\x20"[k];
    const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(huge_png.data() + 12), 17);
    for (int k = 0; k < 4; ++k) huge_png[29 + k] = static_cast<char>(crc >> (24 - 8 * k));
    check_refused(write_bytes("photo_huge.png", huge_png), "20000 x 20000 pixels (400 megapixels) is more than the 100");
    std::string huge_jpeg = jpeg;
    for (std::size_t at = 2; at + 9 < huge_jpeg.size();) {
        const auto marker = static_cast<unsigned char>(huge_jpeg[at + 1]);
        if (marker >= 0xC0 && marker <= 0xC2) {  // start of frame: height, then width, big-endian
            for (int k = 0; k < 4; ++k) huge_jpeg[at + 5 + k] = "\x4e\x20\x4e\x20"[k];
            break;
        }
        at += 2 + (static_cast<unsigned char>(huge_jpeg[at + 2]) << 8) + static_cast<unsigned char>(huge_jpeg[at + 3]);
    }
    check_refused(write_bytes("photo_huge.jpg", huge_jpeg), "20000 x 20000 pixels (400 megapixels) is more than the 100");
}

TEST_CASE("a malformed image view names what is wrong") {
    std::vector<std::uint8_t> pixels(30 * 20 * 3, 128);
    ImageView view{pixels.data(), 30, 20, 30, PixelFormat::rgb8};
    CHECK_THROWS_WITH_AS(face_from_photo(view), doctest::Contains("stride_bytes 30 is less than width x channels = 90"),
                         InvalidArgument);
    view.pixels = nullptr;
    CHECK_THROWS_WITH_AS(face_from_photo(view), doctest::Contains("no pixels"), InvalidArgument);
    view = ImageView{pixels.data(), 0, 20, 90, PixelFormat::rgb8};
    CHECK_THROWS_WITH_AS(face_from_photo(view), doctest::Contains("both sides must be positive"), InvalidArgument);
}

TEST_CASE("a missing cascade folder is a FileError naming it and its package") {
    if (!exists(kAstronaut)) return;
    PhotoOptions options;
    options.cascade_dir = "/nonexistent/cascades";
    options.locator = PhotoLocator::thesis;
    CHECK_THROWS_WITH_AS(face_from_photo_file(kAstronaut, options), doctest::Contains("opencv-data"), FileError);
}

TEST_CASE("the dlib locator is refused with a reason when it is not built in") {
    PhotoOptions options;
    options.locator = PhotoLocator::dlib;
    const cv::Mat blank(100, 100, CV_8UC3, cv::Scalar(180, 180, 180));
    const ImageView view{blank.data, 100, 100, 300, PixelFormat::bgr8};
    if (!has_dlib_locator()) {
        CHECK_THROWS_WITH_AS(face_from_photo(view, options), doctest::Contains("built without dlib"), InvalidArgument);
    } else {
        options.dlib_model_path = "/nonexistent/model.dat";
        CHECK_THROWS_WITH_AS(face_from_photo(view, options), doctest::Contains("libdlib-data"), FileError);
    }
}

TEST_CASE("the debug overlay is a PNG of the photo's size or larger") {
    if (!exists(kAstronaut)) return;
    PhotoOptions options;
    options.locator = PhotoLocator::thesis;
    const PhotoFaceResult result = face_from_photo_file(kAstronaut, options);
    const std::string overlay = test::output_path("photo_overlay.png");
    write_photo_overlay(kAstronaut, result, overlay);
    const cv::Mat written = read_photo(overlay);
    CHECK(written.cols == 512);
    CHECK(written.rows == 512);
}

TEST_CASE("locator names round-trip") {
    for (PhotoLocator locator : {PhotoLocator::thesis, PhotoLocator::dlib, PhotoLocator::automatic}) {
        CHECK(photo_locator_from_name(photo_locator_name(locator)) == locator);
    }
    CHECK_THROWS_WITH_AS(photo_locator_from_name("haar"), doctest::Contains("thesis, dlib or automatic"),
                         InvalidArgument);
}

}  // TEST_SUITE
