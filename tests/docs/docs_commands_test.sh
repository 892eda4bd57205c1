#!/usr/bin/env bash
# Every command the docs show runs as written. Extracts each command of README.md
# and docs/*.md (the lines of ```sh blocks that start with build/bin/, tools/,
# mpirun or sbatch; a line ending in \ goes on) and runs it, each in a fresh copy
# of a folder this test makes first: build/bin (this build's programs); runs/demo.lcmlog,
# a small run (population 6, 41 generations, 300 steps) with its checkpoint; the same
# run as runs/tour.lcmlog, runs/rec-s3.lcmlog and LOG (these two with the checkpoint),
# SENT.lcmlog, RECORDED.lcmlog and tmp/champ.lcmlog; runs/mini and runs/paper (a small
# experiment); g.json (a genome); my.json (a configuration); media/ (a copy).
# Substituted: /tmp/champ.lcmlog by the copy's tmp/champ.lcmlog, and genome 513
# (`--genome 513`) by the small run's best champion. A robozoo-evolve that makes a log
# (--log FILE without --resume) or a robozoo-experiment that makes a folder (--out DIR)
# gets a copy without that file or folder, as a reader has before running it.
# A command passes when it exits 0 within 120 s.
#
# An HTML comment on the line before a block's fence changes that for the block:
#   <!-- docs-test: starts -->          servers and long runs: exit 0, or still
#                                       running after 10 s (then stopped)
#   <!-- docs-test: skip (REASON) -->   not run; every skip is printed
#
#   tests/docs/docs_commands_test.sh BIN_DIR SOURCE_DIR
set -uo pipefail
case "${1:-}" in
  -h|--help) sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
esac
[ $# -eq 2 ] || { echo "docs_commands_test.sh: needs BIN_DIR SOURCE_DIR" >&2; exit 2; }
# A private network (unshare -rn, no root needed) with multicast on its loopback: the
# commands' LCM traffic stays inside it.
if [ -z "${DOCS_TEST_IN_NETNS:-}" ]; then
  exec unshare -rn env DOCS_TEST_IN_NETNS=1 bash -c \
    'ip link set lo up && ip route add 224.0.0.0/4 dev lo && exec bash "$0" "$@"' "$0" "$@"
fi
bin=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The commands: "FILE:LINE<TAB>POLICY<TAB>COMMAND", POLICY one of run, starts, skip (REASON).
extract() {
  awk '
    FNR == 1 { inb = 0; policy = "run"; prev = "" }
    {
      line = $0
      if (line ~ /^[ \t]*```/) {
        if (inb) { inb = 0; policy = "run" }
        else if (line ~ /^[ \t]*```(sh|bash)[ \t]*$/) {
          inb = 1
          policy = "run"
          if (prev ~ /<!-- docs-test: starts -->/) policy = "starts"
          if (match(prev, /<!-- docs-test: skip \([^)]*\) -->/)) policy = substr(prev, RSTART + 16, RLENGTH - 20)
        }
        prev = line; next
      }
      if (line !~ /^[ \t]*$/) prev = line
      if (!inb) next
      sub(/^[ \t]+/, "", line)
      if (cont != "") {
        cmd = cmd " " line
      } else {
        if (line !~ /^(build\/bin\/|tools\/|mpirun |sbatch )/) next
        cmd = line; where = FILENAME ":" FNR; cont = "x"
      }
      if (cmd ~ /\\$/) { sub(/\\$/, "", cmd); next }
      cont = ""
      print where "\t" policy "\t" cmd
    }' README.md docs/*.md
}

# The fixture every command starts from.
fixture="$work/fixture"
mkdir -p "$fixture/build" "$fixture/runs"
ln -s "$bin" "$fixture/build/bin"
cp -r "$src/media" "$fixture/media"
(
  cd "$fixture" || exit 1
  build/bin/robozoo-evolve --regime recurrent --seed 2 --population 6 --generations 41 --steps 300 --workers 2 \
    --quiet --log runs/demo.lcmlog >/dev/null &&
    build/bin/robozoo-evolve --regime recurrent --seed 2 --population 6 --generations 41 --steps 300 \
      --print-config >my.json &&
    build/bin/robozoo-evolve eval --random 7 --save-genome g.json >/dev/null &&
    build/bin/robozoo-experiment --trials 2 --generations 2 --population 6 --steps 300 --workers 2 \
      --out runs/mini >/dev/null 2>experiment.txt &&
    cp -r runs/mini runs/paper
) || { echo "docs_commands_test: FAIL: could not make the small run" >&2; cat "$fixture/experiment.txt" >&2; exit 1; }
rm -f "$fixture/experiment.txt"
mkdir -p "$fixture/tmp"
for name in runs/tour.lcmlog runs/rec-s3.lcmlog LOG SENT.lcmlog RECORDED.lcmlog tmp/champ.lcmlog; do
  cp "$fixture/runs/demo.lcmlog" "$fixture/$name"
done
for name in runs/rec-s3.lcmlog LOG; do cp "$fixture/runs/demo.lcmlog.checkpoint" "$fixture/$name.checkpoint"; done
best=$("$bin/robozoo-log" summary "$fixture/runs/demo.lcmlog" | sed -n 's/.*best: genome \([0-9]*\) .*/\1/p')
[ -n "$best" ] || { echo "docs_commands_test: FAIL: no best genome in the small run's summary" >&2; exit 1; }

# mpirun as root and with more ranks than cores, as the MPI tests run it.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

cd "$src" || exit 2
commands=$(extract)
[ -n "$commands" ] || { echo "docs_commands_test: FAIL: no command found in README.md and docs/*.md" >&2; exit 1; }
passed=0 failed=0 skipped=0 n=0
while IFS=$'\t' read -r where policy cmd; do
  n=$((n + 1))
  case "$policy" in
    skip*) skipped=$((skipped + 1)); echo "SKIP  $where  $cmd   [$policy]"; continue ;;
  esac
  dir="$work/c$n"
  cp -r "$fixture" "$dir"
  # /tmp/champ.lcmlog: the docs' scratch file, kept in the command's own folder.
  run=${cmd//\/tmp\/champ.lcmlog/$dir/tmp/champ.lcmlog}
  run=${run//--genome 513/--genome $best}
  # What the command makes must not exist yet.
  if [[ "$run" == *robozoo-evolve* ]] && [[ " $run " != *" --resume "* ]] && [[ " $run " =~ \ --log\ ([^ ]+) ]]; then
    (cd "$dir" && rm -f "${BASH_REMATCH[1]}" "${BASH_REMATCH[1]}.checkpoint")
  fi
  if [[ " $run " =~ \ --out\ ([^ ]+) ]] && [[ "$run" == *robozoo-experiment* ]]; then
    (cd "$dir" && rm -rf "${BASH_REMATCH[1]}")
  fi
  limit=120
  [ "$policy" = starts ] && limit=10
  (cd "$dir" && timeout -k 5 "$limit" bash -c "$run" </dev/null >"$dir/out.txt" 2>&1)
  rc=$?
  if [ "$rc" -eq 0 ] || { [ "$policy" = starts ] && [ "$rc" -eq 124 ]; }; then
    passed=$((passed + 1))
    note=""
    [ "$rc" -eq 124 ] && note="   [still running after ${limit} s: stopped]"
    echo "ok    $where  $cmd$note"
  else
    failed=$((failed + 1))
    echo "FAIL  $where  $cmd   [exit $rc]"
    head -n 15 "$dir/out.txt" | sed 's/^/        /'
  fi
  rm -rf "$dir"
done <<<"$commands"
echo "docs_commands_test: $n commands: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
