// Whether an MP4-family file (MP4, M4A, MOV) lacks its index, told from its top-level boxes alone:
// FFmpeg only says "Invalid data found" of such a file, which is the commonest damage to a phone's
// recording (issue #13).
#ifndef TALKFACE_AUDIO_MP4_INDEX_HPP
#define TALKFACE_AUDIO_MP4_INDEX_HPP

#include <string>

namespace talkface::detail {

// True for a file that opens with an ISO base media "ftyp" box and whose top-level boxes, walked to
// the end of the file, hold no "moov": the index without which no sample can be found. Encoders and
// recorders write it last unless told otherwise (ffmpeg's +faststart), so a file cut while it was
// copied or recorded, or one still being written, lacks it. False for anything else, including a
// file that cannot be read (the caller reports that).
bool is_mp4_without_index(const std::string& path);

}  // namespace talkface::detail

#endif
