#!/usr/bin/env bash
# clang-format (Debian 12's clang-format 14) over robozoo's C++ sources, with the
# style in .clang-format.
#
#   tools/format.sh --check   # lists the files clang-format would change; exit 1 if any
#   tools/format.sh --fix     # formats them in place
#
# The files: every tracked *.cpp, *.hpp, *.h and *.c (git ls-files).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  --check|--fix) mode=$1 ;;
  -h|--help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  "") echo "format.sh: give --check or --fix (see --help)" >&2; exit 2 ;;
  *) echo "format.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
esac
[ $# -le 1 ] || { echo "format.sh: one option only, not '$*'" >&2; exit 2; }
fmt=$(command -v clang-format-14 || command -v clang-format || true)
[ -n "$fmt" ] || { echo "format.sh: clang-format is missing: run tools/setup.sh" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.c')
if [ "$mode" = --fix ]; then
  printf '%s\0' "${files[@]}" | xargs -0 -n 50 "$fmt" -i --style=file
  echo "format.sh: formatted ${#files[@]} files"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  if ! "$fmt" --style=file "$f" | cmp -s - "$f"; then
    echo "$f"
    bad=$((bad + 1))
  fi
done
if [ "$bad" -gt 0 ]; then
  echo "format.sh: $bad of ${#files[@]} files are not formatted (tools/format.sh --fix)" >&2
  exit 1
fi
echo "format.sh: all ${#files[@]} files formatted"
