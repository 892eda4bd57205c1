#!/usr/bin/env bash
# The paper-size experiment, grown over days with pinned software versions, at low priority.
#
#   tools/experiment/paper_experiment.sh [--dir DIR] [--workers N]  # run (or resume) the milestones
#   tools/experiment/paper_experiment.sh --collect [--dir DIR]      # copy the compact results into the repository
#   tools/experiment/paper_experiment.sh --status [--dir DIR]       # where each milestone stands
#   tools/experiment/paper_experiment.sh --save-checkpoints [--dir DIR]  # trials in progress -> the repository (before a stop)
#
# For a test of the script itself (the paper's sizes are the defaults):
#   --bin BIN: robozoo-evolve and robozoo-experiment from BIN (no clone, no build, no VERSION);
#   --paper FOLDER: the committed results' folder (default media/experiment/paper);
#   --trials N (M1-M3), --sensitivity-trials N, --population N, --steps N,
#   --generations G1,G2,G3,GS,G4,G5,G6 (M1, M2, M3, the sensitivity study, M3's extensions).
#
# The milestones, in order, population 150 and 2,500 steps throughout
# (docs/experiment.md):
#   M1  the four arms (feedforward, recurrent, recurrent-sparse, recurrent-zero), 30 trials
#       each, to generation 30                                      results in results/
#   M2  feedforward and recurrent continued to generation 60        m2/results/
#   M3  feedforward and recurrent, 30 trials each, to generation 60, with the authors' own
#       settings (bias input 0.3, HyperNEAT's weight mapping, fresh add-node numbers)
#                                                                    m3/results/
#   S-<factor>  the sensitivity study: one factor at a time changed from M3's configuration,
#       the first 10 trials of each arm (M3's seeds), to generation 30
#                                                                    sensitivity/<factor>/results/
#       bias-1.0 (growth.bias_input=1.0), proportional-weights (growth.weight_mapping=
#       proportional), shared-add-node (neat.add_node_innovations=shared), no-contact-rule
#       (sim.rolling_contact_rule=false), cap-100 (growth.max_spheres=100)
#   M3-100, M3-150, M3-500  M3's trials continued to generations 100, 150 and 500
#                                                                    m3/g100/results/, ...
# M1 and M2 ran the version in media/experiment/paper/VERSION; M3, the sensitivity study and
# M3's extensions the one in media/experiment/paper/m3/VERSION, which their first start
# writes (this checkout's commit). Each version is cloned from this repository into
# DIR/src-<commit> and its robozoo-evolve and robozoo-experiment built there once; every
# trial runs under nice 19 in a session of its own whose autogroup is at nice 19 too (with
# the kernel's autogroup scheduling, nice ranks a process only within its session), with
# logs in DIR/runs (M1, M2), DIR/m3/runs (M3 and its extensions) and
# DIR/sensitivity/<factor>/runs. Each milestone keeps its own compact results, so a later
# milestone never replaces the results an earlier report was made from; a milestone that
# finished on this machine (DIR/<name>.done) is not run again, and one whose every trial has
# its compact result in the repository is not run at all (nothing is built for it). Stop it
# at any time (kill, or the machine stops); the same command resumes where it stood: trials
# a milestone finished elsewhere count from their committed compact results, the others
# continue from their committed portable checkpoints (--save-checkpoints) and the others
# start again from generation 0 where their logs and checkpoints are not here.
# --collect copies each milestone's compact results into media/experiment/paper/ and
# checks that each continued milestone's trials repeat the one they continue (M2 M1's, M3-100
# M3's, ...: build/bin/robozoo-stats --same-as; exit 1 when one does not).
# --save-checkpoints writes the portable checkpoint of each trial in progress of the
# milestone being run (the first without DIR/<name>.done whose results are not all
# committed) into the repository beside its compact results (checkpoints/ for M1,
# m3/checkpoints/, sensitivity/<factor>/checkpoints/, ...; 40-280 kB a trial) and removes
# those of finished trials, in every milestone, copying their compact results into the
# repository as --collect does (without its checks): commit them, and the run on a fresh clone
# continues those trials from there instead of generation 0. A later milestone that continues
# one finished here (M3-100 M3's) or the one being run gets the portable checkpoints of the
# trials that one finished, in its own checkpoints/ (m3/g100/checkpoints/, ...).
# DIR defaults to /var/tmp/robozoo-paper.
set -euo pipefail
cd "$(dirname "$0")/../.."
repo=$(pwd)
dir=/var/tmp/robozoo-paper
workers=$(nproc)
action=run
bin=""
paper=media/experiment/paper
trials=30
sensitivity_trials=10
population=150
steps=""
generations=30,60,60,30,100,150,500
while [ $# -gt 0 ]; do
  case "$1" in
    --dir) dir=${2:?--dir needs a folder}; shift 2 ;;
    --workers) workers=${2:?--workers needs a number}; shift 2 ;;
    --bin) bin=${2:?--bin needs a folder}; shift 2 ;;
    --paper) paper=${2:?--paper needs a folder}; shift 2 ;;
    --trials) trials=${2:?--trials needs a number}; shift 2 ;;
    --sensitivity-trials) sensitivity_trials=${2:?--sensitivity-trials needs a number}; shift 2 ;;
    --population) population=${2:?--population needs a number}; shift 2 ;;
    --steps) steps=${2:?--steps needs a number}; shift 2 ;;
    --generations) generations=${2:?--generations needs G1,G2,G3,GS,G4,G5,G6}; shift 2 ;;
    --collect) action=collect; shift ;;
    --status) action=status; shift ;;
    --save-checkpoints) action=save; shift ;;
    -h|--help) sed -n '2,/^# DIR defaults/p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "paper_experiment.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
