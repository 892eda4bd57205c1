#!/usr/bin/env bash
# The paper-size experiment, grown over days with one software version, at low priority.
#
#   tools/experiment/paper_experiment.sh [--dir DIR] [--commit COMMIT] [--workers N]  # run (or resume) the milestones
#   tools/experiment/paper_experiment.sh --collect [--dir DIR]                        # copy the compact results into the repository
#   tools/experiment/paper_experiment.sh --status [--dir DIR]
#   tools/experiment/paper_experiment.sh --save-checkpoints [--dir DIR]               # trials in progress -> the repository
#
# For a test of the script itself (the paper's sizes are the defaults):
#   --bin BIN: robozoo-evolve and robozoo-experiment from BIN (no clone, no build, no VERSION);
#   --paper FOLDER: the committed results' folder (default media/experiment/paper);
#   --trials N, --population N, --steps N, --generations G1,G2,G3 (the milestones').
#
# It clones this repository at COMMIT (default: the one recorded in
# media/experiment/paper/VERSION, which the first start writes) into DIR/src, builds
# robozoo-evolve and robozoo-experiment there once, and runs robozoo-experiment under
# nice 19 in a session of its own whose autogroup is at nice 19 too (with the kernel's
# autogroup scheduling, nice ranks a process only within its session), with logs in
# DIR/runs, milestone after milestone: M1 the four arms (feedforward, recurrent,
# recurrent-sparse, recurrent-zero), 30 trials each, to generation 30; M2 feedforward
# and recurrent to generation 60; M3 feedforward and recurrent to generation 500.
# Population 150 and 2,500 steps throughout. Each milestone keeps its own compact
# results (M1 in DIR/results, M2 in DIR/m2/results, M3 in DIR/m3/results, as in
# media/experiment/paper/), so a later milestone never replaces the results an earlier
# report was made from; a milestone that finished on this machine (DIR/M1.done, ...) is
# not run again. Stop it at any time (kill, or the machine stops); the same command
# resumes where it stood: trials a milestone finished elsewhere count from their
# committed compact results, trials in progress elsewhere continue from their committed
# portable checkpoints (--save-checkpoints), the others start again from generation 0
# where their logs and checkpoints are not here.
# --collect copies each milestone's compact results into media/experiment/paper/ and
# checks that each later milestone's trials repeat the earlier one's generations
# (build/bin/robozoo-stats --same-as; exit 1 when one does not).
# --save-checkpoints writes the portable checkpoint of each trial in progress of the
# milestone being run (the first without DIR/M<n>.done) into the repository beside its
# compact results (media/experiment/paper/checkpoints/, m2/checkpoints/, ...; 130-280 kB
# a trial) and removes those of finished trials: commit them, and the run on a fresh
# clone continues those trials from there instead of generation 0.
# DIR defaults to /var/tmp/robozoo-paper.
set -euo pipefail
cd "$(dirname "$0")/../.."
repo=$(pwd)
dir=/var/tmp/robozoo-paper
commit=""
workers=$(nproc)
action=run
bin=""
paper=media/experiment/paper
trials=30
population=150
steps=""
generations=30,60,500
while [ $# -gt 0 ]; do
  case "$1" in
    --dir) dir=${2:?--dir needs a folder}; shift 2 ;;
    --commit) commit=${2:?--commit needs a commit}; shift 2 ;;
    --workers) workers=${2:?--workers needs a number}; shift 2 ;;
    --bin) bin=${2:?--bin needs a folder}; shift 2 ;;
    --paper) paper=${2:?--paper needs a folder}; shift 2 ;;
    --trials) trials=${2:?--trials needs a number}; shift 2 ;;
    --population) population=${2:?--population needs a number}; shift 2 ;;
    --steps) steps=${2:?--steps needs a number}; shift 2 ;;
    --generations) generations=${2:?--generations needs G1,G2,G3}; shift 2 ;;
    --collect) action=collect; shift ;;
    --status) action=status; shift ;;
    --save-checkpoints) action=save; shift ;;
    -h|--help) sed -n '2,39p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "paper_experiment.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
IFS=, read -r g1 g2 g3 <<<"$generations"
for n in "$trials" "$population" "$g1" "$g2" "$g3" ${steps:+"$steps"}; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "paper_experiment.sh: not a positive count: '$n' (see --help)" >&2; exit 2; }
done
mkdir -p "$dir"
# The milestones: name, arms, generations, results folder (under DIR and under $paper).
milestones=(
  "M1 feedforward,recurrent,recurrent-sparse,recurrent-zero $g1 results"
  "M2 feedforward,recurrent $g2 m2/results"
  "M3 feedforward,recurrent $g3 m3/results"
)

