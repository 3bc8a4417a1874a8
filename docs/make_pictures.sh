#!/bin/sh
# Regenerates the pictures in docs/ from a build directory (samples and the talkface command built):
#   docs/make_pictures.sh BUILD_DIR
# Each SVG is screenshot by headless Chromium at the SVG's own size.
set -eu
build_dir=$(cd "${1:?usage: docs/make_pictures.sh BUILD_DIR}" && pwd)
docs_dir=$(cd "$(dirname "$0")" && pwd)
source_dir=$(dirname "$docs_dir")
work_dir=$(mktemp -d)
trap 'rm -rf "$work_dir"' EXIT

# screenshot SVG PNG: the window is the root element's width x height
screenshot() {
    size=$(sed -n 's/^<svg [^>]*width="\([0-9.]*\)" height="\([0-9.]*\)".*/\1 \2/p' "$1" | head -n 1)
    width=$(echo "$size" | awk '{ printf "%d", $1 + 0.999 }')
    height=$(echo "$size" | awk '{ printf "%d", $2 + 0.999 }')
    profile=$(mktemp -d "$work_dir/profile.XXXXXX")
    chromium --headless --no-sandbox --disable-gpu --disable-background-networking \
        --disable-component-update --disable-sync --no-first-run --user-data-dir="$profile" \
        --screenshot="$2" --window-size="$width,$height" "file://$1" >/dev/null 2>&1
    echo "wrote $2 (${width}x${height})"
}

"$build_dir/bin/talkface" render -o "$work_dir/face.svg"
screenshot "$work_dir/face.svg" "$docs_dir/face.png"
"$build_dir/bin/talkface" render --look flat -o "$work_dir/face-flat.svg"
screenshot "$work_dir/face-flat.svg" "$docs_dir/face-flat.png"

"$build_dir/samples/pose_sheet/pose_sheet" "$work_dir/contact-sheet.svg"
screenshot "$work_dir/contact-sheet.svg" "$docs_dir/contact-sheet.png"

if [ -f "$source_dir/samples/faces/female.xml" ]; then
    "$build_dir/samples/pose_sheet/pose_sheet" "$work_dir/contact-sheet-female.svg" \
        "$source_dir/samples/faces/female.xml"
    screenshot "$work_dir/contact-sheet-female.svg" "$docs_dir/contact-sheet-female.png"
    "$build_dir/samples/pose_sheet/pose_sheet" "$work_dir/contact-sheet-female-flat.svg" \
        "$source_dir/samples/faces/female.xml" flat
    screenshot "$work_dir/contact-sheet-female-flat.svg" "$docs_dir/contact-sheet-female-flat.png"
fi
"$build_dir/samples/pose_sheet/pose_sheet" "$work_dir/contact-sheet-flat.svg" default flat
screenshot "$work_dir/contact-sheet-flat.svg" "$docs_dir/contact-sheet-flat.png"

"$build_dir/samples/mouth_shapes/mouth_shapes" "$work_dir/mouth-shapes.svg"
screenshot "$work_dir/mouth-shapes.svg" "$docs_dir/mouth-shapes.png"

# The words as pinyin (the sample's default is 願望 and 波濤): a headless machine may have no CJK font.
"$build_dir/samples/syllable_strip/syllable_strip" "$work_dir/syllable-strip.svg" "yuan4 wang4" "bo1 tao1"
screenshot "$work_dir/syllable-strip.svg" "$docs_dir/syllable-strip.png"

# The pages (issue 17), seeked into the second sentence of the demo speech and screenshot: the
# announcer's frame, and the audio book at a phone's and a desktop's size.
speech_dir="$source_dir/samples/speech"
seek=$("$build_dir/bin/talkface" align "$speech_dir/demo.ogg" "$speech_dir/demo.txt" --json -q |
    python3 -c 'import json, sys; s = json.load(sys.stdin)["sentences"][1]; print("%.3f" % (s["start"] + 0.45 * (s["end"] - s["start"])))')
"$build_dir/bin/talkface" demo -q --app announcer --title "晚間新聞" -o "$work_dir/announcer.html"
"$build_dir/bin/talkface" demo -q --app audiobook --title "會說話的卡通臉" -o "$work_dir/audiobook.html"
# page_screenshot HTML PNG WIDTH HEIGHT [CHROMIUM_FLAG]
page_screenshot() {
    profile=$(mktemp -d "$work_dir/profile.XXXXXX")
    chromium --headless --no-sandbox --disable-gpu --disable-background-networking \
        --disable-component-update --disable-sync --no-first-run --mute-audio --hide-scrollbars \
        --user-data-dir="$profile" --virtual-time-budget=4000 --screenshot="$2" --window-size="$3,$4" \
        ${5:+"$5"} "file://$1#t=$seek&pause" >/dev/null 2>&1
    echo "wrote $2 ($3x$4)"
}
# A phone's only pointer is a finger (Blink's pointer type 2 is coarse, hover type 1 none): the page
# shows it as on a phone, without the keys hint a desktop gets.
phone_pointer="--blink-settings=primaryPointerType=2,availablePointerTypes=2,primaryHoverType=1,availableHoverTypes=1"
page_screenshot "$work_dir/announcer.html" "$docs_dir/announcer.png" 832 482
page_screenshot "$work_dir/audiobook.html" "$docs_dir/audiobook-phone.png" 390 844 "$phone_pointer"
page_screenshot "$work_dir/audiobook.html" "$docs_dir/audiobook-desktop.png" 1280 800
