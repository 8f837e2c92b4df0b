#!/usr/bin/env bash
# The simulate stage on MakeHuman meshes (default braid01, ponytail01 and long01, the
# issue's): milliseconds per frame of the guide simulation (169 guides, the stage's own
# timing of the integrated frames, guides.h5's guide_ms_per_frame) with 1 and 2 threads
# for the default motion and a violent shake, with the default settings and a fast one
# (one step per frame, particles every 0.2 H); the guides, particles, wisps and fixed
# strands; the largest stretch, the deepest a particle went into the body before it was
# pushed out, and the largest share of particles left inside at a frame's end; the setup
# (guides and the body's distance field); and the frame a still head's hair settles at.
# Markdown tables on stdout.
#
#   bench/simulate_makehuman.sh [MAKEHUMAN_DIR]
#
# Environment: BIN (default build/bin), RUNS (default 5), MODELS (default "braid01
# ponytail01 long01"), PARAMS (default pipelines/default), MODEL (style model, default
# models/style_extended.yml).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
runs=${RUNS:-5}
models=${MODELS:-braid01 ponytail01 long01}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
work=$(mktemp -d "${TMPDIR:-/tmp}/simulate_makehuman.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh
copy_binaries simulate_makehuman "$work" extract typeify cluster-middle cluster-all grow classify simulate
bin=$work/bin

# attribute FILE NAME: a numeric root attribute of an HDF5 file.
attribute() { h5dump -a "/$2" "$1" | sed -n 's/^ *(0): *//p' | head -n 1; }
# largest FILE DATASET: the largest value of a 1-D dataset.
largest() { h5dump -d "$2" "$1" | sed -n '/DATA {/,/}/p' | sed 's/([0-9]*)://' | grep -o '[-0-9.e+]\+' | sort -g | tail -n 1; }
# count FILE DATASET: the first extent of a dataset.
count() { h5ls "$1$2" | sed 's/.*{\([0-9]*\).*/\1/'; }
# words FILE DATASET: the values of an enum dataset, comma-separated.
words() { h5dump -d "$2" "$1" | sed -n '/DATA {/,/}/p' | grep -o '[a-z]\+' | grep -v '^data$' | paste -sd, | sed 's/,/, /g'; }

echo "Machine: $(nproc) cores, $(cpu_name); median of $runs runs; parameters $params; style model $model_file."
echo
speed="| model | setting | motion | guides | particles (hair + ghost) | ms/frame, 1 thread | ms/frame, 2 threads | largest stretch | deepest in body before the push (mm) | most left inside at a frame's end | setup (s) |
|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
styles_table="| model | styles (styles.h5) | simulated as | guides per cluster | wisps (points bound) | fixed strands | still head settles at frame |
|---|---|---|---|---|---:|---:|"
for model in $models; do
  dir=$work/$model
  pipeline_to_clusters "$makehuman/hair/$model.obj" "$makehuman/body.obj" "$dir"
  "$bin/grow" "$dir/extract.h5" "$dir/types.h5" "$dir/clusters.h5" -o "$dir/strands.h5" --params "$params/grow.toml" --quiet
  "$bin/classify" "$dir/extract.h5" "$dir/clusters.h5" "$dir/strands.h5" --model "$model_file" -o "$dir/styles.h5" --params "$params/classify.toml" --quiet
  inputs=("$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/simulate.toml" --quiet)
  for setting in default fast; do
    extra=()
    [[ $setting == fast ]] && extra=(--substeps 1 --segment_length_h 0.2)
    for motion in shake violent_shake; do
      declare -A ms=()
      for threads in 1 2; do
        ms[$threads]=$(for ((run = 0; run < runs; ++run)); do
          "$bin/simulate" "${inputs[@]}" "${extra[@]}" --motion "$motion" --threads "$threads" -o "$dir/guides.h5" 2>/dev/null
          attribute "$dir/guides.h5" guide_ms_per_frame
        done | median | awk '{ printf "%.2f", $1 }')
      done
      file=$dir/guides.h5
      guides=$(count "$file" /guides/kind)
      hair=$(count "$file" /guides/rest_points)
      ghosts=$(h5dump -d /guides/ghost_count "$file" | sed -n '/DATA {/,/}/p' | sed 's/([0-9]*)://' | grep -o '[0-9]\+' | awk '{ s += $1 } END { print s + 0 }')
      stretch=$(largest "$file" /frames/max_stretch | awk '{ printf "%.3f", $1 }')
      depth=$(largest "$file" /frames/max_penetration_m | awk '{ printf "%.1f", $1 * 1000 }')
      setup=$(attribute "$file" setup_s | awk '{ printf "%.2f", $1 }')
      inside=$(largest "$file" /frames/inside_fraction | awk '{ printf "%.2f%%", $1 * 100 }')
      speed+=$'\n'"| $model | $setting | $motion | $guides | $hair + $ghosts | ${ms[1]} | ${ms[2]} | $stretch | $depth | $inside | $setup |"
    done
  done
  "$bin/simulate" "${inputs[@]}" --motion still --duration_s 10 -o "$dir/still.h5" 2>/dev/null
  settled=$(attribute "$dir/still.h5" settled_at_frame)
  [[ $settled == -1 ]] && settled="not in 10 s"
  per_cluster=$(h5dump -d /clusters/guide_count "$dir/guides.h5" | sed -n '/DATA {/,/}/p' | sed 's/([0-9]*)://' | grep -o '[0-9]\+' | paste -sd, | sed 's/,/, /g')
  wisps="$(count "$dir/guides.h5" /wisps/guide) ($(count "$dir/guides.h5" /wisps/binding_point) points)"
  styles_table+=$'\n'"| $model | $(words "$dir/guides.h5" /clusters/style) | $(words "$dir/guides.h5" /clusters/simulated_style) | $per_cluster | $wisps | $(attribute "$dir/guides.h5" fixed_strand_count) | $settled |"
done
echo "$speed"
echo
echo "$styles_table"
