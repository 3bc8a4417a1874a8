#!/bin/sh
# Peak memory of the aligner on an hour of speech (issue #4: under 200 MB): joins the clean
# passages of a corpus made by make_corpus, over and over, into one long WAV and transcript, and
# aligns it twice under /usr/bin/time -v: with the transcript as written, and with every
# punctuation mark taken out (one sentence of an hour, no pause marked). Both print how close the
# onsets come to the truth.
#
#   bench/memory_bench.sh CORPUS BUILD/bin/align_bench [MINUTES]   (MINUTES defaults to 60)
set -eu
corpus=$1
align_bench=$2
minutes=${3:-60}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

set --
: > "$work/long.txt"
: > "$work/truth.txt"
samples=0
rate=16000
while [ "$samples" -lt $((minutes * 60 * rate)) ]; do
    for wav in "$corpus"/clean/*.wav; do
        set -- "$@" "$wav"
        cat "${wav%.wav}.txt" >> "$work/long.txt"
        # Where this passage starts in the joined audio, counted in samples so that nothing drifts.
        awk -v n="$samples" -v r="$rate" -v f="${wav%.wav}.json" 'BEGIN { printf "%.6f\t%s\n", n / r, f }' >> "$work/truth.txt"
        samples=$((samples + $(soxi -s "$wav")))
        [ "$samples" -ge $((minutes * 60 * rate)) ] && break
    done
done
sox -V1 "$@" "$work/long.wav"
# Literal replacements, one mark at a time: a bracket expression would match single bytes of
# other characters' UTF-8.
sed -e 's/。//g' -e 's/，//g' -e 's/、//g' -e 's/：//g' -e 's/；//g' -e 's/？//g' -e 's/！//g' \
    -e 's/[.,;:?!]//g' "$work/long.txt" > "$work/bare.txt"
echo "$# passages, $(soxi -d "$work/long.wav") of 16 kHz mono speech, $(du -m "$work/long.wav" | cut -f1) MB of WAV"

for transcript in long bare; do
    [ "$transcript" = long ] && echo "transcript as written:" || echo "transcript without punctuation:"
    /usr/bin/time -v "$align_bench" --file "$work/long.wav" "$work/$transcript.txt" --truth "$work/truth.txt" \
        2> "$work/time.txt" || { cat "$work/time.txt"; exit 1; }
    peak_kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
    grep -E "Elapsed|User time" "$work/time.txt"
    awk -v kb="$peak_kb" 'BEGIN { mb = kb / 1024; printf "peak RSS %.0f MB (target < 200 MB: %s)\n", mb, mb < 200 ? "met" : "NOT MET" }'
done
