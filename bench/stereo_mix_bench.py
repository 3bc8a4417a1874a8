#!/usr/bin/env python3
"""Stereo as recorders leave it, mixed by ChannelMixer (src/audio/audio_source.cpp) and aligned.

    PYTHONPATH=build/python python3 bench/stereo_mix_bench.py /work/corpus/espeak/clean/tuning-001

Makes two channels from a corpus passage (STEM.wav, .txt, .json: 16-bit mono) in memory: the same,
one side's polarity inverted (alone, with that side 10 dB quieter or the other, or 0.5, 2 or 10 ms
late), one side 2.5 ms late and not inverted, the voice in one side and held notes in the other,
music over the inverted side, hiss in one side (and the mono averages a mixer cannot beat by sign), and aligns each through the caller's-samples path
(the mixer every reader uses). Prints % of onsets within 50 and 100 ms of the truth, or the refusal.
"""
import json
import sys
import wave

import numpy

import talkface


def main():
    stem = sys.argv[1]
    with wave.open(stem + ".wav", "rb") as file:
        assert file.getsampwidth() == 2 and file.getnchannels() == 1
        voice = numpy.frombuffer(file.readframes(file.getnframes()), "<i2").astype(numpy.float32) / 32768
        rate_hz = file.getframerate()
    truth = json.load(open(stem + ".json"))["syllables"]
    transcript = talkface.load_transcript(stem + ".txt")

    def late(samples, ms):
        n = int(round(rate_hz * ms / 1000))
        return numpy.concatenate([numpy.zeros(n, numpy.float32), samples[:len(samples) - n]])

    t = numpy.arange(len(voice)) / rate_hz
    # Held notes changing every 0.5 s, peaks near the voice's: music a voice is mixed with.
    notes = numpy.array([220, 277, 330, 392, 440, 523])[(t // 0.5).astype(int) % 6]
    music = (0.25 * numpy.sin(2 * numpy.pi * notes * t) + 0.15 * numpy.sin(3 * numpy.pi * notes * t)).astype(numpy.float32)
    hiss = (0.01 * numpy.random.default_rng(1).standard_normal(len(voice))).astype(numpy.float32)
    cases = {
        "mono": voice,
        "the same in both": numpy.stack([voice, voice], 1),
        "right inverted": numpy.stack([voice, -voice], 1),
        "right inverted, 10 dB quieter": numpy.stack([voice, -0.316 * voice], 1),
        "right inverted, left 10 dB quieter": numpy.stack([0.316 * voice, -voice], 1),
        "right inverted, 0.5 ms late": numpy.stack([voice, -late(voice, 0.5)], 1),
        "right inverted, 2 ms late": numpy.stack([voice, -late(voice, 2)], 1),
        "right inverted, 10 ms late": numpy.stack([voice, -late(voice, 10)], 1),
        "right 2.5 ms late, not inverted": numpy.stack([voice, late(voice, 2.5)], 1),
        "voice left, music right": numpy.stack([voice, music], 1),
        "mono: voice and music averaged": (voice + music) / 2,
        "music left, voice right": numpy.stack([music, voice], 1),
        "right inverted, music over it": numpy.stack([voice, -voice + music], 1),
        "left voice and hiss, right inverted": numpy.stack([voice + hiss, -voice], 1),
        "left hiss only, voice right": numpy.stack([hiss, voice], 1),
        "mono: voice and hiss averaged": (voice + hiss) / 2,
    }
    for name, samples in cases.items():
        try:
            aligned = talkface.SpeechAligner().align(numpy.ascontiguousarray(samples), rate_hz, transcript)
            errors = numpy.array([abs(a.start_s - b["start"]) for a, b in zip(aligned.syllables, truth)])
            print(f"{name:38} {100 * numpy.mean(errors <= 0.05):5.1f} {100 * numpy.mean(errors <= 0.1):5.1f}")
        except talkface.Error as error:
            print(f"{name:38} refused: {str(error)[:90]}")


if __name__ == "__main__":
    main()
