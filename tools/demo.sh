#!/usr/bin/env bash
# The README's main command: install what is missing, build, and run the main job:
# a short evolution (--preset short: population 100, 40 generations, recurrent
# CPPNs, all cores) whose LCM log lands in runs/demo.lcmlog, then a zoo sheet of
# its best champions (runs/demo-zoo.png) and a video of its champion
# (runs/demo-champion.mp4), drawn headless with OSMesa.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh
mkdir -p runs
rm -f runs/demo.lcmlog runs/demo.lcmlog.checkpoint
start=$(date +%s)
build/bin/robozoo-evolve --preset short --regime recurrent --seed 1 --log runs/demo.lcmlog
echo "demo: evolution done in $(( $(date +%s) - start )) s; log runs/demo.lcmlog ($(du -h runs/demo.lcmlog | cut -f1))"
build/bin/robozoo-render zoo runs/demo.lcmlog --top 8 -o runs/demo-zoo.png
build/bin/robozoo-render video runs/demo.lcmlog -o runs/demo-champion.mp4
echo "demo: done in $(( $(date +%s) - start )) s: runs/demo.lcmlog, runs/demo-zoo.png, runs/demo-champion.mp4"