IFS=, read -r g1 g2 g3 gs g4 g5 g6 extra <<<"$generations"
[ -z "${extra:-}" ] || { echo "paper_experiment.sh: --generations takes seven counts (see --help)" >&2; exit 2; }
for n in "$workers" "$trials" "$sensitivity_trials" "$population" "$g1" "$g2" "$g3" "$gs" "$g4" "$g5" "$g6" ${steps:+"$steps"}; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "paper_experiment.sh: not a positive count: '$n' (see --help)" >&2; exit 2; }
done
mkdir -p "$dir"
# M3's configuration, stated in full, so that its checkpoints and results are checked against it.
m3_sets="growth.bias_input=0.3,growth.weight_mapping=rescaled,neat.add_node_innovations=fresh"
# The milestones: name, version file (under $paper), runs folder, arms, generations, trials,
# results folder (under DIR and under $paper), --set assignments (comma-separated, - for none),
# the milestone it continues (- for none: its trials repeat that one's generations).
milestones=(
  "M1 VERSION runs feedforward,recurrent,recurrent-sparse,recurrent-zero $g1 $trials results - -"
  "M2 VERSION runs feedforward,recurrent $g2 $trials m2/results - M1"
  "M3 m3/VERSION m3/runs feedforward,recurrent $g3 $trials m3/results $m3_sets -"
  "S-bias-1.0 m3/VERSION sensitivity/bias-1.0/runs feedforward,recurrent $gs $sensitivity_trials sensitivity/bias-1.0/results growth.bias_input=1.0 -"
  "S-proportional-weights m3/VERSION sensitivity/proportional-weights/runs feedforward,recurrent $gs $sensitivity_trials sensitivity/proportional-weights/results growth.weight_mapping=proportional -"
  "S-shared-add-node m3/VERSION sensitivity/shared-add-node/runs feedforward,recurrent $gs $sensitivity_trials sensitivity/shared-add-node/results neat.add_node_innovations=shared -"
  "S-no-contact-rule m3/VERSION sensitivity/no-contact-rule/runs feedforward,recurrent $gs $sensitivity_trials sensitivity/no-contact-rule/results sim.rolling_contact_rule=false -"
  "S-cap-100 m3/VERSION sensitivity/cap-100/runs feedforward,recurrent $gs $sensitivity_trials sensitivity/cap-100/results growth.max_spheres=100 -"
  "M3-100 m3/VERSION m3/runs feedforward,recurrent $g4 $trials m3/g100/results $m3_sets M3"
  "M3-150 m3/VERSION m3/runs feedforward,recurrent $g5 $trials m3/g150/results $m3_sets M3-100"
  "M3-500 m3/VERSION m3/runs feedforward,recurrent $g6 $trials m3/g500/results $m3_sets M3-150"
)
folder_of() {  # milestone name -> its results folder
  local m name rest
  for m in "${milestones[@]}"; do
    read -r name _ _ _ _ _ rest _ <<<"$m"
    [ "$name" = "$1" ] && { echo "$rest"; return 0; }
  done
  return 1
}

