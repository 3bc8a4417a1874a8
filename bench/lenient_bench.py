#!/usr/bin/env python3
"""Lenient alignment (issue #13): prints, per set, how many texts a word off --lenient finds and
where, beside how many right texts it marks.

Each sentence of corpus/sentences.txt is spoken by espeak-ng (cmn-latn-pinyin, make_corpus --clip,
so every syllable's start is known) and aligned with --lenient three ways: with its own text (a
mark there is a false one), with a two-character word of its middle left out of the text (the
speech has a word the transcript lacks), and with that word replaced by another (a changed word).
A changed word is reported whole (a mismatch names both its syllables), in part (one, or a mark
overlaps its span naming neither) or missed; a word the text lacks is found where a mark overlaps
its span. Printed beside: the first mark's start and the last one's end error, other marks, and
the share of onsets within 50 ms of the syllables no mark names; for right texts, the texts
marked and the same share with and without --lenient. Per-clip marks: OUT_DIR/lenient-details.json.

With --human MAKE_HUMAN_CORPUS, each sentence is also said by a person (make_human_corpus --clip:
gcin-voice's speaker 3, one recording a syllable, joined as running speech, every start known) and
measured the same way, in rows of its own.

With --passages DIR (a condition of make_corpus's or make_human_corpus's corpus, e.g.
/work/corpus/human/r-clean; repeatable), its read passages (right texts of several sentences) are
aligned with --lenient too: passages marked, marks, and onsets within 50 ms outside the marks.

usage: PYTHONPATH=build/python bench/lenient_bench.py build/bin/make_corpus OUT_DIR
           [--human build/bin/make_human_corpus] [--passages CORPUS/CONDITION ...]
(needs espeak-ng and sox: cmake/install-deps.sh bench; --human needs gcin-voice)
"""
import glob
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
    return aligned_transcript(audio, talkface.read_transcript(text))


def aligned_transcript(audio, transcript):
    return talkface.SpeechAligner(talkface.AlignOptions(lenient=True)).align_file(audio, transcript)


