#!/usr/bin/env bash
# Run time against error (issue 9): for each model two references, in which every grown
# strand is a guide simulated at a small time step (REF_SUBSTEPS per frame) with the
# repulsion worked out every frame: the full
# reference, everything as normal hair (the style rules off), and the by-style reference
# (the style rules on). Against them, variants of the defaults: guide counts, substeps, the
# fast setting, the style rules off, the repulsion every frame, and clump-only
# interpolation. Each is simulated and
# interpolated to every strand of every frame; its error is the distance of each strand
# point to the same point of a reference, divided by its strand's length, over all frames
# (mean and 95th percentile). The full reference measures all that the defaults leave out;
# the by-style one isolates the guides, the time step and the interpolation. The time is
# the simulate stage's own ms per integrated frame (guides.h5 guide_ms_per_frame) plus the
# interpolate stage's (frames.h5 interpolation_ms_per_frame), each the median of RUNS runs
# on THREADS threads.
#
#   bench/time_error.sh [MAKEHUMAN_DIR]
#
# Writes OUT/time_error.md (Markdown tables), OUT/time_error.csv, OUT/time_error.png and
# OUT/time_error_by_style.png (the time-error front per model against each reference, the
# defaults marked). Environment: BIN (default
# build/bin), OUT (default docs/bench), MODELS (MakeHuman models, default "braid01
# ponytail01 long01"), SYNTH (hair-synth presets, default "braid"; seed 1), STRANDS (grown
# strands per model, default 2000; the reference simulates all of them), REF_SUBSTEPS
# (default 8), RUNS (default 3), THREADS (default 2), MOTION (default shake), DURATION_S
# (default 1), PARAMS (default pipelines/default), MODEL (default models/style_extended.yml).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
out=${OUT:-docs/bench}
models=${MODELS-braid01 ponytail01 long01}
synth=${SYNTH-braid}
strand_count=${STRANDS:-2000}
ref_substeps=${REF_SUBSTEPS:-8}
runs=${RUNS:-3}
threads=${THREADS:-2}
motion=${MOTION:-shake}
duration_s=${DURATION_S:-1}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
work=$(mktemp -d "${TMPDIR:-/tmp}/time_error.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh
copy_binaries time_error "$work" hair-synth extract typeify cluster-middle cluster-all grow classify simulate interpolate
bin=$work/bin
mkdir -p "$out"

# attribute FILE NAME: a numeric root attribute of an HDF5 file.
attribute() { h5dump -a "/$2" "$1" | sed -n 's/^ *(0): *//p' | head -n 1; }

# The variants: label, simulate options, interpolate options. "default" is the defaults.
variants=(
  "default||"
  "guides 50|--guide_count 50|"
  "guides 500|--guide_count 500|"
  "guides 2000|--guide_count 2000|"
  "guides all|--guide_count 1000000|"
  "substeps 1|--substeps 1|"
  "substeps 4|--substeps 4|"
  "fast: 1 step + 0.2 H|--substeps 1 --segment_length_h 0.2|"
  "style rules off|--by_style=false|"
  "repulsion every frame|--repulsion_interval_frames 1|"
  "clump only||--min_triangle_aspect 1"
)

csv=$work/time_error.csv
echo "model,variant,guides,simulate_ms,interpolate_ms,mean_error,p95_error,max_error,mean_error_by_style,p95_error_by_style,max_error_by_style" >"$csv"

# run_variant DIR LABEL SIM_OPTIONS INTERP_OPTIONS: simulate and interpolate DIR's model
# RUNS times; the medians of the two stages' own timings, and the frames into DIR/LABEL.h5.
run_variant() {
  local dir=$1 label=$2 sim_options=$3 interp_options=$4 run
  local name=${label// /_}
  local sims=() interps=()
  for ((run = 0; run < runs; ++run)); do
    # shellcheck disable=SC2086  # the options are words
    "$bin/simulate" "$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/simulate.toml" \
      --motion "$motion" --duration_s "$duration_s" --threads "$threads" --quiet $sim_options -o "$dir/guides.h5" 2>>"$dir/simulate.log"
    sims+=("$(attribute "$dir/guides.h5" guide_ms_per_frame)")
    # The first run writes every frame (for the error), the others time a few.
    local frames=() target=$dir/frames_$name.h5
    ((run == 0)) || { frames=(--frames 0:6); target=$dir/timing.h5; }
    # shellcheck disable=SC2086
    "$bin/interpolate" "$dir/guides.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/interpolate.toml" \
      --threads "$threads" --quiet $interp_options "${frames[@]}" -o "$target"
    interps+=("$(attribute "$target" interpolation_ms_per_frame)")
  done
  guides_of[$label]=$(h5ls "$dir/guides.h5/guides/strand" | sed 's/.*{\([0-9]*\).*/\1/')
  sim_ms[$label]=$(printf '%s\n' "${sims[@]}" | median)
  interp_ms[$label]=$(printf '%s\n' "${interps[@]}" | median)
}

inputs=()
for model in $models; do inputs+=("$model|$makehuman/hair/$model.obj|$makehuman/body.obj"); done
for preset in $synth; do
  "$bin/hair-synth" --preset "$preset" --seed 1 --name "synth_$preset" --body data/samples/body.obj \
    -o "$work/synth" --reproducible >/dev/null
  inputs+=("synth_$preset|$work/synth/synth_$preset.obj|data/samples/body.obj")
done

for input in "${inputs[@]}"; do
  IFS='|' read -r name mesh body <<<"$input"
  echo "time_error: $name" >&2
  pipeline_to_styles "$mesh" "$body" "$work/$name" --strand_count "$strand_count"
  dir=$work/$name
  declare -A guides_of=() sim_ms=() interp_ms=()
  runs_kept=$runs
  runs=1  # the reference is slow and only its frames are needed
  run_variant "$dir" "full reference" "--by_style=false --guide_count 1000000 --substeps $ref_substeps --repulsion_interval_frames 1" ""
  run_variant "$dir" "by-style reference" "--guide_count 1000000 --substeps $ref_substeps --repulsion_interval_frames 1" ""
  runs=$runs_kept
  for variant in "${variants[@]}"; do
    IFS='|' read -r label sim_options interp_options <<<"$variant"
    run_variant "$dir" "$label" "$sim_options" "$interp_options"
  done
  for variant in "full reference" "by-style reference" "${variants[@]}"; do
    label=${variant%%|*}
    frames=$dir/frames_${label// /_}.h5
    full=$(/usr/bin/python3 bench/time_error_measure.py "$dir/frames_full_reference.h5" "$frames")
    by_style=$(/usr/bin/python3 bench/time_error_measure.py "$dir/frames_by-style_reference.h5" "$frames")
    echo "$name,$label,${guides_of[$label]},${sim_ms[$label]},${interp_ms[$label]},$full,$by_style" >>"$csv"
  done
  rm -f "$dir"/frames_*.h5
done

cp "$csv" "$out/time_error.csv"
/usr/bin/python3 bench/time_error_report.py "$out/time_error.csv" "$out/time_error.png" \
  --title "$motion, ${duration_s} s at 30 fps; $strand_count strands; references at $ref_substeps substeps" \
  >"$out/time_error.md.body"
{
  echo "# Run time against error"
  echo
  echo "\`bench/time_error.sh\` on $(date -u +%Y-%m-%d): $(nproc) cores, $(cpu_name); $threads threads; medians of $runs runs; motion $motion for $duration_s s at 30 fps; $strand_count grown strands per model; references: every strand a guide, $ref_substeps substeps per frame, the repulsion every frame, the style rules off (full) or on (by style)."
  echo
  cat "$out/time_error.md.body"
} >"$out/time_error.md"
rm -f "$out/time_error.md.body"
echo "time_error: wrote $out/time_error.md, $out/time_error.csv, $out/time_error.png" >&2
