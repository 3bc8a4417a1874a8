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

# A short line that a wrong text must not pass (issue #13; bench/short_lines_bench.py's held-out
# line 好啊 as it makes it: espeak-ng at 180 words a minute, cut to its sound, 0.5 s of silence
# around it). check_mode_test aligns it with its text and with 請進 (qing3 jin4), which the third
# alignment, jin's closure after qing's ng set free, once let through.
espeak-ng -v cmn-latn-pinyin -s 180 -w wrong_short_line_raw.wav "hao3 a5"
sox -R -V1 wrong_short_line_raw.wav -r 16000 wrong_short_line_bare.wav silence 1 0.01 0.1% reverse silence 1 0.01 0.1% reverse dither
sox -R -V1 wrong_short_line_bare.wav wrong_short_line_padded.wav pad 0.5 0.5 dither
sox -R -V1 wrong_short_line_padded.wav wrong_short_line.flac
rm wrong_short_line_raw.wav wrong_short_line_bare.wav wrong_short_line_padded.wav
printf '好啊。\n' > wrong_short_line.txt

# A line cut to its sound (issues 12 and 13: a game's line as its file holds it, no silence
# around it): espeak-ng says 好, whose h starts the file; its truth moved with the cut.
"$make_corpus" --clip bare_line --rate-wpm 200 --pitch 50 "好。"
python3 - <<'PY'
import json, subprocess
truth = json.load(open("bare_line.json"))
start, end = truth["sentences"][0]["start"], truth["sentences"][0]["end"]
subprocess.run(["sox", "-R", "-V1", "bare_line.wav", "bare_line.flac", "trim", str(start), "=" + str(end)], check=True)
truth["duration"] = round(end - start, 5)
for item in truth["sentences"] + truth["syllables"]:
    item["start"], item["end"] = round(item["start"] - start, 5), round(item["end"] - start, 5)
with open("bare_line.json", "w") as out:
    json.dump(truth, out, ensure_ascii=False, indent=1)
    out.write("\n")
PY
rm bare_line.wav

# A transcript a word off (issue #13, --lenient): espeak-ng says 公园 where the transcript has
# 学校 (lenient_test.cpp also gives it the transcript without 公园).
"$make_corpus" --clip lenient_espeak --rate-wpm 190 --pitch 50 "小朋友们在公园里放风筝。"
sox -R -V1 lenient_espeak.wav lenient_espeak.flac
rm lenient_espeak.wav
printf '小朋友们在学校里放风筝。\n' > lenient_espeak.txt

# An English word no table reads between Mandarin (issue #13: generic speech): espeak-ng's `en`
# voice says "Zorblax" (cmn-latn-pinyin cannot say English) between two clips of the generator,
# whose silences at the joins are cut to 0 and 0.05 s. The truth holds the Mandarin syllables only,
# moved to where they stand in the joined clip; "word" gives where the English word lies.
"$make_corpus" --clip unknown_word_a --rate-wpm 190 --pitch 50 "我昨天用"
"$make_corpus" --clip unknown_word_b --rate-wpm 190 --pitch 50 "给妈妈打了电话。"
espeak-ng -v en -s 170 -w unknown_word_en.wav "Zorblax"
sox -R -V1 unknown_word_en.wav -r 16000 -b 16 -c 1 unknown_word_w.wav silence 1 0.005 0.5% reverse silence 1 0.005 0.5% reverse
a_end=$(python3 -c 'import json; print(json.load(open("unknown_word_a.json"))["sentences"][0]["end"])')
sox -R -V1 unknown_word_a.wav unknown_word_a_cut.wav trim 0 "$a_end"
sox -R -V1 unknown_word_b.wav unknown_word_b_cut.wav trim 0.25
sox -R -V1 unknown_word_a_cut.wav unknown_word_w.wav unknown_word_b_cut.wav unknown_word.flac
python3 - "$(soxi -D unknown_word_w.wav)" "$(soxi -D unknown_word.flac)" <<'PY'
import json, sys
word_s, duration = float(sys.argv[1]), float(sys.argv[2])
a, b = json.load(open("unknown_word_a.json")), json.load(open("unknown_word_b.json"))
a_end = a["sentences"][0]["end"]
shift = a_end + word_s - 0.25
syllables = [{"text": s["text"], "pinyin": s["pinyin"], "start": round(s["start"], 5), "end": round(s["end"], 5)}
             for s in a["syllables"]]
syllables += [{"text": s["text"], "pinyin": s["pinyin"], "start": round(s["start"] + shift, 5),
               "end": round(s["end"] + shift, 5)} for s in b["syllables"]]
truth = {"generator": "tests/data/speech/make_clips.sh: bench/make_corpus (cmn-latn-pinyin) and espeak-ng en",
         "duration": round(duration, 5), "word": {"text": "Zorblax", "start": round(a_end, 5), "end": round(a_end + word_s, 5)},
         "syllables": syllables}
with open("unknown_word.json", "w") as out:
    json.dump(truth, out, ensure_ascii=False, indent=1)
    out.write("\n")
PY
rm unknown_word_a* unknown_word_b* unknown_word_en.wav unknown_word_w.wav
printf '我昨天用Zorblax给妈妈打了电话。\n' > unknown_word.txt

# Five chat lines said fast (issues 12 and 13: a short line dense in stops inside a passage): the
# benchmark's passage fast/tuning-019 of written_forms_dev26's readings, as bench/README.md's
# session 32 (dialog) makes it, its five sentences drawn by the seed from the whole set.
bin=$(dirname "$make_corpus")
work=$(mktemp -d)
"$bin/written_forms_bench" --sentences ../../../bench/corpus/written_forms_dev26.txt --corpus-sentences "$work/dev26.txt" > /dev/null
"$make_corpus" "$work/corpus" --sentences "$work/dev26.txt" --conditions fast --repeats 3 --seed 1 > /dev/null
sox -R -V1 "$work/corpus/fast/tuning-019.wav" dialogue_fast.flac
cp "$work/corpus/fast/tuning-019.txt" dialogue_fast.txt
cp "$work/corpus/fast/tuning-019.json" dialogue_fast.json
rm -r "$work"
