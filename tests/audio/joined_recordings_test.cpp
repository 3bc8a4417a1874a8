// Two recordings joined into one file (joined_copy.hpp, issue 13 "Bad input"), made here by ffmpeg
// and cat from tests/data/speech/one_sentence.wav: named where the text is refused, searched for
// only where the text's fit is not vouched for (an MP3's restarted frames, told from their headers
// alone, wherever it aligns); and a RIFF file's own extension that is no second
// WAV.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "audio/audio_source.hpp"
#include "audio/chained_stream.hpp"
#include "audio/mp3_restart.hpp"
#include "audio/mp3_toc.hpp"
#include "audio/repeated_sound.hpp"
#include "common/made_by_command.hpp"
#include "common/test_paths.hpp"
#include "talkface/errors.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/transcript.hpp"

using namespace talkface;

namespace {

// ffmpeg's options for an MP3 of frames alone at 32 kb/s, as sox writes one: no ID3 tag, no Xing tag.
constexpr const char* kBareMp3Options =
    "-c:a libmp3lame -b:a 32k -write_xing 0 -id3v2_version 0 -fflags +bitexact -f mp3";

std::string speech_clip(const std::string& file) {
    return test::source_path("tests/data/speech/" + file);
}

// one_sentence.wav encoded by ffmpeg with `options` into test output NAME.
std::string ffmpeg_made(const std::string& name, const std::string& options) {
    return test::made_by_command(
        name, "ffmpeg -nostdin -loglevel error -y -i '" + speech_clip("one_sentence.wav") + "' " + options);
}

// The files at `first` and `second`, one after the other, in test output NAME.
std::string joined(const std::string& name, const std::string& first, const std::string& second) {
    return test::made_by_command(name, "cat '" + first + "' '" + second + "' >");
}

std::size_t file_bytes(const std::string& path) {
    return static_cast<std::size_t>(std::ifstream(path, std::ios::binary | std::ios::ate).tellg());
}

// The refusal of one_sentence.txt for the recording at `path` (empty if it aligned).
std::string refusal_of_one_sentence(const std::string& path) {
    try {
        SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt")));
    } catch (const AlignmentError& error) {
        return error.what();
    }
    return {};
}

// one_sentence.wav and it played backwards, each encoded as Opus by ffmpeg in `format` (ogg, webm),
// joined: the first's path, and the joined file's warnings aligned with one_sentence.txt.
std::pair<std::string, std::vector<std::string>> opus_joined_to_backwards(const std::string& format) {
    const std::string options = "-c:a libopus -b:a 24k -fflags +bitexact -flags:a +bitexact -f " + format;
    const std::string one = ffmpeg_made("one_sentence_opus." + format, options);
    const std::string backwards = ffmpeg_made("backwards_opus." + format, "-af areverse " + options);
    const std::string path = joined("opus_joined_backwards." + format, one, backwards);
    return {one, SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt"))).warnings};
}

// A copy of the WebM file at `path`, in test output NAME, with each Cluster's size written as unknown
// (all ones, in the bytes it took), as Chrome's MediaRecorder writes them: the Segment's children
// walked by their EBML IDs and sizes (ffmpeg's live WebM: its Segment's size already unknown).
std::string with_unknown_cluster_sizes(const std::string& path, const std::string& name) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto length_at = [&](std::size_t at) {
        std::size_t length = 1;
        while ((static_cast<unsigned char>(bytes[at]) & (0x80U >> (length - 1))) == 0) ++length;
        return length;
    };
    const auto size_at = [&](std::size_t at) {
        std::size_t value = static_cast<unsigned char>(bytes[at]) & (0xFFU >> length_at(at));
        for (std::size_t k = 1; k < length_at(at); ++k)
            value = value << 8 | static_cast<unsigned char>(bytes[at + k]);
        return value;
    };
    std::size_t at = 4 + length_at(4) + size_at(4);  // past the EBML header
    at += 4 + length_at(at + 4);                     // into the Segment
    while (at < bytes.size()) {
        const bool is_cluster = bytes.compare(at, 4, "\x1f\x43\xb6\x75") == 0;
        at += length_at(at);
        const std::size_t size_length = length_at(at);
        const std::size_t size = size_at(at);
        if (is_cluster) {
            bytes[at] = static_cast<char>(0xFFU >> (size_length - 1));
            std::fill_n(bytes.begin() + static_cast<std::ptrdiff_t>(at + 1), size_length - 1, '\xff');
        }
        at += size_length + size;
    }
    const std::string out = test::output_path(name);
    std::ofstream(out, std::ios::binary) << bytes;
    return out;
}

// A copy of the MP3 at `path` (FFmpeg's LAME: an Info tag frame first), in test output NAME, whose header
// frame carries a check as LAME's -p writes it: the protection bit of its header cleared and the check's 2
// bytes after the header, in the place of the side information's first 2 (zero in a header frame), the tag
// where it stood.
std::string with_checked_header_frame(const std::string& path, const std::string& name) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t frame = detail::after_id3(bytes);
    bytes[frame + 1] = static_cast<char>(static_cast<unsigned char>(bytes[frame + 1]) & 0xFEU);
    bytes[frame + 4] = '\xd2';
    bytes[frame + 5] = '\xdc';
    const std::string out = test::output_path(name);
    std::ofstream(out, std::ios::binary) << bytes;
    return out;
}

