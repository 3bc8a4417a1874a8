#!/usr/bin/env python3
"""Short lines and the wrong-text check (issue #13): prints, per set and voice, how many correct
lines of 1-5 syllables the aligner refuses (false refusals) beside how many wrong texts it still
catches, at each --check setting.

Each line of corpus/short_lines.txt is spoken by espeak-ng (cmn-latn-pinyin) and by a person:
gcin-voice's speaker 3, one recording a syllable (/usr/share/gcin-voice/ogg/<bopomofo><tone>/3.ogg;
speaker 5 is kept for others' measurement and never read here), joined. Each recording is aligned
bare (cut to its sound) and with 0.5 s of silence on both sides, with its own text and with a wrong
one: the next line of the same set with as many syllables and another text.

usage: PYTHONPATH=build/python bench/short_lines_bench.py OUT_DIR [--check refuse|warn]
(needs espeak-ng, sox and gcin-voice: cmake/install-deps.sh bench)
"""
import argparse
import os
import subprocess
import sys

import talkface

HERE = os.path.dirname(os.path.abspath(__file__))
GCIN = "/usr/share/gcin-voice/ogg"
SPEAKER = "3"

INITIALS = {"b": "ㄅ", "p": "ㄆ", "m": "ㄇ", "f": "ㄈ", "d": "ㄉ", "t": "ㄊ", "n": "ㄋ", "l": "ㄌ", "g": "ㄍ",
            "k": "ㄎ", "h": "ㄏ", "j": "ㄐ", "q": "ㄑ", "x": "ㄒ", "zh": "ㄓ", "ch": "ㄔ", "sh": "ㄕ", "r": "ㄖ",
            "z": "ㄗ", "c": "ㄘ", "s": "ㄙ"}
FINALS = {"a": "ㄚ", "o": "ㄛ", "e": "ㄜ", "ai": "ㄞ", "ei": "ㄟ", "ao": "ㄠ", "ou": "ㄡ", "an": "ㄢ", "en": "ㄣ",
          "ang": "ㄤ", "eng": "ㄥ", "er": "ㄦ", "i": "ㄧ", "ia": "ㄧㄚ", "ie": "ㄧㄝ", "iao": "ㄧㄠ", "iu": "ㄧㄡ",
          "ian": "ㄧㄢ", "in": "ㄧㄣ", "iang": "ㄧㄤ", "ing": "ㄧㄥ", "iong": "ㄩㄥ", "u": "ㄨ", "ua": "ㄨㄚ",
          "uo": "ㄨㄛ", "uai": "ㄨㄞ", "ui": "ㄨㄟ", "uan": "ㄨㄢ", "un": "ㄨㄣ", "uang": "ㄨㄤ", "ong": "ㄨㄥ",
          "v": "ㄩ", "ve": "ㄩㄝ", "van": "ㄩㄢ", "vn": "ㄩㄣ"}
# y- and w- spellings, as finals without an initial.
ZERO_INITIAL = {"yi": "i", "ya": "ia", "ye": "ie", "yao": "iao", "you": "iu", "yan": "ian", "yin": "in",
                "yang": "iang", "ying": "ing", "yong": "iong", "yu": "v", "yue": "ve", "yuan": "van", "yun": "vn",
                "wu": "u", "wa": "ua", "wo": "uo", "wai": "uai", "wei": "ui", "wan": "uan", "wen": "un",
                "wang": "uang", "weng": "ong"}


def bopomofo(pinyin):
    """gcin-voice's folders for a numbered pinyin syllable, best first (tone 1 unmarked; the neutral
    tone, which gcin-voice does not record, as the first of tones 1-4 it has)."""
    tone, body = pinyin[-1], pinyin[:-1]
    body = ZERO_INITIAL.get(body, body)
    initial = next((i for i in ("zh", "ch", "sh") if body.startswith(i)), body[:1] if body[:1] in INITIALS else "")
    final = body[len(initial):]
    if initial in ("j", "q", "x") and final.startswith("u"):
        final = "v" + final[1:]
    if initial in ("zh", "ch", "sh", "r", "z", "c", "s") and final == "i":
        final = ""
    symbols = INITIALS.get(initial, "") + FINALS[final] if final else INITIALS[initial]
    if tone == "5":
        return [symbols + t for t in ("", "2", "3", "4")]
    return [symbols + ("" if tone == "1" else tone)]


