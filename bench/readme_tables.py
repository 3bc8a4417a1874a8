#!/usr/bin/python3
"""Turns align_bench's printouts into the README's benchmark tables.

    build/bin/align_bench /work/corpus/human > human.txt      # and espeak, voice-v, voice-w
    bench/readme_tables.py human.txt [espeak.txt ...]

prints one Markdown table per printout: every condition of the tuning and the held-out sentences on
its own row, the aligner's median onset error, share within 50 and 100 ms, boundaries found and
failed passages and whether the issue's target for the condition is met, beside the naive baseline's shares. Copy them under README.md's "Benchmark" so the
figures there are what the bench prints, not a hand's transcription.
"""

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


def main(paths):
    if not paths:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    for path in paths:
        rows = parse(path)
        if not rows:
            print(f"readme_tables: {path}: no align_bench rows", file=sys.stderr)
            return 1
        print(table(rows))
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
