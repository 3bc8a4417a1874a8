#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "common/test_paths.hpp"
#include "face/fapu_measure.hpp"
#include "talkface/errors.hpp"
#include "talkface/face_model.hpp"

using namespace talkface;

namespace {

std::string broken_face(const std::string& name) {
    return test::source_path("tests/data/faces/" + name);
}

FaceModel sample_face(const std::string& name) {
    return FaceModel::load(test::source_path("samples/faces/" + name));
}

// The default face moved by seeded random amounts, with FAPUs and colours off any round grid, so
// the round trip must carry all 17 significant digits.
FaceModel perturbed_face(std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> shift_px(-3.0, 3.0);
    std::uniform_real_distribution<double> factor(0.5, 2.0);
    std::uniform_int_distribution<int> channel(0, 255);
    FaceModel face = FaceModel::default_face();
    for (const std::string& id : FaceModel::point_ids()) {
        const Point2 p = face.point(id);
        face.set_point(id, {p.x + shift_px(random), p.y + shift_px(random)});
    }
    for (const std::string& name : FaceModel::fapu_names())
        face.set_fapu(name, face.fapu(name) * factor(random));
    FaceColors colours;
    colours.skin = {static_cast<std::uint8_t>(channel(random)), static_cast<std::uint8_t>(channel(random)),
                    static_cast<std::uint8_t>(channel(random))};
    face.set_colors(colours);
    face.set_name("random <&\"> " + std::to_string(seed));
    return face;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

bool bits_equal(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_SUITE("FaceModel") {
    TEST_CASE("save then load gives back the default and sample faces bit for bit") {
        for (const FaceModel& face :
             {FaceModel::default_face(), sample_face("male.xml"), sample_face("female.xml")}) {
            CAPTURE(face.name());
            const std::string path = test::output_path("round_trip_" + face.name() + ".xml");
            face.save(path);
            const FaceModel loaded = FaceModel::load(path);
            CHECK(loaded == face);
            CHECK(loaded.to_xml() == face.to_xml());
        }
    }

    TEST_CASE("save then load is exact for randomly perturbed faces") {
        for (std::uint64_t seed = 1; seed <= 20; ++seed) {
            CAPTURE(seed);
            const FaceModel face = perturbed_face(seed);
            const std::string path = test::output_path("round_trip_random.xml");
            face.save(path);
            const FaceModel loaded = FaceModel::load(path);
            CHECK(loaded == face);
            for (std::size_t i = 0; i < FaceModel::kPointCount; ++i) {
                CHECK(bits_equal(loaded.points()[i].x, face.points()[i].x));
                CHECK(bits_equal(loaded.points()[i].y, face.points()[i].y));
            }
            CHECK(FaceModel::from_xml(face.to_xml()) == face);
        }
    }

    TEST_CASE("negative zero survives the round trip") {
        FaceModel face;
        face.set_point("hair.1", {-0.0, 1e-300});
        const FaceModel loaded = FaceModel::from_xml(face.to_xml());
        CHECK(std::signbit(loaded.point("hair.1").x));
        CHECK(loaded.point("hair.1").y == 1e-300);
    }

    TEST_CASE("the written file is versioned and lists every point") {
        const std::string xml = FaceModel::default_face().to_xml();
        CHECK(xml.find("<talkface-face version=\"1\" name=\"default\">") != std::string::npos);
        for (const std::string& id : FaceModel::point_ids()) {
            CAPTURE(id);
            CHECK(xml.find("<point id=\"" + id + "\"") != std::string::npos);
        }
    }

    TEST_CASE("FAPUs a file leaves out are measured from its points") {
        const FaceModel face = FaceModel::load(broken_face("omitted_fapus.xml"));
        const FaceModel reference = FaceModel::default_face();
        CHECK(face.points() == reference.points());
        for (const std::string& name : FaceModel::fapu_names()) {
            CAPTURE(name);
            CHECK(face.fapu(name) == detail::measured_fapu(face, name));
            CHECK(face.fapu(name) == doctest::Approx(reference.fapu(name)));
        }
        const FaceModel partial =
            FaceModel::from_xml(replaced(reference.to_xml(), "<fapus d=\"65\"", "<fapus d=\"70\""));
        CHECK(partial.fapu("d") == 70.0);
        CHECK(partial.fapu("MW0") == 46.0);
    }

    TEST_CASE("load names file, line, column and point for each kind of error") {
        struct Case {
            const char* file;
            const char* where;
            const char* what;
        };
        const Case cases[] = {
            {"empty.xml", "empty.xml: ", "the file is empty"},
            {"not_xml.xml", "not_xml.xml:1:1: ", "not an XML file"},
            {"broken_xml.xml", "broken_xml.xml:9:3: ", "not a well-formed XML file"},
            {"wrong_root.xml", "wrong_root.xml:3:1: ", "element <face-model>: expected the root element"},
            {"no_version.xml", "no_version.xml:3:1: ", "missing attribute version"},
            {"newer_version.xml", "newer_version.xml:3:16: ", "version 2 is newer than this library reads (up to 1)"},
            {"future_version.xml", "future_version.xml:3:16: ",
             "version 999 is newer than this library reads (up to 1); update talkface"},
            {"missing_y.xml",
             "missing_y.xml:67:5: ", "point \"8.3\": expected attributes x and y, found only x"},
            {"missing_points.xml", "missing_points.xml:6:3: ", "missing 2 points: \"8.3\", \"9.15\""},
            {"duplicate_point.xml",
             "duplicate_point.xml:79:5: ", "point \"8.3\": defined twice, on lines 67 and 79"},
            {"unknown_point.xml", "unknown_point.xml:67:12: ", "point \"8.5\": unknown point id"},
            {"non_numeric.xml",
             "non_numeric.xml:67:21: ", "point \"8.3\": attribute x: expected a number, found \"22e3x\""},
            {"non_finite.xml",
             "non_finite.xml:67:29: ", "point \"8.3\": attribute y: expected a finite number, found \"inf\""},
            {"huge_coordinate.xml",
             "huge_coordinate.xml:67:29: ", "point \"8.3\": attribute y: \"5.2e81\" is beyond +-1e6 px"},
            {"bad_colour.xml", "bad_colour.xml:4:11: ", "colour \"skin\": expected #rrggbb or #rgb"},
            {"non_positive_fapu.xml", "non_positive_fapu.xml:5:", "FAPU \"MW0\": must be positive"},
            {"same_eyeballs.xml",
             "same_eyeballs.xml:78:5: ", "point \"EyeballRight\": at the same place as EyeballLeft"},
        };
        for (const Case& c : cases) {
            CAPTURE(c.file);
            CHECK_THROWS_WITH_AS(FaceModel::load(broken_face(c.file)), doctest::Contains(c.where),
                                 ParseError);
            CHECK_THROWS_WITH_AS(FaceModel::load(broken_face(c.file)), doctest::Contains(c.what), ParseError);
        }
    }

    TEST_CASE("a face file of a future version is refused naming the version this build reads") {
        CHECK(FaceModel::kFileFormatVersion == 1);  // the refusals above say "up to 1"
        const std::string read_here = "up to " + std::to_string(FaceModel::kFileFormatVersion) + ")";
        CHECK_THROWS_WITH_AS(FaceModel::load(broken_face("future_version.xml")),
                             doctest::Contains(read_here.c_str()), ParseError);
    }

    TEST_CASE("a parse error carries path, line, column and item") {
        const std::string path = broken_face("missing_y.xml");
        try {
            FaceModel::load(path);
            FAIL("load should have thrown");
        } catch (const ParseError& error) {
            CHECK(error.path() == path);
            CHECK(error.line() == 67);
            CHECK(error.column() == 5);
            CHECK(error.item() == "point \"8.3\"");
            CHECK(error.code() == ErrorCode::parse);
        }
    }

    TEST_CASE("from_xml reports errors against the source name it is given") {
        const std::string xml = FaceModel::default_face().to_xml();
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(replaced(xml, "y=\"268\"", "y=\"nan\""), "face.xml"),
                             doctest::Contains("face.xml:44:"), ParseError);
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(replaced(xml, "MW0=\"46\"", "MW0=\"0\"")),
                             doctest::Contains("<string>:5:"), ParseError);
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(replaced(xml, "MW0=\"46\"", "MW1=\"46\""), "face.xml"),
                             doctest::Contains("FAPU \"MW1\": unknown FAPU"), ParseError);
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(replaced(xml, "<points>", "<points><dot/>"), "face.xml"),
                             doctest::Contains("face.xml:6:11: element <dot>"), ParseError);
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(replaced(xml, "<points>", "<points>stray"), "face.xml"),
                             doctest::Contains("unexpected text \"stray\""), ParseError);
        CHECK_THROWS_WITH_AS(
            FaceModel::from_xml(replaced(xml, "version=\"1\"", "version=\"one\""), "face.xml"),
            doctest::Contains("face.xml:3:16: attribute version: expected a whole number"), ParseError);
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(replaced(xml, "version=\"1\"", "version=\"0\""), "face.xml"),
                             doctest::Contains("unknown version 0"), ParseError);
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(replaced(xml, "<fapus", "<fapus/><fapus"), "face.xml"),
                             doctest::Contains("appears twice"), ParseError);
    }

    TEST_CASE("a measured FAPU that is not positive is named with its formula") {
        const std::string xml = FaceModel::default_face().to_xml();
        const std::string no_mw0 = replaced(xml, " MW0=\"46\"", "");
        const std::string swapped = replaced(replaced(no_mw0, "id=\"8.4\" x=\"177\"", "id=\"8.4\" x=\"223\""),
                                             "id=\"8.3\" x=\"223\"", "id=\"8.3\" x=\"177\"");
        CHECK_THROWS_WITH_AS(FaceModel::from_xml(swapped, "face.xml"),
                             doctest::Contains("FAPU \"MW0\": not given, and measuring it from the points "
                                               "(8.3.x - 8.4.x) gives -46 px"),
                             ParseError);
    }

    TEST_CASE("a failed load changes nothing") {
        FaceModel face = sample_face("male.xml");
        const FaceModel before = face;
        CHECK_THROWS_AS(face = FaceModel::load(broken_face("missing_y.xml")), ParseError);
        CHECK(face == before);
    }

    TEST_CASE("a missing file is a FileError naming it") {
        const std::string path = broken_face("no_such_face.xml");
        CHECK_THROWS_WITH_AS(FaceModel::load(path), doctest::Contains(path.c_str()), FileError);
    }

    TEST_CASE("save to an unwritable path throws FileError and leaves no file") {
        const FaceModel face;
        const std::string in_missing_directory = test::output_path("no_such_directory/face.xml");
        CHECK_THROWS_WITH_AS(face.save(in_missing_directory), doctest::Contains(in_missing_directory.c_str()),
                             FileError);
        CHECK_FALSE(std::filesystem::exists(in_missing_directory));

        // A directory in the way: the temporary file is written, the rename fails, and the temporary
        // file must be gone afterwards.
        const std::filesystem::path directory = test::output_path("save_blocked");
        std::filesystem::remove_all(directory);
        std::filesystem::create_directories(directory / "face.xml");
        CHECK_THROWS_AS(face.save((directory / "face.xml").string()), FileError);
        CHECK(std::filesystem::is_directory(directory / "face.xml"));
        int entries = 0;
        for (const auto& entry : std::filesystem::directory_iterator(directory)) {
            CAPTURE(entry.path().string());
            ++entries;
        }
        CHECK(entries == 1);
    }

    TEST_CASE("save replaces an existing file whole") {
        const std::string path = test::output_path("replaced_face.xml");
        sample_face("female.xml").save(path);
        const FaceModel male = sample_face("male.xml");
        male.save(path);
        CHECK(FaceModel::load(path) == male);
    }
}
