#!/bin/sh
# Peak memory of the aligner on an hour of speech (issue #4: under 200 MB): joins the clean
# passages of a corpus made by make_corpus, over and over, into one long WAV and transcript, and
# aligns them once under /usr/bin/time -v.
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
seconds=0
while [ "$seconds" -lt $((minutes * 60)) ]; do
    for wav in "$corpus"/clean/*.wav; do
        set -- "$@" "$wav"
        cat "${wav%.wav}.txt" >> "$work/long.txt"
        seconds=$(awk -v s="$seconds" -v d="$(soxi -D "$wav")" 'BEGIN { printf "%d", s + d }')
        [ "$seconds" -ge $((minutes * 60)) ] && break
    done
done
sox -V1 "$@" "$work/long.wav"
echo "$# passages, $(soxi -d "$work/long.wav") of 16 kHz mono speech, $(du -m "$work/long.wav" | cut -f1) MB of WAV"

/usr/bin/time -v "$align_bench" --file "$work/long.wav" "$work/long.txt" 2> "$work/time.txt"
peak_kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
grep -E "Elapsed|User time" "$work/time.txt"
awk -v kb="$peak_kb" 'BEGIN { mb = kb / 1024; printf "peak RSS %.0f MB (target < 200 MB: %s)\n", mb, mb < 200 ? "met" : "NOT MET" }'
