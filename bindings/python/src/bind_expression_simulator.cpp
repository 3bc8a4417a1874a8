// The expression simulator in Python: ExpressionEventKind, ExpressionEvent, ExpressionStyle,
// UserEventMode and ExpressionSimulator; the simulation runs without the GIL.
#include <pybind11/operators.h>

#include <utility>

#include "bind.hpp"

namespace talkface::python {

namespace {

// Sets a field on a copy and validates it: a refused value leaves the style as it was, and since
// the style was valid before, the error names this field.
template <typename Value>
void set_validated(ExpressionStyle& style, Value ExpressionStyle::*member, Value value) {
    ExpressionStyle changed = style;
    changed.*member = value;
    changed.validate();
    style = std::move(changed);
}

template <typename Value>
void def_field(py::class_<ExpressionStyle>& style_class, const char* name, Value ExpressionStyle::*member,
               const char* doc) {
    style_class.def_property(
        name, [member](const ExpressionStyle& style) { return style.*member; },
        [member](ExpressionStyle& style, Value value) { set_validated(style, member, value); }, doc);
}

// A range field as a (min, max) tuple.
void def_range_field(py::class_<ExpressionStyle>& style_class, const char* name,
                     UniformRange ExpressionStyle::*member, const char* doc) {
    style_class.def_property(
        name,
        [member](const ExpressionStyle& style) {
            return std::make_pair((style.*member).min, (style.*member).max);
        },
        [member](ExpressionStyle& style, std::pair<double, double> value) {
            set_validated(style, member, UniformRange{value.first, value.second});
        },
        doc);
}

}  // namespace

void bind_expression_simulator(py::module_& m) {
    py::enum_<ExpressionEventKind>(m, "ExpressionEventKind", R"doc(
What an expression event does: blink, brows, tilt, turn, nod. The values equal the C ABI's
tf_expression_event_kind.

Example:
    >>> talkface.ExpressionEventKind.nod
    >>> talkface.expression_event_kind_name(talkface.ExpressionEventKind.nod)
)doc")
        .value("blink", ExpressionEventKind::blink)
        .value("brows", ExpressionEventKind::brows)
        .value("tilt", ExpressionEventKind::tilt)
        .value("turn", ExpressionEventKind::turn)
        .value("nod", ExpressionEventKind::nod);

    m.def("expression_event_kind_name", &expression_event_kind_name, py::arg("kind"), R"doc(
"blink", "brows", "tilt", "turn" or "nod".

Example:
    >>> talkface.expression_event_kind_name(talkface.ExpressionEventKind.tilt)
    'tilt'
)doc");
    m.def("expression_event_kind_from_name", &expression_event_kind_from_name, py::arg("name"), R"doc(
Parses a name as expression_event_kind_name() writes it.

Raises:
    talkface.InvalidArgument: an unknown name (the message lists the valid ones).

Example:
    >>> talkface.expression_event_kind_from_name("nod")
    >>> talkface.expression_event_kind_from_name("blink") == talkface.ExpressionEventKind.blink
)doc");

    py::class_<ExpressionEvent>(m, "ExpressionEvent", R"doc(
One blink, eyebrow raise or head movement over [start_s, end_s], seconds from the start of the audio.
amount: blink, how far the lids close (0..1); brows, the raise at its peak (0..1); tilt (gamma), turn
(beta), nod (alpha, > 0 down): the angle reached, degrees, within +-15. Blink and brows come back to
neutral by end_s; head movements stay at the angle until the next event of their kind.

Example:
    >>> talkface.ExpressionEvent(talkface.ExpressionEventKind.nod, 1.0, 1.4, 5.0)
    >>> talkface.ExpressionEvent("blink", 2.0, 2.2, 1.0)
)doc")
        .def(py::init([](ExpressionEventKind kind, double start_s, double end_s, double amount) {
                 return ExpressionEvent{kind, start_s, end_s, amount};
             }),
             py::arg("kind"), py::arg("start_s"), py::arg("end_s"), py::arg("amount"), R"doc(
Args:
    kind (ExpressionEventKind | str): blink, brows, tilt, turn or nod.
    start_s, end_s (float): seconds.
    amount (float): 0..1 for blink and brows; degrees for tilt, turn and nod.

Raises:
    talkface.InvalidArgument: kind is a name that is not one of the five.

Example:
    >>> talkface.ExpressionEvent(talkface.ExpressionEventKind.turn, 3.0, 3.5, -6.0)
    >>> talkface.ExpressionEvent("brows", 0.5, 1.2, 0.8)
)doc")
        .def(py::init([](std::string_view kind, double start_s, double end_s, double amount) {
                 return ExpressionEvent{expression_event_kind_from_name(kind), start_s, end_s, amount};
             }),
             py::arg("kind"), py::arg("start_s"), py::arg("end_s"), py::arg("amount"))
        .def_readwrite("kind", &ExpressionEvent::kind, "ExpressionEventKind")
        .def_readwrite("start_s", &ExpressionEvent::start_s, "seconds")
        .def_readwrite("end_s", &ExpressionEvent::end_s, "seconds")
        .def_readwrite("amount", &ExpressionEvent::amount, "0..1 (blink, brows) or degrees (tilt, turn, nod)")
        .def("__eq__", [](const ExpressionEvent& a, const ExpressionEvent& b) { return a == b; })
        .def("__repr__", [](const ExpressionEvent& e) {
            return py::str("talkface.ExpressionEvent({!r}, {!r}, {!r}, {!r})")
                .format(expression_event_kind_name(e.kind), e.start_s, e.end_s, e.amount);
        });

    py::enum_<UserEventMode>(m, "UserEventMode", R"doc(
How a caller's events combine with the simulated ones: add (simulated events overlapping a caller's
event of their kind are dropped) or replace (every simulated event of a kind the caller gives is
dropped).

Example:
    >>> simulator.set_user_events(events, talkface.UserEventMode.replace)
    >>> talkface.UserEventMode.add
)doc")
        .value("add", UserEventMode::add)
        .value("replace", UserEventMode::replace);

