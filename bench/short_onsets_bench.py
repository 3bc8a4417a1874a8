#!/usr/bin/env python3
"""Where a short line's syllables fall (issues 12 and 13): prints, per kind of recording and framing,
tuning and held-out lines apart, how far the aligner puts each syllable's start from the truth
(median, share within 50 and 100 ms), the first syllable's and the line's end error, and how many of
the right lines it refused.

The lines are short_lines_bench.py's (corpus/short_lines*.txt, 1-6 syllables, their tuning and
held-out sets), spoken with their truth by the corpus makers' clip modes: espeak-ng by
`make_corpus --clip` (its word events), a person by `make_human_corpus --clip` (gcin-voice's speaker 3
alone, its syllables joined as the corpus joins them: the truth is where each join put them). Each
line draws its rate and pitch (espeak-ng, 170-230 words a minute and 35-65, as the corpus) or its
tempo (the person, 1.0-1.5, as h-clean) from a stream seeded by the line. The kinds of recording are
short_lines_bench.py's (voice, noise at 15-20 dB, a room, a phone), each bare (cut to the line's
sound) and padded (0.5 s of silence on both sides, the condition applied after the padding). The
truth is not moved for the phone: AMR-NB's coder and decoder put the sound about 8 ms later.

A refused line counts each of its syllables as missed (as align_bench counts a refused passage); the
end error is the last syllable's end against the line's last sound. --tsv writes every syllable's
signed errors (aligned - true) for a closer look.

usage: PYTHONPATH=build/python bench/short_onsets_bench.py OUT_DIR [--bin build/bin] [--kinds ...]
           [--lines short_lines.txt,...] [--framings bare,padded] [--tsv FILE]
(needs espeak-ng, sox with AMR-NB and gcin-voice: cmake/install-deps.sh bench)
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys

import talkface

import short_lines_bench as lines_bench

HERE = os.path.dirname(os.path.abspath(__file__))
PAD_S = 0.5


def clip(binary, stem, text, seed):
    """A line spoken by `binary`'s clip mode: the path of its 16 kHz WAV and its truth (JSON)."""
    draw = random.Random(f"{seed}:delivery")
    if os.path.basename(binary) == "make_corpus":
        extra = ["--rate-wpm", str(draw.randint(170, 230)), "--pitch", str(draw.randint(35, 65))]
    else:
        extra = ["--tempo", f"{draw.uniform(1.0, 1.5):.3f}"]
    subprocess.run([binary, "--clip", stem, "--seed", str(seed), *extra, text], check=True, stdout=subprocess.DEVNULL)
    with open(stem + ".json", encoding="utf-8") as truth:
        return stem + ".wav", json.load(truth)


def cut(source, truth, path):
    """The line cut to its sound (the truth's sentence span) into `path`; its syllables' (start, end)
    counted from the cut."""
    samples, rate = lines_bench.read_wav(source)
    sentence = truth["sentences"][0]
    begin, end = round(sentence["start"] * rate), round(sentence["end"] * rate)
    lines_bench.write_wav(path, samples[begin:end], rate)
    shift = begin / rate
    return [(s["start"] - shift, s["end"] - shift) for s in truth["syllables"]]


def recordings(kind, spoken, stem, seed):
    """The bare and the padded recording of a line of `kind` with each one's syllable times, from
    `spoken` (speaker: (bare path, times)); noise, room and phone as short_lines_bench applies them."""
    voice = lines_bench.KINDS[kind][0]
    speaker = "person" if voice == "voice" else voice
    source, times = spoken[speaker]
    if voice == "voice":
        moved = f"{stem}-voice-moved.wav"
        factor = lines_bench.moved_voice(source, moved, random.Random(f"{seed}:voice"))
        source, times = moved, [(a / factor, b / factor) for a, b in times]
    bare, padded = f"{stem}-{kind}.wav", f"{stem}-{kind}-padded.wav"
    subprocess.run(["sox", "-R", source, bare], check=True)
    lines_bench.pad(bare, padded)
    lines_bench.apply_condition(kind, bare, padded, lines_bench.mean_square(source), seed)
    return {"bare": (bare, times), "padded": (padded, [(a + PAD_S, b + PAD_S) for a, b in times])}


class Score:
    def __init__(self):
        self.lines = self.refused = 0
        self.errors, self.first, self.ends = [], [], []

    def add(self, other):
        self.lines += other.lines
        self.refused += other.refused
        self.errors += other.errors
        self.first += other.first
        self.ends += other.ends


