#!/usr/bin/env bash
# Checks that no function of libhair is longer than a reader can hold in their head:
# every function (and member function) in common/hair is at most MAX_LINES lines from
# its signature to its closing brace (default 120; common/hair/README.md). Reads the
# functions' extents with Universal Ctags (Debian universal-ctags).
#
#   scripts/check-function-length.sh [LIBHAIR_DIR] [MAX_LINES]
#
# Prints each longer function (lines, name, file:line) and exits 1 if there is one; exits
# 2 without Universal Ctags.
set -euo pipefail

root=${1:-"$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/common/hair"}
max_lines=${2:-120}
if ! ctags --version 2>/dev/null | grep -q "Universal Ctags"; then
  echo "check-function-length: needs Universal Ctags (apt-get install universal-ctags)" >&2
  exit 2
fi

# One line per function: end line, start line, name, file.
report=$(ctags -R --languages=C++ --kinds-C++=f --fields=+ne -x \
           --_xformat='%{end} %{line} %N %F' "$root" |
         awk -v max="$max_lines" '$1 - $2 + 1 > max { printf "%d lines: %s (%s:%d)\n", $1 - $2 + 1, $3, $4, $2 }' |
         sort -rn)
count=$(ctags -R --languages=C++ --kinds-C++=f -x --_xformat='%N' "$root" | wc -l)
if [[ -n "$report" ]]; then
  echo "$report"
  echo "check-function-length: $(wc -l <<<"$report") of $count functions in $root are over $max_lines lines" >&2
  exit 1
fi
echo "check-function-length: all $count functions in $root are within $max_lines lines"