    m.def("validate_expression_events", &validate_expression_events, py::arg("events"), R"doc(
Checks a caller's events (any order).

Raises:
    talkface.InvalidArgument: naming the event (index, kind, times): a time not finite or negative,
        an end before its start, an amount out of range, or two events of one kind overlapping.

Example:
    >>> talkface.validate_expression_events([talkface.ExpressionEvent("nod", 1.0, 1.4, 5.0)])
    >>> talkface.validate_expression_events([])
)doc");
    m.def("timeline_end_s", &timeline_end_s, py::arg("timeline"), R"doc(
The end of a timeline, seconds: its duration_s, or the end of its last syllable or sentence if later.

Example:
    >>> talkface.timeline_end_s(timeline)
    >>> talkface.timeline_end_s(talkface.Timeline(duration_s=3.0))
)doc");

    py::class_<ExpressionStyle> style_class(m, "ExpressionStyle", R"doc(
The distributions of the simulation and which kinds of event are simulated at all (thesis chapter 4).
Every field is a property: numbers (seconds), blink_interval_shape (an int, 1..16), ranges as
(min, max) tuples, flags is_<kind>_simulated. Setting a property checks the value at once. The JSON
form (docs/style-format.md) is read by from_json() and load(), written by to_json().

Example:
    >>> style = talkface.ExpressionStyle.announcer()
    >>> style.blink_interval_scale_s = 3.0; style.is_nod_simulated = False
)doc");
    style_class
        .def(py::init([](std::string_view base) { return ExpressionStyle::from_name(base); }),
             py::arg("base") = "normal", R"doc(
A copy of a named style, to change.

Args:
    base (str): "normal" (the thesis's numbers for a normal pace) or "announcer" (TV news announcers).

Raises:
    talkface.InvalidArgument: an unknown name (the message lists the valid ones).

Example:
    >>> talkface.ExpressionStyle()
    >>> talkface.ExpressionStyle("announcer")
)doc")
        .def_static("normal", &ExpressionStyle::normal, R"doc(
The thesis's numbers for speech at a normal pace (the default).

Example:
    >>> talkface.ExpressionStyle.normal().blink_interval_scale_s
    1.48
)doc")
        .def_static("announcer", &ExpressionStyle::announcer, R"doc(
The unadjusted numbers measured on TV news announcers: faster head movements.

Example:
    >>> talkface.ExpressionStyle.announcer().tilt_duration_s
    (0.2, 0.5)
)doc")
        .def_static("from_name", &ExpressionStyle::from_name, py::arg("name"), R"doc(
"normal" or "announcer".

Raises:
    talkface.InvalidArgument: an unknown name (the message lists the valid ones).

Example:
    >>> talkface.ExpressionStyle.from_name("announcer").name
    'announcer'
)doc")
        .def_static("from_json", &ExpressionStyle::from_json, py::arg("text"), py::arg("source") = "<string>",
                    R"doc(
Reads a style from its JSON (docs/style-format.md): keys are field names, all optional, starting from
"normal" or from a "base" key's style; "name" sets the label ("custom" otherwise).

Args:
    text (str): the JSON.
    source (str): what messages call the text.

Raises:
    talkface.ParseError: source:line:column and the key: not JSON, an unknown key (the valid ones are
        listed), a wrong type, a value out of range.

Example:
    >>> talkface.ExpressionStyle.from_json('{"base": "announcer", "is_blink_simulated": false}')
    >>> talkface.ExpressionStyle.from_json(style.to_json()) == style
)doc")
        .def_static("load", &ExpressionStyle::load, py::arg("path"), R"doc(
from_json() of a file.

Raises:
    talkface.FileError (an OSError): the file cannot be read.
    talkface.ParseError: as from_json(), naming the file.

Example:
    >>> style = talkface.ExpressionStyle.load("calm.json")
    >>> talkface.ExpressionSimulator(timeline, 7, style)
)doc")
        .def("to_json", &ExpressionStyle::to_json, R"doc(
The style as JSON that from_json() reads back: every field, one per line; the same style always gives
the same text.

Example:
    >>> pathlib.Path("calm.json").write_text(style.to_json())
    >>> talkface.ExpressionStyle.from_json(style.to_json()) == style
)doc")
        .def("validate", &ExpressionStyle::validate, R"doc(
Checks every field; each property already checks its value as it is set.

Raises:
    talkface.InvalidArgument: naming the first field out of range and what it expected.

Example:
    >>> talkface.ExpressionStyle.announcer().validate()
)doc")
        .def("is_simulated", &ExpressionStyle::is_simulated, py::arg("kind"), R"doc(
Whether events of a kind are simulated (its is_<kind>_simulated field).

Example:
    >>> talkface.ExpressionStyle().is_simulated(talkface.ExpressionEventKind.nod)
    True
)doc")
        .def("set_simulated", &ExpressionStyle::set_simulated, py::arg("kind"), py::arg("is_simulated"),
             R"doc(
Switches the simulation of a kind on or off. A kind switched off gets no simulated events; the other
kinds' events stay the same for the same seed.

Example:
    >>> style.set_simulated(talkface.ExpressionEventKind.blink, False)
    >>> talkface.ExpressionSimulator(timeline, 7, style)
)doc")
        .def_readwrite("name", &ExpressionStyle::name, "a label; \"custom\" for caller-built styles")
        .def(py::self == py::self)
        .def(py::self != py::self)
        .def("__repr__", [](const ExpressionStyle& style) {
            return py::str("<talkface.ExpressionStyle {!r}>").format(style.name);
        });
    const char* const seconds = "seconds";
    const char* const range = "(min, max) of a uniform variable, seconds";
    const char* const kind_flag = "whether this kind of event is simulated";
    def_field(style_class, "blink_interval_shape", &ExpressionStyle::blink_interval_shape,
              "the Gamma distribution's integer shape of the time between blinks, 1..16");
    def_field(style_class, "blink_interval_scale_s", &ExpressionStyle::blink_interval_scale_s,
              "the Gamma distribution's scale of the time between blinks, seconds");
    def_range_field(style_class, "blink_duration_s", &ExpressionStyle::blink_duration_s, range);
    def_range_field(style_class, "brows_interval_s", &ExpressionStyle::brows_interval_s, range);
    def_range_field(style_class, "brows_duration_s", &ExpressionStyle::brows_duration_s, range);
    def_range_field(style_class, "brows_amount", &ExpressionStyle::brows_amount,
                    "(min, max) of the raise at its peak, 0..1 of EyebrowH");
    def_range_field(style_class, "tilt_interval_s", &ExpressionStyle::tilt_interval_s, range);
    def_range_field(style_class, "tilt_duration_s", &ExpressionStyle::tilt_duration_s, range);
    def_range_field(style_class, "tilt_angle_deg", &ExpressionStyle::tilt_angle_deg,
                    "(min, max) of |gamma| reached, degrees (random sign)");
    def_range_field(style_class, "turn_interval_s", &ExpressionStyle::turn_interval_s, range);
    def_range_field(style_class, "turn_duration_s", &ExpressionStyle::turn_duration_s, range);
    def_range_field(style_class, "turn_angle_deg", &ExpressionStyle::turn_angle_deg,
                    "(min, max) of |beta| reached, degrees (random sign)");
    def_range_field(style_class, "nod_lead_s", &ExpressionStyle::nod_lead_s, range);
    def_range_field(style_class, "nod_down_s", &ExpressionStyle::nod_down_s, range);
    def_range_field(style_class, "nod_up_s", &ExpressionStyle::nod_up_s, range);
    def_range_field(style_class, "nod_angle_deg", &ExpressionStyle::nod_angle_deg,
                    "(min, max) of alpha at the bottom of a nod, degrees");
    def_field(style_class, "nod_min_pause_s", &ExpressionStyle::nod_min_pause_s, seconds);
    def_field(style_class, "is_blink_simulated", &ExpressionStyle::is_blink_simulated, kind_flag);
    def_field(style_class, "is_brows_simulated", &ExpressionStyle::is_brows_simulated, kind_flag);
    def_field(style_class, "is_tilt_simulated", &ExpressionStyle::is_tilt_simulated, kind_flag);
    def_field(style_class, "is_turn_simulated", &ExpressionStyle::is_turn_simulated, kind_flag);
    def_field(style_class, "is_nod_simulated", &ExpressionStyle::is_nod_simulated, kind_flag);

    py::class_<ExpressionSimulator>(m, "ExpressionSimulator", R"doc(
Simulates blinks, eyebrow raises, head tilts, turns and nods over a timeline from a seed (thesis
chapter 4): the same seed gives the same events on every platform. Evaluate it at any time with
pose_at() and expression_at(). set_user_events() must not run while another thread uses the same
simulator (animate() included).

Example:
    >>> simulator = talkface.ExpressionSimulator(timeline, seed=42)
    >>> [(talkface.expression_event_kind_name(e.kind), e.start_s) for e in simulator.events()]
)doc")
        .def(py::init([](const Timeline& timeline, std::uint64_t seed, const ExpressionStyle& style) {
                 // Copies: another Python thread may change the caller's objects once the GIL is free.
                 const Timeline timeline_copy = timeline;
                 const ExpressionStyle style_copy = style;
                 py::gil_scoped_release release;
                 return ExpressionSimulator(timeline_copy, seed, style_copy);
             }),
             py::arg("timeline"), py::arg("seed") = 0, py::arg("style") = ExpressionStyle::normal(), R"doc(
Simulates the events of a timeline; releases the GIL while it works. The simulator keeps no reference
to the timeline or the style.

Args:
    timeline (Timeline): aligned sentences and syllables (pauses after sentences get nods).
    seed (int): 0 .. 2**64 - 1.
    style (str | ExpressionStyle): "normal" (the thesis's numbers for a normal pace), "announcer" (TV
        news announcers: faster head movements), or a style of your own.

Raises:
    talkface.InvalidArgument: an unknown style name (the message lists the valid ones), a style field
        out of range (named), or a syllable whose times are not finite or end before they start.

Example:
    >>> talkface.ExpressionSimulator(timeline, 7, style="announcer")
    >>> talkface.ExpressionSimulator(timeline, 7, talkface.ExpressionStyle.load("calm.json"))
)doc")
        .def(py::init([](const Timeline& timeline, std::uint64_t seed, std::string_view style) {
                 const ExpressionStyle chosen = ExpressionStyle::from_name(style);
                 const Timeline timeline_copy = timeline;
                 py::gil_scoped_release release;
                 return ExpressionSimulator(timeline_copy, seed, chosen);
             }),
             py::arg("timeline"), py::arg("seed") = 0, py::arg("style") = "normal")
        .def_property_readonly("seed", &ExpressionSimulator::seed, "the seed")
        .def_property_readonly("style", &ExpressionSimulator::style,
                               "a copy of the ExpressionStyle the events were simulated in")
        .def_property_readonly("duration_s", &ExpressionSimulator::duration_s,
                               "timeline_end_s of the timeline, seconds")
        .def("simulated_events", &ExpressionSimulator::simulated_events, R"doc(
The simulated events, by start time then kind (a new list), whatever the caller's events are.

Example:
    >>> len(simulator.simulated_events())
    >>> simulator.simulated_events()[0]
)doc")
        .def("events", &ExpressionSimulator::events, R"doc(
The events in effect: the simulated ones combined with the caller's, by start time then kind (a new
list).

Example:
    >>> simulator.set_user_events([talkface.ExpressionEvent("nod", 1.0, 1.4, 5.0)])
    >>> [e for e in simulator.events() if e.kind == talkface.ExpressionEventKind.nod]
)doc")
        .def("set_user_events", &ExpressionSimulator::set_user_events, py::arg("events"),
             py::arg("mode") = UserEventMode::add, R"doc(
Sets the caller's events (replacing any set before) and combines them with the simulated ones as
mode says. An empty list restores the simulated events.

Args:
    events (list[ExpressionEvent]): any order; events of one kind must not overlap.
    mode (UserEventMode): add or replace.

Raises:
    talkface.InvalidArgument: naming the event (index, kind, times) that is wrong; nothing changes.

Example:
    >>> simulator.set_user_events([talkface.ExpressionEvent("blink", 0.5, 0.7, 1.0)])
    >>> simulator.set_user_events(events, talkface.UserEventMode.replace)
)doc")
        .def("pose_at", &ExpressionSimulator::pose_at, py::arg("time_s"), R"doc(
The head pose at a time, seconds (a Pose in degrees; 0 before the first event).

Example:
    >>> simulator.pose_at(2.5).alpha_deg
    >>> talkface.FaceState(pose=simulator.pose_at(2.5))
)doc")
        .def("expression_at", &ExpressionSimulator::expression_at, py::arg("time_s"), R"doc(
Blinks (both eyes) and eyebrow raise at a time, seconds (an Expression; smile stays 0).

Example:
    >>> simulator.expression_at(2.5).blink_left
    >>> simulator.expression_at(0.0) == talkface.Expression()
)doc");
}

}  // namespace talkface::python
