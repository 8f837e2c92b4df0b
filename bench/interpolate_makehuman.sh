#!/usr/bin/env bash
# The interpolate stage on MakeHuman meshes (default braid01, ponytail01 and long01):
# milliseconds per frame of interpolation (frames.h5's interpolation_ms_per_frame, the
# stage's own timing of the per-frame loop: the median over the frames, reading the
# guides and writing the points excluded), median of RUNS runs, with 1 and 2 threads, at
# 10,000 and 100,000 grown strands; the strands per method and the largest deviation
# from the grown strands at rest. Markdown tables on stdout.
#
#   bench/interpolate_makehuman.sh [MAKEHUMAN_DIR]
#
# Environment: BIN (default build/bin), RUNS (default 5), MODELS (default "braid01
# ponytail01 long01"), COUNTS (default "10000 100000"), PARAMS (default
# pipelines/default), MODEL (style model, default models/style_extended.yml),
# DURATION_S (simulated seconds, default 1), FRAMES (the frames interpolated, default 0:11:
# the rest state and ten frames of motion, so that 100,000 strands do not write gigabytes).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
runs=${RUNS:-5}
models=${MODELS:-braid01 ponytail01 long01}
counts=${COUNTS:-10000 100000}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
duration=${DURATION_S:-1}
frames=${FRAMES:-0:11}
work=$(mktemp -d "${TMPDIR:-/tmp}/interpolate_makehuman.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh
copy_binaries interpolate_makehuman "$work" extract typeify cluster-middle cluster-all grow classify simulate interpolate
bin=$work/bin

# attribute FILE NAME: a numeric root attribute of an HDF5 file.
attribute() { h5dump -a "/$2" "$1" | sed -n 's/^ *(0): *//p' | head -n 1; }
# method_counts FILE: strands per method, "fixed/barycentric/clump/braided".
method_counts() {
  h5dump -d /strands/method "$1" | sed -n '/DATA {/,/}/p' | grep -o '[a-z]\+' | grep -v '^data$' |
    sort | uniq -c | awk '{n[$2]=$1} END {printf "%d / %d / %d / %d\n", n["fixed"], n["barycentric"], n["clump"], n["braided"]}'
}

echo "Machine: $(nproc) cores, $(cpu_name), load average $(cut -d' ' -f1-3 /proc/loadavg) at the start; median of $runs runs; parameters $params; style model $model_file; frames $frames of ${duration} s of the default motion."
echo
echo "| model | strands | points | fixed / barycentric / clump / braided | max deviation at rest (m) | ms/frame, 1 thread | ms/frame, 2 threads |"
echo "|---|---:|---:|---|---:|---:|---:|"
for model in $models; do
  dir=$work/$model
  pipeline_to_clusters "$makehuman/hair/$model.obj" "$makehuman/body.obj" "$dir"
  "$bin/grow" "$dir/extract.h5" "$dir/types.h5" "$dir/clusters.h5" -o "$dir/strands.h5" --params "$params/grow.toml" --quiet
  # The styles of the 10,000 strands the classifier was trained on, for every count.
  "$bin/classify" "$dir/extract.h5" "$dir/clusters.h5" "$dir/strands.h5" --model "$model_file" -o "$dir/styles.h5" --params "$params/classify.toml" --quiet
  for count in $counts; do
    strands=$dir/strands_$count.h5
    "$bin/grow" "$dir/extract.h5" "$dir/types.h5" "$dir/clusters.h5" -o "$strands" --params "$params/grow.toml" --strand_count "$count" --quiet
    "$bin/simulate" "$dir/extract.h5" "$strands" "$dir/styles.h5" -o "$dir/guides_$count.h5" --params "$params/simulate.toml" --duration_s "$duration" --quiet
    declare -A ms=()
    for threads in 1 2; do
      ms[$threads]=$(for ((run = 0; run < runs; ++run)); do
        "$bin/interpolate" "$dir/guides_$count.h5" "$strands" "$dir/styles.h5" -o "$dir/frames.h5" --params "$params/interpolate.toml" --frames "$frames" --threads "$threads" --quiet
        attribute "$dir/frames.h5" interpolation_ms_per_frame
      done | median | awk '{ printf "%.2f", $1 }')
    done
    points=$(h5ls "$dir/frames.h5/strands/rest_points" | sed 's/.*{\([0-9]*\).*/\1/')
    printf '| %s | %s | %s | %s | %.1e | %s | %s |\n' "$model" "$count" "$points" "$(method_counts "$dir/frames.h5")" \
      "$(attribute "$dir/frames.h5" rest_max_deviation_m)" "${ms[1]}" "${ms[2]}"
    rm -f "$dir/frames.h5"
  done
done
