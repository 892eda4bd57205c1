#!/usr/bin/env bash
# The README's main command: installs what is missing, builds the four programs it
# runs, and shows them together on one short evolution published on LCM (loopback
# only, ttl=0): robozoo-view follows the run live in the browser (its address is
# printed first), robozoo-replay check --lcm-url proves each champion as the run goes
# (its verdict is printed at the end), then robozoo-render draws a zoo sheet of the
# best champions and films the best one from the log.
#
#   tools/demo.sh [--port N] [--population N] [--generations N] [--seed N]
#
# Defaults: port 8080, population 50, 16 generations, seed 1, recurrent CPPNs, one
# worker per core (under 10 minutes on a bare 2-core Debian 12 machine: about 4 to 4.5
# to install the packages, 3.5 to build, 1.5 to run; docs/performance.md).
# Leaves in runs/: demo.lcmlog (and its checkpoint), demo-zoo.png, demo-champion.mp4,
# demo-check.txt (the live check's report) and demo-view.txt (the viewer's output).
# Ctrl-C stops everything it started.
set -euo pipefail
cd "$(dirname "$0")/.."
port=8080
population=50
generations=16
seed=1
number() {  # option, value
  [[ "${2:-}" =~ ^[0-9]+$ ]] || { echo "demo.sh: $1 needs a whole number, not '${2:-}'" >&2; exit 2; }
}
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --port) number "$1" "${2:-}"; port=$2; shift 2 ;;
    --population) number "$1" "${2:-}"; population=$2; shift 2 ;;
    --generations) number "$1" "${2:-}"; generations=$2; shift 2 ;;
    --seed) number "$1" "${2:-}"; seed=$2; shift 2 ;;
    *) echo "demo.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
# LCM's default URL: multicast with ttl=0 never leaves this machine.
url='udpm://239.255.76.67:7667?ttl=0'
bin=build/bin
t0=$(date +%s)
echo "demo: the run will be live at http://127.0.0.1:$port/ once its programs are built (a few minutes)"
tools/setup.sh --demo
tools/build.sh robozoo-evolve robozoo-view robozoo-replay robozoo-render
echo "demo: built in $(($(date +%s) - t0)) s"

mkdir -p runs
rm -f runs/demo.lcmlog runs/demo.lcmlog.checkpoint runs/demo-zoo.png runs/demo-champion.mp4 runs/demo-check.txt \
  runs/demo-view.txt
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
}
trap cleanup EXIT
trap 'echo "demo: interrupted" >&2; exit 130' INT TERM

"$bin/robozoo-view" --lcm-url "$url" --port "$port" --quiet >runs/demo-view.txt 2>&1 &
view=$!
pids+=("$view")
# The viewer prints its address once it listens; a port in use ends it at once.
for _ in $(seq 50); do
  grep -q 'http://' runs/demo-view.txt && break
  kill -0 "$view" 2>/dev/null || break
  sleep 0.1
done
if ! kill -0 "$view" 2>/dev/null; then
  echo "demo: robozoo-view did not start: $(head -n 1 runs/demo-view.txt) (another port: tools/demo.sh --port N)" >&2
  exit 1
fi
echo "demo: watch it live: http://127.0.0.1:$port/"

"$bin/robozoo-replay" check --lcm-url "$url" --idle-exit 20 --no-progress >runs/demo-check.txt 2>&1 &
check=$!
pids+=("$check")

start=$(date +%s)
"$bin/robozoo-evolve" --regime recurrent --seed "$seed" --population "$population" --generations "$generations" \
  --lcm-url "$url" --log runs/demo.lcmlog
echo "demo: evolution done in $(($(date +%s) - start)) s; log runs/demo.lcmlog ($(du -h runs/demo.lcmlog | cut -f1))"

"$bin/robozoo-render" zoo runs/demo.lcmlog --top 8 -o runs/demo-zoo.png
"$bin/robozoo-render" video runs/demo.lcmlog -o runs/demo-champion.mp4

# The live check ends 20 s after the run's last message, with its verdict.
check_status=0
wait "$check" || check_status=$?
echo "demo: robozoo-replay check --lcm-url (runs/demo-check.txt) ended with status $check_status:"
tail -n 5 runs/demo-check.txt | sed 's/^/    /'
echo "demo: done in $(($(date +%s) - t0)) s: runs/demo.lcmlog, runs/demo-zoo.png, runs/demo-champion.mp4;" \
  "the viewer stops now"
exit "$check_status"
