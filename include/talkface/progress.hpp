// talkface: how long calls report their progress and are cancelled (the aligner, the animation
// encoders, the web page).
#ifndef TALKFACE_PROGRESS_HPP
#define TALKFACE_PROGRESS_HPP

#include <functional>
#include <string>

namespace talkface {
inline namespace v0 {

/// Reports progress: the fraction 0..1 of the whole call and the stage it is in (each call lists
/// its stages: the aligner "reading", "sentences", "syllables"; the animation "frames",
/// "encoding"). Return false to cancel, which makes the call throw talkface::Cancelled. Called on
/// the thread that made the call; an empty callback reports nothing.
using ProgressCallback = std::function<bool(double fraction, const std::string& stage)>;

}  // namespace v0
}  // namespace talkface

#endif
