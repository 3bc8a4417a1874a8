// talkface: timings to the tools animators use, and timings from theirs (issue #15). One place
// reads and writes every timing format, by name or by the file's suffix (OpenTimelineIO's adapters):
//
//   talkface::ExportInput input;                       // what an export is drawn from
//   input.timeline = timeline;                         // aligned; duration_s is the audio's end
//   input.mouth_key_frames = animation.mouth_key_frames;
//   input.fps = animation.fps;
//   input.frames = animation.frames;                   // pose and blinks per frame (Live2D)
//   input.audio_path = "speech.wav";
//   talkface::export_to_file("speech.TextGrid", input);                 // format from the suffix
//   talkface::Timeline mine = talkface::read_timing_file("mfa.TextGrid", transcript, duration_s);
//
// Only the timeline JSON (timeline_json.hpp) is lossless; each format here says in
// docs/timing-formats.md what it drops. Functions are pure (files apart) and thread-safe.
#ifndef TALKFACE_TIMING_FORMATS_HPP
#define TALKFACE_TIMING_FORMATS_HPP

#include <string>
#include <string_view>
#include <vector>

#include "talkface/export.h"
#include "talkface/face_pose.hpp"
#include "talkface/lip_sync.hpp"
#include "talkface/speech_aligner.hpp"
#include "talkface/timeline.hpp"

