#!/usr/bin/env bash
# Installs the npm packages robozoo's checks use (tools/npm/package-lock.json:
# @mcap/core and @mcap/support to read MCAP files, ajv to validate JSON,
# @foxglove/schemas, @foxglove/crc) into a folder outside git, by default
# build/npm. Idempotent: installs again only when the lock file changed.
#   tools/npm_deps.sh [DIR]      prints DIR/node_modules on success
set -euo pipefail
case "${1:-}" in
  -h|--help) echo "tools/npm_deps.sh [DIR]: installs the pinned npm packages of the MCAP checks into DIR (default build/npm), prints DIR/node_modules"; exit 0 ;;
  -*) echo "npm_deps.sh: unknown option $1 (tools/npm_deps.sh [DIR])" >&2; exit 2 ;;
esac
if [ $# -gt 1 ]; then echo "npm_deps.sh: one folder at most, not $#" >&2; exit 2; fi

here="$(cd "$(dirname "$0")" && pwd)"
dir="${1:-$here/../build/npm}"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
for tool in node npm; do
  command -v "$tool" >/dev/null 2>&1 || { echo "npm_deps: $tool missing (tools/setup.sh installs Debian's nodejs npm)" >&2; exit 1; }
done
stamp="$dir/.robozoo-lock.sha256"
want="$(sha256sum "$here/npm/package-lock.json" | cut -d' ' -f1)"
if [ -d "$dir/node_modules" ] && [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
  echo "$dir/node_modules"
  exit 0
fi
# Several tests may call this at once: one installs, the others wait for it.
exec 9>"$dir/.lock"
flock 9
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ]; then
  cp "$here/npm/package.json" "$here/npm/package-lock.json" "$dir/"
  (cd "$dir" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error >&2)
  echo "$want" >"$stamp"
fi
echo "$dir/node_modules"
