// A numbered PNG sequence: OUT-000000.png, OUT-000001.png, ... written into a temporary folder
// beside them and moved into place together, so a failed or cancelled run leaves none.
#ifndef TALKFACE_VIDEO_PNG_SEQUENCE_HPP
#define TALKFACE_VIDEO_PNG_SEQUENCE_HPP

#include <cstdint>
#include <string>
#include <vector>

namespace talkface::detail {

class PngSequenceOutput {
public:
    // Frames of `path` ("face.png" -> "face-000000.png" ...). \throws talkface::FileError if the
    // temporary folder cannot be created beside it.
    explicit PngSequenceOutput(const std::string& path);
    PngSequenceOutput(const PngSequenceOutput&) = delete;
    PngSequenceOutput& operator=(const PngSequenceOutput&) = delete;
    // Unfinished: the temporary folder and what it holds are removed.
    ~PngSequenceOutput();

    // Writes the next frame's PNG bytes. \throws talkface::FileError.
    void write_frame(const std::uint8_t* bytes, std::size_t size);
    // Moves every frame into place. \throws talkface::FileError.
    void finish();

    // Frame `index`'s file name for `path`.
    static std::string frame_path(const std::string& path, std::size_t index);

private:
    std::string path_;
    std::string temp_folder_;
    std::size_t frame_count_ = 0;
};

}  // namespace talkface::detail

#endif