namespace talkface {
inline namespace v0 {

/// Everything an export is drawn from. Every export spans 0 to timeline.duration_s.
struct ExportInput {
    Timeline timeline;  ///< aligned or imported; duration_s > 0 is the audio's end, seconds
    std::vector<MouthKeyFrame> mouth_key_frames;  ///< mouth_key_frames(timeline), rising in time
    double fps = 25.0;  ///< frame rate of `frames`, of Moho's frame numbers and of Live2D's Meta.Fps
    /// The face at frame i (time i / fps): pose and expression, for Live2D's blinks, brows and head
    /// angles (Animation::frames). May be empty for the other formats.
    std::vector<FaceState> frames;
    std::string audio_path;  ///< the recording; Rhubarb's metadata.soundFile (written absolute, as Rhubarb does)
};

/// The export format names: "rhubarb-tsv", "rhubarb-json", "rhubarb-xml", "moho", "live2d",
/// "textgrid", "srt", "vtt".
TALKFACE_API const std::vector<std::string>& export_format_names();

/// The export format a file name asks for: .tsv rhubarb-tsv, .xml rhubarb-xml, .dat moho,
/// .motion3.json live2d, .TextGrid textgrid, .srt srt, .vtt vtt. Any other .json is ambiguous.
/// \throws talkface::InvalidArgument naming the suffix, the file and the format names (and, for
///         .json, that --format / a format name must choose).
TALKFACE_API std::string export_format_for_path(const std::string& path);

/// The export as text (UTF-8).
/// \throws talkface::InvalidArgument naming the format if it is not one of export_format_names(),
///         or the input if it cannot be exported (duration_s not positive, key frames out of
///         order, no frames for live2d).
TALKFACE_API std::string export_to_string(const ExportInput& input, const std::string& format);

/// export_to_string written to `path` atomically; `format` empty: export_format_for_path(path).
/// \throws as export_to_string, and talkface::FileError naming the path; nothing is written then.
TALKFACE_API void export_to_file(const std::string& path, const ExportInput& input, const std::string& format = "");

/// The timing import format names: "textgrid", "srt", "vtt", "words-json" (a list of
/// {"text","start","end"} as text-to-speech engines report words or syllables) and "timeline-json".
TALKFACE_API const std::vector<std::string>& timing_format_names();

/// The import format a file name asks for: .TextGrid textgrid, .srt srt, .vtt vtt; .json gives
/// "json", which the readers take as "timeline-json" for an object and "words-json" for a list.
/// \throws talkface::InvalidArgument naming the suffix, the file and the format names.
TALKFACE_API std::string timing_format_for_path(const std::string& path);

/// A transcript timed by a timing file's text instead of the aligner: each syllable of
/// `transcript` takes its times from the timing's word or syllable intervals (a word's span is
/// shared evenly among its syllables); SRT and WebVTT cues time their sentences, and their
/// syllables share each cue evenly (or take WebVTT's cue timestamps, one per syllable: what
/// talkface's vtt export writes). time_transcript() pins the aligner to the cues instead.
/// "timeline-json" is read as it is, once its syllables are found to be the transcript's.
/// `duration_s` is the audio's length (0: unknown, not checked); the result's duration_s is set to it.
/// \throws talkface::ParseError naming source_name:line and what was expected for a malformed
///         file, for times out of order or past duration_s, and for a text that parts from the
///         transcript, naming the first place they part (the timing's item, the transcript's
///         sentence and syllable); InvalidArgument for an unknown format.
TALKFACE_API Timeline read_timing_string(std::string_view utf8_text, const std::string& format,
                                         const Timeline& transcript, double duration_s,
                                         const std::string& source_name = "<timing>");

/// read_timing_string of a file; `format` empty: timing_format_for_path(path).
/// \throws talkface::FileError if it cannot be read; as read_timing_string.
TALKFACE_API Timeline read_timing_file(const std::string& path, const Timeline& transcript, double duration_s,
                                       const std::string& format = "");

/// The transcript spoken in the recording `audio_path`, timed by the timing file `timing_path`
/// instead of aligning the whole recording: word and syllable timings (textgrid, words-json,
/// timeline-json) as read_timing_file reads them, checked against the audio's length; subtitle
/// cues (srt, vtt) that give sentence times only pin the aligner: each sentence is searched only
/// inside its cues instead of between the pauses the aligner would choose (the models are still
/// learned, and a wrong text still refused, over the whole recording); where a cue splits a
/// sentence, its syllables are then kept inside each cue (moved in proportion into it where the
/// aligner put them outside). Cues that time every syllable (a WebVTT cue timestamp before each
/// one after the first, as the vtt export writes, or a cue per syllable) are read as
/// read_timing_file reads them.
/// `format` empty: timing_format_for_path(timing_path). This is what `--timing FILE` does.
/// \throws as read_timing_file; talkface::FileError / ParseError for the audio as
///         SpeechAligner::align_file; AlignmentError as align_file; Cancelled if `progress`
///         returned false.
TALKFACE_API Timeline time_transcript(const std::string& timing_path, const std::string& audio_path,
                                      const Timeline& transcript, const std::string& format = "",
                                      const ProgressCallback& progress = {});

/// time_transcript, the aligner that subtitle cues pin taking `options` (the other one takes
/// the defaults): AlignOptions::check decides what a wrong text does, and with
/// AlignOptions::lenient a stretch inside the cues that does not say its text is reported
/// (Timeline::mismatches) rather than refused. The cues cut the sentences whatever
/// options.sentence_cut says. Where a cue splits a sentence and its syllables are moved into it,
/// a mismatch keeps its stretch of the audio. This is what `--timing FILE --lenient` does.
/// \throws as time_transcript; talkface::InvalidArgument naming the option if `options` are out
///         of range (as SpeechAligner's constructor), or naming "lenient" when options.lenient
///         and the file times every syllable itself (textgrid, words-json, timeline-json, or cues
///         with a timestamp per syllable): nothing is aligned, so nothing could be found not to
///         say its text.
TALKFACE_API Timeline time_transcript(const std::string& timing_path, const std::string& audio_path,
                                      const Timeline& transcript, const AlignOptions& options,
                                      const std::string& format = "", const ProgressCallback& progress = {});

/// The length of a recording, seconds, from its header.
/// \throws talkface::FileError / ParseError as SpeechAligner::align_file.
TALKFACE_API double audio_duration_s(const std::string& audio_path);

/// The timeline in an import format ("textgrid", "srt", "vtt", "words-json", "timeline-json"),
/// so that read_timing_string of it gives the timeline's times back (syllable by syllable for
/// textgrid and words-json; sentence by sentence for srt and vtt).
/// \throws talkface::InvalidArgument naming the format if it is not one of timing_format_names().
TALKFACE_API std::string write_timing_string(const Timeline& timeline, const std::string& format);

}  // namespace v0
}  // namespace talkface

#endif
