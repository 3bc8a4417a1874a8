"""ExpressionStyle in Python: every field a property (ranges as (min, max)), named styles, the style
JSON (docs/style-format.md), errors naming the field or key, kinds switched off, and the onset table
of LipSyncOptions."""
import json

import pytest

import talkface

from test_expression_simulator import long_timeline

KINDS = list(talkface.ExpressionEventKind.__members__.values())


def of_kind(events, kind):
    return [e for e in events if e.kind == kind]


def test_every_json_key_is_a_property_and_the_stub_lists_it():
    style = talkface.ExpressionStyle()
    fields = json.loads(style.to_json())
    assert len(fields) == 23  # name and the 22 fields
    assert style.blink_interval_shape == 2
    assert style.blink_interval_scale_s == 1.48
    assert style.tilt_interval_s == (0.0, 6.64)
    assert style.is_nod_simulated is True
    stub = open(talkface.__file__.replace("__init__.py", "_talkface.pyi"), encoding="utf-8").read()
    for name, value in fields.items():
        got = getattr(style, name)
        assert (list(got) if isinstance(got, tuple) else got) == value, name
        assert f"    {name}: " in stub, name
    style.validate()


def test_named_styles_and_the_constructor():
    assert talkface.ExpressionStyle() == talkface.ExpressionStyle.normal()
    assert talkface.ExpressionStyle("announcer") == talkface.ExpressionStyle.announcer()
    assert talkface.ExpressionStyle.from_name("announcer").tilt_duration_s == (0.2, 0.5)
    assert talkface.ExpressionStyle.normal() != talkface.ExpressionStyle.announcer()
    with pytest.raises(talkface.InvalidArgument, match="announcer"):
        talkface.ExpressionStyle("shouty")


def test_setting_a_property_checks_it_and_names_the_field():
    style = talkface.ExpressionStyle()
    style.turn_angle_deg = (1.0, 3.0)
    style.blink_interval_shape = 3
    style.is_blink_simulated = False
    assert (style.turn_angle_deg, style.blink_interval_shape, style.is_blink_simulated) == ((1.0, 3.0), 3, False)
    with pytest.raises(talkface.InvalidArgument, match=r"turn_angle_deg: expected a range .* got \[2, 20\]"):
        style.turn_angle_deg = (2.0, 20.0)
    with pytest.raises(ValueError, match="blink_interval_shape"):
        style.blink_interval_shape = 0
    with pytest.raises(ValueError, match="nod_down_s"):
        style.nod_down_s = (0.5, 0.2)
    assert style.turn_angle_deg == (1.0, 3.0)
    assert style.nod_down_s == (0.34, 0.94)


def test_json_round_trip_and_base():
    style = talkface.ExpressionStyle.announcer()
    style.name = "calm"
    style.blink_interval_scale_s = 2.5
    style.is_tilt_simulated = False
    text = style.to_json()
    assert talkface.ExpressionStyle.from_json(text) == style
    assert talkface.ExpressionStyle.from_json(text).to_json() == text
    based = talkface.ExpressionStyle.from_json('{"base": "announcer", "nod_angle_deg": [1, 2]}')
    assert based.name == "custom"
    assert based.nod_angle_deg == (1.0, 2.0)
    assert based.turn_duration_s == talkface.ExpressionStyle.announcer().turn_duration_s


def test_json_errors_name_the_file_line_and_key(tmp_path):
    path = tmp_path / "calm.json"
    path.write_text('{\n  "blink_interval_scale_s": 2.0,\n  "tilt_angle": [1, 2]\n}\n', encoding="utf-8")
    with pytest.raises(talkface.ParseError, match=r'calm.json:3:3: key "tilt_angle": unknown key; the keys are '
                                                  r'base, name, blink_interval_shape') as caught:
        talkface.ExpressionStyle.load(str(path))
    assert caught.value.line == 3
    with pytest.raises(talkface.ParseError, match=r'key "is_nod_simulated": expected true or false, found "no"'):
        talkface.ExpressionStyle.from_json('{"is_nod_simulated": "no"}')
    with pytest.raises(talkface.FileError, match="missing.json") as missing:
        talkface.ExpressionStyle.load(str(tmp_path / "missing.json"))
    assert isinstance(missing.value, OSError)


def test_a_custom_style_changes_the_events():
    timeline = long_timeline(3000.0)
    slow = talkface.ExpressionStyle()
    slow.blink_interval_scale_s = 4.0

    def mean_blink_interval(simulator):
        end_s, total, blinks = 0.0, 0.0, of_kind(simulator.simulated_events(), talkface.ExpressionEventKind.blink)
        for blink in blinks:
            total += blink.start_s - end_s
            end_s = blink.end_s
        return total / len(blinks)

    # Gamma(2, theta) has mean 2 theta; ~350 draws at theta = 4 keep the mean within 10%.
    assert mean_blink_interval(talkface.ExpressionSimulator(timeline, 4, slow)) == pytest.approx(8.0, rel=0.1)
    assert mean_blink_interval(talkface.ExpressionSimulator(timeline, 4)) == pytest.approx(2.96, rel=0.1)
    simulator = talkface.ExpressionSimulator(timeline, 4, slow)
    assert simulator.style == slow
    assert simulator.style.name == "normal"


def test_a_kind_switched_off_has_no_events_and_leaves_the_others_alone():
    timeline = long_timeline()
    everything = talkface.ExpressionSimulator(timeline, 12).events()
    for kind in KINDS:
        style = talkface.ExpressionStyle()
        style.set_simulated(kind, False)
        assert not style.is_simulated(kind)
        events = talkface.ExpressionSimulator(timeline, 12, style).events()
        assert of_kind(everything, kind)
        assert not of_kind(events, kind)
        assert events == [e for e in everything if e.kind != kind]
    style = talkface.ExpressionStyle.from_json('{"is_blink_simulated": false, "is_nod_simulated": false}')
    kinds = {e.kind for e in talkface.ExpressionSimulator(timeline, 12, style).events()}
    assert kinds == {talkface.ExpressionEventKind.brows, talkface.ExpressionEventKind.tilt,
                     talkface.ExpressionEventKind.turn}


def test_onset_table_is_settable_and_moves_the_key_frames():
    timeline = long_timeline(4.0)
    assert talkface.LipSyncOptions().onsets == talkface.ShapeOnsetTable()
    assert talkface.ShapeOnsetTable().three_shapes == [0.1688, 0.6025]
    late = talkface.LipSyncOptions(fps=100.0, onsets=talkface.ShapeOnsetTable(two_shapes=[0.6]))
    assert late.onsets.two_shapes == [0.6]

    def first_a(options):
        return next(k.time_s for k in talkface.mouth_key_frames(timeline, options)
                    if k.shape == talkface.MouthShape.a and k.syllable == 0)

    # ma1 at 0.4-0.7 s is m a: the a starts at 0.1905 of it by default, at 0.6 of it here.
    assert first_a(talkface.LipSyncOptions(fps=100.0)) == pytest.approx(0.46)
    assert first_a(late) == pytest.approx(0.58)
    options = talkface.LipSyncOptions()
    table = options.onsets
    table.three_shapes = [0.7, 0.2]
    options.onsets = table
    with pytest.raises(talkface.InvalidArgument, match="ShapeOnsetTable::three_shapes"):
        talkface.mouth_key_frames(timeline, options)
    with pytest.raises(TypeError):
        talkface.ShapeOnsetTable(two_shapes=[0.1, 0.2])
