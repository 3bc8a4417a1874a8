#!/bin/sh
# Installs the Debian 12 packages talkface builds and tests with, only those that are missing.
# Run as root (or through sudo). Every package here is from Debian main; licences are listed in
# README.md ("Dependencies and licences").
#
# usage: cmake/install-deps.sh [build|test|bench]
#   build  what the library, the command and the Python module need (default)
#   test   that, plus what the tests drive: pytest, Pillow, headless Chromium, a venv for pip
#   bench  that, plus what bench/ needs: espeak-ng (corpus), sox (conditions), GNU time (memory), praat (another person's voice, make_human_corpus w-)
set -eu

build_packages="build-essential cmake pkg-config git libeigen3-dev libpugixml-dev libcli11-dev
nlohmann-json3-dev doctest-dev pybind11-dev python3-dev python3-numpy libsndfile1-dev libsamplerate0-dev
libopencv-dev opencv-data libpng-dev libjpeg-dev libdlib-dev libblas-dev liblapack-dev zlib1g-dev libdeflate-dev
libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libswresample-dev libavfilter-dev libcairo2-dev"
# libcairo2-dev: the raster renderer (FrameRenderer) draws frames with cairo.
# libavformat-dev, libavcodec-dev, libswresample-dev and libavutil-dev also decode the recordings
# libsndfile does not read (MP3, AAC/M4A, Opus, a video's sound track: src/audio/).
# libpng-dev and libjpeg-dev read photo files (face from a photo). libdlib-dev's CMake package also
# links libblas.so, liblapack.so, libjpeg.so and libz.so by path, and does not depend on the -dev
# packages that provide them.
# zlib1g-dev keeps an animated GIF's frames deflated (src/video/); libdeflate-dev packs the pages'
# animation (gzip, src/apps/), 13% smaller than zlib's best level.
# libav*-dev and libsw*-dev encode videos and the pages' compressed audio (src/video/); Debian's
# libavcodec59 brings libx264, libvpx, libopus and libwebp with it; libavfilter-dev's palettegen and
# paletteuse make an animated GIF's palette.
# libdlib-data is dlib's 95 MB landmark model: only the dlib photo locator reads it, at run time.
# python3-skimage and python-matplotlib-data ship the real test photos (astronaut.png,
# grace_hopper.jpg). fonts-noto-cjk gives the browser tests and the screenshots in docs/ real
# Chinese characters (the pages name it among each system's CJK fonts).
# praat reads the exported TextGrids and ffmpeg's ffprobe the exported subtitles, as the programs
# their users open them with (issue #15). gcin-voice holds every Mandarin syllable as a person
# recorded it: its speaker 3 is the aligner's human test voice (tests/speech/human_speech_test.cpp,
# bench/make_human_corpus).
# python3-dask and python3-distributed run the batch jobs (talkface.batch, `python3 -m talkface batch`)
# and start the real scheduler and workers of its test.
# The Lottie export is played by the players its users have: librlottie-dev (rlottie, Telegram's and
# many Android apps' player; tests/render/lottie_player_test.cpp) and lottie-web, which is not in
# Debian: npm installs it into ~/.cache/talkface/npm for tests/apps/test_browser_lottie.py (Debian's
# nodejs and npm where no npm is on the PATH: a Node.js from elsewhere brings its own).
test_packages="python3-pil python3-pytest python3-venv python3-pip python3-setuptools chromium fonts-dejavu-core
python3-skimage python-matplotlib-data librsvg2-bin libdlib-data fonts-noto-cjk praat ffmpeg gcin-voice
python3-dask python3-distributed librlottie-dev"
lottie_web_version="5.13.0"
npm_prefix="${HOME}/.cache/talkface/npm"
bench_packages="espeak-ng libespeak-ng-dev sox libsox-fmt-all time praat"

case "${1:-build}" in
  build) wanted=$build_packages ;;
  test) wanted="$build_packages $test_packages" ;;
  bench) wanted="$build_packages $test_packages $bench_packages" ;;
  *) echo "usage: $0 [build|test|bench]" >&2; exit 2 ;;
esac

if [ "${1:-build}" != build ] && ! command -v npm >/dev/null; then
  wanted="$wanted nodejs npm"
fi

missing=""
for package in $wanted; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" || missing="$missing $package"
done

# lottie-web from the npm registry, pinned, for the user who runs the tests (no root needed).
install_lottie_web() {
  [ "${1:-build}" = build ] && return 0
  [ -f "$npm_prefix/node_modules/lottie-web/build/player/lottie.min.js" ] && return 0
  command -v npm >/dev/null || return 0  # the packages above bring it; a second run installs lottie-web
  mkdir -p "$npm_prefix"
  echo "talkface: installing lottie-web $lottie_web_version into $npm_prefix" >&2
  npm install --no-audit --no-fund --prefix "$npm_prefix" "lottie-web@$lottie_web_version" >/dev/null
}

if [ -z "$missing" ]; then
  install_lottie_web "${1:-build}"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "talkface: these Debian packages are missing:$missing" >&2
  echo "talkface: run this script as root (sudo $0 ${1:-build}) to install them" >&2
  exit 1
fi
echo "talkface: installing$missing" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# shellcheck disable=SC2086 # the list is meant to split into words
apt-get install -y -qq --no-install-recommends $missing >/dev/null
install_lottie_web "${1:-build}"
