#!/bin/sh
# Remakes demo.ogg, the speech `talkface demo` animates, from the pinyin of demo.txt (the
# transcript as `talkface syllables demo.txt` reads it), with espeak-ng's Mandarin voice.
set -eu
cd "$(dirname "$0")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# One espeak-ng word per syllable; commas and full stops where the transcript pauses.
espeak-ng -v cmn-latn-pinyin -s 190 -p 55 -w "$tmp/speech.wav" \
  "da4 jia1 hao3, wo3 shi4 hui4 shuo1 hua4 de5 ka3 tong1 lian3. \
jin1 tian1 tian1 qi4 hen3 hao3, wo3 men5 yi1 qi3 qu4 gong1 yuan2 san4 bu4 ba5. \
qing3 ni3 da3 kai1 shu1, gen1 wo3 yi1 qi3 da4 sheng1 lang3 du2."
# Half a second of silence before and after, 22.05 kHz mono Ogg Vorbis; -R keeps it reproducible.
sox -R "$tmp/speech.wav" -C 3 demo.ogg pad 0.5 0.5
