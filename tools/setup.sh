#!/usr/bin/env bash
# Installs every Debian 12 package robozoo needs to build, test and run.
# Idempotent: runs `apt-get update` and `apt-get install` only when something is missing.
set -euo pipefail
case "${1:-}" in
  "") ;;
  -h|--help) echo "tools/setup.sh: installs the Debian 12 packages robozoo needs (apt-get, as root or with sudo); no options"; exit 0 ;;
  *) echo "setup.sh: unknown option $1 (no options but --help)" >&2; exit 2 ;;
esac

PACKAGES=(
  build-essential cmake pkg-config git
  liblcm-dev liblcm-bin liblcm-java libglib2.0-dev default-jdk-headless
  libode-dev libeigen3-dev
  libosmesa6-dev libglu1-mesa-dev libpng-dev
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev ffmpeg
  libfreetype-dev fonts-dejavu-core
  libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libboost-math-dev libboost-dev
  libjs-three chromium
  libgtest-dev gnuplot-nox
  openmpi-bin libopenmpi-dev
  iproute2 util-linux
  zlib1g-dev                 # CRC-32 (worker frames, MCAP)
  libzstd-dev liblz4-dev graphviz nodejs npm   # robozoo-log export (MCAP) and cppn; the MCAP check's node
  clang libclang-rt-14-dev   # libFuzzer and clang's sanitizer runtimes (tools/fuzz.sh)
  clang-format               # tools/format.sh (clang-format 14)
)

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
