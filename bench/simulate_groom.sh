#!/usr/bin/env bash
# How simulated hair keeps its groom and moves (issue 27), on the MakeHuman meshes
# (default braid01, ponytail01, long01) after extract to classify: each guide's tip drift
# in the head's frame as a share of its length, under a still head for 10 s, at the end of
# the shake preset, and 2 s after a 2 s shake has stopped (keyframes); the guides that
# flipped over their root; and, under the shake, the spread of the cluster with the most
# guides (a ponytail's tail) at three quarters of its length over its spread at rest.
# With BEFORE=DIR (a build/bin of another commit), the same for its simulate on the same
# inputs (its own pipelines/default/simulate.toml beside DIR/../..), and the time per
# frame of both, RUNS runs each in turns (the stage's own guide_ms_per_frame, 2 threads).
# Markdown tables on stdout (hair-sim-report's rows).
#
#   bench/simulate_groom.sh [MAKEHUMAN_DIR]
#
# Environment: BIN (default build/bin), BEFORE (unset: no comparison), RUNS (default 3),
# MODELS (default "braid01 ponytail01 long01"), PARAMS (default pipelines/default), MODEL
# (style model, default models/style_extended.yml).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
runs=${RUNS:-3}
models=${MODELS:-braid01 ponytail01 long01}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
work=$(mktemp -d "${TMPDIR:-/tmp}/simulate_groom.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh
copy_binaries simulate_groom "$work" extract typeify cluster-middle cluster-all grow classify simulate hair-sim-report
bin=$work/bin
builds=(after)
if [[ -n ${BEFORE:-} ]]; then
  mkdir -p "$work/before"
  cp "$BEFORE/simulate" "$work/before/"
  before_params=$(cd "$BEFORE/../.." && pwd)/pipelines/default/simulate.toml
  builds=(before after)
fi
simulate_of() { [[ $1 == before ]] && echo "$work/before/simulate" || echo "$bin/simulate"; }
params_of() { [[ $1 == before ]] && echo "$before_params" || echo "$params/simulate.toml"; }

# The shake preset's first cycle (30 degrees of yaw at 1.5 Hz, ramped in over half a
# period), then the head still.
keyframes=$work/shake_then_still.csv
awk 'BEGIN { print "time_s,yaw_deg"; pi = atan2(0, -1)
  for (i = 0; i <= 120; ++i) { t = i / 60; u = t * 3; if (u > 1) u = 1
    ramp = u * u * u * (u * (u * 6 - 15) + 10)
    printf "%.5f,%.6f\n", t, 30 * ramp * sin(2 * pi * 1.5 * t) }
  print "6,0" }' > "$keyframes"

echo "Machine: $(nproc) cores, $(cpu_name); parameters $params; style model $model_file."
echo
drift="$("$bin/hair-sim-report" --header)"
tails="$("$bin/hair-sim-report" --tail --header)"
timing="| model | build | ms/frame (2 threads, shake), runs in turns | median |
|---|---|---|---:|"
for model in $models; do
  dir=$work/$model
  pipeline_to_clusters "$makehuman/hair/$model.obj" "$makehuman/body.obj" "$dir"
  "$bin/grow" "$dir/extract.h5" "$dir/types.h5" "$dir/clusters.h5" -o "$dir/strands.h5" --params "$params/grow.toml" --quiet
  "$bin/classify" "$dir/extract.h5" "$dir/clusters.h5" "$dir/strands.h5" --model "$model_file" -o "$dir/styles.h5" --params "$params/classify.toml" --quiet
  inputs=("$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" --quiet)
  for build in "${builds[@]}"; do
    sim=$(simulate_of "$build")
    p=$(params_of "$build")
    "$sim" "${inputs[@]}" --params "$p" --motion still --duration_s 10 -o "$dir/$build-still.h5"
    "$sim" "${inputs[@]}" --params "$p" --motion shake -o "$dir/$build-shake.h5"
    "$sim" "${inputs[@]}" --params "$p" --keyframes "$keyframes" --duration_s 4 -o "$dir/$build-after.h5"
    drift+=$'\n'"$("$bin/hair-sim-report" "$dir/$build-still.h5" --name "$model, $build: still head, 10 s")"
    drift+=$'\n'"$("$bin/hair-sim-report" "$dir/$build-shake.h5" --name "$model, $build: end of the shake")"
    drift+=$'\n'"$("$bin/hair-sim-report" "$dir/$build-after.h5" --name "$model, $build: 2 s after a 2 s shake")"
    # No cluster of two strand guides or more (braid01 with its caps fixed: one wisp): no row.
    tails+=$'\n'"$("$bin/hair-sim-report" --tail "$dir/$build-shake.h5" --name "$model, $build: shake" 2>/dev/null ||
      echo "| $model, $build: shake | no cluster of two strand guides | | | | |")"
  done
  declare -A ms=()
  for ((run = 0; run < runs; ++run)); do
    for build in "${builds[@]}"; do
      ms[$build]+="$("$(simulate_of "$build")" "${inputs[@]}" --params "$(params_of "$build")" --threads 2 -o "$dir/time.h5" 2>/dev/null; h5dump -a /guide_ms_per_frame "$dir/time.h5" | sed -n 's/^ *(0): *//p' | head -n 1) "
    done
  done
  for build in "${builds[@]}"; do
    med=$(tr ' ' '\n' <<<"${ms[$build]}" | grep . | median | awk '{ printf "%.2f", $1 }')
    timing+=$'\n'"| $model | $build | ${ms[$build]} | $med |"
  done
  unset ms
done
echo "$drift"
echo
echo "$tails"
echo
echo "$timing"
