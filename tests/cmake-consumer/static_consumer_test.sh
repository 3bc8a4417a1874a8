#!/bin/sh
# A static libtalkface (BUILD_SHARED_LIBS=OFF), installed into a fresh prefix and linked into the C
# consumer as a user's project would (find_package; the package's static branch finds what
# libtalkface.a needs), opens FFmpeg's module for a video frame (src/audio/ffmpeg_module.cpp). The
# program is the file holding libtalkface's code, so the module is looked for in talkface/ beside
# the program, then at the path the build compiled in (LIBDIR/talkface/ under its
# CMAKE_INSTALL_PREFIX), which `cmake --install --prefix` elsewhere cannot move. Checked: beside the
# program it is found; without it, found at the compiled-in path if the module is there, else the
# call fails naming both places.
# usage: static_consumer_test.sh BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR CONFIGURED_MODULE   (WORK_DIR is emptied)
set -eu
build_dir=$1
consumer_dir=$2
work_dir=$3
configured_module=$4
prefix="$work_dir/prefix"

. "$(dirname "$0")/install_and_build.sh"
install_and_build_consumer "$build_dir" "$consumer_dir" "$work_dir" --target consumer_c
program="$work_dir/build/consumer_c"
if readelf -d "$program" | grep NEEDED | grep -E 'libtalkface|libav|libsw'; then
  echo "the static consumer loads libtalkface or FFmpeg (above): it should hold libtalkface and open the module" >&2
  exit 1
fi
installed_module=$(find "$prefix" -path '*/talkface/talkface_ffmpeg.so' | head -n 1)
test -n "$installed_module" || { echo "FFmpeg's module is not installed under $prefix" >&2; exit 1; }

# Beside the program.
mkdir -p "$work_dir/build/talkface" "$work_dir/beside"
cp "$installed_module" "$work_dir/build/talkface/"
"$program" "$work_dir/beside"
test -s "$work_dir/beside/frame-000000.png"
rm -r "$work_dir/build/talkface"

# Not beside it: the compiled-in path.
mkdir -p "$work_dir/compiled-in"
if [ -e "$configured_module" ]; then
  "$program" "$work_dir/compiled-in"
  test -s "$work_dir/compiled-in/frame-000000.png"
  echo "static consumer: the module found beside the program and at $configured_module"
else
  if "$program" "$work_dir/compiled-in" >"$work_dir/missing.out" 2>&1; then
    echo "the static consumer wrote a frame with no FFmpeg module beside it or at $configured_module" >&2
    exit 1
  fi
  if ! grep -F "$work_dir/build/talkface/talkface_ffmpeg.so" "$work_dir/missing.out" >/dev/null ||
    ! grep -F "$configured_module" "$work_dir/missing.out" >/dev/null; then
    echo "the failure does not name both places the module was looked for:" >&2
    cat "$work_dir/missing.out" >&2
    exit 1
  fi
  echo "static consumer: the module found beside the program; missing, the failure names both places:"
  cat "$work_dir/missing.out"
fi
