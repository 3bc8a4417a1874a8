#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "common/atomic_file.hpp"
#include "common/markup_escape.hpp"
#include "common/number_format.hpp"
#include "common/text_location.hpp"
#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/library.hpp"
#include "talkface/types.hpp"

using namespace talkface;

TEST_SUITE("common") {
    TEST_CASE("a byte offset becomes a 1-based line and column") {
        const std::string text = "ab\ncd\n\nxyz";
        CHECK(detail::locate_offset(text, 0).line == 1);
        CHECK(detail::locate_offset(text, 0).column == 1);
        CHECK(detail::locate_offset(text, 4).line == 2);
        CHECK(detail::locate_offset(text, 4).column == 2);
        CHECK(detail::locate_offset(text, 8).line == 4);
        CHECK(detail::locate_offset(text, 8).column == 2);
        CHECK(detail::locate_offset(text, 1000).line == 4);
    }

    TEST_CASE("shortest number text reads back exactly") {
        for (double value : {0.1, 1.0 / 3.0, 123.456, -7.25e-9, 1e300, 0.0}) {
            CAPTURE(value);
            const auto text = detail::format_shortest(value);
            const auto back = detail::parse_double(text);
            REQUIRE(back.has_value());
            CHECK(*back == value);
        }
        CHECK(detail::format_shortest(12.5) == "12.5");
    }

    TEST_CASE("fixed number text drops trailing zeros and negative zero") {
        CHECK(detail::format_fixed(12.5, 2) == "12.5");
        CHECK(detail::format_fixed(3.0, 2) == "3");
        CHECK(detail::format_fixed(-0.001, 2) == "0");
        CHECK(detail::format_fixed(2.345678, 3) == "2.346");
    }

    TEST_CASE("parse_double accepts whole numbers only") {
        CHECK(detail::parse_double("12.5").value() == 12.5);
        CHECK(detail::parse_double("+3").value() == 3.0);
        CHECK_FALSE(detail::parse_double("12.5px").has_value());
        CHECK_FALSE(detail::parse_double("").has_value());
        CHECK_FALSE(detail::parse_double("abc").has_value());
        CHECK(std::isinf(detail::parse_double("inf").value()));
    }

    TEST_CASE("colours round-trip through hex text") {
        CHECK(to_hex(Rgb{0x12, 0xab, 0xff}) == "#12abff");
        CHECK(rgb_from_hex("#12ABff") == Rgb{0x12, 0xab, 0xff});
        CHECK(rgb_from_hex("#fa0") == Rgb{0xff, 0xaa, 0x00});
        CHECK_THROWS_WITH_AS(rgb_from_hex("red", "skin"), doctest::Contains("skin"), InvalidArgument);
        CHECK_THROWS_AS(rgb_from_hex("#12345g"), InvalidArgument);
    }

    TEST_CASE("an atomic write replaces the file whole and a failed one leaves nothing") {
        const auto path = test::output_path("atomic.txt");
        detail::write_file_atomically(path, "first");
        detail::write_file_atomically(path, "second");
        CHECK(detail::read_file(path) == "second");
        CHECK_THROWS_WITH_AS(detail::write_file_atomically("/nonexistent-dir/x.txt", "x"),
                             doctest::Contains("/nonexistent-dir/x.txt"), FileError);
        CHECK_THROWS_WITH_AS(detail::read_file("/nonexistent-dir/x.txt"),
                             doctest::Contains("/nonexistent-dir/x.txt"), FileError);
    }

    // The error paths after the temporary file exists: a write refused past the file-size limit (EFBIG:
    // SIGXFSZ ignored, as a shell's ulimit -f leaves it to the program), and a rename refused where the
    // target is a directory. Each throws naming the target, leaves it as it was and no temporary beside it.
    TEST_CASE("a failed atomic write or rename leaves the target as it was and no temporary file") {
        namespace fs = std::filesystem;
        const fs::path folder = test::output_path("atomic-failures");
        fs::remove_all(folder);
        fs::create_directories(folder / "a-folder");
        const auto target = (folder / "kept.txt").string();
        detail::write_file_atomically(target, "old");

        constexpr rlim_t kSmallFileLimit = 16;  // bytes: under the content below, over "old"
        rlimit saved_limit{};
        REQUIRE(::getrlimit(RLIMIT_FSIZE, &saved_limit) == 0);
        const auto saved_signal = std::signal(SIGXFSZ, SIG_IGN);
        rlimit small_limit = saved_limit;
        small_limit.rlim_cur = kSmallFileLimit;
        REQUIRE(::setrlimit(RLIMIT_FSIZE, &small_limit) == 0);
        const std::string content(4 * kSmallFileLimit, 'x');
        CHECK_THROWS_WITH_AS(detail::write_file_atomically(target, content),
                             doctest::Contains("cannot write"), FileError);
        ::setrlimit(RLIMIT_FSIZE, &saved_limit);
        std::signal(SIGXFSZ, saved_signal);

        CHECK_THROWS_WITH_AS(detail::write_file_atomically((folder / "a-folder").string(), "x"),
                             doctest::Contains("cannot replace"), FileError);

        CHECK(detail::read_file(target) == "old");
        std::vector<std::string> left;
        for (const auto& entry : fs::directory_iterator(folder))
            left.push_back(entry.path().filename().string());
        std::sort(left.begin(), left.end());
        CHECK(left == std::vector<std::string>{"a-folder", "kept.txt"});
    }

    TEST_CASE("errors carry their code and a message naming where") {
        const ParseError parse("face.xml", 12, 5, "point \"8.3\"", "expected x");
        CHECK(std::string(parse.what()) == "face.xml:12:5: point \"8.3\": expected x");
        CHECK(parse.code() == ErrorCode::parse);
        CHECK(parse.line() == 12);
        const InvalidArgument invalid("beta_deg", "20 is outside -15..15");
        CHECK(std::string(invalid.what()) == "beta_deg: 20 is outside -15..15");
        CHECK(invalid.code() == ErrorCode::invalid_argument);
        CHECK(FileError("a.wav", "no such file").code() == ErrorCode::file);
    }

    TEST_CASE("the loaded library's version is the headers' version") {
        CHECK(std::string(talkface::version()) == TALKFACE_VERSION_STRING);
    }

    TEST_CASE("markup escaping: & < > always, the quotes as HTML, XML or not at all") {
        const std::string text = "<a href=\"x\">Tom's & 會說話</a>";
        CHECK(detail::escape_markup(text, detail::QuoteEscape::none) ==
              "&lt;a href=\"x\"&gt;Tom's &amp; 會說話&lt;/a&gt;");
        CHECK(detail::escape_markup(text, detail::QuoteEscape::html) ==
              "&lt;a href=&quot;x&quot;&gt;Tom&#39;s &amp; 會說話&lt;/a&gt;");
        CHECK(detail::escape_markup(text, detail::QuoteEscape::xml) ==
              "&lt;a href=&quot;x&quot;&gt;Tom&apos;s &amp; 會說話&lt;/a&gt;");
    }
}
