// talkface: talking cartoon faces. This umbrella header includes the whole C++ API but the photo
// stage (talkface/face_from_photo.hpp, library talkface::photo). The whole pipeline:
//
//   #include <talkface/talkface.hpp>
//
//   int main() {
//       const auto face = talkface::FaceModel::load("face.xml");          // or FaceModel::default_face()
//       const auto transcript = talkface::load_transcript("speech.txt");  // sentences and syllables
//       const auto timeline = talkface::SpeechAligner().align_file("speech.ogg", transcript);  // any audio
//       const talkface::ExpressionSimulator expressions(timeline, /*seed=*/7);  // blinks, nods ...
//       const auto animation = talkface::animate(face, timeline, expressions);
//       talkface::write_web_page("talk.html", talkface::SvgAnimator(face), animation, timeline,
//                                "speech.ogg");                            // atomic: all or nothing
//   }
//
// (tests/headers/ builds this example from the text above and runs it on samples/speech/.)
//
// Errors are exceptions derived from talkface::Error (errors.hpp); each message names the file,
// line, point, parameter or time that was wrong. Nothing in talkface prints or reads global state:
// functions are pure unless documented otherwise, and const objects are safe to share across threads.
// The C ABI is talkface/talkface.h; the Python module is `import talkface`.
#ifndef TALKFACE_TALKFACE_HPP
#define TALKFACE_TALKFACE_HPP

#include "talkface/alignment_plot.hpp"
#include "talkface/animation.hpp"
#include "talkface/errors.hpp"
#include "talkface/expression.hpp"
#include "talkface/expression_simulator.hpp"
#include "talkface/face_lift.hpp"
#include "talkface/face_look.hpp"
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/face_video.hpp"
#include "talkface/frame_renderer.hpp"
#include "talkface/library.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/mouth_controls.hpp"
#include "talkface/mouth_shape.hpp"
#include "talkface/progress.hpp"
#include "talkface/rotation3d.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/svg_animator.hpp"
#include "talkface/timeline.hpp"
#include "talkface/timeline_json.hpp"
#include "talkface/timing_formats.hpp"
#include "talkface/transcript.hpp"
#include "talkface/types.hpp"
#include "talkface/version.h"
#include "talkface/video_writer.hpp"
#include "talkface/web_page.hpp"

#endif
