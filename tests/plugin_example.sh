#!/usr/bin/env bash
# The ctest fixture of tests/plugin_test.cc: installs the build into a
# temporary prefix and builds examples/plugin against it, as a user would
# (examples/plugin/README.md); checks on the way that the package also
# serves code that embeds the static libraries (tests/package_consumer/).
# Usage: plugin_example.sh CMAKE BUILD_DIR SOURCE_DIR WORK_DIR CXX GENERATOR
set -euo pipefail
cmake=$1 build=$2 source=$3 work=$4 cxx=$5 generator=$6

# configure_and_build SOURCE BUILD: a project against the installed package.
configure_and_build() {
  "$cmake" -S "$1" -B "$2" -G "$generator" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
  "$cmake" --build "$2" -j2
}

rm -rf "$work"
"$cmake" --install "$build" --prefix "$work/prefix" >/dev/null
configure_and_build "$source/examples/plugin" "$work/build"
configure_and_build "$source/tests/package_consumer" "$work/consumer"
out=$("$work/consumer/consumer")
if [ "$out" != "HC4 chain" ]; then
  echo "plugin_example.sh: the package consumer printed '$out'" >&2
  exit 1
fi

# One registry: the plugin reaches the executable's, it carries none itself.
lib="$work/build/libhc4_twice.so"
if nm -C --defined-only "$lib" | grep -q 'icp::RegisterAlgorithm\|icp::Algorithms()'; then
  echo "plugin_example.sh: $lib defines the registry itself" >&2
  exit 1
fi
