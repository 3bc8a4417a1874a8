#!/usr/bin/env python3
"""Lenient alignment (issue #13): prints, per set, how many texts a word off --lenient finds and
where, beside how many right texts it marks.

Each sentence of corpus/sentences.txt is spoken by espeak-ng (cmn-latn-pinyin, make_corpus --clip,
so every syllable's start is known) and aligned with --lenient three ways: with its own text (a
mark there is a false one), with a two-character word of its middle left out of the text (the
speech has a word the transcript lacks), and with that word replaced by another (a changed word).
Found: a mismatch that overlaps the word's true span; its start and end errors are printed, and
the worst start error of the syllables outside the word.

With --human MAKE_HUMAN_CORPUS, each sentence is also said by a person (make_human_corpus --clip:
gcin-voice's speaker 3, one recording a syllable, joined as running speech, every start known) and
measured the same way, in rows of its own.

usage: PYTHONPATH=build/python bench/lenient_bench.py build/bin/make_corpus OUT_DIR
           [--human build/bin/make_human_corpus]
(needs espeak-ng and sox: cmake/install-deps.sh bench; --human needs gcin-voice)
"""
import json
import os
import re
import statistics
import subprocess
import sys

import talkface

HERE = os.path.dirname(os.path.abspath(__file__))
# Words put in place of the one the speech says: two syllables whose sounds differ from most.
SUBSTITUTES = ["电脑", "火车", "足球", "沙发"]


def sentences():
    with open(os.path.join(HERE, "corpus", "sentences.txt"), encoding="utf-8") as corpus:
        for line in corpus:
            if line.startswith("#") or "\t" not in line:
                continue
            set_name, text = line.rstrip("\n").split("\t")
            yield set_name, re.sub(r"\{[^}]*\}", "", text)


def is_han(c):
    return "\u4e00" <= c <= "\u9fff"


def middle_word(text):
    """Index in `text` and syllable index of two Han characters near the middle."""
    han = [i for i, c in enumerate(text) if is_han(c)]
    for k in sorted(range(len(han) - 1), key=lambda k: abs(k - len(han) // 2)):
        if han[k + 1] == han[k] + 1 and 1 <= k < len(han) - 3:
            return han[k], k
    return None


def aligned(audio, text):
    options = talkface.AlignOptions(lenient=True)
    return talkface.SpeechAligner(options).align_file(audio, talkface.read_transcript(text))


def main():
    make_corpus, out_dir = sys.argv[1], sys.argv[2]
    voices = [("espeak-ng", [make_corpus, "--clip"], ["--rate-wpm", "190", "--pitch", "50"])]
    if "--human" in sys.argv:
        voices.append(("person", [sys.argv[sys.argv.index("--human") + 1], "--clip"], []))
    os.makedirs(out_dir, exist_ok=True)
    rows = {}
    for n, (set_name, text) in enumerate(sentences()):
        found = middle_word(text)
        if found is None:
            continue
        for voice, command, options in voices:
            stem = os.path.join(out_dir, f"{voice}-s{n}")
            subprocess.run(command + [stem] + options + [text], check=True, stdout=subprocess.DEVNULL)
            measure(rows.setdefault((set_name, voice), {"right": 0, "marked": 0, "lacks": [], "changed": []}),
                    stem, text, found, n)
    print("| set | voice | right texts marked | kind | found | other marks | start error (median) | "
          "end error (median) | other syllables within 50 ms |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (set_name, voice), row in sorted(rows.items(), key=lambda item: (item[0][0] != "tuning", item[0][1])):
        for kind in ("lacks", "changed"):
            cases = row[kind]
            hit = [c for c in cases if c[0]]
            median = lambda values: f"{1000 * statistics.median(values):.0f} ms" if values else "-"
            print(f"| {set_name} | {voice} | {row['marked']} of {row['right']} | {kind} | {len(hit)} of {len(cases)} | "
                  f"{sum(c[1] for c in cases)} | {median([c[2] for c in hit])} | {median([c[3] for c in hit])} | "
                  f"{sum(c[4] < 0.05 for c in cases)} of {len(cases)} |")


def measure(row, stem, text, found, n):
    """Aligns the clip at `stem` with its right text and two texts a word off into `row`."""
    at, syllable = found
    audio = stem + (".flac" if os.path.exists(stem + ".flac") else ".wav")
    truth = json.load(open(stem + ".json", encoding="utf-8"))
    starts = [s["start"] for s in truth["syllables"]]
    word = (starts[syllable], starts[syllable + 2])
    row["right"] += 1
    if aligned(audio, text).mismatches:
        row["marked"] += 1
    for kind, wrong in (("lacks", text[:at] + text[at + 2:]),
                        ("changed", text[:at] + SUBSTITUTES[n % len(SUBSTITUTES)] + text[at + 2:])):
        result = aligned(audio, wrong)
        hits = [m for m in result.mismatches if m.start_s < word[1] and m.end_s > word[0]]
        if kind == "lacks":
            pairs = zip(result.syllables, starts[:syllable] + starts[syllable + 2:])
        else:
            pairs = [(s, t) for i, (s, t) in enumerate(zip(result.syllables, starts)) if not syllable <= i < syllable + 2]
        others = [abs(s.start_s - t) for s, t in pairs]
        row[kind].append((bool(hits), len(result.mismatches) - len(hits),
                          abs(hits[0].start_s - word[0]) if hits else None,
                          abs(hits[0].end_s - word[1]) if hits else None, max(others)))


if __name__ == "__main__":
    main()
