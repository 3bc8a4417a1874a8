#!/bin/sh
# Installs the build into a fresh prefix, then builds and runs the consumer programs in project/
# against it: with find_package(talkface) and, for the C one, with pkg-config talkface_c.
# usage: consumer_test.sh BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR [C_COMPILER]   (WORK_DIR is emptied)
set -eu
build_dir=$1
consumer_dir=$2
work_dir=$3
c_compiler=${4:-cc}
prefix="$work_dir/prefix"

rm -rf "$work_dir"
mkdir -p "$work_dir"
cmake --install "$build_dir" --prefix "$prefix" >"$work_dir/install.log"

cmake -S "$consumer_dir" -B "$work_dir/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  >"$work_dir/configure.log"
cmake --build "$work_dir/build" --parallel 2 >"$work_dir/build.log"
"$work_dir/build/consumer_cpp"
"$work_dir/build/consumer_c"

pc_dir=$(dirname "$(find "$prefix" -name talkface_c.pc)")
flags=$(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs talkface_c)
# shellcheck disable=SC2086 # the flags are meant to split into words
"$c_compiler" -std=c99 -o "$work_dir/consumer_c_pkgconfig" "$consumer_dir/consumer.c" $flags
LD_LIBRARY_PATH="$(PKG_CONFIG_PATH="$pc_dir" pkg-config --variable=libdir talkface_c)" \
  "$work_dir/consumer_c_pkgconfig"
