#!/usr/bin/env bash
# The same bits from another build: builds robozoo-evolve and robozoo-replay a second
# time with clang (build-clang/, Release) and with gcc at -O0 (build-O0/), then proves
# in both directions that a run made by one build passes `robozoo-replay check` and
# `check --full` under the other, message for message, for both regimes.
#
#   tools/cross_build.sh            # after tools/build.sh (uses build/ as the reference build)
#   tools/cross_build.sh --help
#
# Environment: BUILD_DIR (the reference build, default build), JOBS (default nproc).
# A difference makes robozoo-replay name the first differing message and field; the
# script then exits non-zero. The runs are small (population 20, 3 generations, 600
# steps) so that the -O0 build's slow evaluations stay within a minute.
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  "") ;;
  -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "cross_build.sh: unknown option $1 (only --help)" >&2; exit 2 ;;
esac

ref="${BUILD_DIR:-build}"
jobs="${JOBS:-$(nproc)}"
[ -x "$ref/bin/robozoo-evolve" ] && [ -x "$ref/bin/robozoo-replay" ] || {
  echo "cross_build.sh: $ref/bin/robozoo-evolve and robozoo-replay are missing: run tools/build.sh first" >&2
  exit 2
}

# Only the two programs and the libraries they link, no tests, with the heavy
# headers precompiled and the sources compiled in batches (ROBOZOO_PCH,
# ROBOZOO_UNITY: a quicker cold build; ccache caches neither well, so it is not
# used here). The bits must not depend on these either.
build_other() {  # dir, cmake args...
  local dir=$1; shift
  local generator=()
  [ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
  cmake -S . -B "$dir" "${generator[@]}" -DBUILD_TESTING=OFF -DROBOZOO_PCH=ON -DROBOZOO_UNITY=ON "$@" >/dev/null
  cmake --build "$dir" -j"$jobs" --target robozoo-evolve robozoo-replay
}
echo "cross_build.sh: building with clang (build-clang/)"
build_other build-clang -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
echo "cross_build.sh: building with gcc -O0 (build-O0/)"
build_other build-O0 -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG=-O0 -DCMAKE_CXX_FLAGS_DEBUG=-O0

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
# Makes a run with build $1 and checks it with build $2.
cross() {
  local maker=$1 checker=$2 regime=$3
  local log="$work/$(basename "$maker")-$regime.lcmlog"
  if [ ! -f "$log" ]; then
    "$maker/bin/robozoo-evolve" --regime "$regime" --seed 7 --population 20 --generations 3 --steps 600 \
      --pose-every 20 --workers "$jobs" --quiet --log "$log" >/dev/null
  fi
  for mode in "" "--full"; do
    checks=$((checks + 1))
    if "$checker/bin/robozoo-replay" check $mode --no-progress "$log" >"$work/out" 2>&1; then
      echo "cross_build.sh: ok    $regime run made by $maker, checked by $checker ${mode:-(champions)}"
    else
      failures=$((failures + 1))
      echo "cross_build.sh: FAIL  $regime run made by $maker, checked by $checker ${mode:-(champions)}:" >&2
      sed 's/^/    /' "$work/out" >&2
    fi
  done
}
for regime in feedforward recurrent; do
  for other in build-clang build-O0; do
    cross "$ref" "$other" "$regime"
    cross "$other" "$ref" "$regime"
  done
done
echo "cross_build.sh: $((checks - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
