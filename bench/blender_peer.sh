#!/usr/bin/env bash
# Peer benchmark (issue 9): Blender's hair dynamics (Debian's blender, headless, run by
# bench/blender_hair_dynamics.py) against our simulate stage on the same strands and the
# same head motion (the shake preset, 30 fps, one cycle: 60 integrated frames). For each
# MakeHuman model: our ms per integrated frame (guides.h5's guide_ms_per_frame, --threads
# THREADS, median of RUNS) for our default 169 guides and for --guide_count 1000, without
# and with body collisions (--body_collisions, on by default); Blender's
# ms per frame (median over the frames, median of RUNS) with THREADS threads (-t and
# OMP_NUM_THREADS) on (a) our
# guides' rest shapes, each resampled to KEYS keys, and (b) 1,000 grown strands of
# strands.h5 (every len/1000-th) resampled to KEYS keys, each without and with the body as
# a collision object. Blender's own check (hairs have the guide shapes at frame 1, roots
# follow the head, tips moved) is in the table. A Markdown table on stdout.
#
#   bench/blender_peer.sh [MAKEHUMAN_DIR]
#
# Environment: BIN (default build/bin), RUNS (default 3), MODELS (default "braid01
# ponytail01 long01"), THREADS (default 2), KEYS (default 16), FRAMES (Blender's frames
# after the rest frame; default 0: all of guides.h5's), PARAMS (default pipelines/default),
# MODEL (style model, default models/style_extended.yml), BLENDER (default blender),
# QUICK=1 (a smoke run: one model, ponytail01, 1 run, 10 frames).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

blender=${BLENDER:-blender}
if ! command -v "$blender" >/dev/null; then
  echo "blender_peer: '$blender' is not installed: nothing measured (apt-get install blender)."
  exit 0
fi
makehuman=${1:-../shared/data/makehuman}
runs=${RUNS:-3}
models=${MODELS:-braid01 ponytail01 long01}
threads=${THREADS:-2}
keys=${KEYS:-16}
frames=${FRAMES:-0}
if [[ ${QUICK:-0} == 1 ]]; then runs=1 models=${MODELS:-ponytail01} frames=${FRAMES:-10}; fi
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
work=$(mktemp -d "${TMPDIR:-/tmp}/blender_peer.XXXXXX")
trap 'rm -rf "$work"' EXIT

# Both simulators use OpenMP. libgomp's default spin-waiting made Blender's solver (an
# "omp parallel sections" per matrix product) take up to 3 s for some frames of 31 hairs
# when other jobs share the cores, and it slows ours too: both run with passive waiting.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE}

source bench/common.sh
copy_binaries blender_peer "$work" extract typeify cluster-middle cluster-all grow classify simulate
bin=$work/bin
py=/usr/bin/python3

attribute() { h5dump -a "/$2" "$1" | sed -n 's/^ *(0): *//p' | head -n 1; }
count() { h5ls "$1$2" | sed 's/.*{\([0-9]*\).*/\1/'; }
# ours GUIDES COLLISIONS: our ms/frame, median of $runs runs, writing $dir/guides_GUIDES.h5.
ours() {
  for ((run = 0; run < runs; ++run)); do
    "$bin/simulate" "$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/simulate.toml" --quiet \
      --motion shake --guide_count "$1" --body_collisions="$2" --threads "$threads" -o "$dir/guides_$1.h5" 2>/dev/null
    attribute "$dir/guides_$1.h5" guide_ms_per_frame
  done | median | awk '{ printf "%.2f", $1 }'
}
# theirs JSON [--body OBJ]: Blender's median ms/frame over $runs runs, then its check.
theirs() {
  local input=$1 run
  shift
  for ((run = 0; run < runs; ++run)); do
    OMP_NUM_THREADS=$threads "$blender" -b --factory-startup -noaudio -t "$threads" \
      --python-exit-code 1 -P bench/blender_hair_dynamics.py -- --input "$input" --keys "$keys" --frames "$frames" \
      --output "$work/result.json" "$@" >"$work/blender.log" 2>&1 || { cat "$work/blender.log" >&2; exit 1; }
    $py -c 'import json,sys; print(json.load(open(sys.argv[1]))["median_ms_per_frame"])' "$work/result.json"
  done | median | awk '{ printf "%.1f", $1 }'
  $py -c 'import json,sys; r = json.load(open(sys.argv[1])); c = r["check"]
inside = "" if c["last_frame_share_inside_body"] is None else ", %.1f%% inside body" % (100 * c["last_frame_share_inside_body"])
print(" (%s: keys %.1g m off, tips moved %.0f mm%s)" % ("ok" if c["passed"] else "CHECK FAILED", c["frame1_max_key_error_m"], 1e3 * c["last_frame_tip_offset_m_median"], inside))' "$work/result.json"
}

echo "Machine: $(nproc) cores, $(cpu_name); load average $(cut -d' ' -f1-3 /proc/loadavg); OMP_WAIT_POLICY=$OMP_WAIT_POLICY; $("$blender" --version 2>/dev/null | head -n 1); $threads threads; median of $runs runs; $keys keys per Blender hair; motion shake; parameters $params."
echo
echo "| model | strands | our points per guide (mean) | ours ms/frame, no collisions | ours ms/frame, body collisions | Blender ms/frame, no collisions | Blender ms/frame, body collisions |"
echo "|---|---|---:|---:|---:|---:|---:|"
for model in $models; do
  dir=$work/$model
  pipeline_to_styles "$makehuman/hair/$model.obj" "$makehuman/body.obj" "$dir" 2>/dev/null
  for n in 169 1000; do
    ms_free=$(ours "$n" false)
    ms=$(ours "$n" true)
    g=$dir/guides_$n.h5
    points=$(( $(count "$g" /guides/rest_points) / $(count "$g" /guides/kind) ))
    if [[ $n == 169 ]]; then
      $py bench/blender_hair_input.py "$g" -o "$dir/hairs.json" --extract "$dir/extract.h5" --body-obj "$dir/body.obj"
      what="$(count "$g" /guides/kind) guides"
    else
      $py bench/blender_hair_input.py "$g" -o "$dir/hairs.json" --strands "$dir/strands.h5" --count 1000
      what="ours: $(count "$g" /guides/kind) guides; Blender: 1000 grown strands"
    fi
    free=$(theirs "$dir/hairs.json")
    body=$(theirs "$dir/hairs.json" --body "$dir/body.obj")
    echo "| $model | $what | $points | $ms_free | $ms | $free | $body |"
  done
done
