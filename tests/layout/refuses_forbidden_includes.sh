#!/usr/bin/env bash
# The layout check must fail where the layout is broken: on a copy of libhair, a
# simulation header that includes the style features (an earlier phase's internals),
# core including the HDF5 layer, and a file outside the folders, each reported by name.
set -euo pipefail
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$source_dir/common/hair" "$work/hair"

bash "$source_dir/scripts/check-layout.sh" "$work/hair" >/dev/null  # the copy passes as is

sed -i '1i #include "hair/style/style_features.h"' "$work/hair/sim/guide_selection.h"
sed -i '1i #include "hair/h5/file.h"' "$work/hair/core/error.cpp"
touch "$work/hair/stray.cpp"
status=0
report=$(bash "$source_dir/scripts/check-layout.sh" "$work/hair" 2>&1) || status=$?
echo "$report"
[[ $status == 1 ]] || { echo "expected exit 1, got $status"; exit 1; }
for expected in "sim/guide_selection.h:1: includes hair/style/style_features.h" \
                "core/error.cpp:1: includes hair/h5/file.h" \
                "stray.cpp: lies outside the folders" "3 violation(s)"; do
  grep -qF "$expected" <<<"$report" || { echo "missing: $expected"; exit 1; }
done
