#!/usr/bin/env bash
# Configures and builds robozoo (Release) into ./build, using every core, through
# ccache when it is installed (the same objects, sooner on a rebuild or a fresh
# clone), else with the heavy headers precompiled and the sources compiled in
# batches (ROBOZOO_PCH, ROBOZOO_UNITY: the same results, a cold build in half the time).
#
#   tools/build.sh                      # every program and test
#   tools/build.sh robozoo-evolve ...   # only these targets (and what they link)
#   tools/build.sh --werror [TARGET...] # warnings are errors (ROBOZOO_WERROR=ON, what CI builds)
#
# Environment: BUILD_DIR (default build), JOBS (compile jobs, default: cores),
# CCACHE_DISABLE (set: build as without ccache).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
cmake_args=()
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --werror) cmake_args+=(-DROBOZOO_WERROR=ON); shift ;;
    -*) echo "build.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) targets+=(--target "$1"); shift ;;
  esac
done
if command -v ccache >/dev/null 2>&1 && [ -z "${CCACHE_DISABLE:-}" ]; then
  cmake_args+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DROBOZOO_PCH=OFF
    -DROBOZOO_UNITY=OFF)
else
  # No compiler cache (or CCACHE_DISABLE set): precompiled headers and batches instead (a quicker cold
  # build; ccache would cache neither well). An earlier ccache configuration of the folder is undone.
  cmake_args+=(-UCMAKE_C_COMPILER_LAUNCHER -UCMAKE_CXX_COMPILER_LAUNCHER -DROBOZOO_PCH=ON -DROBOZOO_UNITY=ON)
fi
# Ninja keeps both cores busy across targets (make builds one target at a time, and a
# target of one or two batches would leave a core idle); a folder keeps the generator
# it was first configured with.
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then
  cmake_args+=(-G Ninja)
fi
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${cmake_args[@]}" >/dev/null
cmake --build "$BUILD_DIR" -j"${JOBS:-$(nproc)}" "${targets[@]}"
