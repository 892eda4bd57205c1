#!/usr/bin/env bash
# check_layers.sh: the floors of robozoo's rooms. Every #include of a robozoo
# header ("FOLDER/..." or <FOLDER/...>) in a C++ file under a top-level folder
# must name its own folder or a folder on a lower floor; folders on the same
# floor do not include each other. The order, bottom up, written once here:
#
#   util, the generated lcmtypes (robozoo/...)
#   evolve                    (robozoo_core, robozoo_mpi, robozoo-evolve)
#   runlog                    (the one reader of logs)
#   study                     (the experiment and its analysis)
#   render, replay            (draw and check runs, logged or compact)
#   view, tools
#   tests, fuzz               (may include anything)
#
# So evolve/ includes only evolve/, util/ and robozoo/; runlog/ adds evolve/.
# Prints each include that breaks the rule (file:line) and exits 1; exits 0
# when none does. Run by ctest (check_layers; check_layers_test plants
# violations in a made-up tree and expects them found). docs/architecture.md.
#
#   tools/check_layers.sh             # the repository this script is in
#   tools/check_layers.sh --root DIR  # another tree laid out the same way
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --root)
      [ $# -ge 2 ] || { echo "check_layers.sh: --root needs a folder" >&2; exit 2; }
      root="$2"; shift 2 ;;
    *) echo "check_layers.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
[ -d "$root" ] || { echo "check_layers.sh: $root is not a folder" >&2; exit 2; }

# The floors, bottom up: the one place the order is written.
floors=(
  "util robozoo"
  "evolve"
  "runlog"
  "study"
  "render replay"
  "view tools"
  "tests fuzz"
)
declare -A floor_of
for i in "${!floors[@]}"; do
  for f in ${floors[$i]}; do floor_of[$f]=$i; done
done
known="$(echo "${floors[@]}" | tr ' ' '|')"

status=0
checked=0
include_re="^[[:space:]]*#[[:space:]]*include[[:space:]]*[\"<]([a-z]+)/"
for i in "${!floors[@]}"; do
  for folder in ${floors[$i]}; do
    [ -d "$root/$folder" ] || continue
    while IFS=: read -r file line text; do
      checked=$((checked + 1))
      [[ "$text" =~ $include_re ]] || continue
      target="${BASH_REMATCH[1]}"
      [ "$target" = "$folder" ] && continue
      if [ "${floor_of[$target]}" -ge "$i" ]; then
        echo "${file#"$root"/}:$line: $folder/ (floor $i) includes $target/ (floor ${floor_of[$target]}):" \
             "$folder/ may include only its own folder and the floors below it"
        status=1
      fi
    done < <(grep -rnE --include='*.cpp' --include='*.hpp' --include='*.h' --include='*.c' --include='*.cc' \
               --exclude-dir=node_modules "^[[:space:]]*#[[:space:]]*include[[:space:]]*[\"<]($known)/" \
               "$root/$folder" || true)
  done
done
if [ "$status" -ne 0 ]; then
  echo "check_layers.sh: a lower floor includes a higher one (above); move the code down or the include up" >&2
else
  echo "check_layers.sh: $checked includes of robozoo headers, each on its own floor or below"
fi
exit "$status"
