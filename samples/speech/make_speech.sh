#!/bin/sh
# Remakes demo.ogg, the speech `talkface demo` animates, from the pinyin of demo.txt (the
# transcript as `talkface syllables demo.txt` reads it), with espeak-ng's Mandarin voice.
set -eu
cd "$(dirname "$0")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# One espeak-ng word per syllable, a comma where the transcript pauses inside a sentence. Each
# sentence is spoken on its own and followed by 0.45 s of silence, as a reader pauses between
# sentences: the voice makes no pause at a full stop after a tone digit ("lian3." reads as a number).
n=0
for sentence in \
  "da4 jia1 hao3, wo3 shi4 hui4 shuo1 hua4 de5 ka3 tong1 lian3" \
  "jin1 tian1 tian1 qi4 hen3 hao3, wo3 men5 yi1 qi3 qu4 gong1 yuan2 san4 bu4 ba5" \
  "qing3 ni3 da3 kai1 shu1, gen1 wo3 yi1 qi3 da4 sheng1 lang3 du2"; do
  n=$((n + 1))
  espeak-ng -v cmn-latn-pinyin -s 190 -p 55 -w "$tmp/$n.wav" "$sentence"
  sox -R "$tmp/$n.wav" "$tmp/$n-paused.wav" pad 0 0.45
done
# Half a second of silence before and after, 22.05 kHz mono Ogg Vorbis; -R keeps it reproducible.
sox -R "$tmp/1-paused.wav" "$tmp/2-paused.wav" "$tmp/3.wav" -C 3 demo.ogg pad 0.5 0.5
