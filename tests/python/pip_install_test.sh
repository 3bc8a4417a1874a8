#!/bin/sh
# pip installs talkface into a fresh virtual environment and imports it from outside the source tree.
# usage: pip_install_test.sh PYTHON SOURCE_DIR WORK_DIR   (WORK_DIR is emptied first)
set -eu
python=$1
source_dir=$2
work_dir=$3

rm -rf "$work_dir"
mkdir -p "$work_dir"
"$python" -m venv --system-site-packages "$work_dir/venv"

# Two jobs and a quiet pip: this runs beside other tests on small CI machines.
export CMAKE_BUILD_PARALLEL_LEVEL=2
export TALKFACE_CMAKE_BUILD_DIR="$work_dir/cmake-build"
unset PYTHONPATH
"$work_dir/venv/bin/pip" install -q --no-build-isolation --no-index "$source_dir" >"$work_dir/pip.log" 2>&1 ||
  { cat "$work_dir/pip.log"; exit 1; }

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
print("talkface", talkface.__version__, "from", location.parent, "d =", d)
'
