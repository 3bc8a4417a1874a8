#!/usr/bin/env python3
"""Short lines and the wrong-text check (issue #13): prints, per set and kind of recording, how many
correct lines of 1-5 syllables the aligner refuses (false refusals) beside how many wrong texts it
still catches, at each --check setting.

Each line of corpus/short_lines.txt and corpus/short_lines_13.txt is spoken by espeak-ng
(cmn-latn-pinyin) and by a person: gcin-voice's speaker 3, one recording a syllable
(/usr/share/gcin-voice/ogg/<bopomofo><tone>/3.ogg; the other speaker is kept for others' measurement
and never read here), joined. Kinds of recording (--kinds):
  espeak, person        as spoken, 16 kHz (the kinds before session 13)
  voice                 the person made into another voice: pitch and formants moved together by
                        2-4 semitones up or down (sox speed, drawn per line), as align_bench's v- conditions
  voice-noise           that voice under white or pink noise at SNR 15-20 dB (drawn per line)
  voice-room            that voice in a room (sox reverb 40 50 60)
  voice-phone, person-phone, espeak-phone
                        pink noise at SNR 30 dB, then the telephone band (300-3400 Hz) at 8 kHz through
                        AMR-NB 12.2 kb/s (sox), decoded to 8 kHz WAV
Each recording is aligned bare (cut to its sound) and with 0.5 s of silence on both sides (noise,
room and phone applied after the padding), with its own text and with a wrong one: the next line of
the same file and set with as many syllables and another text.

usage: PYTHONPATH=build/python bench/short_lines_bench.py OUT_DIR [--check refuse|warn|off]
           [--kinds espeak,person,...] [--lines short_lines.txt,short_lines_13.txt]
(needs espeak-ng, sox with AMR-NB and gcin-voice: cmake/install-deps.sh bench)
"""
import argparse
import array
import math
import os
import random
import subprocess
import sys
import wave

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


def read_lines(name):
    lines = []
    with open(os.path.join(HERE, "corpus", name), encoding="utf-8") as corpus:
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


def read_wav(path):
    with wave.open(path, "rb") as audio:
        assert audio.getsampwidth() == 2 and audio.getnchannels() == 1, path
        samples = array.array("h", audio.readframes(audio.getnframes()))
        return [s / 32768.0 for s in samples], audio.getframerate()


def write_wav(path, samples, rate):
    data = array.array("h", (max(-32768, min(32767, round(s * 32768.0))) for s in samples))
    with wave.open(path, "wb") as audio:
        audio.setnchannels(1)
        audio.setsampwidth(2)
        audio.setframerate(rate)
        audio.writeframes(data.tobytes())


def make_noise(count, colour, rng):
    """Gaussian white noise, or pink by Paul Kellet's filter (as bench/corpus_tools.cpp makes it)."""
    noise = []
    b0 = b1 = b2 = 0.0
    for _ in range(count):
        white = rng.gauss(0.0, 1.0)
        if colour == "pink":
            b0 = 0.99765 * b0 + white * 0.0990460
            b1 = 0.96300 * b1 + white * 0.2965164
            b2 = 0.57000 * b2 + white * 1.0526913
            white = b0 + b1 + b2 + white * 0.1848
        noise.append(white)
    return noise


def add_noise(path, speech_power, colour, snr_db, rng):
    """Noise over the whole file at `snr_db` below `speech_power` (the bare line's mean square)."""
    samples, rate = read_wav(path)
    noise = make_noise(len(samples), colour, rng)
    noise_power = sum(n * n for n in noise) / len(noise)
    gain = math.sqrt(speech_power / (noise_power * 10 ** (snr_db / 10)))
    write_wav(path, [s + gain * n for s, n in zip(samples, noise)], rate)


def mean_square(path):
    samples, _ = read_wav(path)
    return sum(s * s for s in samples) / max(len(samples), 1)


def moved_voice(path, out, rng):
    """speaker 3 made into another voice: pitch and formants moved together by 2-4 semitones, up or
    down (align_bench's v- conditions, bench/make_human_corpus.cpp with_voice). Returns the factor it
    is played faster by: every time in it is that many times earlier."""
    semitones = rng.uniform(2.0, 4.0) * rng.choice((-1, 1))
    factor = float(f"{2 ** (semitones / 12):.6f}")
    run("sox", "-R", path, "-b", "16", out, "speed", f"{factor:.6f}", "rate", "-v", "16k")
    return factor


def in_room(path):
    moved = path + ".room.wav"
    run("sox", "-R", path, "-b", "16", moved, "reverb", "40", "50", "60", "gain", "-n", "-3")
    os.replace(moved, path)


def over_phone(path, speech_power, rng):
    """Pink noise at SNR 30 dB, the telephone band at 8 kHz, AMR-NB 12.2 kb/s as sox writes it
    (comfort noise and empty frames in the pauses), decoded to 8 kHz WAV."""
    add_noise(path, speech_power, "pink", 30.0, rng)
    coded = path + ".amr"
    run("sox", "-R", path, "-r", "8000", "-c", "1", "-C", "7", "-t", "amr-nb", coded, "sinc", "300-3400", "rate", "-v",
        "8k")
    run("sox", "-R", "-t", "amr-nb", coded, "-b", "16", path)
    os.remove(coded)


