#!/usr/bin/env bash
# How many events of a live robozoo-evolve run does lcm-logger 1.3.1 lose under
# each pacing of the bus: the default (one message every 20 ms and 1 MB/s), bytes
# only (--bus-message-rate 0: small poses go out 64 kB at once, past LCM's queue
# of 31 messages) and none? Each trial runs in a private network namespace
# (unshare -rn, no root needed): lcm-logger records the bus while robozoo-evolve
# publishes a run at the default --pose-every (4); robozoo-log bus then counts
# what the recording lacks. Prints one line per trial and a table per variant.
#
#   tools/measure/bus_loss_study.sh [TRIALS]  # default 5 trials per variant
set -euo pipefail
cd "$(dirname "$0")/../.."
trials="${1:-5}"
case "$trials" in -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
[ $# -le 1 ] && [[ "$trials" =~ ^[1-9][0-9]*$ ]] || {
  echo "bus_loss_study.sh: unknown option $* (only TRIALS, a positive number, or --help)" >&2
  exit 2
}
bin=build/bin
for b in robozoo-evolve robozoo-log; do
  [ -x "$bin/$b" ] || { echo "bus_loss_study: $bin/$b is missing: run tools/build.sh first" >&2; exit 2; }
done
command -v lcm-logger >/dev/null || { echo "bus_loss_study: lcm-logger is missing: run tools/setup.sh" >&2; exit 2; }
url="udpm://239.255.76.67:7667?ttl=0"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# name | lcm-logger's URL suffix | evolve's pacing options
variants=(
  "default (50 messages/s, 1 MB/s)||"
  "bytes only (--bus-message-rate 0)||--bus-message-rate 0"
  "unpaced||--bus-rate 0 --bus-message-rate 0"
)
printf "%-38s %6s %9s %9s %9s %s\n" variant trial sent missing pose_json_kB note
declare -A lost_trials total_missing
for v in "${variants[@]}"; do
  IFS='|' read -r name suffix pacing <<<"$v"
  lost_trials[$name]=0
  total_missing[$name]=0
  for t in $(seq 1 "$trials"); do
    d="$work/$t"; rm -rf "$d"; mkdir -p "$d"
    unshare -rn sh -c "ip link set lo up && ip route add 224.0.0.0/4 dev lo && \
      (lcm-logger -f --lcm-url='$url$suffix' '$d/bus.lcmlog' >/dev/null 2>&1 & L=\$!; sleep 1; \
       $bin/robozoo-evolve --log '$d/own.lcmlog' --seed $((t + 100)) --population 24 --generations 4 \
         --steps 1000 --workers 1 --quiet --lcm-url '$url' $pacing >'$d/evolve.txt' 2>&1; \
       sleep 1; kill -INT \$L; wait \$L)" || { echo "trial failed"; cat "$d/evolve.txt"; exit 1; }
    out=$($bin/robozoo-log bus "$d/own.lcmlog" "$d/bus.lcmlog" --json || true)
    sent=$(sed -E 's/.*"sent":([0-9]+).*/\1/' <<<"$out")
    missing=$(sed -E 's/.*"missing":([0-9]+).*/\1/' <<<"$out")
    defect=$(sed -E 's/.*"defect":("[^"]*"|null).*/\1/' <<<"$out")
    kb=$($bin/robozoo-log cat "$d/own.lcmlog" --channel pose | awk '{n++; b+=length($0)} END {if (n) printf "%.1f", b/n/1024; else print "-"}')
    failures=$(grep -o '[0-9]* publish failures' "$d/evolve.txt" || echo "?")
    printf '%-38s %6s %9s %9s %9s %s\n' "$name" "$t" "$sent" "$missing" "$kb" "defect ${defect}, evolve: $failures"
    [ "$missing" != "0" ] && lost_trials[$name]=$(( ${lost_trials[$name]} + 1 ))
    total_missing[$name]=$(( ${total_missing[$name]} + missing ))
  done
done
echo
printf '%-38s %18s %14s\n' variant "trials with loss" "events lost"
for v in "${variants[@]}"; do
  IFS='|' read -r name _ _ <<<"$v"
  printf '%-38s %12s of %-3s %14s\n' "$name" "${lost_trials[$name]}" "$trials" "${total_missing[$name]}"
done
echo "(load average while measuring: $(cut -d' ' -f1-3 /proc/loadavg))"