# Copies a milestone's compact results from DIR into the repository (name, results folder):
# n counts them, copied those that were not there as they are.
copy_results() {
  local f target
  n=0
  copied=0
  for f in "$dir/$2"/*.results.json; do
    [ -e "$f" ] || continue
    n=$((n + 1))
    target="$paper/$2/$(basename "$f")"
    cmp -s "$f" "$target" && continue
    mkdir -p "$paper/$2"
    if ! { cp "$f" "$paper/$2/.tmp.$$" && mv "$paper/$2/.tmp.$$" "$target"; }; then
      echo "paper_experiment.sh: $1: could not copy $f into $paper/$2" >&2
      rm -f "$paper/$2/.tmp.$$"
      exit 1
    fi
    copied=$((copied + 1))
  done
}

if [ "$action" = collect ]; then
  # A continued milestone's trials must repeat the one they continue (runs are
  # deterministic): robozoo-stats --same-as checks it, with this checkout's build.
  stats="${bin:-build/bin}/robozoo-stats"
  status=0
  for m in "${milestones[@]}"; do
    read -r name _ _ _ _ _ folder _ continues <<<"$m"
    copy_results "$name" "$folder"
    [ "$n" -gt 0 ] || [ -d "$paper/$folder" ] || continue
    echo "paper_experiment.sh: $name: $n compact results in $paper/$folder/"
    [ "$continues" != - ] || continue
    prev_folder=$(folder_of "$continues")
    if [ -d "$paper/$folder" ] && [ -d "$paper/$prev_folder" ]; then
      if [ ! -x "$stats" ]; then
        echo "paper_experiment.sh: $name: not checked against $continues's results: no $stats (tools/build.sh robozoo-stats)"
      elif check=$("$stats" "$paper/$folder" --same-as "$paper/$prev_folder" 2>&1); then
        echo "paper_experiment.sh: $name: $(tail -n 1 <<<"$check") ($continues's)"
      else
        echo "paper_experiment.sh: $name: its results do not repeat $continues's generations:" >&2
        grep -v ' agree$' <<<"$check" >&2 || true
        status=1
      fi
    fi
  done
  exit $status
fi

# True when every trial of a milestone (results folder, arms, trials) has its compact result in
# the repository.
all_committed() {
  local arm_list
  IFS=, read -r -a arm_list <<<"$2"
  [ "$(find "$paper/$1" -maxdepth 1 -name '*.results.json' 2>/dev/null | wc -l)" -ge $((${#arm_list[@]} * $3)) ]
}

# True when the programs of the version recorded in $paper/$1 are built here (or --bin).
version_built() {
  [ -z "$fixed_bin" ] || return 0
  [ -f "$paper/$1" ] || return 1
  local commit
  commit=$(git rev-parse -q --verify "$(head -n 1 "$paper/$1")^{commit}") || return 1
  [ -x "$dir/src-${commit:0:12}/build/bin/robozoo-experiment" ] && [ -x "$dir/src-${commit:0:12}/build/bin/robozoo-evolve" ]
}

# Sets bin to the programs of the version recorded in $paper/$1 (writing it first: this
# checkout's commit), cloned and built once in DIR/src-<commit>; with --bin, that folder.
use_version() {
  [ -z "$fixed_bin" ] || { bin=$fixed_bin; return 0; }
  local file="$paper/$1" commit
  if [ -f "$file" ]; then
    commit=$(head -n 1 "$file")
  else
    commit=$(git rev-parse HEAD)
    if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
      echo "paper_experiment.sh: the work tree has uncommitted changes; commit them before $file is written" >&2
      exit 2
    fi
    mkdir -p "$(dirname "$file")"
    echo "$commit" >"$file"
    echo "paper_experiment.sh: recorded the version of the milestones that use $file ($commit): commit that file"
  fi
  git cat-file -e "$commit^{commit}" 2>/dev/null || { echo "paper_experiment.sh: no commit $commit here" >&2; exit 2; }
  commit=$(git rev-parse "$commit")
  local src="$dir/src-${commit:0:12}"
  bin="$src/build/bin"
  if [ ! -x "$bin/robozoo-experiment" ] || [ ! -x "$bin/robozoo-evolve" ]; then
    echo "paper_experiment.sh: building robozoo $commit in $src"
    rm -rf "$src"
    git clone -q "$repo" "$src"
    git -C "$src" checkout -q "$commit"
    local launcher=()
    command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    cmake -S "$src" -B "$src/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF "${launcher[@]}" >/dev/null
    nice -n 10 cmake --build "$src/build" -j"$(nproc)" --target robozoo-evolve robozoo-experiment >/dev/null
  fi
  echo "paper_experiment.sh: robozoo $("$bin/robozoo-evolve" --version)"
}
fixed_bin=$bin

# A milestone's portable checkpoints in the repository: beside its results folder (results -> checkpoints).
checkpoints_folder() { echo "$paper/${1%results}checkpoints"; }
experiment_command() {  # runs folder, arms, generations, trials, results folder, sets: sets cmd
  cmd=("$bin/robozoo-experiment" --out "$dir/$1" --results "$dir/$5" --trials "$4" --population "$population"
    --workers "$workers" --arms "$2" --generations "$3" ${steps:+--steps "$steps"})
  # M1 and M2's version predates portable checkpoints: its robozoo-experiment has no --checkpoints.
  # (Read whole, not piped to grep -q: grep's early exit would fail the pipe under pipefail.)
  if [[ "$("$bin/robozoo-experiment" --help 2>/dev/null || true)" == *--checkpoints* ]]; then
    cmd+=(--checkpoints "$(checkpoints_folder "$5")")
  fi
  local kv
  if [ "$6" != - ]; then
    IFS=, read -r -a assignments <<<"$6"
    for kv in "${assignments[@]}"; do cmd+=(--set "$kv"); done
  fi
}
if [ "$action" = save ]; then
  # A trial with its compact result (committed, or finished here) is no longer in progress:
  # its portable checkpoint goes, in every milestone, the finished ones included, and the
  # compact results finished here come into the repository in its place (as --collect copies
  # them), so that no trial leaves the repository as a checkpoint without arriving as a result.
  # (Before and after: a trial that finishes while this runs is counted too.)
  copy_all_results() {
    local m name folder
    for m in "${milestones[@]}"; do
      read -r name _ _ _ _ _ folder _ _ <<<"$m"
      copy_results "$name" "$folder"
      [ "$copied" -eq 0 ] || echo "paper_experiment.sh: $name: $copied compact results finished here -> $paper/$folder/"
    done
  }
  copy_all_results
  for m in "${milestones[@]}"; do
    read -r name _ _ _ _ _ folder _ _ <<<"$m"
    for f in "$(checkpoints_folder "$folder")"/*.portable-checkpoint; do
      [ -e "$f" ] || continue
      trial=$(basename "$f" .portable-checkpoint)
      if [ -e "$paper/$folder/$trial.results.json" ] || [ -e "$dir/$folder/$trial.results.json" ]; then
        rm -f "$f"
        echo "paper_experiment.sh: $name: $trial finished: removed $f"
      fi
    done
  done
  save_milestone() {  # milestone line: writes the portable checkpoints of its trials in progress here
    local name version runs arms gens ntrials folder sets
    read -r name version runs arms gens ntrials folder sets _ <<<"$1"
    use_version "$version"
    experiment_command "$runs" "$arms" "$gens" "$ntrials" "$folder" "$sets"
    if [[ "$("$bin/robozoo-experiment" --help 2>/dev/null || true)" != *--save-checkpoints* ]]; then
      echo "paper_experiment.sh: $name runs a robozoo version without portable checkpoints ($paper/$version): its trials in progress cannot be saved" >&2
      exit 2
    fi
    "${cmd[@]}" --save-checkpoints "$(checkpoints_folder "$folder")"
  }
  # The milestone being run: the first not finished here whose results are not all committed.
  active=""
  status=0
  for m in "${milestones[@]}"; do
    read -r name _ _ arms _ ntrials folder _ _ <<<"$m"
    [ -e "$dir/$name.done" ] && continue
    all_committed "$folder" "$arms" "$ntrials" && continue
    active=$name
    echo "paper_experiment.sh: $name: portable checkpoints of its trials in progress -> $(checkpoints_folder "$folder")"
    save_milestone "$m" || status=$?
    break
  done
  # A later milestone that continues one finished here, or the one being run, continues the
  # trials that one finished from their logs here: they travel too, in the later milestone's
  # checkpoints/ (a new machine has neither those logs nor the trials in it otherwise, and would
  # run them again from generation 0). A trial still running in the milestone being run travels
  # in that milestone's checkpoints/ only.
  for m in "${milestones[@]}"; do
    read -r name _ _ arms _ ntrials folder _ continues <<<"$m"
    [ "$continues" != - ] && [ "$name" != "$active" ] || continue
    [ -e "$dir/$name.done" ] && continue
    all_committed "$folder" "$arms" "$ntrials" && continue
    [ -e "$dir/$continues.done" ] || [ "$continues" = "$active" ] || continue
    echo "paper_experiment.sh: $name: portable checkpoints of the trials $continues finished here -> $(checkpoints_folder "$folder")"
    save_milestone "$m" || status=$?
    [ "$continues" = "$active" ] || continue
    prev_folder=$(folder_of "$continues")
    for f in "$(checkpoints_folder "$folder")"/*.portable-checkpoint; do
      [ -e "$f" ] || continue
      trial=$(basename "$f" .portable-checkpoint)
      if [ ! -e "$paper/$prev_folder/$trial.results.json" ] && [ ! -e "$dir/$prev_folder/$trial.results.json" ]; then
        rm -f "$f"
        echo "paper_experiment.sh: $name: $trial is still running in $continues: removed $f"
      fi
    done
  done
  copy_all_results
  [ -n "$active" ] || echo "paper_experiment.sh: every milestone finished on this machine: no trial in progress"
  exit $status
fi
if [ "$action" = status ]; then
  for m in "${milestones[@]}"; do
    read -r name version runs arms gens ntrials folder sets _ <<<"$m"
    if all_committed "$folder" "$arms" "$ntrials"; then
      echo "paper_experiment.sh: $name: every trial's compact result is in $paper/$folder"
      continue
    fi
    done_note=""
    [ -e "$dir/$name.done" ] && done_note=" (finished on this machine)"
    echo "paper_experiment.sh: $name: $arms to generation $gens, $ntrials trials each$done_note"
    # A question builds nothing: a milestone whose version is not built here has not started here.
    if ! version_built "$version"; then
      echo "  not started on this machine (its version, $paper/$version, is not built in $dir)"
      continue
    fi
    use_version "$version"
    experiment_command "$runs" "$arms" "$gens" "$ntrials" "$folder" "$sets"
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

milestone() {  # name, version file, runs folder, arms, generations, trials, results folder, sets
  local name=$1 version=$2 runs=$3 arms=$4 gens=$5 ntrials=$6 folder=$7 sets=$8
  if [ -e "$dir/$name.done" ]; then
    echo "paper_experiment.sh: $name finished before on this machine ($dir/$name.done)"
    return 0
  fi
  # Trials this milestone finished on another machine count from their committed compact results.
  mkdir -p "$dir/$folder"
  local f
  for f in "$paper/$folder"/*.results.json; do
    [ -e "$f" ] && [ ! -e "$dir/$folder/$(basename "$f")" ] && cp "$f" "$dir/$folder/"
  done
  if all_committed "$folder" "$arms" "$ntrials"; then
    echo "paper_experiment.sh: $name: every trial's compact result is in $paper/$folder; nothing to run"
    return 0
  fi
  echo "paper_experiment.sh: $name: $arms to generation $gens, $ntrials trials each ($(date -u +%FT%TZ))"
  use_version "$version"
  experiment_command "$runs" "$arms" "$gens" "$ntrials" "$folder" "$sets"
  low_priority "${cmd[@]}"
  # Run again later, robozoo-experiment would write this milestone's results anew from logs
  # that a later milestone has extended: the marker keeps them as they are.
  date -u +%FT%TZ >"$dir/$name.done"
  echo "paper_experiment.sh: $name done ($(date -u +%FT%TZ))"
}
for m in "${milestones[@]}"; do
  read -r name version runs arms gens ntrials folder sets _ <<<"$m"
  milestone "$name" "$version" "$runs" "$arms" "$gens" "$ntrials" "$folder" "$sets"
done