// The frames the file at `path` reads as, to its end.
std::size_t frames_in(const std::string& path) {
    const auto source = detail::open_audio_file(path);
    std::vector<float> block(4096);
    std::size_t frames = 0;
    while (const std::size_t got = source->read(block.data(), block.size())) frames += got;
    return frames;
}

bool has_warning_with(const Timeline& timeline, const std::string& part) {
    for (const std::string& warning : timeline.warnings)
        if (warning.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_SUITE("joined recordings") {
    TEST_CASE(
        "two MP3s without an ID3 tag joined are named by their Xing or Info tags where the text is refused") {
        // FFmpeg's MP3 with no ID3 tag: its first frame holds LAME's Info tag (a constant rate).
        const std::string one = ffmpeg_made(
            "untagged_32k.mp3", "-c:a libmp3lame -b:a 32k -id3v2_version 0 -fflags +bitexact -f mp3");
        const std::string other = ffmpeg_made(
            "untagged_64k.mp3", "-c:a libmp3lame -b:a 64k -id3v2_version 0 -fflags +bitexact -f mp3");
        for (const auto& [name, second] : {std::pair{"copy", one}, std::pair{"another", other}}) {
            CAPTURE(name);
            const std::string path = joined(std::string("untagged_joined_") + name + ".mp3", one, second);
            const std::string refusal = refusal_of_one_sentence(path);
            CHECK(refusal.find(
                      "a second MP3 header frame (a Xing or Info tag, which an encoder writes once, in a "
                      "recording's first frame) starts at byte " +
                      std::to_string(file_bytes(one)) + ": a second copy of the recording") !=
                  std::string::npos);
        }
        // A second recording with no tag of its own starts where the first's tag says its frames end.
        const std::string bare = ffmpeg_made("bare_32k.mp3", kBareMp3Options);
        const std::string refusal = refusal_of_one_sentence(joined("tagged_then_bare.mp3", one, bare));
        CHECK(refusal.find("its first frame's Xing or Info tag counts its MP3 frames to byte " +
                           std::to_string(file_bytes(one)) +
                           ", and a second stream of frames starts there") != std::string::npos);
        // The file alone aligns, with no word of a join.
        const Timeline alone =
            SpeechAligner().align_file(one, load_transcript(speech_clip("one_sentence.txt")));
        CHECK_FALSE(has_warning_with(alone, "MP3 header frame"));
    }

    TEST_CASE(
        "a joined file whose text fits both recordings is not searched in refuse mode, and is in check mode "
        "off") {
        const std::string flac = ffmpeg_made("one_sentence.flac", "-fflags +bitexact -f flac");
        const std::string path = joined("joined_twice.flac", flac, flac);
        std::string text;
        std::getline(std::ifstream(speech_clip("one_sentence.txt")), text);
        const Timeline both = read_transcript(text + "\n" + text + "\n");
        const Timeline aligned = SpeechAligner().align_file(path, both);
        CHECK_FALSE(has_warning_with(aligned, "recur at byte"));
        AlignOptions unchecked;
        unchecked.check = CheckMode::off;
        const Timeline unchecked_aligned = SpeechAligner(unchecked).align_file(path, both);
        CHECK(has_warning_with(unchecked_aligned, "its first 32 bytes (its header) recur at byte " +
                                                      std::to_string(file_bytes(flac))));
    }

    TEST_CASE(
        "an MP3 of frames alone joined to itself is named by its sound repeating where the text is refused") {
        // No ID3 tag, no Xing tag (as sox writes an MP3): no header recurs in its bytes, and the
        // join was refused as a text that does not fit with no word of why.
        const std::string bare = ffmpeg_made("bare_32k.mp3", kBareMp3Options);
        const std::string path = joined("bare_joined.mp3", bare, bare);
        const std::string refusal = refusal_of_one_sentence(path);
        CHECK_MESSAGE(
            refusal.find(" on again, sample for sample, as no voice repeats itself: a second copy of "
                         "the recording begins at ") != std::string::npos,
            refusal);
        const auto repeat = detail::repeated_sound(path);
        REQUIRE(repeat);
        const auto alone = detail::open_audio_file(bare);
        std::vector<float> block(1 << 16);
        std::size_t frames = 0;
        while (const std::size_t got = alone->read(block.data(), block.size())) frames += got;
        // The second copy starts where the first's frames end: its decoded length, the encoder's
        // delay cut from the first copy alone.
        const std::size_t copy_start = repeat->repeat_frame - repeat->original_frame;
        CHECK(copy_start >= frames);
        CHECK(copy_start <= frames + 1152);
        // Neither the file alone nor a tone that repeats at its period is a copy.
        CHECK_FALSE(detail::repeated_sound(bare));
        const std::string tone = test::made_by_command("tone_1khz.wav",
                                                       "ffmpeg -nostdin -loglevel error -y -f lavfi -i "
                                                       "sine=frequency=1000:sample_rate=16000:duration=3");
        CHECK_FALSE(detail::repeated_sound(tone));
    }

    TEST_CASE(
        "two different MP3s of frames alone joined are named by the second's bit reservoir starting afresh "
        "where the text is refused") {
        // Of one rate and bit rate, with no ID3 or Xing tag (as sox writes them): the decoder reads the
        // second recording's frames on as the first's, and no bytes or sound recur.
        const std::string options = kBareMp3Options;
        const std::string one = ffmpeg_made("bare_32k.mp3", options);
        const std::string other = test::made_by_command(
            "joined_second_two_sentences_32k.mp3",
            "ffmpeg -nostdin -loglevel error -y -i '" + speech_clip("two_sentences.wav") + "' " + options);
        const std::string path = joined("bare_joined_another.mp3", one, other);
        const std::string refusal = refusal_of_one_sentence(path);
        CHECK_MESSAGE(refusal.find("(the file: its MP3 frame at byte " + std::to_string(file_bytes(one)) +
                                   " (") != std::string::npos,
                      refusal);
        CHECK_MESSAGE(refusal.find(" s) begins its data afresh, throwing away the ") != std::string::npos,
                      refusal);
        CHECK_MESSAGE(
            refusal.find("as only a recording's first frame does: a second copy of the recording, or a "
                         "second recording, begins there") != std::string::npos,
            refusal);
        const auto restart = detail::restarted_mp3_stream(path);
        REQUIRE(restart);
        CHECK(restart->byte == file_bytes(one));
        // Neither recording alone starts afresh after its first frame.
        CHECK_FALSE(detail::restarted_mp3_stream(one));
        CHECK_FALSE(detail::restarted_mp3_stream(other));
    }

    TEST_CASE("an MP3 of frames alone joined to another recording is named where its text fits the first") {
        // The text fits one_sentence.wav and was stretched over the recording joined after it (the
        // same sentence played backwards, as the sweep's joined_another kind), aligned with no word.
        const std::string options = kBareMp3Options;
        const std::string one = ffmpeg_made("bare_32k.mp3", options);
        const std::string backwards = ffmpeg_made("bare_backwards_32k.mp3", "-af areverse " + options);
        const std::string path = joined("bare_joined_backwards.mp3", one, backwards);
        const Timeline aligned =
            SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt")));
        CHECK(has_warning_with(aligned, "its MP3 frame at byte " + std::to_string(file_bytes(one)) + " ("));
        CHECK(
            has_warning_with(aligned, "a second copy of the recording, or a second recording, begins there"));
        CHECK_FALSE(has_warning_with(
            SpeechAligner().align_file(one, load_transcript(speech_clip("one_sentence.txt"))),
            "begins its data afresh"));
    }

    TEST_CASE(
        "MP3s of frames alone at 16 kHz 32 kb/s, the second opening in digital silence, are named by its "
        "reservoir starting afresh") {
        // LAME keeps 124 bytes of reservoir in a frame's 131 here: the second's first empty frame points
        // nowhere, and the next empty one 124 bytes back, inside its area, not at its start; the text,
        // which fits the first, aligned over both with no word of the join.
        const std::string options = kBareMp3Options;
        const std::string one = ffmpeg_made("bare_32k.mp3", options);
        const std::string other =
            ffmpeg_made("bare_silence_backwards_32k.mp3", "-af areverse,adelay=500:all=1 " + options);
        const std::string path = joined("bare_joined_silence_backwards.mp3", one, other);
        const auto restart = detail::restarted_mp3_stream(path);
        REQUIRE(restart);
        CHECK(restart->byte == file_bytes(one));
        const double first_s = static_cast<double>(frames_in(one)) / 16000.0;
        CHECK(restart->seconds >= first_s);
        CHECK(restart->seconds <= first_s + 0.015);
        const Timeline aligned =
            SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt")));
        CHECK(has_warning_with(aligned, "its MP3 frame at byte " + std::to_string(file_bytes(one)) + " ("));
        // Nor recording alone, whose empty frames point at the reservoir they hold.
        CHECK_FALSE(detail::restarted_mp3_stream(one));
        CHECK_FALSE(detail::restarted_mp3_stream(other));
    }

    TEST_CASE("an MP3 encoded once is named as no join where LAME empties its reservoir as its sound ends") {
        // Where a frame's own data leaves more of its area unused than the reservoir LAME keeps, LAME
        // writes the reservoir out as ancillary bytes and the frame points back nowhere: a steady tone's
        // frames at 16 kHz 128 kb/s (140-170 bytes of sound in a 563-byte area, 255 kept), as a speech's
        // last frame before digital silence in a person's recording, were named as a second recording's
        // start (the tone's third frame, 0.003 s).
        struct Kind {
            int rate_hz;
            int kbps;
        };
        for (const Kind kind : {Kind{8000, 64}, Kind{11025, 64}, Kind{16000, 128}, Kind{22050, 128}}) {
            const std::string name = std::to_string(kind.rate_hz) + "_" + std::to_string(kind.kbps) + "k";
            const std::string tone = test::made_by_command(
                "tone_" + name + ".mp3",
                "ffmpeg -nostdin -loglevel error -y -f lavfi -i sine=frequency=440:sample_rate=" +
                    std::to_string(kind.rate_hz) + ":duration=1,apad=pad_dur=0.5 -c:a libmp3lame -b:a " +
                    std::to_string(kind.kbps) + "k -write_xing 0 -id3v2_version 0 -fflags +bitexact -f mp3");
            CAPTURE(name);
            CHECK_FALSE(detail::restarted_mp3_stream(tone));
            // Two of them joined are named where the second starts, its first frame of sound pointing
            // back nowhere.
            if (kind.rate_hz == 16000) {
                const auto join =
                    detail::restarted_mp3_stream(joined("tone_joined_" + name + ".mp3", tone, tone));
                REQUIRE(join);
                CHECK(join->byte == file_bytes(tone));
            }
        }
    }

    TEST_CASE(
        "an MP3 joined to a second recording that opens in digital silence is named by its header frame") {
        // LAME as FFmpeg runs it writes 0 in an empty frame's main_data_begin: the second recording's
        // first frames (0.5 s of digital silence) point nowhere in the reservoir, and the text, which
        // fits the first, aligned with no word of the join; the second's Info tag frame tells it.
        const std::string options = "-c:a libmp3lame -b:a 64k -fflags +bitexact -flags:a +bitexact -f mp3";
        const std::string one = ffmpeg_made("tagged_64k.mp3", options);
        const std::string other =
            ffmpeg_made("tagged_silence_backwards_64k.mp3", "-af areverse,adelay=500:all=1 " + options);
        const std::string path = joined("tagged_joined_silence_backwards.mp3", one, other);
        const Timeline aligned =
            SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt")));
        CHECK(has_warning_with(aligned,
                               "holds an encoder's header (a Xing, Info or VBRI tag), which an encoder "
                               "writes once, in a recording's first frame: a second copy of the "
                               "recording, or a second recording, begins there"));
        // FFmpeg's decoder refuses the second recording's Info tag frame (its ID3 tag joined to it by
        // the parser), which holds no sound: "the file is damaged: 0.036 s of its sound could not be
        // decoded" stood beside the join's warning, at the same place.
        CHECK_MESSAGE(aligned.warnings.size() == 1, aligned.warnings.front());
        const auto restart = detail::restarted_mp3_stream(path);
        REQUIRE(restart);
        CHECK(restart->is_header_frame);
        // Past the second file's ID3 tag.
        CHECK(restart->byte > file_bytes(one));
        CHECK(restart->byte < file_bytes(one) + 100);
        CHECK_FALSE(detail::restarted_mp3_stream(one));
        CHECK_FALSE(detail::restarted_mp3_stream(other));
    }

    TEST_CASE("a joined MP3's join is named at the time the first recording's decoded sound ends") {
        // The frames before the join counted the first's header frame and the encoder's and decoder's
        // delay, which the reader drops: 3.204 s where one_sentence.wav's copy ends at 3.099 s
        // (3.090 s of sound and its last frame's padding). A user cuts the file at the time named.
        // As the tests above join them: LAME's tagged MP3 to one opening in digital silence (named by its
        // header frame), and MP3s of frames alone (named by the second's reservoir starting afresh).
        struct Kind {
            const char* name;
            std::string options;
            const char* second_filter;
        };
        const Kind kinds[] = {
            {"tagged", "-c:a libmp3lame -b:a 64k -fflags +bitexact -flags:a +bitexact -f mp3",
             "areverse,adelay=500:all=1"},
            {"bare", kBareMp3Options, "areverse"}};
        for (const auto& [name, options, second_filter] : kinds) {
            CAPTURE(name);
            const std::string one = ffmpeg_made(std::string("join_time_") + name + ".mp3", options);
            const std::string backwards = ffmpeg_made(std::string("join_time_backwards_") + name + ".mp3",
                                                      std::string("-af ") + second_filter + " " + options);
            const std::string path = joined(std::string("join_time_joined_") + name + ".mp3", one, backwards);
            const Timeline aligned =
                SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt")));
            const std::string frame = "its MP3 frame at byte ";
            std::string warning;
            for (const std::string& each : aligned.warnings)
                if (each.find(frame) != std::string::npos) warning = each;
            REQUIRE_FALSE(warning.empty());
            const std::size_t open = warning.find(" (", warning.find(frame));
            const double named_s = std::stod(warning.substr(open + 2));
            const double first_s = static_cast<double>(frames_in(one)) / 16000.0;
            CHECK(named_s >= first_s);
            // Within the first's last frame's padding, which the reader keeps where a second stream follows.
            CHECK(named_s <= first_s + 0.015);
        }
    }

    TEST_CASE(
        "an MP3 header frame with a check (LAME's -p) is read as a header frame, its tag where LAME puts "
        "it") {
        // LAME writes the Xing or Info tag of a frame with a check where it stands without one, and FFmpeg
        // reads it there; the tag was looked for 2 bytes on, so the frame was taken for sound: the join's
        // time counted it (36 ms late), a second recording's header frame was not seen, and where the text
        // was refused only the first's stated bytes named the join.
        const std::string options = "-c:a libmp3lame -b:a 64k -fflags +bitexact -flags:a +bitexact -f mp3";
        const std::string one =
            with_checked_header_frame(ffmpeg_made("tagged_64k.mp3", options), "checked_64k.mp3");
        const std::string other = with_checked_header_frame(
            ffmpeg_made("tagged_silence_backwards_64k.mp3", "-af areverse,adelay=500:all=1 " + options),
            "checked_silence_backwards_64k.mp3");
        std::ifstream in(one, std::ios::binary);
        std::string head(4096, '\0');
        in.read(head.data(), static_cast<std::streamsize>(head.size()));
        const std::size_t frame = detail::after_id3(head);
        const auto header = detail::read_mp3_frame_header(head.substr(frame, 4));
        REQUIRE(header);
        REQUIRE(header->has_crc);
        CHECK(detail::is_mp3_tag_frame(head.substr(frame), *header));
        CHECK(detail::read_mp3_toc(head, static_cast<std::int64_t>(file_bytes(one))));

        const std::string path = joined("checked_joined_silence_backwards.mp3", one, other);
        const auto restart = detail::restarted_mp3_stream(path);
        REQUIRE(restart);
        CHECK(restart->is_header_frame);
        const double first_s = static_cast<double>(frames_in(one)) / 16000.0;
        CHECK(restart->seconds >= first_s);
        CHECK(restart->seconds <= first_s + 0.015);

        const std::string untagged_options =
            "-c:a libmp3lame -b:a 32k -id3v2_version 0 -fflags +bitexact -f mp3";
        const std::string untagged = with_checked_header_frame(
            ffmpeg_made("untagged_32k.mp3", untagged_options), "checked_untagged_32k.mp3");
        const std::string refusal =
            refusal_of_one_sentence(joined("checked_untagged_joined.mp3", untagged, untagged));
        CHECK_MESSAGE(
            refusal.find("a second MP3 header frame (a Xing or Info tag, which an encoder writes once, "
                         "in a recording's first frame) starts at byte " +
                         std::to_string(file_bytes(untagged))) != std::string::npos,
            refusal);
    }

    TEST_CASE("a chained Ogg file's second stream is read, and the join named") {
        // libsndfile read a chained Vorbis file's first stream alone: the second recording was lost
        // without a word. The second's serial number differs, as any two encodings' do.
        const std::string options = "-c:a libvorbis -q:a 2 -fflags +bitexact -flags:a +bitexact -f ogg";
        const std::string one = ffmpeg_made("one_sentence_vorbis.ogg", options);
        const std::string backwards =
            ffmpeg_made("backwards_vorbis.ogg", "-af areverse " + options + " -serial_offset 7");
        const std::string path = joined("vorbis_chained_backwards.ogg", one, backwards);
        CHECK(frames_in(path) > frames_in(one) * 19 / 10);
        // Read on through the second recording, the text is refused: the join is said.
        const std::string refusal = refusal_of_one_sentence(path);
        CHECK_MESSAGE(
            refusal.find("(the file: a second Ogg stream (its own header pages, which open a recording) "
                         "starts at byte " +
                         std::to_string(file_bytes(one)) + ", where the first ends (3.") != std::string::npos,
            refusal);
        CHECK_FALSE(detail::chained_stream(one));
    }

    TEST_CASE(
        "an Opus file chained to another of its serial number is no damage, and its join is said once") {
        // FFmpeg's -bitexact writes serial number 0 in both: the second stream's pages, numbered from 0
        // again, were taken for a damaged file's, and "its header states 3.1 s of sound, the file holds
        // 6.2 s" was all the join's word.
        const auto [one, warnings] = opus_joined_to_backwards("ogg");
        REQUIRE(warnings.size() == 1);
        CHECK_MESSAGE(warnings[0].find("a second Ogg stream (its own header pages, which open a recording) "
                                       "starts at byte " +
                                       std::to_string(file_bytes(one))) != std::string::npos,
                      warnings[0]);
    }

    TEST_CASE(
        "the digital silence a chained Ogg file's second recording opens with is the join's, not a "
        "silenced word's") {
        // Read on through the join, the text is refused over both recordings, and the second's opening
        // 2 s of zeros lay inside its sentence: they were named as a word an editor silenced as well.
        const std::string options = "-c:a libopus -b:a 24k -fflags +bitexact -flags:a +bitexact -f ogg";
        const std::string one = ffmpeg_made("one_sentence_opus.ogg", options);
        const std::string silence_first = ffmpeg_made(
            "silence_then_one_sentence_opus.ogg", "-af adelay=2000:all=1 " + options + " -serial_offset 7");
        const std::string refusal =
            refusal_of_one_sentence(joined("opus_joined_silence_first.ogg", one, silence_first));
        CHECK_MESSAGE(
            refusal.find("(the file: a second Ogg stream (its own header pages, which open a recording) "
                         "starts at byte " +
                         std::to_string(file_bytes(one)) + ", where the first ends (3.") != std::string::npos,
            refusal);
        CHECK_MESSAGE(refusal.find("is digital silence") == std::string::npos, refusal);
    }

    TEST_CASE("a WebM file joined to another is named by its second Segment where the text fits the first") {
        const auto [one, warnings] = opus_joined_to_backwards("webm");
        REQUIRE(warnings.size() == 1);
        CHECK_MESSAGE(
            warnings[0].find("a second Matroska file (its own EBML header and Segment, which open a "
                             "recording) starts at byte " +
                             std::to_string(file_bytes(one)) + ", where the first's Segment ends") !=
                std::string::npos,
            warnings[0]);
        CHECK_FALSE(detail::chained_stream(one));
    }

    TEST_CASE(
        "a live WebM (a Segment of unknown size) joined to another is named by its second EBML header") {
        // A browser's MediaRecorder writes its Segment's size as unknown (all ones), as ffmpeg's live
        // WebM does, and Chrome its Clusters' too: no stated size led to the second file, and the join
        // was told only by the opening bytes recurring where the text was refused.
        const std::string options =
            "-c:a libopus -b:a 24k -fflags +bitexact -flags:a +bitexact -f webm "
            "-live 1 -cluster_time_limit 500";
        const std::string one = ffmpeg_made("one_sentence_live.webm", options);
        const std::string backwards = ffmpeg_made("backwards_live.webm", "-af areverse " + options);
        const std::string chrome_one = with_unknown_cluster_sizes(one, "one_sentence_live_clusters.webm");
        const std::string chrome_backwards =
            with_unknown_cluster_sizes(backwards, "backwards_live_clusters.webm");
        for (const auto& [name, first, second] :
             {std::tuple{"clusters of stated size", one, backwards},
              std::tuple{"clusters of unknown size", chrome_one, chrome_backwards}}) {
            CAPTURE(name);
            const std::string path =
                joined(std::string("live_joined_") + (first == one ? "a" : "b") + ".webm", first, second);
            const auto chained = detail::chained_stream(path);
            REQUIRE(chained);
            CHECK(chained->byte == file_bytes(first));
            CHECK(chained->is_live_segment);
            CHECK_FALSE(detail::chained_stream(first));
            const Timeline aligned =
                SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt")));
            CHECK(has_warning_with(aligned,
                                   "a second Matroska file (its own EBML header and Segment, which open a "
                                   "recording) starts at byte " +
                                       std::to_string(file_bytes(first)) +
                                       ", where the first's Segment, of unknown size"));
        }
    }

    TEST_CASE(
        "a WebM joined to another is named at the time the first's sound ends, and the digital silence the "
        "second opens with is the join's") {
        // The time was not read from the file: the join's warning named no time, and where the text was
        // refused the second recording's opening zeros were named as a word an editor silenced as well.
        const std::string options = "-c:a libopus -b:a 24k -fflags +bitexact -flags:a +bitexact -f webm";
        const std::string live = options + " -live 1 -cluster_time_limit 500";
        const std::string one = ffmpeg_made("one_sentence_opus.webm", options);
        const std::string backwards =
            ffmpeg_made("silence_backwards_opus.webm", "-af areverse,adelay=500:all=1 " + options);
        const std::string live_one = ffmpeg_made("one_sentence_live.webm", live);
        const std::string live_backwards =
            ffmpeg_made("silence_backwards_live.webm", "-af areverse,adelay=500:all=1 " + live);
        const std::string chrome_one =
            with_unknown_cluster_sizes(live_one, "one_sentence_live_clusters.webm");
        const std::string chrome_backwards =
            with_unknown_cluster_sizes(live_backwards, "silence_backwards_live_clusters.webm");
        const auto source = detail::open_audio_file(one);
        const double first_s =
            static_cast<double>(frames_in(one)) / static_cast<double>(source->sample_rate_hz());
        for (const auto& [name, first, second] :
             {std::tuple{"stated", one, backwards}, std::tuple{"live", live_one, live_backwards},
              std::tuple{"live_clusters", chrome_one, chrome_backwards}}) {
            CAPTURE(name);
            const std::string path = joined(std::string("joined_silence_") + name + ".webm", first, second);
            const Timeline aligned =
                SpeechAligner().align_file(path, load_transcript(speech_clip("one_sentence.txt")));
            REQUIRE(aligned.warnings.size() == 1);
            const std::string& warning = aligned.warnings.front();
            const std::size_t ends = warning.find("ends (");
            REQUIRE_MESSAGE(ends != std::string::npos, warning);
            const double named_s = std::stod(warning.substr(ends + 6));
            // Opus's frames are 20 ms; the blocks' times are counted in ms.
            CHECK(std::abs(named_s - first_s) <= 0.002);
        }
        const std::string silence_first =
            ffmpeg_made("silence_then_one_sentence_opus.webm", "-af adelay=2000:all=1 " + options);
        const std::string refusal =
            refusal_of_one_sentence(joined("opus_joined_silence_first.webm", one, silence_first));
        CHECK_MESSAGE(refusal.find("(the file: its first 32 bytes (its header) recur at byte " +
                                   std::to_string(file_bytes(one))) != std::string::npos,
                      refusal);
        CHECK_MESSAGE(refusal.find("is digital silence") == std::string::npos, refusal);
    }

    TEST_CASE("a refused WebM or Ogg join whose opening recurs names the time the first recording ends") {
        // Two files of one encoder's settings open with the same 32 bytes, which is what the refusal
        // said of the join: its time, read from the first's blocks or pages, was left out of it.
        for (const std::string format : {"webm", "ogg"}) {
            CAPTURE(format);
            const std::string options =
                "-c:a libopus -b:a 24k -fflags +bitexact -flags:a +bitexact -f " + format;
            const std::string one = ffmpeg_made("one_sentence_opus." + format, options);
            const std::string silence_first =
                ffmpeg_made("silence_then_one_sentence_opus." + format, "-af adelay=2000:all=1 " + options);
            const std::string refusal =
                refusal_of_one_sentence(joined("opus_recurring_silence_first." + format, one, silence_first));
            const std::string said =
                "recur at byte " + std::to_string(file_bytes(one)) + ", where the first recording ends (";
            const std::size_t at = refusal.find(said);
            REQUIRE_MESSAGE(at != std::string::npos, refusal);
            const double named_s = std::stod(refusal.substr(at + said.size()));
            const double first_s = static_cast<double>(frames_in(one)) /
                                   static_cast<double>(detail::open_audio_file(one)->sample_rate_hz());
            CHECK(std::abs(named_s - first_s) <= 0.002);
        }
    }

    TEST_CASE("an AVI's OpenDML extension (a RIFF AVIX after the first RIFF) is no second WAV") {
        const std::string avi = ffmpeg_made("voice.avi", "-c:a pcm_s16le -fflags +bitexact -f avi");
        // An OpenDML AVI past 1 GB goes on in RIFF AVIX chunks, which FFmpeg reads: one, holding an
        // empty movi list.
        const std::string extended = test::made_by_command(
            "voice_avix.avi",
            "{ cat '" + avi + "'; printf 'RIFF\\020\\000\\000\\000AVIXLIST\\004\\000\\000\\000movi'; } >");
        const auto source = detail::open_audio_file(extended);
        CHECK(source->notes().empty());
    }
}
