#include "transcript_option.hpp"

namespace talkface_cli {

CLI::Option* add_transcript_argument(CLI::App& command, TranscriptArgument& transcript,
                                     const std::string& help) {
    CLI::Option* positional =
        command.add_option("TRANSCRIPT", transcript.path, help)->check(CLI::ExistingFile);
    command.add_option(
        "--transcript-encoding", transcript.options.encoding,
        "The transcript's encoding when it is not UTF-8 and has no byte order mark (UTF-16 and "
        "UTF-32 with one are read as they are): gb18030 (GBK, GB2312: Simplified Chinese Windows), "
        "big5 or big5-hkscs (Traditional), utf-16le, or any name `iconv -l` lists");
    command.add_flag(
        "--keep-directions", transcript.options.keep_directions,
        "Say a script's stage directions, （笑） [掌声] 【音乐】, and its speakers' labels at line "
        "starts, 主持人： A:, which are otherwise left out with a warning (docs/transcripts.md)");
    command.add_flag_callback(
        "--no-pinyin-input", [&transcript] { transcript.options.read_pinyin = false; },
        "Read Latin letters as letters or English words, never as pinyin (ni3 hao3, nihao)");
    return positional;
}

}  // namespace talkface_cli
