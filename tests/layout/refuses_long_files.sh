#!/usr/bin/env bash
# The file-length check must fail on a file over the limit, naming it, and pass one at the
# limit: a source and a header of 801 lines, a source of 800.
set -euo pipefail
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/hair/grow"
lines_of() { for ((i = 0; i < $1; ++i)); do echo "// line $i"; done; }
lines_of 800 >"$work/hair/grow/at_the_limit.cpp"
lines_of 801 >"$work/hair/grow/too_long.cpp"
lines_of 801 >"$work/hair/grow/too_long.h"

status=0
report=$(bash "$source_dir/scripts/check-file-length.sh" "$work/hair" 800 2>&1) || status=$?
echo "$report"
[[ $status == 1 ]] || { echo "expected exit 1, got $status"; exit 1; }
for expected in "801 lines: $work/hair/grow/too_long.cpp" "801 lines: $work/hair/grow/too_long.h" \
                "2 of 3 files"; do
  grep -qF "$expected" <<<"$report" || { echo "missing: $expected"; exit 1; }
done
if grep -qF "at_the_limit" <<<"$report"; then echo "at_the_limit was reported"; exit 1; fi
