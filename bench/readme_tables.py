#!/usr/bin/python3
"""Turns align_bench's printouts into the README's benchmark tables.

    build/bin/align_bench /work/corpus/human > human.txt      # and espeak, voice-v, voice-w
    bench/readme_tables.py human.txt [espeak.txt ...]

prints one Markdown table per printout: every condition of the tuning and the held-out sentences on
its own row, the aligner's median onset error, share within 50 and 100 ms, boundaries found and
failed passages and whether the issue's target for the condition is met, beside the naive baseline's shares. Copy them under README.md's "Benchmark" so the
figures there are what the bench prints, not a hand's transcription.

    bench/readme_tables.py --readme README.md --sha SHA espeak.txt human.txt voice-v.txt voice-w.txt

puts them there itself: from README.md's paragraph starting "Measured on the 2-core build machine" up
to the one starting "A syllable's confidence below 0.5", the tables in the order they stand (one
printout each), each "<N>x real time" of the prose in the same order (align_bench's speed line) and
the first "main at <sha>"; the prose between them is kept as written.
"""

import argparse

import re
import sys


def parse(path):
    """[(set, condition, aligner fields, baseline fields)] in the printout's order."""
    rows = []
    current_set = None
    condition = None
    aligner = None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("tuning sentences"):
                current_set = "tuning"
            elif line.startswith("held-out sentences"):
                current_set = "held out"
            elif line.startswith("confidence") or line.startswith("all"):
                current_set = None
            if current_set is None:
                continue
            m = re.match(r"^(\S+)?\s+aligner\s+(\d+)(?: \((\d+) failed\))?\s+(\d+)\s+(\S+)\s+(\S+)%\s+(\S+)%\s+(\S+)", line)
            if m:
                condition = m.group(1)
                aligner = {
                    "failed": int(m.group(3) or 0),
                    "median": m.group(5),
                    "in50": m.group(6),
                    "in100": m.group(7),
                    "boundaries": m.group(8).replace("/", " of "),
                    "target": "no" if "NOT MET" in line else ("yes" if line.rstrip().endswith(": met") else "-"),
                }
                continue
            m = re.match(r"^\s+baseline\s+\d+\s+\d+\s+\S+\s+(\S+)%\s+(\S+)%", line)
            if m and aligner is not None:
                rows.append((current_set, condition, aligner, {"in50": m.group(1), "in100": m.group(2)}))
                aligner = None
    return rows


def table(rows):
    out = [
        "| set | condition | median | within 50 ms | within 100 ms | boundaries | target met | baseline: 50 / 100 ms |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for current_set, condition, a, b in rows:
        failed = f" ({a['failed']} failed)" if a["failed"] else ""
        out.append(
            f"| {current_set} | {condition} | {a['median']} ms | {a['in50']}% | {a['in100']}%{failed} "
            f"| {a['boundaries']} | {a['target']} | {b['in50']}% / {b['in100']}% |"
        )
    return "\n".join(out)


def speed(path):
    """align_bench's whole-corpus speed, the N of "= Nx real time"."""
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = re.match(r"^speed: .*= (\d+)x real time", line)
            if m:
                return m.group(1)
    raise ValueError(f"{path}: no speed line")


def update_readme(readme, sha, paths):
    """README.md's benchmark section with each printout's table and speed in turn (see the module doc)."""
    with open(readme, encoding="utf-8") as f:
        lines = f.read().split("\n")
    start = next(i for i, l in enumerate(lines) if l.startswith("Measured on the 2-core build machine"))
    end = next(i for i, l in enumerate(lines) if l.startswith("A syllable's confidence below 0.5"))
    region, out, tables = lines[start:end], [], 0
    i = 0
    while i < len(region):
        if not region[i].startswith("|"):
            out.append(region[i])
            i += 1
            continue
        while i < len(region) and region[i].startswith("|"):
            i += 1
        if tables < len(paths):
            out.extend(table(parse(paths[tables])).split("\n"))
        tables += 1
    if tables != len(paths):
        raise ValueError(f"{readme}: {tables} tables in the benchmark section, {len(paths)} printouts given")
    text = re.sub(r"main at [0-9a-f]{7,40}", f"main at {sha}", "\n".join(out), count=1)
    speeds = iter([speed(p) for p in paths])
    text, count = re.subn(r"\d+x(\s+real time)", lambda m: next(speeds) + "x" + m.group(1), text)
    if count != len(paths):
        raise ValueError(f"{readme}: {count} speeds in the benchmark section's prose, {len(paths)} printouts given")
    lines[start:end] = text.split("\n")
    with open(readme, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.strip().split("\n")[0])
    parser.add_argument("printouts", nargs="*")
    parser.add_argument("--readme", help="put the tables in this README.md instead of printing them")
    parser.add_argument("--sha", help="with --readme: the commit the printouts were measured on")
    args = parser.parse_args(argv)
    if not args.printouts:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    for path in args.printouts:
        if not parse(path):
            print(f"readme_tables: {path}: no align_bench rows", file=sys.stderr)
            return 1
    if args.readme:
        if not args.sha:
            print("readme_tables: --readme needs --sha", file=sys.stderr)
            return 2
        try:
            update_readme(args.readme, args.sha, args.printouts)
        except ValueError as error:
            print(f"readme_tables: {error}", file=sys.stderr)
            return 1
        return 0
    for path in args.printouts:
        print(table(parse(path)))
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
