#!/usr/bin/env bash
# Installs the Debian 12 packages robozoo needs (apt-get, as root or with sudo).
# Idempotent: runs `apt-get update` and `apt-get install` only when something is missing.
#
#   tools/setup.sh             # everything: build, run, test, fuzz, format, the browser and MCAP checks
#   tools/setup.sh --demo      # only what tools/demo.sh needs: to build the programs and run its four
set -euo pipefail
usage() { sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; }
demo_only=0
case "${1:-}" in
  "") ;;
  --demo) demo_only=1 ;;
  -h|--help) usage; exit 0 ;;
  *) echo "setup.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
esac
[ $# -le 1 ] || { echo "setup.sh: one option at most (see --help)" >&2; exit 2; }

# To build every program (and configure the tests), and run robozoo-evolve, -replay, -render and -view.
PROGRAMS=(
  build-essential cmake ninja-build pkg-config git
  liblcm-dev liblcm-bin libglib2.0-dev
  libode-dev libeigen3-dev
  libosmesa6-dev libglu1-mesa-dev libpng-dev
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  libfreetype-dev fonts-dejavu-core
  libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libboost-math-dev libboost-dev
  libjs-three                # robozoo-view's 3-D scene
  libgtest-dev               # the tests are configured with the programs
  openmpi-bin libopenmpi-dev # robozoo-evolve --mpi
  zlib1g-dev                 # CRC-32 (worker frames, MCAP)
  libzstd-dev liblz4-dev     # robozoo-log export (MCAP chunks)
)
# The rest: the tests, the study tools' figures, lcm-spy and the development tools.
DEVELOPMENT=(
  liblcm-java default-jdk-headless   # lcm-spy and its Java message types
  ffmpeg                     # ffprobe and ffmpeg, to look at the videos
  chromium                   # the browser tests
  gnuplot-nox                # robozoo-stats' figures
  iproute2 util-linux        # the private network namespaces of the bus tests
  graphviz nodejs npm        # robozoo-log cppn; the MCAP check's node
  clang libclang-rt-14-dev   # libFuzzer and clang's sanitizer runtimes (tools/fuzz.sh)
  clang-format               # tools/format.sh (clang-format 14)
  debootstrap                # a bare Debian 12 folder, to time tools/demo.sh as a new machine (docs/performance.md)
)
PACKAGES=("${PROGRAMS[@]}")
[ "$demo_only" = 1 ] || PACKAGES+=("${DEVELOPMENT[@]}")

missing=()
for p in "${PACKAGES[@]}"; do
  # NodeSource's nodejs package carries npm itself and conflicts with Debian's npm package.
  if [ "$p" = npm ] && command -v npm >/dev/null 2>&1; then continue; fi
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
