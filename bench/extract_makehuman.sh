#!/usr/bin/env bash
# extract on every MakeHuman mesh: groups, strands, points, how many groups each
# orientation rule decided, and the median wall time of RUNS runs, as a Markdown
# table on stdout (docs/extract.md quotes it).
#
#   bench/extract_makehuman.sh [MAKEHUMAN_DIR]
#
# Environment: BIN (default build/bin), RUNS (default 5), THREADS (default 0 = all).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
bin=${BIN:-build/bin}
runs=${RUNS:-5}
threads=${THREADS:-0}
work=$(mktemp -d "${TMPDIR:-/tmp}/extract_makehuman.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh

echo "Machine: $(nproc) cores, $(cpu_name); extract --threads $threads; median of $runs runs."
echo
echo "| model | vertices | groups | strands | points | vertex_order | scalp_distance | continuation | uv | height | parting | time (ms) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for mesh in "$makehuman"/hair/*.obj; do
  model=$(basename "$mesh" .obj)
  times=()
  for ((run = 0; run < runs; ++run)); do
    start=$(date +%s%N)
    "$bin/extract" "$mesh" --body "$makehuman/body.obj" --unit_scale 0.1 --threads "$threads" \
      -o "$work/$model.h5" 2>"$work/$model.log"
    times+=($(( ($(date +%s%N) - start) / 1000000 )))
  done
  counts=$(sed -n 's/.*: info: .*: \([0-9]*\) groups, \([0-9]*\) strands, \([0-9]*\) points.*/\1 | \2 | \3/p' "$work/$model.log")
  rules=$(sed -n 's/.*orientation rules: vertex_order \([0-9]*\), scalp_distance \([0-9]*\), continuation \([0-9]*\), uv \([0-9]*\), height \([0-9]*\), parting \([0-9]*\)/\1 | \2 | \3 | \4 | \5 | \6/p' "$work/$model.log")
  vertices=$(grep -c '^v ' "$mesh")
  echo "| $model | $vertices | $counts | $rules | $(printf '%s\n' "${times[@]}" | median) |"
done
