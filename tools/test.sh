#!/usr/bin/env bash
# The README's test command: install what is missing, check the sources'
# formatting (tools/format.sh --check), build with warnings as errors, run every
# test, prove the same bits from clang and gcc -O0 builds (tools/cross_build.sh),
# then run every fuzz target for 10 s (tools/fuzz.sh).
#
#   tools/test.sh              # all of it (CI)
#   tools/test.sh --no-fuzz    # build/ (-Werror) and ctest only
#   tools/test.sh --sanitize   # the whole suite under AddressSanitizer and
#                              # UndefinedBehaviorSanitizer, in build-sanitize/
# Environment: ROBOZOO_FORMAT_CHECK=0 skips the formatting check (while editing);
# ROBOZOO_CROSS_BUILD=0 skips the cross-build check.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
case "$mode" in
  ""|--no-fuzz|--sanitize) ;;
  -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "test.sh: unknown option $mode (use --no-fuzz or --sanitize)" >&2; exit 2 ;;
esac
tools/setup.sh

if [ "$mode" = "--sanitize" ]; then
  dir="${SANITIZE_BUILD_DIR:-build-sanitize}"
  flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
  launcher=()
  command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # -O1 (asserts on): quicker to build than -O3, and what the sanitizers' authors advise.
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_C_FLAGS_RELEASE=-O1 -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" "${launcher[@]}" >/dev/null
  cmake --build "$dir" -j"${JOBS:-$(nproc)}"
  # Every ASan/LSan report of every process goes to a file in $reports, not to the
  # process's stderr: the tests, the programs they start, and the workers and ranks
  # whose end a test may not look at (killed on purpose, started in the background).
  # UBSan ignores log_path when it runs beside ASan (gcc's two runtimes), so its
  # reports ("runtime error:") are looked for in the output of every test, passed
  # or not (ctest's LastTest.log). Any report fails the run and is printed after ctest.
  reports="$(cd "$dir" && pwd)/sanitizer-reports"
  rm -rf "$reports" && mkdir -p "$reports"
  # Leaks inside Open MPI, OSMesa and the other libraries robozoo links are theirs (tools/lsan.supp).
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:log_path=$reports/asan"
  export LSAN_OPTIONS="suppressions=$PWD/tools/lsan.supp:print_suppressions=0"
  # MPI ranks: Open MPI (Debian's, built without frame pointers) ends ASan's fast
  # malloc stacks one frame into libmpi or a dlopen'ed component, so tools/lsan.supp
  # never sees the libmpi.so frame of MPI_Init's ~110 kB left at exit and every rank
  # fails its leak check (every *_mpi_* test did). The ranks mpirun starts (whoever
  # starts mpirun: a test, robozoo-experiment, the sbatch script) unwind malloc
  # stacks fully instead, through Open MPI's own list of variables to set in them.
  # Measured: the 15 MPI tests (ctest -R 'Mpi|RobozooTrials' -j2) 107 s -> 208 s; nothing else is slowed.
  export OMPI_MCA_mca_base_env_list="ASAN_OPTIONS=$ASAN_OPTIONS:fast_unwind_on_malloc=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  status=0
  (cd "$dir" && ctest --output-on-failure -j"${JOBS:-$(nproc)}") || status=$?
  grep -B2 -A30 "runtime error:" "$dir/Testing/Temporary/LastTest.log" >"$reports/ubsan-in-test-output" || true
  found=$(find "$reports" -type f -size +0 | sort)
  if [ -n "$found" ]; then
    echo "test.sh --sanitize: $(echo "$found" | wc -l) sanitizer report(s), in $reports:" >&2
    for f in $found; do echo "==== $f" >&2; head -n 60 "$f" >&2; done
    status=1
  fi
  if [ "$status" -eq 0 ]; then echo "test.sh --sanitize: every test passed, no sanitizer report"; fi
  exit "$status"
fi

if [ "${ROBOZOO_FORMAT_CHECK:-1}" = 1 ]; then
  tools/format.sh --check
fi
tools/build.sh --werror
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j"$(nproc)")
if [ "$mode" != "--no-fuzz" ]; then
  # The cross-build check: a run made by gcc -O3, clang and gcc -O0, checked under each other
  # (about 9 minutes cold on 2 cores: docs/performance.md). ROBOZOO_CROSS_BUILD=0 skips it.
  if [ "${ROBOZOO_CROSS_BUILD:-1}" = 1 ]; then tools/cross_build.sh; fi
  tools/fuzz.sh 10
fi
