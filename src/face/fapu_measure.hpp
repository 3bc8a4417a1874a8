// FAPUs measured from a face's points, for files that leave them out (SPEC "Face model").
#ifndef TALKFACE_FACE_FAPU_MEASURE_HPP
#define TALKFACE_FACE_FAPU_MEASURE_HPP

#include <string_view>

#include "talkface/export.h"
#include "talkface/face_model.hpp"

namespace talkface::detail {

// The value a FAPU takes when a face file leaves it out, from the face's points:
//   d          |EyeballLeft - EyeballRight|
//   LeftEyeH   3.4.y - 3.2.y              RightEyeH  3.3.y - 3.1.y
//   UpperLipH  2.2.y - 8.1.y              LowerLipH  8.2.y - 2.3.y
//   MNS0       2.2.y - 9.15.y (MPEG-4: nose bottom to the upper inner lip)
//   MW0        8.3.x - 8.4.x              JawH       2.1.y - 8.2.y
//   r1, r2     half of LeftEyeH, RightEyeH (MPEG-4 neutral face: the eyelids touch the iris)
//   EyebrowH   0.12 d, EyebrowH2 0.09 d: the brow's thickness at 4.4 and 4.4a times 1.3 (Algorithm 2.1
//              puts G and F that far below); not measurable from the 72 points, so set from d.
// Exported from libtalkface for talkface::photo (not in the installed headers: not API).
TALKFACE_API double measured_fapu(const FaceModel& face, std::string_view name);

}  // namespace talkface::detail

#endif
