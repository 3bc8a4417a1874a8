"""animate() and Animation in Python: frames, key frames, the JSON and TSV exports."""
import json

import numpy
import pytest

import talkface


def spoken_timeline():
    """媽媽好，你好。: ma1 ma1 hao3 (pause) ni3 hao3 from 0.5 s, 3 s of audio."""
    timeline = talkface.read_transcript("媽媽好，你好。")
    starts = [0.5, 0.75, 1.0, 1.75, 2.0]
    syllables = timeline.syllables
    for syllable, start_s in zip(syllables, starts):
        syllable.start_s, syllable.end_s = start_s, start_s + 0.25
    timeline.syllables = syllables
    sentences = timeline.sentences
    sentences[0].start_s, sentences[0].end_s = 0.5, 2.25
    timeline.sentences = sentences
    timeline.duration_s = 3.0
    return timeline


def test_frames_cover_the_duration_and_the_mouth_opens_and_closes(face):
    timeline = spoken_timeline()
    animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 11),
                                 talkface.LipSyncOptions(fps=30.0))
    assert animation.fps == 30.0
    assert animation.duration_s == 3.0
    assert len(animation) == len(animation.frames) == 91
    openings = numpy.array([frame.mouth.down[1] - frame.mouth.up[1] for frame in animation.frames])
    neutral = talkface.neutral_mouth_controls(face)
    numpy.testing.assert_allclose(openings[0], neutral.down[1] - neutral.up[1], atol=1e-9)
    assert openings.max() > openings[0] + 1.0
    assert openings[15] == pytest.approx(openings[0], abs=1e-9)  # 0.5 s: the m of ma1 closes the lips
    projected = talkface.project_face(face, animation.frames[20])
    assert projected.image_xy.shape == (89, 2)


def test_key_frames_follow_the_syllables(face):
    timeline = spoken_timeline()
    animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 11))
    keys = animation.mouth_key_frames
    assert keys[0] == talkface.MouthKeyFrame(0.0, talkface.MouthShape.m, None)
    syllable_keys = [k for k in keys if k.syllable == 0]
    assert [talkface.mouth_shape_name(k.shape) for k in syllable_keys] == ["m", "a"]
    assert keys == talkface.mouth_key_frames(timeline)
    assert all(a.time_s < b.time_s for a, b in zip(keys, keys[1:]))


def test_json_and_tsv_exports_have_the_contract_shape(face):
    timeline = spoken_timeline()
    simulator = talkface.ExpressionSimulator(timeline, 11)
    simulator.set_user_events([talkface.ExpressionEvent("nod", 1.0, 1.4, 5.0)])
    animation = talkface.animate(face, timeline, simulator)
    document = json.loads(animation.key_frames_json())
    assert list(document) == ["fps", "duration", "mouth", "events"]
    assert document["fps"] == animation.fps and document["duration"] == round(animation.duration_s, 3)
    assert document["mouth"][0] == {"time": 0, "shape": "m", "syllable": None}
    assert all(list(item) == ["time", "shape", "syllable"] for item in document["mouth"])
    assert {"kind": "nod", "start": 1.0, "end": 1.4, "amount": 5.0} in document["events"]
    assert all(list(item) == ["kind", "start", "end", "amount"] for item in document["events"])
    lines = animation.key_frames_tsv().splitlines()
    assert len(lines) == len(document["mouth"])
    assert lines[0] == "0\tm"
    assert animation.key_frames_json() == talkface.key_frames_json(animation.mouth_key_frames, animation.events,
                                                                   animation.fps, animation.duration_s)
    with pytest.raises(talkface.InvalidArgument, match="fps"):
        talkface.key_frames_json([], [], 0.0, 1.0)


def test_animation_is_deterministic_for_a_seed(face):
    timeline = spoken_timeline()
    first = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3))
    second = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 3))
    assert first.key_frames_json() == second.key_frames_json()
    assert [f.pose for f in first.frames] == [f.pose for f in second.frames]


def test_bad_pinyin_and_bad_options_are_named(face):
    timeline = talkface.Timeline([talkface.Sentence("x", 0.0, 1.0)],
                                 [talkface.Syllable("x", "xx1", 0, 0.2, 0.5)], duration_s=1.0)
    simulator = talkface.ExpressionSimulator(timeline, 1)
    with pytest.raises(talkface.InvalidArgument, match="xx1"):
        talkface.animate(face, timeline, simulator)
    with pytest.raises(talkface.InvalidArgument, match="fps"):
        talkface.animate(face, spoken_timeline(), simulator, talkface.LipSyncOptions(fps=0.0))
