#!/bin/sh
# pip installs talkface into a fresh virtual environment from a read-only copy of the source tree,
# checks that nothing was written into that copy (no build-pip/, no egg-info, no CMake build), and
# imports the package from outside the tree, face from a photo included where it was built, and
# writes a video frame through FFmpeg's module.
# usage: pip_install_test.sh PYTHON SOURCE_DIR WORK_DIR   (WORK_DIR is emptied first)
set -eu
python=$1
source_dir=$2
work_dir=$3

rm -rf "$work_dir"
mkdir -p "$work_dir/source"
"$python" -m venv --system-site-packages "$work_dir/venv"

# The copy holds what git tracks (or, outside a checkout, the tree without build folders), made
# read-only. Root ignores file modes, so the listing before and after is what proves nothing was
# written.
if git -C "$source_dir" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  (cd "$source_dir" && git ls-files -z --cached --others --exclude-standard | xargs -0 tar cf -) |
    tar xf - -C "$work_dir/source"
else
  (cd "$source_dir" && tar cf - --exclude='./build*' --exclude='./.git' .) | tar xf - -C "$work_dir/source"
fi
chmod -R a-w "$work_dir/source"
(cd "$work_dir/source" && find . | LC_ALL=C sort) >"$work_dir/before.txt"

# Two jobs and a quiet pip: this runs beside other tests on small CI machines. The modules are built
# unoptimised (build type None: no -O, no -g) through CMAKE_ARGS, which setup.py honours: this test
# is about what pip builds, installs and imports, not how fast the result runs, and the longest test
# of a CI run on a bare machine takes 3.0 minutes so instead of 4.7 (320 -> 248 CPU seconds, idle).
export CMAKE_BUILD_PARALLEL_LEVEL=2
export CMAKE_ARGS="-DCMAKE_BUILD_TYPE=None"
export TALKFACE_PIP_BUILD_DIR="$work_dir/pip-build"
unset PYTHONPATH TALKFACE_CMAKE_BUILD_DIR
"$work_dir/venv/bin/pip" install -q --no-build-isolation --no-index "$work_dir/source" >"$work_dir/pip.log" 2>&1 ||
  { cat "$work_dir/pip.log"; exit 1; }

if ! grep -q '^CMAKE_BUILD_TYPE:STRING=None$' "$work_dir/pip-build/cmake/CMakeCache.txt"; then
  echo "setup.py did not pass CMAKE_ARGS to CMake (no CMAKE_BUILD_TYPE=None in the pip build's cache)" >&2
  exit 1
fi

(cd "$work_dir/source" && find . | LC_ALL=C sort) >"$work_dir/after.txt"
if ! diff -u "$work_dir/before.txt" "$work_dir/after.txt"; then
  echo "pip install wrote into the source tree (lines marked + above)" >&2
  exit 1
fi
chmod -R u+w "$work_dir/source"

cd "$work_dir"
"$work_dir/venv/bin/python" -c '
import pathlib, sys
import talkface
location = pathlib.Path(talkface.__file__).resolve()
assert "venv" in location.parts, f"talkface imported from {location}, not from the virtual environment"
d = talkface.FaceModel.default().fapu("d")
assert d > 0, d
assert talkface.__version__ == talkface.version()
svg = talkface.SvgAnimator(talkface.FaceModel.default()).render_svg(talkface.FaceState())
assert svg.startswith("<?xml")
assert "talkface._talkface_photo" not in sys.modules, "import talkface loaded the photo stage"
if any(location.parent.glob("_talkface_photo*.so")):
    import numpy
    try:
        talkface.face_from_photo(numpy.full((64, 64), 128, dtype=numpy.uint8))
        raise AssertionError("a blank photo gave a face")
    except ValueError as error:
        assert "no face" in str(error), error
# FFmpeg is the library'"'"'s module, talkface/talkface_ffmpeg.so in the package, opened on first use.
import numpy
writer = talkface.VideoWriter("frame.png", talkface.VideoOptions(width_px=16, height_px=16))
writer.write_frame(numpy.full((16, 16, 4), 128, dtype=numpy.uint8))
writer.finish()
assert pathlib.Path("frame-000000.png").stat().st_size > 0
assert (location.parent / "talkface" / "talkface_ffmpeg.so").is_file()
print("talkface", talkface.__version__, "from", location.parent, "d =", d)
'
