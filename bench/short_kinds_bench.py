#!/usr/bin/env python3
"""Short lines as users record them (issues 12 and 13): prints, per kind of recording, tuning and
held-out lines apart, the right lines refused, the wrong texts caught, and where the syllables fall
(median onset error, share within 50 / 100 ms; the first and the last syllable apart, as a line cut
tight puts them at the file's edges).

The lines are corpus/short_lines_28.txt (game and chat dialogue, 1-8 syllables, digits and English
among them). Each is spoken with its truth by one of four speakers, taken in turn per line and kind
so that every kind hears all four: espeak-ng (`make_corpus --clip`, rate 170-230 words a minute,
pitch 35-65), gcin-voice's speaker 3 (`make_human_corpus --clip`, tempo 1.0-1.5), that person made
into another voice (v: pitch and formants moved together by 2-4 semitones, as the v- conditions)
and into another person (w: praat's Change gender, formants by 0.86-0.93 or 1.08-1.20, a pitch of
its own, a microphone's shelves and low-pass, as the w- conditions). Where speaker 3 never recorded
a syllable (OK's kei), espeak-ng says the line for the person, v and w. Every draw comes from a seed
of the line and the kind.

A line is recorded with 0.3-0.6 s of a headset's hiss (pink, 45 dB under the voice) before and after
it, then (the kinds):
  plain        nothing more
  p-...        the thirteen phone kinds of make_phone_kinds.py, each chain applied to the line
               (babble: other lines of the same set)
  clipped      driven 6-14 dB past full scale and clipped hard
  click        a click (a 1-3 ms decaying burst) 0.05-0.25 s before the line
  breath       an in-breath (band noise 400-3000 Hz, 0.25-0.45 s, 12-20 dB under the voice) ending
               0.05-0.2 s before the line
  room         a room of its own (sox reverb, reverberance 30-70, room scale 40-100)
  babble       3-5 other lines of the same set at SNR 10-20 dB
  tight        cut tight: no hiss around it, its start 10-30 ms into the first syllable (the first
               consonant partly cut), its end 0-20 ms before the last sound
  breath-after an out-breath (the breath's band noise) starting 0.1-0.3 s after the line, the hiss
               after it lengthened to hold it (session 29; the other kinds' recordings are as they were)
  p-breath     an in-breath before the line and an out-breath after it (breath's and breath-after's),
               then one of five narrowband codecs (p-speex8, p-opus6, p-opus12, p-g723, p-g726): a
               breath through a telephone band, where no voice keeps its fundamental (session 30)
  click-after  a click (the click kind's) 0.05-0.3 s after the line, the hiss after it lengthened to
               hold it (session 32)
The wrong text is the next line of the same set with as many syllables (short_lines_bench's).
A refused line counts each syllable as missed, as align_bench counts a refused passage. A right
line aligned with the finding "the transcript may not match the audio" as a warning (a short line
on weak evidence, session 44) is a false alarm, counted as warned; a wrong text is caught refused
or warned of, and of those caught, refused counts the refusals. The last row of each set sums the
lines with digits or English over every kind.

usage: PYTHONPATH=build/python /usr/bin/python3 bench/short_kinds_bench.py OUT_DIR [--bin build/bin] [--kinds ...]
           [--lines short_lines_28.txt] [--tsv FILE] [--reuse]
--reuse aligns the recordings an earlier run left in OUT_DIR (to compare two builds on the same
files); without --kinds, every kind it holds. Needs numpy, espeak-ng, sox, ffmpeg and praat (cmake/install-deps.sh bench).
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys
import zlib

import numpy as np
import talkface

import make_phone_kinds as phone
import short_lines_bench as lines_bench
import short_onsets_bench as onsets_bench

HERE = os.path.dirname(os.path.abspath(__file__))
SPEAKERS = ("espeak", "person", "v", "w")
EDGE_KINDS = ("plain", "clipped", "click", "breath", "room", "babble", "tight", "breath-after", "p-breath",
              "click-after")
# The narrowband codecs p-breath draws from (make_phone_kinds.py's chains: pink noise at 30 dB, the
# telephone band, the codec).
BREATH_CODECS = ("p-speex8", "p-opus6", "p-opus12", "p-g723", "p-g726")
KINDS = EDGE_KINDS[:1] + tuple(phone.kinds) + EDGE_KINDS[1:]
HISS_DB = 45.0
# How a warning of the check's finding begins (CheckMode::warn's, and a short line's on weak evidence).
FINDING = "the transcript may not match the audio"


def change_voice_script():
    """praat's Change gender as make_human_corpus's w- conditions run it (kChangeVoiceScript), read
    from its source so that the two never part."""
    with open(os.path.join(HERE, "make_human_corpus.cpp"), encoding="utf-8") as source:
        text = source.read()
    start = text.index('kChangeVoiceScript = R"(') + len('kChangeVoiceScript = R"(')
    return text[start:text.index(')";', start)]


def another_person(source, out, draw, work):
    """`source` said by another person (make_human_corpus's draw_person): times do not move."""
    script = os.path.join(work, "change_voice.praat")
    if not os.path.exists(script):
        with open(script, "w", encoding="utf-8") as f:
            f.write(change_voice_script())
    ratio = draw.uniform(1.08, 1.20) if draw.random() < 0.5 else draw.uniform(0.86, 0.93)
    median = math.exp(draw.uniform(math.log(95.0), math.log(240.0)))
    changed = out + ".praat.wav"
    subprocess.run(["praat", "--run", script, source, changed, f"{ratio:.4f}", f"{median:.2f}",
                    f"{draw.uniform(0.6, 1.5):.3f}"], check=True, stdout=subprocess.DEVNULL)
    effects = ["bass", f"{draw.uniform(-8, 6):.2f}", "150", "treble", f"{draw.uniform(-8, 6):.2f}", "3000"]
    if draw.random() < 0.5:
        effects += ["lowpass", f"{draw.uniform(4500, 7000):.0f}"]
    lines_bench.run("sox", "-R", changed, "-b", "16", out, *effects, "rate", "-v", "16k", "gain", "-n", "-3")
    os.remove(changed)


def speak(speaker, text, stem, seed, bin_dir):
    """The line said by `speaker`, cut to its sound: (samples at 16 kHz, [(start, end)] per syllable)."""
    maker = "make_corpus" if speaker == "espeak" else "make_human_corpus"
    try:
        source, truth = onsets_bench.clip(os.path.join(bin_dir, maker), f"{stem}-{speaker}-clip", text, seed)
    except subprocess.CalledProcessError:
        # Speaker 3 never recorded some syllables (OK's kei): espeak-ng says the line in its place.
        source, truth = onsets_bench.clip(os.path.join(bin_dir, "make_corpus"), f"{stem}-{speaker}-clip", text, seed)
    cut = f"{stem}-{speaker}.wav"
    times = onsets_bench.cut(source, truth, cut)
    if speaker == "v":
        factor = lines_bench.moved_voice(cut, cut + ".moved.wav", random.Random(f"{seed}:voice"))
        os.replace(cut + ".moved.wav", cut)
        times = [(a / factor, b / factor) for a, b in times]
    elif speaker == "w":
        another_person(cut, cut + ".person.wav", random.Random(f"{seed}:person"), os.path.dirname(stem))
        os.replace(cut + ".person.wav", cut)
    x, sr = phone.load(cut)
    assert sr == 16000, cut
    return x, times


def power(x):
    return float(np.mean(x ** 2))


def around(x, rng, before_s, after_s, sr=16000):
    """`x` with a headset's hiss before, under and after it."""
    y = np.concatenate([np.zeros(round(before_s * sr)), x, np.zeros(round(after_s * sr))])
    return phone.add(y, phone.coloured(len(y), rng, 1), power(x), HISS_DB)


def click(n, rng, sr=16000):
    length = round(rng.uniform(0.001, 0.003) * sr)
    return rng.standard_normal(length) * np.exp(-np.arange(length) / (length / 4)) * (n / 3)


def breath(n_power, rng, sr=16000):
    length = round(rng.uniform(0.25, 0.45) * sr)
    noise = phone.sox(rng.standard_normal(length), sr, ["sinc", "400-3000"])[:length] * np.hanning(length)
    return phone.add(np.zeros(length), noise, n_power, rng.uniform(12, 20))


def record(kind, x, times, rng, others):
    """The recording of `kind` made from the line `x` (16 kHz) and its syllables' times in it."""
    sr = 16000
    if kind == "tight":
        begin = times[0][0] + rng.uniform(0.010, 0.030)
        end = times[-1][1] - rng.uniform(0.0, 0.020)
        y = x[round(begin * sr):round(end * sr)]
        y = phone.add(y, phone.coloured(len(y), rng, 1), power(x), HISS_DB)
        return y, sr, [(max(0.0, a - begin), b - begin) for a, b in times]
    before, after = rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6)
    if kind in ("breath-after", "p-breath"):
        gap = rng.uniform(0.1, 0.3)
        b = breath(power(x), rng)
        after += gap + len(b) / sr
    elif kind == "click-after":
        gap = rng.uniform(0.05, 0.3)
        c = click(np.max(np.abs(x)) * rng.uniform(0.3, 0.9), rng)
        after += gap + len(c) / sr
    y = around(x, rng, before, after)
    moved = [(a + before, b + before) for a, b in times]
    truth = {"sentences": [{"start": before, "end": before + len(x) / sr}]}
    at = round(before * sr)
    if kind in phone.kinds:
        y, sr = phone.kinds[kind][2](y, 16000, truth, rng, others)
    elif kind == "clipped":
        y = np.clip(y * 10 ** (rng.uniform(6, 14) / 20) / np.max(np.abs(y)), -1.0, 1.0)
    elif kind == "click":
        c = click(np.max(np.abs(x)) * rng.uniform(0.3, 0.9), rng)
        start = at - round(rng.uniform(0.05, 0.25) * sr)
        y[start:start + len(c)] += c
    elif kind == "breath":
        b = breath(power(x), rng)
        end = at - round(rng.uniform(0.05, 0.2) * sr)
        y[max(0, end - len(b)):end] += b[max(0, len(b) - end):]
    elif kind == "breath-after":
        start = at + len(x) + round(gap * sr)
        y[start:start + len(b)] += b
    elif kind == "click-after":
        start = at + len(x) + round(gap * sr)
        y[start:start + len(c)] += c
    elif kind == "p-breath":
        start = at + len(x) + round(gap * sr)
        y[start:start + len(b)] += b
        before_line = breath(power(x), rng)
        end = at - round(rng.uniform(0.05, 0.2) * sr)
        y[max(0, end - len(before_line)):end] += before_line[max(0, len(before_line) - end):]
        y, sr = phone.kinds[BREATH_CODECS[rng.integers(len(BREATH_CODECS))]][2](y, 16000, truth, rng, others)
    elif kind == "room":
        y = phone.sox(y, sr, ["reverb", str(rng.integers(30, 71)), "50", str(rng.integers(40, 101)),
                              "gain", "-n", "-3"])[:len(y)]
    elif kind == "babble":
        y = phone.babble(y, sr, truth, rng, others, 10, 20)
    return y, sr, moved


