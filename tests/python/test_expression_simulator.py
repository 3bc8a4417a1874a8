"""ExpressionSimulator in Python: seeded events, styles, the caller's events (add / replace), errors
naming the event, and simulation on several threads."""
import threading

import pytest

import talkface


def long_timeline(seconds=60.0):
    """One 3-syllable sentence every 2 s, as an aligner would give."""
    sentences, syllables = [], []
    start_s = 0.4
    while start_s + 1.0 < seconds:
        index = len(sentences)
        sentences.append(talkface.Sentence("媽媽好。", start_s, start_s + 0.9))
        for k, pinyin in enumerate(["ma1", "ma1", "hao3"]):
            syllables.append(talkface.Syllable("媽", pinyin, index, start_s + 0.3 * k, start_s + 0.3 * (k + 1)))
        start_s += 2.0
    return talkface.Timeline(sentences, syllables, [], seconds)


def test_same_seed_gives_the_same_events_and_another_seed_others():
    timeline = long_timeline()
    first = talkface.ExpressionSimulator(timeline, 42).events()
    assert first == talkface.ExpressionSimulator(timeline, seed=42).events()
    assert first != talkface.ExpressionSimulator(timeline, 43).events()
    kinds = {event.kind for event in first}
    assert kinds == set(talkface.ExpressionEventKind.__members__.values())
    assert all(a.start_s <= b.start_s for a, b in zip(first, first[1:]))


def test_styles_are_named_and_an_unknown_one_is_refused():
    timeline = long_timeline()
    announcer = talkface.ExpressionSimulator(timeline, 1, style="announcer")
    assert announcer.style == talkface.ExpressionStyle.announcer()
    assert announcer.style.name == "announcer"
    assert announcer.seed == 1
    assert announcer.duration_s == 60.0
    with pytest.raises(talkface.InvalidArgument, match="announcer"):
        talkface.ExpressionSimulator(timeline, 1, style="shouty")


def test_replace_keeps_only_the_callers_events_of_that_kind():
    simulator = talkface.ExpressionSimulator(long_timeline(), 5)
    nod = talkface.ExpressionEvent(talkface.ExpressionEventKind.nod, 10.0, 10.4, 6.0)
    simulator.set_user_events([nod], talkface.UserEventMode.replace)
    nods = [e for e in simulator.events() if e.kind == talkface.ExpressionEventKind.nod]
    assert nods == [nod]
    assert simulator.pose_at(10.4).alpha_deg == pytest.approx(6.0)
    blinks = [e for e in simulator.simulated_events() if e.kind == talkface.ExpressionEventKind.blink]
    assert blinks == [e for e in simulator.events() if e.kind == talkface.ExpressionEventKind.blink]


def test_add_drops_only_the_overlapping_simulated_events():
    simulator = talkface.ExpressionSimulator(long_timeline(), 5)
    simulated = [e for e in simulator.events() if e.kind == talkface.ExpressionEventKind.blink]
    blink = talkface.ExpressionEvent("blink", 30.0, 30.3, 1.0)
    simulator.set_user_events([blink])
    blinks = [e for e in simulator.events() if e.kind == talkface.ExpressionEventKind.blink]
    assert blink in blinks
    kept = [e for e in simulated if e.end_s <= 30.0 or e.start_s >= 30.3]
    assert sorted(kept + [blink], key=lambda e: e.start_s) == blinks
    assert simulator.expression_at(30.09).blink_left == pytest.approx(1.0)
    simulator.set_user_events([])
    assert simulator.events() == simulator.simulated_events()


def test_a_bad_event_is_refused_by_index_and_nothing_changes():
    simulator = talkface.ExpressionSimulator(long_timeline(), 5)
    before = simulator.events()
    events = [talkface.ExpressionEvent("blink", 1.0, 1.2, 1.0), talkface.ExpressionEvent("turn", 2.0, 2.5, 40.0)]
    with pytest.raises(talkface.InvalidArgument, match=r"event 1 \(turn, 2"):
        simulator.set_user_events(events)
    assert simulator.events() == before
    with pytest.raises(talkface.InvalidArgument, match="wink"):
        talkface.ExpressionEvent("wink", 0.0, 0.1, 1.0)
    with pytest.raises(talkface.InvalidArgument, match="overlaps"):
        talkface.validate_expression_events(
            [talkface.ExpressionEvent("nod", 1.0, 2.0, 3.0), talkface.ExpressionEvent("nod", 1.5, 2.5, 3.0)])


def test_simulations_on_two_threads_match_one_thread():
    timeline = long_timeline(600.0)
    expected = talkface.ExpressionSimulator(timeline, 9).events()
    results = [None, None]

    def simulate(slot):
        results[slot] = talkface.ExpressionSimulator(timeline, 9).events()

    threads = [threading.Thread(target=simulate, args=(slot,)) for slot in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert results == [expected, expected]
