#!/usr/bin/env bash
# Builds robozoo's libFuzzer targets (fuzz/) with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-fuzz/, makes their seed corpora from a
# short real robozoo-evolve run, and runs each target for SECONDS (default 10).
#
#   tools/fuzz.sh [SECONDS] [TARGET...]      e.g. tools/fuzz.sh 600 fuzz_pose_t
#   tools/fuzz.sh --seconds 600 [TARGET...]  the same
#
# Prints executions, coverage and the result per target; exits 1 when a target
# found a crash, a hang (an input running over 10 s), an OOM (over 2 GiB, or one
# allocation over 512 MiB) or a broken property. What it found is kept in
# build-fuzz/findings/<target>/; inputs that reached new coverage in
# build-fuzz/corpus-work/<target>/ (reused by the next run).
# Environment: FUZZ_BUILD_DIR (build-fuzz), BUILD_DIR (build: the normal build's
# robozoo-evolve makes the seed run), JOBS (compile jobs, default: cores).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=10
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --seconds) SECONDS_EACH="${2:-}"; shift 2 || shift ;;
    -*) echo "fuzz.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    fuzz_*) targets+=("$1"); shift ;;
    *) SECONDS_EACH="$1"; shift ;;
  esac
done
if ! [[ "$SECONDS_EACH" =~ ^[0-9]+$ ]]; then
  echo "fuzz.sh: SECONDS must be a whole number of seconds, not '$SECONDS_EACH'" >&2; exit 2
fi
for t in "${targets[@]}"; do
  compgen -G "fuzz/*/$t.cpp" >/dev/null || { echo "fuzz.sh: no fuzz target $t (fuzz/*/fuzz_*.cpp)" >&2; exit 2; }
done
FUZZ_DIR="${FUZZ_BUILD_DIR:-build-fuzz}"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"

launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
t0=$(date +%s)
cmake -S . -B "$FUZZ_DIR" -DROBOZOO_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=OFF \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" >/dev/null
cmake --build "$FUZZ_DIR" --target fuzz -j"$JOBS"
t1=$(date +%s)
echo "fuzz: built in $((t1 - t0)) s"

# Seed corpora from a short real run (made once per build folder).
seeds="$FUZZ_DIR/corpus-seed"
if [ ! -f "$seeds/.done" ]; then
  evolve="$BUILD_DIR/bin/robozoo-evolve"
  if [ ! -x "$evolve" ]; then
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
    cmake --build "$BUILD_DIR" --target robozoo-evolve -j"$JOBS"
  fi
  run="$FUZZ_DIR/seed-run"
  rm -rf "$run" "$seeds"
  mkdir -p "$run"
  "$evolve" --regime recurrent --seed 3 --population 12 --generations 3 --steps 200 --workers 1 --quiet \
    --log "$run/run.lcmlog"
  "$evolve" --regime recurrent --seed 3 --population 12 --generations 3 --steps 200 --print-config >"$run/config.json"
  "$FUZZ_DIR/fuzz/robozoo-fuzz-corpus" "$run/run.lcmlog" "$run/run.lcmlog.checkpoint" "$run/config.json" "$seeds"
  touch "$seeds/.done"
fi

if [ ${#targets[@]} -eq 0 ]; then
  for f in fuzz/*/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi

failed=0
printf '%-22s %12s %10s %8s %8s %7s  %s\n' target executions exec/s cov features corpus result
for t in "${targets[@]}"; do
  name="${t#fuzz_}"
  work="$FUZZ_DIR/corpus-work/$name"
  findings="$FUZZ_DIR/findings/$name"
  mkdir -p "$work" "$findings"
  dirs=("$work")
  [ -d "$seeds/$name" ] && dirs+=("$seeds/$name")
  [ -d "fuzz/seeds/$name" ] && dirs+=("fuzz/seeds/$name")
  out="$FUZZ_DIR/findings/$name.log"
  set +e
  "$FUZZ_DIR/fuzz/$t" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 \
    -print_final_stats=1 -artifact_prefix="$findings/" "${dirs[@]}" >"$out" 2>&1
  rc=$?
  set -e
  # A target that stops on a finding prints no final statistics: take its last status line.
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$out" | tail -1 | awk '{print $2}' || true)
  last=$(grep -E '^#[0-9]+' "$out" | tail -1 || true)
  [ -n "$execs" ] || execs=$(sed -n 's/^#\([0-9]*\).*/\1/p' <<<"$last")
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\)\/.*/\1/p' <<<"$last")
  rate=$(( ${execs:-0} / (SECONDS_EACH > 0 ? SECONDS_EACH : 1) ))
  if [ $rc -eq 0 ]; then result=ok; else
    result="FOUND (exit $rc): $(grep -m1 -E 'ERROR: |fuzz property violated|==ERROR|runtime error' "$out" | cut -c1-100 || true) -> $findings/"
    failed=1
  fi
  printf '%-22s %12s %10s %8s %8s %7s  %s\n' "$t" "${execs:-?}" "$rate" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$result"
done
echo "fuzz: $((SECONDS_EACH)) s per target, $(( $(date +%s) - t1 )) s of fuzzing; logs in $FUZZ_DIR/findings/"
exit $failed
