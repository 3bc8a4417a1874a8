// talkface: simulated blinks, eyebrow raises, head tilts, turns and nods (thesis chapter 4,
// SPEC "Statistics"), reproducible from a seed on every platform.
//
//   talkface::ExpressionSimulator simulator(timeline, /*seed=*/42);          // style "normal"
//   talkface::ExpressionStyle calm = talkface::ExpressionStyle::load("calm.json");  // or set fields
//   calm.is_nod_simulated = false;
//   talkface::ExpressionSimulator calm_simulator(timeline, 42, calm);
//   simulator.set_user_events({{talkface::ExpressionEventKind::nod, 1.0, 1.4, 5.0}});
//   talkface::Pose pose = simulator.pose_at(2.5);
//   talkface::Expression expression = simulator.expression_at(2.5);
//
// Thread safety: const members may be called from several threads at once; set_user_events() may
// not run at the same time as any other member.
#ifndef TALKFACE_EXPRESSION_SIMULATOR_HPP
#define TALKFACE_EXPRESSION_SIMULATOR_HPP

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "talkface/export.h"
#include "talkface/expression.hpp"
#include "talkface/face_pose.hpp"
#include "talkface/timeline.hpp"

namespace talkface {
inline namespace v0 {

/// What an expression event does. The numeric values are stable within a major version.
enum class ExpressionEventKind : int { blink = 0, brows = 1, tilt = 2, turn = 3, nod = 4 };

/// "blink", "brows", "tilt", "turn", "nod".
TALKFACE_API const char* expression_event_kind_name(ExpressionEventKind kind);
/// Parses a name as expression_event_kind_name() writes it.
/// \throws talkface::InvalidArgument listing the valid names.
TALKFACE_API ExpressionEventKind expression_event_kind_from_name(std::string_view name);

/// One blink, eyebrow raise or head movement over [start_s, end_s], seconds from the start of the
/// audio.
///
/// blink and brows are excursions that come back: the amount is reached inside the event and the
/// face is neutral again at end_s. Blink: the lids close over the first 30% (cosine ease) and
/// reopen over the other 70% (lids close faster than they open). Brows: raised over the first 30%,
/// held, lowered over the last 30%.
///
/// tilt, turn and nod are head movements as the thesis measures them (4.2, Table 4.8: the head
/// starts moving at start_s and stops at end_s): the angle moves, with a cosine ease, from where
/// the previous event of the kind left it (0 before the first) to `amount`, and stays there until
/// the next event of the kind. A nod is two events: down to its depth, then up to 0.
struct ExpressionEvent {
    ExpressionEventKind kind = ExpressionEventKind::blink;
    double start_s = 0.0;
    double end_s = 0.0;
    /// blink: how far the lids close, 0..1 (1 = shut); brows: the raise at its peak, 0..1 of
    /// EyebrowH; tilt (gamma), turn (beta), nod (alpha, > 0 down): the angle reached, degrees,
    /// within +-kMaxPoseAngleDeg.
    double amount = 0.0;
    friend bool operator==(const ExpressionEvent& a, const ExpressionEvent& b) {
        return a.kind == b.kind && a.start_s == b.start_s && a.end_s == b.end_s && a.amount == b.amount;
    }
    friend bool operator!=(const ExpressionEvent& a, const ExpressionEvent& b) { return !(a == b); }
};

/// A closed range [min, max] a uniform random variable is drawn from.
struct UniformRange {
    double min = 0.0;
    double max = 0.0;
    friend bool operator==(const UniformRange& a, const UniformRange& b) {
        return a.min == b.min && a.max == b.max;
    }
    friend bool operator!=(const UniformRange& a, const UniformRange& b) { return !(a == b); }
};

/// The distributions of the simulation, and which kinds of event are simulated at all. Times are
/// seconds; a "time between" events runs from the end of one to the start of the next (thesis
/// 4.2). normal() and announcer() are the thesis's; any field may be changed. validate() checks
/// every field and names the first one out of range; the simulator does the same.
struct TALKFACE_API ExpressionStyle {
    std::string name = "normal";  ///< a label; "custom" for caller-built styles

    /// Time between blinks: Gamma(shape, scale), drawn as -scale ln(U1 ... U_shape) (thesis 4.3,
    /// Lin and Tsai: shape 2, scale 1.48 s). The shape is an integer from 1 to 16.
    int blink_interval_shape = 2;
    double blink_interval_scale_s = 1.48;
    /// Not in the thesis: spontaneous blinks last about 0.1-0.4 s (Schiffman, "Sensation and
    /// Perception"), most near 0.15-0.3 s; the lid closes faster than it reopens (VanderWerf et
    /// al. 2003, J. Neurophysiol. 89).
    UniformRange blink_duration_s{0.15, 0.30};

    UniformRange brows_interval_s{0.90, 12.54};  ///< thesis 4.4: mean 6.72 +- sd 5.82
    UniformRange brows_duration_s{0.51, 0.99};   ///< thesis 4.4: mean 0.75 +- sd 0.24
    UniformRange brows_amount{0.5, 1.0};         ///< chosen: a clear but not startled raise

    UniformRange tilt_interval_s{0.0, 6.64};  ///< thesis 4.5.1, doubled for a normal pace
    UniformRange tilt_duration_s{0.4, 1.0};   ///< thesis 4.5.1, doubled for a normal pace
    UniformRange tilt_angle_deg{1.5, 5.0};    ///< chosen: |gamma| reached, random sign

    UniformRange turn_interval_s{0.08, 7.92};  ///< thesis Table 4.7, adjusted
    UniformRange turn_duration_s{0.4, 0.92};   ///< thesis Table 4.7, adjusted
    UniformRange turn_angle_deg{2.0, 8.0};     ///< chosen: |beta| reached, random sign

    /// Nods, one per pause starting at t (thesis 4.5.3, Table 4.12): down over
    /// [t - t1 - d1, t - t1], held, up over [t, t + d2].
    UniformRange nod_lead_s{0.07, 0.35};   ///< t1
    UniformRange nod_down_s{0.34, 0.94};   ///< d1, adjusted for a normal pace
    UniformRange nod_up_s{0.34, 0.70};     ///< d2, adjusted for a normal pace
    UniformRange nod_angle_deg{3.0, 5.0};  ///< chosen: alpha at the bottom of the nod
    /// A transcript pause (Syllable::pause_after) is a pause for nodding when the gap after the
    /// syllable is at least this long; the end of a sentence always is (chosen: about the
    /// shortest pause Algorithm 3.1 cuts sentences at).
    double nod_min_pause_s = 0.2;

    /// Whether each kind is simulated at all. A kind switched off has no simulated events (a
    /// caller's events of that kind still apply, see set_user_events()); the other kinds' events
    /// stay exactly what they are for the same seed, since every kind draws from its own stream.
    bool is_blink_simulated = true;
    bool is_brows_simulated = true;
    bool is_tilt_simulated = true;
    bool is_turn_simulated = true;
    bool is_nod_simulated = true;

    /// The thesis's numbers for speech at a normal pace (the default).
    static ExpressionStyle normal();
    /// The unadjusted numbers measured on TV news announcers (Tables 4.7, 4.12, section 4.5.1):
    /// faster head movements for fast speech.
    static ExpressionStyle announcer();
    /// "normal" or "announcer". \throws talkface::InvalidArgument listing the valid names.
    static ExpressionStyle from_name(std::string_view name);

    /// Reads a style from the JSON of docs/style-format.md: an object whose keys are field names
    /// (all optional, ranges as [min, max], flags as true / false), starting from "normal" or from
    /// the style named by a "base" key; "name" sets the label, which is "custom" otherwise.
    /// `source` names the text in messages (a file name, or "<string>").
    /// \throws talkface::ParseError at source:line:column naming the key: text that is not JSON,
    ///         an unknown key (the message lists the valid ones), a value of the wrong type, a value
    ///         out of range, a key given twice.
    static ExpressionStyle from_json(std::string_view text, const std::string& source = "<string>");
    /// from_json() of a file's content. \throws talkface::FileError if it cannot be read; as
    /// from_json() otherwise, naming the file.
    static ExpressionStyle load(const std::string& path);
    /// The style as from_json() reads it back (every field, one per line, numbers in their shortest
    /// exact form): the same style always gives the same bytes.
    std::string to_json() const;

    /// Checks every field against the limits docs/style-format.md gives (durations and scales
    /// above 0, amounts within 0..1, angles within 0..kMaxPoseAngleDeg, min <= max, the shape
    /// within 1..16, times at most 3600 s). \throws talkface::InvalidArgument naming the first field out of
    /// range
    ///         ("ExpressionStyle::tilt_angle_deg") and what it expected.
    void validate() const;
    /// Whether events of `kind` are simulated (its is_<kind>_simulated field).
    bool is_simulated(ExpressionEventKind kind) const;
    /// Switches the simulation of a kind on or off. \throws talkface::InvalidArgument for a value
    ///         outside ExpressionEventKind.
    void set_simulated(ExpressionEventKind kind, bool is_simulated);
};

/// Every field equal, name included.
TALKFACE_API bool operator==(const ExpressionStyle& a, const ExpressionStyle& b);
TALKFACE_API bool operator!=(const ExpressionStyle& a, const ExpressionStyle& b);

/// How caller-given events combine with the simulated ones.
enum class UserEventMode : int {
    /// Simulated events of a kind that overlap a caller's event of that kind are dropped; the
    /// rest stay.
    add = 0,
    /// Every simulated event of a kind the caller gives events for is dropped.
    replace = 1,
};

/// Checks events a caller gives. The events may come in any order; indices in messages are
/// positions in `events`.
/// \throws talkface::InvalidArgument naming the event (index, kind, times): a time not finite or
///         negative, an end before its start, an angle beyond +-kMaxPoseAngleDeg, a blink or brows
///         amount outside 0..1, or an event overlapping another of its kind (both named).
TALKFACE_API void validate_expression_events(const std::vector<ExpressionEvent>& events);

/// Where the speech pauses, seconds: the end of each sentence's last syllable, and the end of a
/// syllable marked pause_after when the gap after it is at least min_pause_s. Rising.
TALKFACE_API std::vector<double> pause_starts_s(const Timeline& timeline, double min_pause_s);

/// The end of a timeline, seconds: its duration_s, or the end of its last syllable or sentence if
/// that is later.
TALKFACE_API double timeline_end_s(const Timeline& timeline);

/// Simulates the face's behaviour over a timeline, from a seed, and evaluates it at any time.
///
/// Random numbers come from xoshiro256** seeded through splitmix64, one stream per event kind (so
/// that changing how one kind is drawn never changes another), and uniform and gamma variates are
/// computed here, not by <random>'s distributions, whose output differs between standard
/// libraries: the same seed gives the same events everywhere. Simulated events of a kind never
/// overlap and all lie in [0, timeline_end_s], except that a nod's way up may end after it.
class TALKFACE_API ExpressionSimulator {
public:
    /// Simulates the events for `timeline`.
    /// Kinds the style switches off get no simulated events.
    /// \throws talkface::InvalidArgument naming the style field that is out of range (a range with
    ///         min > max, negative times, zero durations, an angle beyond +-kMaxPoseAngleDeg), or
    ///         the syllable whose times are not finite or end before they start.
    ExpressionSimulator(const Timeline& timeline, std::uint64_t seed,
                        const ExpressionStyle& style = ExpressionStyle::normal());
    ~ExpressionSimulator();
    ExpressionSimulator(ExpressionSimulator&&) noexcept;
    ExpressionSimulator& operator=(ExpressionSimulator&&) noexcept;
    ExpressionSimulator(const ExpressionSimulator&) = delete;
    ExpressionSimulator& operator=(const ExpressionSimulator&) = delete;

    std::uint64_t seed() const;            ///< the seed it was made with
    const ExpressionStyle& style() const;  ///< the style it was made with
    double duration_s() const;             ///< timeline_end_s of the timeline

    /// The simulated events, by start time (then kind).
    const std::vector<ExpressionEvent>& simulated_events() const;
    /// Sets the caller's events (replacing any set before) and combines them with the simulated
    /// ones as `mode` says. An empty list restores the simulated events.
    /// \throws talkface::InvalidArgument as validate_expression_events(); nothing changes then.
    void set_user_events(const std::vector<ExpressionEvent>& events, UserEventMode mode = UserEventMode::add);
    /// The events in effect: simulated and the caller's, by start time (then kind).
    const std::vector<ExpressionEvent>& events() const;

    /// The head pose at a time, seconds (any time; 0 before the first event).
    Pose pose_at(double time_s) const;
    /// Blinks (both eyes) and eyebrow raise at a time, seconds; smile stays 0.
    Expression expression_at(double time_s) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace v0
}  // namespace talkface

#endif
