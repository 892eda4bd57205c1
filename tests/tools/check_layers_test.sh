#!/usr/bin/env bash
# tools/check_layers.sh finds a lower floor that includes a higher one: in a
# made-up tree laid out as robozoo's, a clean tree passes and each planted
# violation (evolve/ including study/ and runlog/, the old way of
# robozoo-evolve champion; a folder including its sibling on the same floor;
# util/ including the generated lcmtypes) fails with the file and line named.
# Includes of a floor below, of its own folder, of third-party headers and in
# comments pass. Usage: check_layers_test.sh SOURCE_DIR
set -euo pipefail
src="${1:?usage: check_layers_test.sh SOURCE_DIR}"
check="$src/tools/check_layers.sh"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# A tree that keeps the rule.
make_tree() {
  rm -rf "$tmp/tree" && mkdir -p "$tmp/tree"
  cd "$tmp/tree"
  mkdir -p util evolve/app evolve/io runlog/read study/analysis render replay view tools/log tests/evolve fuzz
  printf '#include "util/exit_status.hpp"\n#include <string>\n' >util/a.cpp
  printf '#include "evolve/record/run_results.hpp"\n#include "util/exit_status.hpp"\n#include "robozoo/run_t.hpp"\n#include <CLI/CLI.hpp>\n// #include "study/analysis/x.hpp" (a comment)\n' >evolve/app/champion_command.cpp
  printf '#include "evolve/io/event_log.hpp"\n' >runlog/read/log_reader.cpp
  printf '#include "runlog/read/log_reader.hpp"\n#include <evolve/record/run_summary.hpp>\n' >study/analysis/b.cpp
  printf '#include "runlog/read/log_reader.hpp"\n#include "study/analysis/b.hpp"\n' >render/c.hpp
  printf '#include "runlog/read/log_reader.hpp"\n' >replay/d.h
  printf '#include "study/analysis/b.hpp"\n#include "render/c.hpp"\n' >view/e.cpp
  printf '#include "study/analysis/b.hpp"\n' >tools/log/robozoo-log.cpp
  printf '#include "view/e.hpp"\n#include "tools/x.hpp"\n#include "tests/support/s.hpp"\n' >tests/evolve/t_test.cpp
  printf '#include "fuzz/fuzz_check.hpp"\n#include "study/analysis/b.hpp"\n' >fuzz/fuzz_x.cpp
  cd - >/dev/null
}

# expect_violation NAME FILE TEXT: TEXT appended to FILE makes the check fail, naming FILE.
expect_violation() {
  local name="$1" file="$2" text="$3" out rc=0
  make_tree
  printf '%s\n' "$text" >>"$tmp/tree/$file"
  out="$(bash "$check" --root "$tmp/tree" 2>&1)" || rc=$?
  [ "$rc" -eq 1 ] || fail "$name: exit $rc, expected 1:"$'\n'"$out"
  case "$out" in *"$file:"*) ;; *) fail "$name: $file not named:"$'\n'"$out" ;; esac
}

make_tree
out="$(bash "$check" --root "$tmp/tree" 2>&1)" || fail "a clean tree is refused:"$'\n'"$out"

expect_violation "evolve includes study" evolve/app/champion_command.cpp '#include "study/analysis/read/champion_log.hpp"'
expect_violation "evolve includes runlog" evolve/io/x.hpp '#include "runlog/robots/regrow.hpp"'
expect_violation "evolve includes view (angle brackets)" evolve/io/y.cpp '  #  include <view/serve/server.hpp>'
expect_violation "runlog includes study" runlog/read/log_reader.cpp '#include "study/analysis/b.hpp"'
expect_violation "study includes render, above it" study/analysis/b.cpp '#include "render/c.hpp"'
expect_violation "render includes its sibling replay" render/c.cpp '#include "replay/d.h"'
expect_violation "replay includes tools" replay/d.h '#include "tools/log/x.hpp"'
expect_violation "view includes its sibling tools" view/e.cpp '#include "tools/log/x.hpp"'
expect_violation "util includes evolve" util/a.cpp '#include "evolve/core/rng.hpp"'
expect_violation "util includes the generated lcmtypes" util/a.cpp '#include "robozoo/run_t.hpp"'

# The real tree keeps the rule (ctest's check_layers says so too).
out="$(bash "$check" --root "$src" 2>&1)" || fail "the source tree breaks the rule:"$'\n'"$out"
# Usage: --help names the script, an unknown option is refused with exit 2.
bash "$check" --help | grep -q check_layers.sh || fail "--help does not name the script"
rc=0; bash "$check" --bogus 2>/dev/null || rc=$?
[ "$rc" -eq 2 ] || fail "--bogus: exit $rc, expected 2"

if [ "$failures" -ne 0 ]; then
  echo "check_layers_test: $failures failure(s)" >&2
  exit 1
fi
echo "check_layers_test: the clean tree passes, every planted violation is found"
