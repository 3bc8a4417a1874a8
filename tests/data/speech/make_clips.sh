#!/bin/sh
# Remakes the aligner's test clips with the benchmark's generator (bench/README.md):
#   tests/data/speech/make_clips.sh build-bench/bin/make_corpus
# Needs espeak-ng and sox with libsox-fmt-all. The output is the same on every run.
set -eu
make_corpus=$(realpath "$1")
cd "$(dirname "$0")"

"$make_corpus" --clip one_sentence --rate-wpm 200 --pitch 50 "小朋友們在公園裡放風箏。"
"$make_corpus" --clip two_sentences --rate-wpm 190 --pitch 45 --pause-s 0.9 "今天下午有雨。我们明天再去吧。"

# Three sentences with no pause between them: only the commas inside them pause.
"$make_corpus" --clip run_together --rate-wpm 190 --pitch 50 --pause-s 0 "他每天早上跑步，锻炼身体。我们都觉得他的脸色很好。明天，他要去北京开会。"
sox -R -V1 run_together.wav run_together.flac
rm run_together.wav

"$make_corpus" --clip comma_pause --rate-wpm 210 --pitch 55 "请把桌子上的杯子拿给我，谢谢。"
sox -R -V1 comma_pause.wav comma_pause.flac
rm comma_pause.wav

"$make_corpus" --clip stereo_44k --rate-wpm 180 --pitch 60 "這條路晚上很安靜。"
sox -R -V1 stereo_44k.wav -C 4 stereo_44k.ogg remix 1 1v0.8 rate -v 44100
rm stereo_44k.wav

# A short line spoken by a person (issue #13): gcin-voice's speaker 3 (never speaker 5), one
# recording a syllable, joined, with 0.3 s of silence around it. Needs gcin-voice.
gcin=/usr/share/gcin-voice/ogg
sox -R -V1 "$gcin/ㄋㄧ3/3.ogg" "$gcin/ㄏㄠ3/3.ogg" -r 16000 -b 16 short_line.flac silence 1 0.01 0.5% reverse silence 1 0.01 0.5% reverse pad 0.3 0.3
printf '你好。\n' > short_line.txt

# A transcript a word off (issue #13, --lenient): espeak-ng says 公园 where the transcript has
# 学校 (lenient_test.cpp also gives it the transcript without 公园).
"$make_corpus" --clip lenient_espeak --rate-wpm 190 --pitch 50 "小朋友们在公园里放风筝。"
sox -R -V1 lenient_espeak.wav lenient_espeak.flac
rm lenient_espeak.wav
printf '小朋友们在学校里放风筝。\n' > lenient_espeak.txt
