#!/usr/bin/env bash
# The paper-size experiment, grown over days with one software version, at low priority.
#
#   tools/paper_experiment.sh [--dir DIR] [--commit COMMIT] [--workers N]   # run (or resume) the milestones
#   tools/paper_experiment.sh --collect [--dir DIR]                         # copy the compact results into the repository
#   tools/paper_experiment.sh --status [--dir DIR]
#
# It clones this repository at COMMIT (default: the one recorded in
# media/experiment/paper/VERSION, which the first start writes) into DIR/src, builds
# robozoo-evolve and robozoo-experiment there once, and runs robozoo-experiment under
# nice 19 in a session of its own whose autogroup is at nice 19 too (with the kernel's
# autogroup scheduling, nice ranks a process only within its session), with logs in
# DIR/runs and compact results in DIR/results, milestone after milestone: M1 the four
# arms (feedforward, recurrent, recurrent-sparse, recurrent-zero), 30 trials each, to
# generation 30; M2 feedforward and recurrent to generation 60; M3 feedforward and
# recurrent to generation 500. Population 150 and 2,500 steps throughout. Stop it at
# any time (kill, or the machine stops); the same command resumes where it stood.
# --collect copies DIR/results/*.results.json into media/experiment/paper/results/.
# DIR defaults to /var/tmp/robozoo-paper.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
dir=/var/tmp/robozoo-paper
commit=""
workers=$(nproc)
action=run
while [ $# -gt 0 ]; do
  case "$1" in
    --dir) dir=${2:?--dir needs a folder}; shift 2 ;;
    --commit) commit=${2:?--commit needs a commit}; shift 2 ;;
    --workers) workers=${2:?--workers needs a number}; shift 2 ;;
    --collect) action=collect; shift ;;
    --status) action=status; shift ;;
    -h|--help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "paper_experiment.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
paper=media/experiment/paper
mkdir -p "$dir"

if [ "$action" = collect ]; then
  mkdir -p "$paper/results"
  n=0
  for f in "$dir"/results/*.results.json; do
    [ -e "$f" ] || continue
    cp "$f" "$paper/results/.tmp.$$" && mv "$paper/results/.tmp.$$" "$paper/results/$(basename "$f")"
    n=$((n + 1))
  done
  echo "paper_experiment.sh: $n compact results in $paper/results/"
  exit 0
fi

if [ -z "$commit" ]; then
  if [ -f "$paper/VERSION" ]; then
    commit=$(head -n 1 "$paper/VERSION")
  else
    commit=$(git rev-parse HEAD)
    if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
      echo "paper_experiment.sh: the work tree has uncommitted changes; commit them or name --commit" >&2
      exit 2
    fi
  fi
fi
git cat-file -e "$commit^{commit}" 2>/dev/null || { echo "paper_experiment.sh: no commit $commit here" >&2; exit 2; }
if [ ! -f "$paper/VERSION" ]; then
  mkdir -p "$paper"
  echo "$commit" >"$paper/VERSION"
  echo "paper_experiment.sh: recorded the experiment's version in $paper/VERSION ($commit): commit that file"
fi

src="$dir/src"
bin="$src/build/bin"
if [ ! -x "$bin/robozoo-experiment" ] || [ ! -x "$bin/robozoo-evolve" ] || [ "$(git -C "$src" rev-parse HEAD 2>/dev/null)" != "$(git rev-parse "$commit")" ]; then
  echo "paper_experiment.sh: building robozoo $commit in $src"
  rm -rf "$src"
  git clone -q "$repo" "$src"
  git -C "$src" checkout -q "$commit"
  launcher=()
  command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$src" -B "$src/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF "${launcher[@]}" >/dev/null
  nice -n 10 cmake --build "$src/build" -j"$(nproc)" --target robozoo-evolve robozoo-experiment >/dev/null
fi
echo "paper_experiment.sh: robozoo $("$bin/robozoo-evolve" --version)"

common=(--out "$dir/runs" --results "$dir/results" --trials 30 --population 150 --workers "$workers")
if [ "$action" = status ]; then
  "$bin/robozoo-experiment" "${common[@]}" --arms feedforward,recurrent,recurrent-sparse,recurrent-zero \
    --generations 30 --status
  exit 0
fi
# Trials finished on another machine count from their committed compact results.
mkdir -p "$dir/results"
for f in "$paper"/results/*.results.json; do
  [ -e "$f" ] && [ ! -e "$dir/results/$(basename "$f")" ] && cp "$f" "$dir/results/"
done
# Runs a command at the lowest priority: nice 19 in a new session whose autogroup is at nice 19
# too, so that it yields to work in every other session (a build, a shell), not only its own.
# SIGINT, SIGTERM and SIGHUP to this script are passed on (robozoo-experiment then stops cleanly).
low_priority() {
  setsid bash -c 'echo 19 > /proc/self/autogroup 2>/dev/null || true; exec nice -n 19 "$@"' low_priority "$@" &
  local child=$! rc=0
  trap 'kill -TERM "$child" 2>/dev/null || true' INT TERM HUP
  wait "$child" || rc=$?
  while kill -0 "$child" 2>/dev/null; do rc=0; wait "$child" || rc=$?; done
  trap - INT TERM HUP
  return "$rc"
}

milestone() {  # name, arms, generations
  echo "paper_experiment.sh: $1: $2 to generation $3 ($(date -u +%FT%TZ))"
  # A trial known here only from its compact result (its log and checkpoint stayed on another
  # machine) cannot be extended: it runs again from generation 0, which gives the same
  # generations as the committed result (a run is deterministic), then on to the milestone.
  local arm f
  for arm in ${2//,/ }; do
    for f in "$dir/results/$arm"-s*.results.json; do
      [ -e "$f" ] || continue
      local trial=$(basename "$f" .results.json)
      [ -e "$dir/runs/$trial.lcmlog.checkpoint" ] || [ -e "$dir/runs/$trial.lcmlog" ] && continue
      local reached=$(grep -o '"generations": *[0-9][0-9]*' "$f" | head -n 1 | grep -o '[0-9]*$')
      if [ -n "$reached" ] && [ "$reached" -lt "$3" ]; then
        echo "paper_experiment.sh: $trial has only its compact result (generation $reached): it runs again from 0"
        rm -f "$f"
      fi
    done
  done
  low_priority "$bin/robozoo-experiment" "${common[@]}" --arms "$2" --generations "$3"
  echo "paper_experiment.sh: $1 done ($(date -u +%FT%TZ))"
}
milestone M1 feedforward,recurrent,recurrent-sparse,recurrent-zero 30
milestone M2 feedforward,recurrent 60
milestone M3 feedforward,recurrent 500
