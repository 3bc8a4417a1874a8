// What the audio reader says of each recording it reads whole (issue 13, "Bad input"): its notes,
// the warnings a file gives however it is aligned (a damaged WAV's cut zeros and clicks, a file that
// goes on past its stated end, a header's length its tracks belie), or its refusal. Run over every
// corpus's recordings, it counts the false warnings a reader's check gives on good files, without
// the alignment's cost.
//
//   reading_notes FILE_OR_FOLDER...
//
// Folders are walked for recordings (by extension). Prints "PATH<TAB>note" for each note and
// "PATH<TAB>refused: MESSAGE" for each refusal, then how many files were read, noted and refused.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "audio/audio_source.hpp"
#include "talkface/errors.hpp"

namespace {

bool is_recording(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* kind : {".wav", ".flac", ".ogg", ".opus", ".mp3", ".m4a", ".mp4", ".mov", ".mkv",
                             ".webm", ".amr", ".aiff", ".caf", ".3gp"})
        if (extension == kind) return true;
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> paths;
    for (int i = 1; i < argc; ++i) {
        if (!std::filesystem::is_directory(argv[i])) {
            paths.emplace_back(argv[i]);
            continue;
        }
        for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[i]))
            if (entry.is_regular_file() && is_recording(entry.path())) paths.push_back(entry.path().string());
    }
    std::sort(paths.begin(), paths.end());
    std::size_t noted = 0, refused = 0;
    std::vector<float> block(1 << 16);
    for (const std::string& path : paths) {
        try {
            const auto source = talkface::detail::open_audio_file(path);
            while (source->read(block.data(), block.size()) > 0) {
            }
            for (const std::string& note : source->notes())
                std::printf("%s\t%s\n", path.c_str(), note.c_str());
            noted += source->notes().empty() ? 0 : 1;
        } catch (const talkface::Error& error) {
            std::printf("%s\trefused: %s\n", path.c_str(), error.what());
            ++refused;
        }
    }
    std::printf("%zu files read, %zu with a note, %zu refused\n", paths.size(), noted, refused);
    return 0;
}
