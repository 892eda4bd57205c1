#!/usr/bin/env bash
# The README's main command: install what is missing, build, run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
tools/build.sh
echo "demo: XOR with CPPN-NEAT (the proof of the NEAT core)"
build/bin/robozoo-xor --runs 10 --seed 1
