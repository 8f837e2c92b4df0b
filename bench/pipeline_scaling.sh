#!/usr/bin/env bash
# Pipeline timings per stage and model, and how each stage's cost grows (issue 9): the
# wall time of every stage (median of RUNS runs, the stage's whole process: reading,
# work, writing) on MakeHuman meshes; then the strand count (1k, 10k, 100k grown strands:
# grow, classify, simulate, interpolate) and the mesh size (hair meshes subdivided by
# bench/subdivide_obj.py, from about 1k to 60k vertices: extract, typeify, cluster-middle,
# cluster-all, grow), with the growth exponent of each stage (the slope of log time
# against log size between the smallest and the largest case).
#
#   bench/pipeline_scaling.sh [MAKEHUMAN_DIR]
#
# Writes OUT/pipeline.md (Markdown), OUT/pipeline.csv and OUT/pipeline_scaling.png.
# Environment: BIN (default build/bin), OUT (default docs/bench), MODELS (per-stage table,
# default "braid01 ponytail01 long01 short04 bob01"), STRAND_MODELS (default "ponytail01
# long01"), STRAND_COUNTS (default "1000 10000 100000"), MESH_MODELS (model:levels,
# default "short03:3 long01:2"), RUNS (default 3; one run from LARGE strands, default
# 100000), THREADS (default 2), FRAMES (interpolated frames, default 0:3: at 100,000
# strands of long01 a frame is 14 million points, 170 MB before compression), PARAMS,
# MODEL (style model).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
out=${OUT:-docs/bench}
models=${MODELS:-braid01 ponytail01 long01 short04 bob01}
strand_models=${STRAND_MODELS:-ponytail01 long01}
strand_counts=${STRAND_COUNTS:-1000 10000 100000}
mesh_models=${MESH_MODELS:-short03:3 long01:2}
runs=${RUNS:-3}
large=${LARGE:-100000}
threads=${THREADS:-2}
frames=${FRAMES:-0:3}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
work=$(mktemp -d "${TMPDIR:-/tmp}/pipeline_scaling.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh
copy_binaries pipeline_scaling "$work" extract typeify cluster-middle cluster-all grow classify simulate interpolate
bin=$work/bin
body=$makehuman/body.obj
mkdir -p "$out"
csv=$work/pipeline.csv
echo "study,model,vertices,strands,stage,ms" >"$csv"

# stage STUDY MODEL VERTICES STRANDS NAME COMMAND...: times COMMAND (median of RUNS runs;
# one run where STRANDS is at least LARGE) into the CSV; a failed run stops the bench.
stage() {
  local study=$1 model=$2 vertices=$3 strands=$4 name=$5 run start times=()
  shift 5
  local count=$runs
  ((strands < large)) || count=1
  for ((run = 0; run < count; ++run)); do
    start=$(date +%s%N)
    "$@" >/dev/null 2>&1 || { echo "pipeline_scaling: $name failed on $model: $*" >&2; exit 1; }
    times+=($((($(date +%s%N) - start) / 1000000)))
  done
  echo "$study,$model,$vertices,$strands,$name,$(printf '%s\n' "${times[@]}" | median)" >>"$csv"
}

# stages STUDY MODEL MESH DIR STRANDS LAST: the stages from extract to LAST (grow or
# interpolate) of MESH into DIR, timed.
stages() {
  local study=$1 model=$2 mesh=$3 dir=$4 strands=$5 last=$6
  local vertices
  vertices=$(grep -c '^v ' "$mesh")
  mkdir -p "$dir"
  local common=(--quiet --threads "$threads")
  local id=("$study" "$model" "$vertices" "$strands")
  stage "${id[@]}" extract "$bin/extract" "$mesh" --body "$body" -o "$dir/extract.h5" --params "$params/extract.toml" "${common[@]}"
  stage "${id[@]}" typeify "$bin/typeify" "$dir/extract.h5" -o "$dir/types.h5" --params "$params/typeify.toml" "${common[@]}"
  stage "${id[@]}" cluster-middle "$bin/cluster-middle" "$dir/types.h5" -o "$dir/middle.h5" --params "$params/cluster-middle.toml" "${common[@]}"
  stage "${id[@]}" cluster-all "$bin/cluster-all" "$dir/types.h5" "$dir/middle.h5" -o "$dir/clusters.h5" --params "$params/cluster-all.toml" "${common[@]}"
  stage "${id[@]}" grow "$bin/grow" "$dir/extract.h5" "$dir/types.h5" "$dir/clusters.h5" -o "$dir/strands.h5" --params "$params/grow.toml" --strand_count "$strands" "${common[@]}"
  [[ $last == grow ]] && return
  stage "${id[@]}" classify "$bin/classify" "$dir/extract.h5" "$dir/clusters.h5" "$dir/strands.h5" --model "$model_file" -o "$dir/styles.h5" --params "$params/classify.toml" "${common[@]}"
  stage "${id[@]}" simulate "$bin/simulate" "$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" -o "$dir/guides.h5" --params "$params/simulate.toml" "${common[@]}"
  stage "${id[@]}" interpolate "$bin/interpolate" "$dir/guides.h5" "$dir/strands.h5" "$dir/styles.h5" -o "$dir/frames.h5" --frames "$frames" --params "$params/interpolate.toml" "${common[@]}"
  rm -f "$dir/frames.h5"
}

for model in $models; do
  echo "pipeline_scaling: stages of $model" >&2
  stages stages "$model" "$makehuman/hair/$model.obj" "$work/stages/$model" 10000 interpolate
done
for model in $strand_models; do
  for count in $strand_counts; do
    echo "pipeline_scaling: $model with $count strands" >&2
    stages strands "$model" "$makehuman/hair/$model.obj" "$work/strands/$model-$count" "$count" interpolate
  done
done
for entry in $mesh_models; do
  model=${entry%%:*}
  for ((level = 0; level <= ${entry##*:}; ++level)); do
    echo "pipeline_scaling: $model subdivided $level times" >&2
    mesh=$work/meshes/${model}_$level.obj
    mkdir -p "$work/meshes"
    /usr/bin/python3 bench/subdivide_obj.py "$makehuman/hair/$model.obj" "$mesh" "$level"
    stages mesh "$model" "$mesh" "$work/mesh/$model-$level" 10000 grow
  done
done

cp "$csv" "$out/pipeline.csv"
{
  echo "# Pipeline timings and scaling"
  echo
  echo "\`bench/pipeline_scaling.sh\` on $(date -u +%Y-%m-%d): $(nproc) cores, $(cpu_name); --threads $threads; wall time of each stage's whole process (reading, work, writing), median of $runs runs (one run at $large strands and more); parameters $params; simulate: the default motion and its one cycle; interpolate: frames $frames."
  echo
  /usr/bin/python3 bench/pipeline_scaling_report.py "$out/pipeline.csv" "$out/pipeline_scaling.png"
} >"$work/pipeline.md"
mv "$work/pipeline.md" "$out/pipeline.md"
echo "pipeline_scaling: wrote $out/pipeline.md, $out/pipeline.csv, $out/pipeline_scaling.png" >&2