def read_lines():
    lines = []
    with open(os.path.join(HERE, "corpus", "short_lines.txt"), encoding="utf-8") as corpus:
        for row in corpus:
            if row.startswith("#") or not row.strip():
                continue
            subset, text = row.rstrip("\n").split("\t")
            lines.append((subset, text, talkface.read_transcript(text)))
    return lines


def run(*command):
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def speak_espeak(pinyin, path):
    raw = path + ".raw.wav"
    run("espeak-ng", "-v", "cmn-latn-pinyin", "-s", "180", "-w", raw, " ".join(pinyin))
    # Cut to the sound, 16 kHz; a faint floor of noise, as every recording has.
    run("sox", "-R", raw, "-r", "16000", path, "silence", "1", "0.01", "0.1%", "reverse", "silence", "1", "0.01",
        "0.1%", "reverse", "dither")
    os.remove(raw)


def speak_person(pinyin, path):
    clips = []
    for syllable in pinyin:
        found = [c for c in (os.path.join(GCIN, folder, SPEAKER + ".ogg") for folder in bopomofo(syllable))
                 if os.path.exists(c)]
        if not found:
            raise FileNotFoundError(f"gcin-voice has no {syllable} ({bopomofo(syllable)[0]})")
        clips.append(found[0])
    run("sox", "-R", *clips, "-r", "16000", path, "silence", "1", "0.01", "0.5%", "reverse", "silence", "1", "0.01",
        "0.5%", "reverse", "dither")


def pad(path, padded):
    run("sox", "-R", path, padded, "pad", "0.5", "0.5", "dither")


def wrong_text(lines, k):
    subset, text, transcript = lines[k]
    count = len(transcript.syllables)
    for step in range(1, len(lines)):
        other = lines[(k + step) % len(lines)]
        if other[0] == subset and len(other[2].syllables) == count and other[1] != text:
            return other[2]
    return None


def outcome(aligner, audio, transcript):
    """(found, why): whether the check found the text wrong (refused it, or warned of it with
    CheckMode.warn) and its message, cut after the file's name."""
    try:
        timeline = aligner.align_file(audio, transcript)
    except talkface.AlignmentError as error:
        return True, str(error).split(": ", 1)[-1]
    strong = [w for w in timeline.warnings if w.startswith("the transcript may not match the audio")]
    return bool(strong), strong[0] if strong else ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--check", default="refuse", choices=["refuse", "warn"])
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    options = talkface.AlignOptions()
    options.check = talkface.CheckMode.__members__[args.check]
    aligner = talkface.SpeechAligner(options)
    lines = read_lines()
    # counts[(subset, voice)] = [right lines, refused, wrong texts, caught]
    counts = {}
    refused_lines = []
    for k, (subset, text, transcript) in enumerate(lines):
        pinyin = [s.pinyin for s in transcript.syllables]
        wrong = wrong_text(lines, k)
        for voice, speak in (("espeak", speak_espeak), ("person", speak_person)):
            bare = os.path.join(args.out, f"{voice}-{k:02d}.wav")
            speak(pinyin, bare)
            padded = os.path.join(args.out, f"{voice}-{k:02d}-padded.wav")
            pad(bare, padded)
            for audio, framing in ((bare, "bare"), (padded, "padded")):
                tally = counts.setdefault((subset, voice), [0, 0, 0, 0])
                tally[0] += 1
                refused, why = outcome(aligner, audio, transcript)
                if refused:
                    tally[1] += 1
                    refused_lines.append(f"{subset} {voice} {framing}: {text}: {why}")
                if wrong is not None:
                    tally[2] += 1
                    tally[3] += outcome(aligner, audio, wrong)[0]
    print(f"short lines, --check {args.check}: correct lines refused (warned of) | wrong texts caught")
    print(f"{'set':9} {'voice':7} {'refused':>14} {'caught':>14}")
    for (subset, voice), (right, refused, wrongs, caught) in sorted(counts.items(), key=lambda kv: (kv[0][0] != "tuning", kv[0][1])):
        print(f"{subset:9} {voice:7} {refused:>5} of {right:<5} {caught:>5} of {wrongs:<5}")
    for line in refused_lines:
        print("found wrong:", line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
