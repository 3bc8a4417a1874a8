#!/usr/bin/python3
"""Generates src/text/data/readings.cpp: every Han character's Mandarin readings, most frequent
first, in numbered pinyin, plus the set of legal toneless syllables, from Unihan.

Source: /usr/share/unicode/Unihan_Readings.txt.bz2 (Debian package unicode-data; the Unicode
License for data files, see docs/data-licences.md). Run from anywhere: /usr/bin/python3 tools/make_readings.py

Reading order per character: kHanyuPinlu by its corpus frequency (the only field with counts),
then kMandarin (first value: zh-Hans; second: zh-Hant), then the dictionaries kTGHZ2013,
kXHC1983, kHanyuPinyin in the order they list readings. The first reading is what a character
gets when no phrase covers it.
"""

import bz2
import collections
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pinyin_rules  # noqa: E402
import embed_text  # noqa: E402

UNIHAN = "/usr/share/unicode/Unihan_Readings.txt.bz2"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(ROOT, "src", "text", "data", "readings.cpp")

# Fields from modern dictionaries and corpora: a character with more than one toneless reading
# here is polyphonic for make_phrases.py. kHanyuPinyin (a historical dictionary) lists many
# archaic readings, so it only breaks ties and fills characters nothing else covers.
MODERN_FIELDS = ("kHanyuPinlu", "kMandarin", "kTGHZ2013", "kXHC1983")
ALL_FIELDS = MODERN_FIELDS + ("kHanyuPinyin",)


def _field_readings(field, value):
    """Marked readings of one Unihan field, in the field's order."""
    if field == "kHanyuPinlu":
        pairs = re.findall(r"([^\s(]+)\((\d+)\)", value)
        pairs.sort(key=lambda pair: -int(pair[1]))  # stable: ties keep Unihan's order
        return [reading for reading, _ in pairs]
    if field == "kMandarin":
        return value.split()
    readings = []
    for entry in value.split():
        readings.extend(entry.split(":", 1)[1].split(","))
    return readings


def load_unihan():
    """{character: {field: [numbered readings]}} for every character with a Mandarin reading."""
    table = collections.defaultdict(dict)
    with bz2.open(UNIHAN, "rt", encoding="utf-8") as lines:
        for line in lines:
            if line.startswith("#") or not line.strip():
                continue
            code, field, value = line.rstrip("\n").split("\t")
            if field not in ALL_FIELDS:
                continue
            character = chr(int(code[2:], 16))
            numbered = []
            for marked in _field_readings(field, value):
                reading = pinyin_rules.to_numbered(marked)
                # "ê" (欸, 誒) is dropped: those characters also read ei / ai, and numbered pinyin
                # has no agreed ASCII spelling for it.
                # kHanyuPinlu counts the erhua suffix 儿/兒 as "r"; spoken alone it is "er".
                if reading == "r5":
                    reading = "er5"
                if reading is not None and reading not in numbered:
                    numbered.append(reading)
            if numbered:
                table[character][field] = numbered
    return table


def ordered_readings(fields):
    readings = []
    for field in ALL_FIELDS:
        for reading in fields.get(field, []):
            if reading not in readings:
                readings.append(reading)
    return readings


def modern_toneless(fields):
    """The distinct toneless readings modern sources give; all sources if none does."""
    names = [field for field in MODERN_FIELDS if field in fields] or ["kHanyuPinyin"]
    toneless = []
    for field in names:
        for reading in fields[field]:
            if reading[:-1] not in toneless:
                toneless.append(reading[:-1])
    return toneless


def main():
    table = load_unihan()
    syllables = set()
    lines = []
    for character in sorted(table):
        readings = ordered_readings(table[character])
        syllables.update(reading[:-1] for reading in readings)
        lines.append(f"{character}\t{' '.join(readings)}")
    illegal = sorted(s for s in syllables if not pinyin_rules.is_legal_toneless(s))
    if illegal:
        sys.exit(f"make_readings: Unihan readings outside the syllable grammar: {illegal}")
    # The toneless syllables every reading uses, checked against the grammar above: the run-time
    # check of reading fixes and pinyin input.
    syllable_lines = sorted(syllables)
    embed_text.write_cpp(
        OUTPUT, "tools/make_readings.py",
        ["Modified data derived from Unihan_Readings.txt (Debian unicode-data 15.0),",
         "Copyright (c) 1991-2022 Unicode, Inc., under the Unicode License: readings converted",
         "to numbered pinyin and reordered by frequency; other Unihan fields left out."],
        {"readings_text": lines, "syllables_text": syllable_lines})
    print(f"make_readings: {len(lines)} characters, {len(syllable_lines)} toneless syllables "
          f"-> {os.path.relpath(OUTPUT, ROOT)}")


if __name__ == "__main__":
    main()