if [ "$action" = collect ]; then
  # A later milestone's trials must repeat the earlier one's generations (runs are
  # deterministic): robozoo-stats --same-as checks it, with this checkout's build.
  stats="${bin:-build/bin}/robozoo-stats"
  prev_name="" prev_folder="" status=0
  for m in "${milestones[@]}"; do
    read -r name _ _ folder <<<"$m"
    n=0
    for f in "$dir/$folder"/*.results.json; do
      [ -e "$f" ] || continue
      mkdir -p "$paper/$folder"
      cp "$f" "$paper/$folder/.tmp.$$" && mv "$paper/$folder/.tmp.$$" "$paper/$folder/$(basename "$f")"
      n=$((n + 1))
    done
    echo "paper_experiment.sh: $name: $n compact results in $paper/$folder/"
    if [ -n "$prev_name" ] && [ -d "$paper/$folder" ] && [ -d "$paper/$prev_folder" ]; then
      if [ ! -x "$stats" ]; then
        echo "paper_experiment.sh: $name: not checked against $prev_name's results: no $stats (tools/build.sh robozoo-stats)"
      elif check=$("$stats" "$paper/$folder" --same-as "$paper/$prev_folder" 2>&1); then
        echo "paper_experiment.sh: $name: $(tail -n 1 <<<"$check") ($prev_name's)"
      else
        echo "paper_experiment.sh: $name: its results do not repeat $prev_name's generations:" >&2
        grep -v ' agree$' <<<"$check" >&2
        status=1
      fi
    fi
    prev_name=$name prev_folder=$folder
  done
  exit $status
fi

if [ -z "$bin" ]; then
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
fi
echo "paper_experiment.sh: robozoo $("$bin/robozoo-evolve" --version)"

# A milestone's portable checkpoints in the repository: beside its results folder (results -> checkpoints).
checkpoints_folder() { echo "$paper/${1%results}checkpoints"; }
experiment_command() {  # arms, generations, results folder: sets cmd
  cmd=("$bin/robozoo-experiment" --out "$dir/runs" --results "$dir/$3" --trials "$trials" --population "$population"
    --workers "$workers" --arms "$1" --generations "$2" ${steps:+--steps "$steps"}
    --checkpoints "$(checkpoints_folder "$3")")
}
if [ "$action" = save ]; then
  for m in "${milestones[@]}"; do
    read -r name arms generations folder <<<"$m"
    [ -e "$dir/$name.done" ] && continue
    experiment_command "$arms" "$generations" "$folder"
    echo "paper_experiment.sh: $name: portable checkpoints of its trials in progress -> $(checkpoints_folder "$folder")"
    "${cmd[@]}" --save-checkpoints "$(checkpoints_folder "$folder")"
    exit $?
  done
  echo "paper_experiment.sh: every milestone finished on this machine: no trial in progress"
  exit 0
fi
if [ "$action" = status ]; then
  for m in "${milestones[@]}"; do
    read -r name arms generations folder <<<"$m"
    done_note=""
    [ -e "$dir/$name.done" ] && done_note=" (finished on this machine)"
    echo "paper_experiment.sh: $name: $arms to generation $generations$done_note"
    experiment_command "$arms" "$generations" "$folder"
    "${cmd[@]}" --status
  done
  exit 0
fi
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

milestone() {  # name, arms, generations, results folder
  if [ -e "$dir/$1.done" ]; then
    echo "paper_experiment.sh: $1 finished before on this machine ($dir/$1.done)"
    return 0
  fi
  echo "paper_experiment.sh: $1: $2 to generation $3 ($(date -u +%FT%TZ))"
  # Trials this milestone finished on another machine count from their committed compact results.
  mkdir -p "$dir/$4"
  local f
  for f in "$paper/$4"/*.results.json; do
    [ -e "$f" ] && [ ! -e "$dir/$4/$(basename "$f")" ] && cp "$f" "$dir/$4/"
  done
  experiment_command "$2" "$3" "$4"
  low_priority "${cmd[@]}"
  # Run again later, robozoo-experiment would write this milestone's results anew from logs
  # that a later milestone has extended: the marker keeps them as they are.
  date -u +%FT%TZ >"$dir/$1.done"
  echo "paper_experiment.sh: $1 done ($(date -u +%FT%TZ))"
}
for m in "${milestones[@]}"; do
  read -r name arms generations folder <<<"$m"
  milestone "$name" "$arms" "$generations" "$folder"
done