def median_ms(values):
    if not values:
        return "-"
    ordered = sorted(values)
    n = len(ordered)
    middle = ordered[n // 2] if n % 2 else 0.5 * (ordered[n // 2 - 1] + ordered[n // 2])
    return "inf" if math.isinf(middle) else f"{1000 * middle:.1f}"


def within(values, limit_s):
    return f"{100.0 * sum(v <= limit_s for v in values) / len(values):.1f}" if values else "-"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--bin", default=os.path.join(HERE, os.pardir, "build", "bin"))
    parser.add_argument("--kinds", default=",".join(lines_bench.KINDS))
    parser.add_argument("--lines", default="short_lines.txt,short_lines_13.txt,short_lines_21.txt")
    parser.add_argument("--framings", default="bare,padded")
    parser.add_argument("--tsv", help="every syllable: set, kind, framing, line, syllable, true start, signed errors")
    args = parser.parse_args()
    kinds = args.kinds.split(",")
    for kind in kinds:
        if kind not in lines_bench.KINDS:
            parser.error(f"--kinds: no kind {kind!r}; kinds: {', '.join(lines_bench.KINDS)}")
    framings = args.framings.split(",")
    makers = {"espeak": os.path.join(args.bin, "make_corpus"), "person": os.path.join(args.bin, "make_human_corpus")}
    speakers = {"person" if lines_bench.KINDS[k][0] == "voice" else lines_bench.KINDS[k][0] for k in kinds}
    os.makedirs(args.out, exist_ok=True)
    aligner = talkface.SpeechAligner(talkface.AlignOptions())
    scores = {}
    rows, refusals = [], []
    for file_index, name in enumerate(args.lines.split(",")):
        for k, (subset, text, transcript) in enumerate(lines_bench.read_lines(name)):
            seed = 1000 * file_index + k
            stem = os.path.join(args.out, f"{file_index}-{k:02d}")
            spoken = {}
            for speaker in sorted(speakers):
                source, truth = clip(makers[speaker], f"{stem}-{speaker}-clip", text, seed)
                spoken[speaker] = (f"{stem}-{speaker}-cut.wav", cut(source, truth, f"{stem}-{speaker}-cut.wav"))
            for kind in kinds:
                for framing, (audio, times) in recordings(kind, spoken, stem, seed).items():
                    if framing not in framings:
                        continue
                    score = scores.setdefault((subset, kind, framing), Score())
                    score.lines += 1
                    try:
                        aligned = aligner.align_file(audio, transcript).syllables
                    except talkface.AlignmentError as error:
                        refusals.append(f"{subset} {kind} {framing}: {text}: {str(error).split(': ', 1)[-1]}")
                        score.refused += 1
                        score.errors += [math.inf] * len(times)
                        score.first.append(math.inf)
                        score.ends.append(math.inf)
                        continue
                    signed = [a.start_s - t[0] for a, t in zip(aligned, times)]
                    score.errors += [abs(e) for e in signed]
                    score.first.append(abs(signed[0]))
                    end = aligned[-1].end_s - times[-1][1]
                    score.ends.append(abs(end))
                    for i, (syllable, error) in enumerate(zip(aligned, signed)):
                        rows.append(f"{subset}\t{kind}\t{framing}\t{text}\t{i}\t{syllable.pinyin}\t"
                                    f"{times[i][0]:.3f}\t{1000 * error:.1f}\t{1000 * end:.1f}")
    print("short lines' onsets: |aligned - true start| per syllable (refused lines count as missed), the first")
    print("syllable's, and |aligned - true end| of the line's last syllable (median ms)")
    print(f"{'set':9} {'kind':13} {'framing':8} {'lines':>5} {'syll':>5} {'median':>7} {'in50%':>6} {'in100%':>7} "
          f"{'first':>6} {'end':>6} {'refused':>7}")
    for subset in ("tuning", "held-out"):
        for framing in framings:
            total = Score()
            for kind in kinds:
                score = scores.get((subset, kind, framing), Score())
                total.add(score)
                print(f"{subset:9} {kind:13} {framing:8} {score.lines:>5} {len(score.errors):>5} "
                      f"{median_ms(score.errors):>7} {within(score.errors, 0.05):>6} {within(score.errors, 0.1):>7} "
                      f"{median_ms(score.first):>6} {median_ms(score.ends):>6} {score.refused:>7}")
            print(f"{subset:9} {'all':13} {framing:8} {total.lines:>5} {len(total.errors):>5} "
                  f"{median_ms(total.errors):>7} {within(total.errors, 0.05):>6} {within(total.errors, 0.1):>7} "
                  f"{median_ms(total.first):>6} {median_ms(total.ends):>6} {total.refused:>7}")
    for line in refusals:
        print("refused:", line)
    if args.tsv:
        with open(args.tsv, "w", encoding="utf-8") as out:
            out.write("set\tkind\tframing\tline\tindex\tpinyin\ttrue_start_s\terror_ms\tend_error_ms\n")
            out.write("\n".join(rows) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