VOICES = {"espeak": speak_espeak, "person": speak_person}
# kind: (voice, condition)
KINDS = {"espeak": ("espeak", None), "person": ("person", None), "voice": ("voice", None),
         "voice-noise": ("voice", "noise"), "voice-room": ("voice", "room"), "voice-phone": ("voice", "phone"),
         "person-phone": ("person", "phone"), "espeak-phone": ("espeak", "phone")}


# The spoken recordings this run has made.
MADE = set()


def record(kind, pinyin, stem, seed):
    """The bare and the padded recording of a line of `kind`, as paths. `seed` names the line: its
    voice, noise and SNR are drawn from streams seeded by it and the kind, so a line sounds the same
    whatever other kinds are asked for."""
    voice = KINDS[kind][0]
    speaker = "person" if voice == "voice" else voice
    source = f"{stem}-{speaker}.wav"
    # Made once a run: a file left in OUT_DIR by an earlier run may hold another line.
    if source not in MADE:
        VOICES[speaker](pinyin, source)
        MADE.add(source)
    spoken = source
    if voice == "voice":
        spoken = f"{stem}-voice.wav"
        if spoken not in MADE:
            moved_voice(source, spoken, random.Random(f"{seed}:voice"))
            MADE.add(spoken)
    bare, padded = f"{stem}-{kind}.wav", f"{stem}-{kind}-padded.wav"
    if spoken != bare:
        run("sox", "-R", spoken, bare)
    pad(bare, padded)
    apply_condition(kind, bare, padded, mean_square(spoken), seed)
    return bare, padded


def apply_condition(kind, bare, padded, power, seed):
    """`kind`'s noise, room or phone on the bare and the padded recording of line `seed`, in place;
    `power` is the spoken line's mean square (the noise's SNR is set against it)."""
    condition = KINDS[kind][1]
    if condition is None:
        return
    draw = random.Random(f"{seed}:{kind}")
    colour, snr_db = draw.choice(("white", "pink")), draw.uniform(15.0, 20.0)
    for path, framing in ((bare, "bare"), (padded, "padded")):
        noise_rng = random.Random(f"{seed}:{kind}:{framing}")
        if condition == "noise":
            add_noise(path, power, colour, snr_db, noise_rng)
        elif condition == "room":
            in_room(path)
        else:
            over_phone(path, power, noise_rng)


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
    parser.add_argument("--check", default="refuse", choices=["refuse", "warn", "off"])
    parser.add_argument("--kinds", default=",".join(KINDS), help="comma-separated, of: " + ", ".join(KINDS))
    parser.add_argument("--lines", default="short_lines.txt,short_lines_13.txt", help="files of bench/corpus")
    parser.add_argument("--framings", default="bare,padded")
    args = parser.parse_args()
    kinds = args.kinds.split(",")
    for kind in kinds:
        if kind not in KINDS:
            parser.error(f"--kinds: no kind {kind!r}; kinds: {', '.join(KINDS)}")
    framings = args.framings.split(",")
    os.makedirs(args.out, exist_ok=True)
    options = talkface.AlignOptions()
    options.check = talkface.CheckMode.__members__[args.check]
    aligner = talkface.SpeechAligner(options)
    # counts[(subset, kind)] = [right lines, refused, wrong texts, caught]
    counts = {}
    refused_lines, caught_lines = [], []
    for file_index, name in enumerate(args.lines.split(",")):
        lines = read_lines(name)
        for k, (subset, text, transcript) in enumerate(lines):
            pinyin = [s.pinyin for s in transcript.syllables]
            wrong = wrong_text(lines, k)
            # The first file keeps the stems (and so the recordings) it had before session 13.
            stem = os.path.join(args.out, f"{file_index}-{k:02d}")
            for kind in kinds:
                bare, padded = record(kind, pinyin, stem, 1000 * file_index + k)
                for audio, framing in ((bare, "bare"), (padded, "padded")):
                    if framing not in framings:
                        continue
                    tally = counts.setdefault((subset, kind), [0, 0, 0, 0])
                    tally[0] += 1
                    refused, why = outcome(aligner, audio, transcript)
                    if refused:
                        tally[1] += 1
                        refused_lines.append(f"{subset} {kind} {framing}: {text}: {why}")
                    if wrong is not None:
                        tally[2] += 1
                        found, why = outcome(aligner, audio, wrong)
                        tally[3] += found
                        if found:
                            caught_lines.append(f"{subset} {kind} {framing}: {text} as {wrong.sentences[0].text}: {why}")
    print(f"short lines, --check {args.check}: correct lines refused (warned of) | wrong texts caught")
    print(f"{'set':9} {'kind':13} {'refused':>14} {'caught':>14}")
    for subset in ("tuning", "held-out"):
        total = [0, 0, 0, 0]
        for kind in kinds:
            right, refused, wrongs, caught = counts.get((subset, kind), [0, 0, 0, 0])
            total = [a + b for a, b in zip(total, (right, refused, wrongs, caught))]
            print(f"{subset:9} {kind:13} {refused:>5} of {right:<5} {caught:>5} of {wrongs:<5}")
        print(f"{subset:9} {'all':13} {total[1]:>5} of {total[0]:<5} {total[3]:>5} of {total[2]:<5}")
    for line in refused_lines:
        print("found wrong:", line)
    for line in caught_lines:
        print("caught:", line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
