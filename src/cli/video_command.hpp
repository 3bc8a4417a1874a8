// What `talkface video` and `talkface demo -o OUT.mp4` share: a speech, its transcript and a face
// in, a video of the talking face out (video_command.cpp).
#ifndef TALKFACE_CLI_VIDEO_COMMAND_HPP
#define TALKFACE_CLI_VIDEO_COMMAND_HPP

#include <string>

#include <CLI/CLI.hpp>
#include <talkface/talkface.hpp>

#include "animate_command.hpp"

namespace talkface_cli {

struct VideoCommandOptions {
    AnimateOptions animate;        // face, fps, seed, style, background, output, quiet
    std::string size = "1280x720";
    std::string app = "announcer";  // announcer or plain
    int crf = -1;
    bool transparent = false;
};

// Adds the options of `talkface video` (all but the inputs) to `command`; fps defaults to 30.
void add_video_options(CLI::App& command, VideoCommandOptions& options);

// Aligns `audio_path` with `transcript`, animates the face and writes the video at
// options.animate.output_path, with a progress bar; Ctrl-C stops it, leaves no file and exits 130.
void make_video(const VideoCommandOptions& options, const std::string& audio_path,
                const talkface::Timeline& transcript);

// True if `path`'s extension is a video's (.mp4, .webm, .webp, .gif, .png).
bool is_video_output(const std::string& path);

}  // namespace talkface_cli

#endif
