// talkface: the animation editor (thesis 5.4, 7.1): a syllable timeline and a face become every
// frame of a talking face, with lips on the syllables and simulated blinks, brows and head moves.
//
//   auto face = talkface::FaceModel::default_face();
//   talkface::ExpressionSimulator expressions(timeline, /*seed=*/7);
//   talkface::Animation animation = talkface::animate(face, timeline, expressions);
//   std::string json = talkface::key_frames_json(animation.mouth_key_frames, animation.events,
//                                                animation.fps, animation.duration_s);
//
// Functions here are pure and may be called from several threads at once.
#ifndef TALKFACE_ANIMATION_HPP
#define TALKFACE_ANIMATION_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "talkface/export.h"
#include "talkface/expression_simulator.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/timeline.hpp"

namespace talkface {
inline namespace v0 {

/// A finished animation: what it was made from and every frame.
struct Animation {
    double fps = 25.0;        ///< frames per second, LipSyncOptions::fps of animate()
    double duration_s = 0.0;  ///< the later of the timeline's end and the simulator's
    std::vector<MouthKeyFrame> mouth_key_frames;  ///< mouth_key_frames(timeline, options) of animate()
    std::vector<ExpressionEvent> events;  ///< the simulator's events() when the frames were made
    /// Frame i shows time i / fps, for i = 0 .. floor(duration_s * fps); the mouth is always set.
    std::vector<FaceState> frames;
};

/// Builds every frame: mouth_key_frames() and mouth_frames() for the lips, the simulator's pose and
/// expression for the rest.
/// \throws talkface::InvalidArgument as mouth_key_frames() and mouth_frames() do.
TALKFACE_API Animation animate(const FaceModel& neutral, const Timeline& timeline,
                               const ExpressionSimulator& expressions, const LipSyncOptions& options = {});

/// The key frames as JSON, one line per item, numbers with at most 3 decimals (milliseconds):
/// {"fps":25,"duration":s, "mouth":[{"time":s,"shape":"a","syllable":k}, ...],
/// "events":[{"kind":"blink","start":s,"end":s,"amount":x}, ...]}: the frame rate the key frames sit
/// on and the animation's length in seconds (Animation::fps and duration_s), so a player needs
/// nothing else. A rest key frame has "syllable":null. The same input always gives the same bytes.
/// \throws talkface::InvalidArgument naming "fps" unless it is finite and > 0, or "duration_s"
///         unless it is finite and >= 0.
TALKFACE_API std::string key_frames_json(const std::vector<MouthKeyFrame>& mouth_key_frames,
                                         const std::vector<ExpressionEvent>& events, double fps,
                                         double duration_s);

/// The mouth key frames as tab-separated text, one "time<TAB>shape" line each (time in seconds
/// with at most 3 decimals, shape as mouth_shape_name() writes it), no header.
TALKFACE_API std::string key_frames_tsv(const std::vector<MouthKeyFrame>& mouth_key_frames);

}  // namespace v0
}  // namespace talkface

#endif
