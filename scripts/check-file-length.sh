#!/usr/bin/env bash
# Checks that every source file of libhair holds one concept a reader can take in: at most
# MAX_LINES lines (default 800; common/hair/README.md). A file over it holds several
# concepts and is split along their seams.
#
#   scripts/check-file-length.sh [LIBHAIR_DIR] [MAX_LINES]
#
# Prints each longer file (lines, path) and exits 1 if there is one.
set -euo pipefail

root=${1:-"$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/common/hair"}
max_lines=${2:-800}
files=$(find "$root" -type f \( -name '*.cpp' -o -name '*.h' \) | sort)
count=$(wc -l <<<"$files")
report=$(while read -r file; do
           lines=$(wc -l <"$file")
           if ((lines > max_lines)); then echo "$lines lines: $file"; fi
         done <<<"$files" | sort -rn)
if [[ -n "$report" ]]; then
  echo "$report"
  echo "check-file-length: $(wc -l <<<"$report") of $count files in $root are over $max_lines lines" >&2
  exit 1
fi
echo "check-file-length: all $count files in $root are within $max_lines lines"
