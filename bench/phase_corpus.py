#!/usr/bin/env python3
"""Copies of a corpus (made by make_corpus, make_human_corpus or make_music_kinds.py) with the
first samples of every recording cut off, so that the aligner's 10 ms frames fall elsewhere against
the same speech: a user's recording has any such phase.

    phase_corpus.py CORPUS OUT [--cuts 0,40,80,120] [--conditions A,B,...] [--keep-times]

makes OUT/cut<N>/ for each N (samples at the recording's rate; at 16 kHz 40 samples are 2.5 ms),
a corpus align_bench reads as it reads CORPUS: each recording trimmed with sox, its truth's times
moved earlier by the cut, its transcript the same. Then, e.g.

    for n in 0 40 80 120; do build/bin/align_bench OUT/cut$n --conditions A,B; done

The refused passages are named on stderr; their counts are the rows' "failed". `align_bench
--mismatch` cuts its clips at the truth's times: with them moved, a clip holds the same samples at
every cut. With --keep-times the truths are copied as they are, the clips are cut at the same
seconds of the shorter recordings, and their speech falls N samples later against the frames:

    phase_corpus.py CORPUS OUT --keep-times --conditions A,B
    for n in 0 40 120; do build/bin/align_bench --mismatch OUT/cut$n --conditions A,B; done
"""
import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path


def shifted_truth(truth, seconds):
    truth = dict(truth)
    truth["duration"] = max(0.0, truth["duration"] - seconds)
    for key in ("sentences", "syllables"):
        items = []
        for item in truth[key]:
            item = dict(item)
            item["start"] -= seconds
            item["end"] -= seconds
            items.append(item)
        truth[key] = items
    return truth


def sample_rate(path):
    return int(subprocess.run(["soxi", "-r", str(path)], check=True, capture_output=True, text=True).stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("corpus", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--cuts", default="0,40,80,120")
    parser.add_argument("--conditions", default="")
    parser.add_argument("--keep-times", action="store_true", help="copy the truths as they are (for --mismatch)")
    args = parser.parse_args()
    cuts = [int(c) for c in args.cuts.split(",")]
    wanted = set(filter(None, args.conditions.split(",")))
    lines = (args.corpus / "conditions.txt").read_text(encoding="utf-8").splitlines()
    kept = [line for line in lines if line.split("\t")[0] and (not wanted or line.split("\t")[0] in wanted)]
    if not kept:
        sys.exit(f"{args.corpus}/conditions.txt: no condition selected")
    for cut in cuts:
        root = args.out / f"cut{cut}"
        root.mkdir(parents=True, exist_ok=True)
        (root / "conditions.txt").write_text("\n".join(kept) + "\n", encoding="utf-8")
        for line in kept:
            condition = line.split("\t")[0]
            source = args.corpus / condition
            target = root / condition
            target.mkdir(exist_ok=True)
            for truth_path in sorted(source.glob("*.json")):
                audio = next(truth_path.with_suffix(s) for s in (".wav", ".ogg", ".flac")
                             if truth_path.with_suffix(s).exists())
                rate = sample_rate(audio)
                if args.keep_times:
                    shutil.copyfile(truth_path, target / truth_path.name)
                else:
                    truth = json.loads(truth_path.read_text(encoding="utf-8"))
                    (target / truth_path.name).write_text(
                        json.dumps(shifted_truth(truth, cut / rate), ensure_ascii=False), encoding="utf-8")
                shutil.copyfile(truth_path.with_suffix(".txt"), target / truth_path.with_suffix(".txt").name)
                subprocess.run(["sox", str(audio), str(target / audio.name), "trim", f"{cut}s"], check=True)


if __name__ == "__main__":
    main()
