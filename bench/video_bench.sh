#!/bin/sh
# issue #16's video benchmark: a 3-minute speech made into a 1280x720, 30 fps MP4 by `talkface video`,
# the whole process (alignment, drawing, encoding) on one core, beside the naive route (an SVG per
# frame, rsvg-convert, ffmpeg; bench/naive_video.py, sampled) measured in the same run. Prints
# seconds (wall and CPU), real-time factor, peak memory and MB per minute.
#
# usage: bench/video_bench.sh SPEECH TRANSCRIPT BUILD_DIR [CORE]
#   SPEECH, TRANSCRIPT  about 3 minutes: pipeline_bench's joined passages (CORPUS/pipeline/speech.wav
#                       and speech.txt), or the demo said 14 times (bench/README.md, "Video")
#   BUILD_DIR           a build with the command and the Python module (build/bin/talkface, build/python)
#   CORE                the CPU to pin both routes to (default 0)
# On a machine shared with other builds the wall times are low estimates; the CPU times are the
# fairer figure there.
set -eu
speech=$1
transcript=$2
build=$3
core=${4:-0}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
speech_s=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$speech")

taskset -c "$core" /usr/bin/time -f "%e %U %S %M" -o "$out/time" \
  "$build/bin/talkface" video "$speech" "$transcript" -o "$out/talk.mp4" -q
read -r wall user sys peak_kb < "$out/time"
bytes=$(stat -c %s "$out/talk.mp4")
video_s=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$out/talk.mp4")
awk -v s="$speech_s" -v v="$video_s" -v w="$wall" -v u="$user" -v y="$sys" -v m="$peak_kb" -v b="$bytes" 'BEGIN {
  cpu = u + y
  printf "talkface video: speech %.1f s, video %.3f s; wall %.1f s (%.1fx real time), cpu %.1f s (%.1fx), peak %.0f MB, %.2f MB a minute\n",
         s, v, w, s / w, cpu, s / cpu, m / 1024, b / 1e6 / (s / 60) }'

PYTHONPATH="$build/python" taskset -c "$core" /usr/bin/python3 "$(dirname "$0")/naive_video.py" \
  "$speech" "$transcript" "$out/naive" --step 20 | tee "$out/naive.txt" | head -1
sed -n 's/^naive_total_wall_s=\([0-9.]*\) naive_total_cpu_s=\([0-9.]*\)$/\1 \2/p' "$out/naive.txt" | {
  read -r naive_wall naive_cpu
  awk -v s="$speech_s" -v w="$naive_wall" -v c="$naive_cpu" 'BEGIN {
    printf "naive route (extrapolated): wall %.0f s (%.2fx real time), cpu %.0f s (%.2fx)\n", w, s / w, c, s / c }'
}
