"""Timelines as the `align` JSON document of SPEC "Contracts", read and written with the json module.

The library reads no JSON (it has no JSON dependency), so the document is read here in Python and by
the talkface command in C++; both accept the same document and name what is wrong the same way::

    {"sentences": [{"text": "你好。", "start": 0.5, "end": 1.1}],
     "syllables": [{"text": "你", "pinyin": "ni3", "start": 0.5, "end": 0.8, "sentence": 0}, ...]}

Besides the contract's keys a sentence after the first may carry "paragraph" (true when it begins
one; the first always does), a syllable may carry "final_start" (seconds or null), "confidence"
(0..1) and "pause_after" (true/false), and the document "duration" (seconds) and "warnings" (a list
of strings); missing times are 0, as in the output of `talkface syllables --json`.
"""

import json
import math

from ._talkface import ParseError, Sentence, Syllable, Timeline


def _parse_error(source_name, item, problem, line=0, column=0):
    where = f"{source_name}:{line}:{column}" if line else source_name
    error = ParseError(f"{where}: {item}: {problem}" if item else f"{where}: {problem}")
    error.path = source_name
    error.line = line
    error.column = column
    error.item = item
    return error


def _found(value):
    return json.dumps(value, ensure_ascii=False)[:40]


class _Reader:
    def __init__(self, source_name):
        self.source_name = source_name

    def fail(self, item, problem):
        return _parse_error(self.source_name, item, problem)

    def object(self, value, item):
        if not isinstance(value, dict):
            raise self.fail(item, f"expected an object, found {_found(value)}")
        return value

    def list(self, value, item):
        if not isinstance(value, list):
            raise self.fail(item, f"expected a list, found {_found(value)}")
        return value

    def text(self, owner, key, item):
        if key not in owner:
            raise self.fail(item, f'"{key}" is missing')
        if not isinstance(owner[key], str):
            raise self.fail(f"{item}.{key}", f"expected a string, found {_found(owner[key])}")
        return owner[key]

    def number(self, owner, key, item, default):
        if key not in owner:
            return default
        value = owner[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise self.fail(f"{item}.{key}", f"expected a number of seconds, found {_found(value)}")
        return float(value)


def timeline_from_json(text, source_name="<timeline>"):
    """Reads a timeline from the `align` JSON document (see the module's docstring).

    Args:
        text (str | bytes): the document.
        source_name (str): names the document in messages (a path, say).

    Raises:
        talkface.ParseError: the text is not JSON (source:line:column) or an item is missing or of
            the wrong type (named, e.g. 'syllables[3].start'); .item holds the item.

    Example:
        >>> timeline = talkface.timeline_from_json(open("aligned.json").read(), "aligned.json")
        >>> animation = talkface.animate(face, timeline, talkface.ExpressionSimulator(timeline, 7))
    """
    try:
        document = json.loads(text)
    except json.JSONDecodeError as error:
        raise _parse_error(source_name, "", error.msg, error.lineno, error.colno) from None
    reader = _Reader(source_name)
    reader.object(document, "document")
    for key in ("sentences", "syllables"):
        if key not in document:
            raise reader.fail("document", f'"{key}" is missing')
    sentences = []
    for index, entry in enumerate(reader.list(document["sentences"], "sentences")):
        item = f"sentences[{index}]"
        reader.object(entry, item)
        paragraph = entry.get("paragraph", index == 0)
        if not isinstance(paragraph, bool):
            raise reader.fail(f"{item}.paragraph", f"expected true or false, found {_found(paragraph)}")
        sentences.append(Sentence(reader.text(entry, "text", item), reader.number(entry, "start", item, 0.0),
                                  reader.number(entry, "end", item, 0.0), paragraph))
    syllables = []
    for index, entry in enumerate(reader.list(document["syllables"], "syllables")):
        item = f"syllables[{index}]"
        reader.object(entry, item)
        sentence = entry.get("sentence")
        if isinstance(sentence, bool) or not isinstance(sentence, int) or not 0 <= sentence < len(sentences):
            raise reader.fail(f"{item}.sentence",
                              f"expected a sentence index 0..{len(sentences) - 1}, found {_found(sentence)}")
        confidence = reader.number(entry, "confidence", item, 1.0)
        if not 0.0 <= confidence <= 1.0:
            raise reader.fail(f"{item}.confidence", f"expected 0..1, found {_found(entry['confidence'])}")
        final_start = None if entry.get("final_start") is None else reader.number(entry, "final_start", item, None)
        pause_after = entry.get("pause_after", False)
        if not isinstance(pause_after, bool):
            raise reader.fail(f"{item}.pause_after", f"expected true or false, found {_found(pause_after)}")
        syllables.append(Syllable(reader.text(entry, "text", item), reader.text(entry, "pinyin", item), sentence,
                                  reader.number(entry, "start", item, 0.0), reader.number(entry, "end", item, 0.0),
                                  final_start, confidence, pause_after))
    warnings = reader.list(document.get("warnings", []), "warnings")
    for index, warning in enumerate(warnings):
        if not isinstance(warning, str):
            raise reader.fail(f"warnings[{index}]", f"expected a string, found {_found(warning)}")
    return Timeline(sentences, syllables, warnings, reader.number(document, "duration", "document", 0.0))


def timeline_to_json(timeline):
    """The timeline as the `align` JSON document, one item per line, characters as UTF-8;
    timeline_from_json() reads it back equal.

    Example:
        >>> text = talkface.timeline_to_json(timeline)
        >>> talkface.timeline_from_json(text).syllables == timeline.syllables
        True
    """
    def dump(value):
        return json.dumps(value, ensure_ascii=False, separators=(",", ":"))

    # The first sentence always begins a paragraph: only the others say so.
    sentences = [dump({"text": s.text, "start": s.start_s, "end": s.end_s,
                       **({"paragraph": True} if s.starts_paragraph and k > 0 else {})})
                 for k, s in enumerate(timeline.sentences)]
    syllables = []
    for s in timeline.syllables:
        entry = {"text": s.text, "pinyin": s.pinyin, "start": s.start_s, "end": s.end_s, "sentence": s.sentence}
        if s.final_start_s is not None:
            entry["final_start"] = s.final_start_s
        entry["confidence"] = s.confidence
        entry["pause_after"] = s.pause_after
        syllables.append(dump(entry))

    def block(items):
        return "[\n" + ",\n".join(items) + "\n]" if items else "[]"

    return (f'{{"sentences":{block(sentences)},\n"syllables":{block(syllables)},\n'
            f'"duration":{dump(timeline.duration_s)},\n"warnings":{block([dump(w) for w in timeline.warnings])}}}\n')
