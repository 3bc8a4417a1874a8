#!/bin/sh
# Installs the build into a fresh prefix, then uses it as a user would, with nothing from the source
# or build tree: builds and runs the consumer programs in project/ with find_package(talkface) and,
# for the C one, with pkg-config talkface_c; runs the installed command (its run path is relative,
# $ORIGIN/../lib, so no LD_LIBRARY_PATH) and imports the installed Python package; and checks that
# libtalkface itself loads no OpenCV (the photo stage is libtalkface_photo) and links no FFmpeg (its
# module does, opened by the C program's video frame, here from the install).
# usage: consumer_test.sh BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR [C_COMPILER [PYTHON]]   (WORK_DIR is emptied)
set -eu
build_dir=$1
consumer_dir=$2
work_dir=$3
c_compiler=${4:-cc}
python=${5:-}
prefix="$work_dir/prefix"

. "$(dirname "$0")/install_and_build.sh"
install_and_build_consumer "$build_dir" "$consumer_dir" "$work_dir"
"$work_dir/build/consumer_cpp"
mkdir -p "$work_dir/run"
"$work_dir/build/consumer_c" "$work_dir/run"
test -s "$work_dir/run/frame-000000.png"
if [ -e "$work_dir/build/consumer_photo" ]; then
  "$work_dir/build/consumer_photo"
fi

pc_dir=$(dirname "$(find "$prefix" -name talkface_c.pc)")
flags=$(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs talkface_c)
# shellcheck disable=SC2086 # the flags are meant to split into words
"$c_compiler" -std=c99 -o "$work_dir/consumer_c_pkgconfig" "$consumer_dir/consumer.c" $flags
LD_LIBRARY_PATH="$(PKG_CONFIG_PATH="$pc_dir" pkg-config --variable=libdir talkface_c)" \
  "$work_dir/consumer_c_pkgconfig"

libdir=$(PKG_CONFIG_PATH="$pc_dir" pkg-config --variable=libdir talkface)
# Its direct needs.
if readelf -d "$libdir/libtalkface.so" | grep NEEDED | grep -Ei 'opencv|dlib|png|jpeg'; then
  echo "libtalkface needs the photo stage's libraries (above); they belong to libtalkface_photo" >&2
  exit 1
fi
if ldd "$libdir/libtalkface.so" | grep -Ei 'opencv|dlib'; then
  echo "libtalkface loads OpenCV or dlib (above); they belong to libtalkface_photo" >&2
  exit 1
fi
# FFmpeg's libraries are the FFmpeg module's (LIBDIR/talkface/), which libtalkface opens on first use.
if readelf -d "$libdir/libtalkface.so" | grep NEEDED | grep -E 'libav|libsw'; then
  echo "libtalkface links FFmpeg's libraries (above); they belong to its module, talkface_ffmpeg" >&2
  exit 1
fi
test -f "$libdir/talkface/talkface_ffmpeg.so" ||
  { echo "FFmpeg's module is not installed in $libdir/talkface/" >&2; exit 1; }

# The installed command, from a folder of its own, found through its relative run path.
if [ -x "$prefix/bin/talkface" ]; then
  readelf -d "$prefix/bin/talkface" | grep -q 'RUNPATH.*\$ORIGIN/\.\./lib' ||
    { echo "bin/talkface has no \$ORIGIN/../lib run path" >&2; readelf -d "$prefix/bin/talkface" >&2; exit 1; }
  mkdir -p "$work_dir/run"
  (cd "$work_dir/run" && "$prefix/bin/talkface" render -o face.svg)
  grep -q '<svg' "$work_dir/run/face.svg"
  # face-from-photo opens its module (LIBDIR/talkface/), which links the photo stage: here it loads
  # and refuses a file that is no photo, naming it (not the module).
  if "$prefix/bin/talkface" face-from-photo --help >/dev/null 2>&1; then
    printf 'not a photo\n' >"$work_dir/run/photo.png"
    if (cd "$work_dir/run" && "$prefix/bin/talkface" face-from-photo photo.png -o face.xml 2>photo.err); then
      echo "face-from-photo read a file that is no photo" >&2; exit 1
    fi
    grep -q 'photo.png' "$work_dir/run/photo.err" && ! grep -q 'could not be loaded' "$work_dir/run/photo.err" ||
      { echo "the installed face-from-photo did not run its module:" >&2; cat "$work_dir/run/photo.err" >&2; exit 1; }
  fi
  echo "installed command: $("$prefix/bin/talkface" --version)"
fi

# The installed Python package, from the prefix alone.
if [ -n "$python" ] && [ -d "$prefix/lib/python3/dist-packages/talkface" ]; then
  (cd "$work_dir/run" && PYTHONPATH="$prefix/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1 "$python" -c '
import pathlib, sys
import talkface
location = pathlib.Path(talkface.__file__).resolve()
assert pathlib.Path(sys.argv[1]).resolve() in location.parents, f"talkface imported from {location}"
assert talkface.__version__ == talkface.version()
svg = talkface.SvgAnimator(talkface.FaceModel.default()).render_svg(talkface.FaceState())
assert svg.startswith("<?xml")
assert "_talkface_photo" not in sys.modules, "import talkface loaded the photo stage"
if any(location.parent.glob("_talkface_photo*.so")):
    talkface.has_dlib_locator()
    assert "talkface._talkface_photo" in sys.modules
print("installed Python package: talkface", talkface.__version__, "from", location.parent)
' "$prefix")
fi
