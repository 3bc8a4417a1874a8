#!/bin/sh
# Remakes the recordings of tests/audio/ (issue #13) from tests/data/speech/one_sentence.wav (espeak-ng,
# 3.2 s): each a format people have, at a low bit rate to stay small. Needs sox and ffmpeg.
#   sox_22050.mp3, sox_44100.mp3  sox's MP3s (no LAME tag): libsndfile called them truncated
#   ffmpeg_16000.mp3, ffmpeg_48000.mp3  MP3 at the other common rates, with a LAME tag
#   phone.m4a                      AAC-LC in MP4 at 48 kHz mono, as phones record
#   voice.opus                     Opus in Ogg
#   clip.mp4, clip.mov             H.264 + AAC; clip.mkv, clip.webm VP8 + Opus (a 16x16 picture)
#   no_sound.mp4                   a video without a sound track
#   two_tracks.mkv                 two Opus sound tracks, the first silent (a screen recorder's)
#   subtitle_only.mkv              a subtitle track and no sound
#   voice.3gp                      AAC-LC in 3GP at 16 kHz, as older phones record
set -eu
here=$(cd "$(dirname "$0")" && pwd)
speech="$here/../speech/one_sentence.wav"
ff="ffmpeg -nostdin -loglevel error -y -bitexact"
video="-f lavfi -i color=c=gray:s=16x16:r=2:d=3.3"
sox "$speech" -C 32 -r 22050 "$here/sox_22050.mp3"
sox "$speech" -C 32 -r 44100 "$here/sox_44100.mp3"
$ff -i "$speech" -ar 16000 -b:a 24k "$here/ffmpeg_16000.mp3"
$ff -i "$speech" -ar 48000 -b:a 32k "$here/ffmpeg_48000.mp3"
$ff -i "$speech" -ar 48000 -ac 1 -c:a aac -b:a 24k "$here/phone.m4a"
$ff -i "$speech" -c:a libopus -b:a 16k "$here/voice.opus"
$ff $video -i "$speech" -shortest -c:v libx264 -crf 40 -c:a aac -b:a 24k "$here/clip.mp4"
$ff $video -i "$speech" -shortest -c:v libx264 -crf 40 -c:a aac -b:a 24k "$here/clip.mov"
$ff $video -i "$speech" -shortest -c:v libvpx -b:v 8k -c:a libopus -b:a 16k "$here/clip.mkv"
$ff $video -i "$speech" -shortest -c:v libvpx -b:v 8k -c:a libopus -b:a 16k "$here/clip.webm"
$ff $video -c:v libx264 -crf 40 "$here/no_sound.mp4"
$ff -f lavfi -i anullsrc=r=48000:cl=mono -i "$speech" -t 3.3 -map 0:a -map 1:a -c:a libopus -b:a 16k "$here/two_tracks.mkv"
printf '1\n00:00:00,000 --> 00:00:03,000\n小朋友們在公園裡放風箏。\n' > "$here/subtitle.srt"
$ff -i "$here/subtitle.srt" -c:s srt "$here/subtitle_only.mkv"
rm "$here/subtitle.srt"
$ff -i "$speech" -ar 16000 -ac 1 -c:a aac -b:a 16k "$here/voice.3gp"
