#!/usr/bin/env bash
# The README's main command: install what is missing, build, and run the main job:
# a short evolution (--preset short: population 100, 40 generations, recurrent
# CPPNs, all cores) whose LCM log lands in runs/demo.lcmlog.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh
mkdir -p runs
rm -f runs/demo.lcmlog runs/demo.lcmlog.checkpoint
start=$(date +%s)
build/bin/robozoo-evolve --preset short --regime recurrent --seed 1 --log runs/demo.lcmlog
echo "demo: evolution done in $(( $(date +%s) - start )) s; log runs/demo.lcmlog ($(du -h runs/demo.lcmlog | cut -f1))"
