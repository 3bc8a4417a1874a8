# shellcheck shell=sh
# Sourced by consumer_test.sh and static_consumer_test.sh.
# install_and_build_consumer BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR [BUILD_OPTION ...]: empties
# WORK_DIR, installs the build into WORK_DIR/prefix and builds the consumer project in
# WORK_DIR/build against it as a user's project would: find_package(talkface), nothing from the
# source or build tree (LD_LIBRARY_PATH and PYTHONPATH unset for the rest of the script). The options
# go to cmake --build (--target NAME).
install_and_build_consumer() {
  install_build_dir=$1
  install_consumer_dir=$2
  install_work_dir=$3
  shift 3
  rm -rf "$install_work_dir"
  mkdir -p "$install_work_dir"
  cmake --install "$install_build_dir" --prefix "$install_work_dir/prefix" >"$install_work_dir/install.log"
  unset LD_LIBRARY_PATH PYTHONPATH
  cmake -S "$install_consumer_dir" -B "$install_work_dir/build" -DCMAKE_PREFIX_PATH="$install_work_dir/prefix" \
    -DCMAKE_BUILD_TYPE=Release >"$install_work_dir/configure.log"
  cmake --build "$install_work_dir/build" --parallel 2 "$@" >"$install_work_dir/build.log"
}
