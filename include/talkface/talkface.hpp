// talkface: talking cartoon faces. This umbrella header includes the whole C++ API.
//
//   #include <talkface/talkface.hpp>
//
//   int main() {
//       auto face = talkface::FaceModel::default_face();            // or FaceModel::load("face.xml")
//       talkface::FaceState state;
//       state.pose = {0.0, 10.0, -5.0};                              // nod, turn, tilt in degrees
//       state.expression.smile = 0.6;
//       state.mouth = talkface::mouth_controls(face, talkface::MouthShape::a);
//       talkface::SvgAnimator animator(face);
//       animator.write_svg("face.svg", state);                       // atomic: all or nothing
//   }
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
#include "talkface/face_model.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/frame_renderer.hpp"
#include "talkface/library.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/mouth_controls.hpp"
#include "talkface/mouth_shape.hpp"
#include "talkface/rotation3d.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/svg_animator.hpp"
#include "talkface/timeline.hpp"
#include "talkface/timeline_json.hpp"
#include "talkface/transcript.hpp"
#include "talkface/types.hpp"
#include "talkface/version.h"
#include "talkface/web_page.hpp"

#endif
