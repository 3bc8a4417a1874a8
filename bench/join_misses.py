#!/usr/bin/env python3
"""Where the aligner's syllable starts fall more than 50 ms off (issue 12), by the kind of join.

Reads `align_bench CORPUS --dump SYLLABLES.tsv` and the truths beside the corpus's recordings, and
classes every syllable of the chosen set (tuning unless --set says otherwise) more than 50 ms off
by its join: the class of the syllable before's last sound (a vowel a e i o u v, the apical vowel
of zi ci si zhi chi shi ri, a nasal, a liquid; "pause" after a pause or at a passage's start) and
the class of this syllable's first sound (its initial, or its first vowel where it has none, y- and
w- as the medials i u v). Per kind it prints how many, how many late (the rest early), how many
beside a light-tone syllable (this one's or the one before's), how many alone (neither neighbour
also more than 50 ms off: not a run slipped a syllable), and the pairs of characters most often.
Passages the aligner refused are not in the dump, so not counted here.

usage: bench/join_misses.py SYLLABLES.tsv CORPUS [--set tuning|held-out] [--pairs N]
"""
import argparse
import collections
import csv
import json
import os

INITIAL_KINDS = {
    **dict.fromkeys(("b", "d", "g"), "stop"), **dict.fromkeys(("p", "t", "k"), "aspirated stop"),
    **dict.fromkeys(("j", "zh", "z", "q", "ch", "c"), "affricate"), **dict.fromkeys(("s", "sh", "x"), "sibilant"),
    "f": "f h", "h": "f h", "m": "nasal", "n": "nasal", "l": "liquid", "r": "liquid",
}
INITIALS = ("zh", "ch", "sh", "b", "p", "m", "f", "d", "t", "n", "l", "g", "k", "h", "j", "q", "x", "r", "z", "c",
            "s", "y", "w")
APICAL_INITIALS = ("z", "c", "s", "zh", "ch", "sh", "r")


def split(pinyin):
    """Initial and final as phone_chain.cpp splits them: y- and w- become the medials i, u, v."""
    toneless = pinyin.rstrip("012345").lower().replace("u:", "v").replace("ü", "v")
    if toneless in ("m", "n", "ng", "hm", "hng", "r"):
        return "", toneless
    for initial in INITIALS:
        if len(toneless) > len(initial) and toneless.startswith(initial):
            final = toneless[len(initial):]
            if initial in ("j", "q", "x", "y") and final[0] == "u":
                final = "v" + final[1:]
            if initial == "y":
                return "", final if final[0] in "iv" else "i" + final
            if initial == "w":
                return "", final if final[0] == "u" else "u" + final
            return initial, final
    return "", toneless


def vowel_kind(letter):
    return letter if letter in "aeiouv" else "e"


def last_sound(pinyin):
    initial, final = split(pinyin)
    if final in ("m", "n", "ng", "hm", "hng") or (len(final) >= 2 and final.endswith("n")) or final.endswith("ng"):
        return "nasal"
    if final in ("r", "er"):
        return "liquid"
    if final == "i" and initial in APICAL_INITIALS:
        return "apical"
    if final.endswith("ao"):
        return "u"
    return vowel_kind(final[-1])


def first_sound(pinyin):
    initial, final = split(pinyin)
    if initial:
        return INITIAL_KINDS[initial]
    if final in ("m", "n", "ng"):
        return "nasal"
    return "e" if final == "er" else vowel_kind(final[0])


def misses(dump, corpus, wanted_set):
    errors = collections.defaultdict(dict)
    for row in csv.DictReader(open(dump, encoding="utf-8"), delimiter="\t"):
        errors[(row["condition"], row["passage"])][int(row["syllable"])] = float(row["error_ms"])
    found, total = [], 0
    for (condition, passage), by_syllable in sorted(errors.items()):
        with open(os.path.join(corpus, condition, passage + ".json"), encoding="utf-8") as file:
            truth = json.load(file)
        if truth["set"] != wanted_set:
            continue
        syllables = truth["syllables"]
        for i, error in by_syllable.items():
            total += 1
            if abs(error) <= 50:
                continue
            syllable = syllables[i]
            before = "pause" if i == 0 or syllable["after_pause"] else last_sound(syllables[i - 1]["pinyin"])
            found.append({
                "join": before + " -> " + first_sound(syllable["pinyin"]),
                "late": error > 0,
                "light": syllable["pinyin"].endswith("5") or (i > 0 and syllables[i - 1]["pinyin"].endswith("5")),
                "alone": not any(abs(by_syllable.get(j, 0.0)) > 50 for j in (i - 1, i + 1)),
                "pair": (syllables[i - 1]["text"] if i > 0 else "|") + syllable["text"],
            })
    return found, total


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dump")
    parser.add_argument("corpus")
    parser.add_argument("--set", default="tuning", choices=("tuning", "held-out"))
    parser.add_argument("--pairs", type=int, default=4, help="pairs of characters shown per kind")
    args = parser.parse_args()
    found, total = misses(args.dump, args.corpus, args.set)
    print(f"{args.dump}, {args.set}: {len(found)} of {total} syllables more than 50 ms off "
          f"({100.0 * len(found) / max(total, 1):.1f}%): {sum(m['late'] for m in found)} late, "
          f"{sum(m['light'] for m in found)} beside a light tone, {sum(m['alone'] for m in found)} alone")
    print(f"{'join':26s} {'off':>5s} {'late':>5s} {'light':>6s} {'alone':>6s}  pairs")
    by_join = collections.defaultdict(list)
    for miss in found:
        by_join[miss["join"]].append(miss)
    for join, kind in sorted(by_join.items(), key=lambda item: (-len(item[1]), item[0])):
        pairs = collections.Counter(miss["pair"] for miss in kind).most_common(args.pairs)
        print(f"{join:26s} {len(kind):5d} {sum(m['late'] for m in kind):5d} {sum(m['light'] for m in kind):6d} "
              f"{sum(m['alone'] for m in kind):6d}  " + " ".join(f"{pair} {count}" for pair, count in pairs))


if __name__ == "__main__":
    main()
