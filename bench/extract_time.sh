#!/usr/bin/env bash
# Wall time of the extract stage on the largest MakeHuman mesh (bob01, 5203
# vertices), median of repeated runs, with the machine it ran on.
#
#   bench/extract_time.sh [HAIR_MESH [BODY_MESH]]
#
# Defaults: ../shared/data/makehuman/hair/bob01.obj and its body.obj. Uses
# hyperfine when installed (apt-get install hyperfine), else a loop of RUNS runs.
# Environment: BIN (default build/bin), RUNS (default 10), THREADS (extract
# --threads, default 0 = all cores).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/common.sh

makehuman=../shared/data/makehuman
hair=${1:-$makehuman/hair/bob01.obj}
body=${2:-$makehuman/body.obj}
bin=${BIN:-build/bin}
runs=${RUNS:-10}
threads=${THREADS:-0}

for file in "$bin/extract" "$hair" "$body"; do
  [[ -e "$file" ]] || { echo "extract_time: $file is missing" >&2; exit 1; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/extract_time.XXXXXX")
trap 'rm -rf "$work"' EXIT
command=("$bin/extract" "$hair" --body "$body" --unit_scale 0.1 --quiet --threads "$threads"
         -o "$work/extract.h5")
"${command[@]}"  # once, to check that it works and to warm the file cache

cpu=$(cpu_name)
echo "machine:  $(nproc) cores, ${cpu:-unknown CPU}; load average $(cut -d ' ' -f 1-3 /proc/loadavg)"
echo "extract:  $bin/extract at $(git describe --always --dirty 2>/dev/null || echo unknown)," \
     "--threads $threads"
echo "mesh:     $hair ($(grep -c '^v ' "$hair") vertices), body $body"

if command -v hyperfine >/dev/null; then
  printf -v quoted '%q ' "${command[@]}"
  hyperfine --style none --warmup 2 --runs "$runs" --export-json "$work/times.json" \
    "$quoted" >/dev/null
  median_s=$(grep -o '"median": *[0-9.eE+-]*' "$work/times.json" | head -n 1 | sed 's/.*: *//')
  method="hyperfine, $runs runs after 2 warm-up runs"
else
  for ((run = 0; run < runs; ++run)); do
    start=$(date +%s.%N)
    "${command[@]}"
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ printf "%.6f\n", $2 - $1 }'
  done | sort -g >"$work/times.txt"
  median_s=$(awk '{ t[NR] = $1 } END { print (NR % 2) ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2 }' \
    "$work/times.txt")
  method="shell loop, $runs runs"
fi
awk -v s="$median_s" -v how="$method" 'BEGIN { printf "median:   %.1f ms wall (%s)\n", s * 1000, how }'
