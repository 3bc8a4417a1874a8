// The subcommands of `talkface`. Each adds itself to the app and runs its work from its own
// callback, after the whole command line has parsed (CLI11's subcom_in_files pattern).
#ifndef TALKFACE_CLI_COMMANDS_HPP
#define TALKFACE_CLI_COMMANDS_HPP

#include <CLI/CLI.hpp>

namespace talkface_cli {

// What each command that reads a speech says of its AUDIO argument: every format it reads.
inline constexpr const char* kSpeechFormatsHelp =
    "Speech: WAV, FLAC, Ogg, MP3, M4A, Opus, AMR (a phone's voice memo) or a video's sound track (MP4, MOV, "
    "MKV, WebM, MPEG-TS, MPEG)";

// What `align` and `syllables` say of their TRANSCRIPT argument: every form of transcript they read.
inline constexpr const char* kTranscriptHelp =
    "Text, Traditional or Simplified, or numbered pinyin (fix a reading in place: 行{hang2}), in UTF-8, "
    "UTF-16 or UTF-32 with a byte order mark, or --transcript-encoding; or SRT or WebVTT subtitles or a TextGrid, "
    "whose text is read";

// `talkface render`: one face state drawn as an SVG file (render_command.cpp).
void setup_render_command(CLI::App& app);

// `talkface syllables`: a transcript's sentences and readings, plain or JSON (syllables_command.cpp).
void setup_syllables_command(CLI::App& app);

// `talkface keyframes`: mouth key frames and expression events as JSON or TSV (keyframes_command.cpp).
void setup_keyframes_command(CLI::App& app);

// `talkface export`: the timing for Rhubarb, Moho, Live2D, Praat and subtitle tools (export_command.cpp).
void setup_export_command(CLI::App& app);

// `talkface align`: sentence and syllable times of a speech, as a table or JSON, and a plot (align_command.cpp).
void setup_align_command(CLI::App& app);

// `talkface animate`: a speech and its transcript as a web page where the face talks (animate_command.cpp).
void setup_animate_command(CLI::App& app);

// `talkface video`: a speech and its transcript as a video of the talking face (video_command.cpp).
void setup_video_command(CLI::App& app);

// `talkface demo`: animate on the built-in face and the bundled speech (demo_command.cpp).
void setup_demo_command(CLI::App& app);

// `talkface face-from-photo`: a face file from a frontal photo, with a debug overlay (face_from_photo_command.cpp).
void setup_face_from_photo_command(CLI::App& app);

}  // namespace talkface_cli

#endif