def main():
    make_corpus, out_dir = sys.argv[1], sys.argv[2]
    directories = [sys.argv[i + 1] for i, arg in enumerate(sys.argv) if arg == "--passages"]
    voices = [("espeak-ng", [make_corpus, "--clip"], ["--rate-wpm", "190", "--pitch", "50"])]
    if "--human" in sys.argv:
        voices.append(("person", [sys.argv[sys.argv.index("--human") + 1], "--clip"], []))
    os.makedirs(out_dir, exist_ok=True)
    rows = {}
    details = []
    for n, (set_name, text) in enumerate(sentences()):
        found = middle_word(text)
        if found is None:
            continue
        for voice, command, options in voices:
            stem = os.path.join(out_dir, f"{voice}-s{n}")
            if not os.path.exists(stem + ".json"):
                subprocess.run(command + [stem] + options + [text], check=True, stdout=subprocess.DEVNULL)
            row = rows.setdefault((set_name, voice), {"right": [], "lacks": [], "changed": []})
            measure(row, stem, text, found, n)
            details.append({"set": set_name, "voice": voice, "clip": stem, "right": row["right"][-1],
                            "lacks": row["lacks"][-1], "changed": row["changed"][-1]})
    with open(os.path.join(out_dir, "lenient-details.json"), "w", encoding="utf-8") as out:
        json.dump(details, out, ensure_ascii=False, indent=1)
    ordered = sorted(rows.items(), key=lambda item: (item[0][0] != "tuning", item[0][1]))
    median = lambda values: f"{1000 * statistics.median(values):.0f} ms" if values else "-"
    share = lambda values: f"{100 * sum(v < 0.05 for v in values) / len(values):.1f}%" if values else "-"
    print("Right texts: texts marked (marks), onsets within 50 ms outside the marks, and aligned without --lenient\n")
    print("| set | voice | right texts marked | marks | onsets within 50 ms (lenient) | (plain) |")
    print("|---|---|---|---|---|---|")
    for (set_name, voice), row in ordered:
        cases = row["right"]
        print(f"| {set_name} | {voice} | {sum(c['marks'] > 0 for c in cases)} of {len(cases)} | "
              f"{sum(c['marks'] for c in cases)} | {share([e for c in cases for e in c['errors']])} | "
              f"{share([e for c in cases for e in c['plain_errors']])} |")
    print("\nTexts a word off: the word's two syllables reported whole, in part or missed (a word the text "
          "lacks: found where a mark overlaps its span); other marks; onsets within 50 ms outside the marks\n")
    print("| set | voice | kind | whole | in part | missed | other marks | start error (median) | "
          "end error (median) | onsets within 50 ms outside the marks |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for (set_name, voice), row in ordered:
        for kind in ("lacks", "changed"):
            cases = row[kind]
            hit = [c for c in cases if c["found"] != "missed"]
            count = lambda found: sum(c["found"] == found for c in cases)
            print(f"| {set_name} | {voice} | {kind} | {count('whole')} of {len(cases)} | "
                  f"{count('in part') if kind == 'changed' else '-'} | {count('missed')} | "
                  f"{sum(c['other_marks'] for c in cases)} | {median([c['start_error'] for c in hit])} | "
                  f"{median([c['end_error'] for c in hit])} | {share([e for c in cases for e in c['errors']])} |")
    if directories:
        print("\nRead passages, right texts of several sentences\n")
        print("| condition | set | passages marked | marks | onsets within 50 ms outside the marks |")
        print("|---|---|---|---|---|")
        for directory in directories:
            passages(directory)


def passages(directory):
    """Prints, per set, how many of the right passages in `directory` --lenient marks."""
    rows = {}
    for audio in sorted(glob.glob(os.path.join(directory, "*.wav"))):
        stem = audio[:-len(".wav")]
        set_name = os.path.basename(stem).rsplit("-", 1)[0]
        truth = [s["start"] for s in json.load(open(stem + ".json", encoding="utf-8"))["syllables"]]
        result = aligned_transcript(audio, talkface.load_transcript(stem + ".txt"))
        row = rows.setdefault(set_name, {"count": 0, "marked": 0, "marks": 0, "errors": []})
        row["count"] += 1
        row["marked"] += bool(result.mismatches)
        row["marks"] += len(result.mismatches)
        row["errors"] += unmarked_errors(result, truth)
    for set_name, row in sorted(rows.items(), key=lambda item: item[0] != "tuning"):
        within = 100 * sum(e < 0.05 for e in row["errors"]) / max(1, len(row["errors"]))
        print(f"| {os.path.basename(directory.rstrip('/'))} | {set_name} | {row['marked']} of {row['count']} | "
              f"{row['marks']} | {within:.1f}% |")


def unmarked_errors(result, truth_starts, skip=()):
    """Start errors of the syllables no mismatch reports (and not in `skip`), against `truth_starts`,
    a truth per syllable of the result's text (None: no truth)."""
    marked = {m.first_syllable + k for m in result.mismatches for k in range(m.syllable_count)}
    return [abs(s.start_s - t) for i, (s, t) in enumerate(zip(result.syllables, truth_starts))
            if i not in marked and i not in skip and t is not None]


def measure(row, stem, text, found, n):
    """Aligns the clip at `stem` with its right text and two texts a word off into `row`."""
    at, syllable = found
    audio = stem + (".flac" if os.path.exists(stem + ".flac") else ".wav")
    truth = json.load(open(stem + ".json", encoding="utf-8"))
    starts = [s["start"] for s in truth["syllables"]]
    word = (starts[syllable], starts[syllable + 2])
    right = aligned(audio, text)
    plain = talkface.SpeechAligner(talkface.AlignOptions(check=talkface.CheckMode.off)).align_file(audio, talkface.read_transcript(text))
    row["right"].append({"marks": len(right.mismatches), "errors": unmarked_errors(right, starts),
                         "plain_errors": [abs(s.start_s - t) for s, t in zip(plain.syllables, starts)],
                         "marked": [(m.expected_text, round(m.start_s, 2), round(m.end_s, 2)) for m in right.mismatches]})
    for kind, wrong in (("lacks", text[:at] + text[at + 2:]),
                        ("changed", text[:at] + SUBSTITUTES[n % len(SUBSTITUTES)] + text[at + 2:])):
        result = aligned(audio, wrong)
        overlaps = lambda m: m.start_s < word[1] and m.end_s > word[0]
        if kind == "lacks":
            truth_starts = starts[:syllable] + starts[syllable + 2:]
            hits = [m for m in result.mismatches if overlaps(m)]
            found_as = "whole" if hits else "missed"
        else:
            truth_starts = [t if not syllable <= i < syllable + 2 else None for i, t in enumerate(starts)]
            covers = lambda m, i: m.first_syllable <= i < m.first_syllable + m.syllable_count
            hits = [m for m in result.mismatches if overlaps(m) or covers(m, syllable) or covers(m, syllable + 1)]
            reported = sum(any(covers(m, i) for m in hits) for i in (syllable, syllable + 1))
            found_as = ["missed", "in part", "whole"][reported]
        row[kind].append({"found": found_as, "other_marks": len(result.mismatches) - len(hits),
                          "start_error": abs(hits[0].start_s - word[0]) if hits else None,
                          "end_error": abs(hits[-1].end_s - word[1]) if hits else None,
                          "errors": unmarked_errors(result, truth_starts),
                          "marked": [(m.expected_text, round(m.start_s, 2), round(m.end_s, 2)) for m in result.mismatches],
                          "word": [round(word[0], 2), round(word[1], 2)]})


if __name__ == "__main__":
    main()