class Score(onsets_bench.Score):
    def __init__(self):
        super().__init__()
        self.warned = self.wrong = self.caught = self.wrong_refused = 0
        self.last = []

    def add(self, other):
        super().add(other)
        self.warned += other.warned
        self.wrong += other.wrong
        self.caught += other.caught
        self.wrong_refused += other.wrong_refused
        self.last += other.last


def has_written_form(text):
    return any(c.isascii() and c.isalnum() for c in text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--bin", default=os.path.join(HERE, os.pardir, "build", "bin"))
    parser.add_argument("--kinds", help="a comma-separated list; default: every kind (with --reuse, every kind OUT_DIR has)")
    parser.add_argument("--lines", default="short_lines_28.txt")
    parser.add_argument("--tsv", help="every syllable: set, kind, speaker, line, index, pinyin, true start, error")
    parser.add_argument("--reuse", action="store_true", help="align the recordings an earlier run made")
    args = parser.parse_args()
    kinds = args.kinds.split(",") if args.kinds else list(KINDS)
    for kind in kinds:
        if kind not in KINDS:
            parser.error(f"--kinds: no kind {kind!r}; kinds: {', '.join(KINDS)}")
    os.makedirs(args.out, exist_ok=True)
    lines = [line for name in args.lines.split(",") for line in lines_bench.read_lines(name)]
    if not args.reuse:
        make(args, lines, kinds)
    elif not args.kinds:
        # An earlier run's recordings lack the kinds added since (click-after, session 32).
        made = [kind for kind in kinds if os.path.exists(os.path.join(args.out, f"00-{kind}.json"))]
        for kind in sorted(set(kinds) - set(made)):
            print(f"short_kinds_bench: {args.out} has no {kind} recordings; left out", file=sys.stderr)
        kinds = made
    aligner = talkface.SpeechAligner(talkface.AlignOptions())
    scores, rows, refusals, alarms = {}, [], [], []
    for k, (subset, text, transcript) in enumerate(lines):
        wrong = lines_bench.wrong_text(lines, k)
        for kind in kinds:
            audio = os.path.join(args.out, f"{k:02d}-{kind}.wav")
            with open(audio[:-4] + ".json", encoding="utf-8") as f:
                made = json.load(f)
            times = made["times"]
            keys = [(subset, kind)] + ([(subset, "digits, English")] if has_written_form(text) else [])
            score = Score()
            score.lines = 1
            try:
                timeline = aligner.align_file(audio, transcript)
                aligned = timeline.syllables
                for warning in timeline.warnings:
                    if warning.startswith(FINDING):
                        score.warned = 1
                        alarms.append(f"{subset} {kind} {made['speaker']}: {text}: {warning}")
                signed = [a.start_s - t[0] for a, t in zip(aligned, times)]
                score.errors = [abs(e) for e in signed]
                score.first, score.last = [abs(signed[0])], [abs(signed[-1])]
                score.ends = [abs(aligned[-1].end_s - times[-1][1])]
                for i, (syllable, error) in enumerate(zip(aligned, signed)):
                    rows.append(f"{subset}\t{kind}\t{made['speaker']}\t{text}\t{i}\t{syllable.pinyin}\t"
                                f"{times[i][0]:.3f}\t{1000 * error:.1f}")
            except talkface.AlignmentError as error:
                refusals.append(f"{subset} {kind} {made['speaker']}: {text}: {str(error).split(': ', 1)[-1]}")
                score.refused = 1
                score.errors = [math.inf] * len(times)
                score.first = score.last = score.ends = [math.inf]
            if wrong is not None:
                score.wrong = 1
                found, why = lines_bench.outcome(aligner, audio, wrong)
                score.caught = int(found)
                score.wrong_refused = int(found and not why.startswith(FINDING))
            for key in keys:
                scores.setdefault(key, Score()).add(score)
    report(scores, kinds, refusals, alarms)
    if args.tsv:
        with open(args.tsv, "w", encoding="utf-8") as out:
            out.write("set\tkind\tspeaker\tline\tindex\tpinyin\ttrue_start_s\terror_ms\n")
            out.write("\n".join(rows) + "\n")
    return 0


def make(args, lines, kinds):
    """Every line's recordings of `kinds` into OUT_DIR, each with its truth and speaker (JSON)."""
    spoken = {}
    for k, (subset, text, _) in enumerate(lines):
        for speaker in SPEAKERS:
            spoken[k, speaker] = speak(speaker, text, os.path.join(args.out, f"{k:02d}"),
                                       10 * k + SPEAKERS.index(speaker), args.bin)
    for kind_index, kind in enumerate(KINDS):
        if kind not in kinds:
            continue
        for k, (subset, text, _) in enumerate(lines):
            speaker = SPEAKERS[(k + kind_index) % len(SPEAKERS)]
            x, times = spoken[k, speaker]
            rng = np.random.default_rng(zlib.crc32(f"{kind}:{k}".encode()))
            others = [os.path.join(args.out, f"{j:02d}-person.wav") for j, other in enumerate(lines)
                      if j != k and other[0] == subset]
            y, sr, moved = record(kind, x, times, rng, others)
            peak = np.max(np.abs(y))
            if peak > 0.99:
                y *= 0.99 / peak
            stem = os.path.join(args.out, f"{k:02d}-{kind}")
            phone.save(stem + ".wav", y, sr)
            with open(stem + ".json", "w", encoding="utf-8") as f:
                json.dump({"speaker": speaker, "times": moved}, f)


def report(scores, kinds, refusals, alarms):
    ms, within = onsets_bench.median_ms, onsets_bench.within
    print("short lines as users record them: right lines refused and warned of (false alarms), wrong texts")
    print("caught (refused or warned of) and, of those, refused; |aligned - true start|")
    print("per syllable (median ms, % within 50 / 100 ms; refused lines count as missed), the first and the")
    print("last syllable's (median ms, % within 50 ms), |aligned - true end| of the last syllable (median ms)")
    print(f"{'set':9} {'kind':16} {'lines':>5} {'refused':>7} {'warned':>6} {'caught':>9} {'w-ref':>5} {'syll':>5} {'median':>7} {'in50%':>6} "
          f"{'in100%':>7} {'first':>6} {'f50%':>6} {'last':>6} {'l50%':>6} {'end':>6}")
    for subset in ("tuning", "held-out"):
        total = Score()
        for kind in list(kinds) + ["all", "digits, English"]:
            score = total if kind == "all" else scores.get((subset, kind), Score())
            if kind in kinds:
                total.add(score)
            print(f"{subset:9} {kind:16} {score.lines:>5} {score.refused:>7} {score.warned:>6} "
                  f"{score.caught:>4} of {score.wrong:<2} {score.wrong_refused:>5} "
                  f"{len(score.errors):>5} {ms(score.errors):>7} {within(score.errors, 0.05):>6} "
                  f"{within(score.errors, 0.1):>7} {ms(score.first):>6} {within(score.first, 0.05):>6} "
                  f"{ms(score.last):>6} {within(score.last, 0.05):>6} {ms(score.ends):>6}")
    for line in refusals:
        print("refused:", line)
    for line in alarms:
        print("warned:", line)


if __name__ == "__main__":
    sys.exit(main())
