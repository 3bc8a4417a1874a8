// `talkface demo`: `talkface animate` on the built-in face and the bundled Mandarin speech
// (samples/speech/, compiled into the command), so one command shows what talkface does.
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "animate_command.hpp"
#include "video_command.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "embedded_demo.hpp"
#include "written_report.hpp"

namespace talkface_cli {

namespace {

std::string_view view_of(EmbeddedFile file) {
    return {reinterpret_cast<const char*>(file.bytes), file.size};
}

// The speech as a temporary file for the aligner, which reads files; removed when done.
class TemporarySpeech {
public:
    TemporarySpeech() {
        std::string pattern = (std::filesystem::temp_directory_path() / "talkface-demo-XXXXXX.ogg").string();
        const int fd = ::mkstemps(pattern.data(), 4);
        if (fd < 0) throw talkface::FileError(pattern, std::strerror(errno));
        ::close(fd);
        path_ = pattern;
        talkface::detail::write_file_atomically(path_, view_of(demo_speech()));
    }
    ~TemporarySpeech() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    TemporarySpeech(const TemporarySpeech&) = delete;
    TemporarySpeech& operator=(const TemporarySpeech&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

void run_demo(const AnimateOptions& options, const CLI::App& demo) {
    const TemporarySpeech speech;
    const talkface::Timeline transcript =
        talkface::read_transcript(view_of(demo_transcript()), {}, "samples/speech/demo.txt");
    if (is_video_output(options.output_path)) {
        // A video at the video's defaults (1280x720, 30 fps, the announcer), unless asked otherwise.
        VideoCommandOptions video;
        video.animate = options;
        if (demo.count("--fps") == 0) video.animate.fps = talkface::VideoOptions{}.fps;
        if (demo.count("--app") != 0) video.app = options.app == "announcer" ? "announcer" : "plain";
        make_video(video, speech.path(), transcript);
        return;
    }
    std::string linked_url;
    if (options.audio == talkface::WebPageAudio::link) {
        // A linked page needs the speech beside it: written there as OUT.ogg.
        const std::filesystem::path audio = std::filesystem::path(options.output_path).replace_extension(".ogg");
        talkface::detail::write_file_atomically(audio.string(), view_of(demo_speech()));
        linked_url = audio.filename().generic_string();
        if (!options.quiet) report_written(std::cerr, audio.string(), "the demo speech (Ogg Vorbis)", std::nullopt);
    }
    make_talking_face(options, speech.path(), transcript, linked_url);
}

}  // namespace

void setup_demo_command(CLI::App& app) {
    auto options = std::make_shared<AnimateOptions>();
    CLI::App* demo = app.add_subcommand(
        "demo",
        "Make the web page (or, for -o OUT.mp4/.webm/.webp/.gif/.png, the video) of the built-in face saying a short "
        "bundled Mandarin speech");
    add_page_options(*demo, *options);
    demo->callback([options, demo] { run_demo(*options, *demo); });
}

}  // namespace talkface_cli
