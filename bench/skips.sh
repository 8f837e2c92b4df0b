#!/usr/bin/env bash
# What each skip saves (issue 9), on models where it applies, medians of RUNS runs of the
# stage's wall time (its whole process) with THREADS threads:
# - no middle groups: cluster-middle writes an empty clustering at once; its time on models
#   without middle groups beside its time on models with them;
# - the style rules: fixed clusters move with the head unsimulated, a braid is one wisp;
#   simulate + interpolate by style against --by_style=false (every cluster as normal
#   hair, the same guide count);
# - a still head: the simulation stops once the hair settles; simulate --motion still for
#   STILL_S seconds against the same with settling off (--settle_speed_h_s 0).
#
#   bench/skips.sh [MAKEHUMAN_DIR]
#
# Prints Markdown on stdout. Environment: BIN (default build/bin),
# RUNS (default 3), THREADS (default 2), STILL_S (default 15), FRAMES (interpolated frames,
# default 0:31), PARAMS, MODEL (style model).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
runs=${RUNS:-3}
threads=${THREADS:-2}
still_s=${STILL_S:-15}
frames=${FRAMES:-0:31}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
work=$(mktemp -d "${TMPDIR:-/tmp}/skips.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh
copy_binaries skips "$work" extract typeify cluster-middle cluster-all grow classify simulate interpolate
bin=$work/bin

# attribute FILE NAME: a numeric root attribute of an HDF5 file.
attribute() { h5dump -a "/$2" "$1" | sed -n 's/^ *(0): *//p' | head -n 1; }
# saved WITH WITHOUT: the share of WITHOUT's time that WITH saves, as a percentage.
saved() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.0f%%", 100 * (1 - a / b) }'; }
# count FILE DATASET: the first extent of a dataset.
count() { h5ls "$1$2" | sed 's/.*{\([0-9]*\).*/\1/'; }

for model in braid01 ponytail01 long01 short02 short03 afro01; do
  echo "skips: $model" >&2
  pipeline_to_styles "$makehuman/hair/$model.obj" "$makehuman/body.obj" "$work/$model"
done

echo "# What the skips save"
echo
echo "\`bench/skips.sh\` on $(date -u +%Y-%m-%d): $(nproc) cores, $(cpu_name); --threads $threads; wall time of each stage's whole process, median of $runs runs; parameters $params; 10,000 grown strands."
echo
echo "## No middle groups: cluster-middle"
echo
echo "| model | middle groups | cluster-middle ms |"
echo "|---|---:|---:|"
for model in short02 short03 long01 braid01 afro01; do
  dir=$work/$model
  middle=$(/usr/bin/python3 -c "import h5py,sys; f=h5py.File(sys.argv[1]); print(int((f['/groups/type'][:] == 2).sum()))" "$dir/types.h5" 2>/dev/null || echo "?")
  ms=$(time_ms "$bin/cluster-middle" "$dir/types.h5" -o "$work/middle.h5" --params "$params/cluster-middle.toml" --quiet --threads "$threads")
  echo "| $model | $middle | $ms |"
done
echo
echo "## The style rules: fixed clusters and braid wisps"
echo
echo "Simulate (the default motion, one cycle) and interpolate (frames $frames) by style, and with every cluster as normal hair (\`--by_style=false\`), at the default guide count."
echo
echo "| model | styles | strands fixed / in wisps | simulate ms, by style | simulate ms, all normal | simulate saved | interpolate ms, by style | interpolate ms, all normal | both saved |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
for model in ponytail01 braid01; do
  dir=$work/$model
  declare -A ms=()
  for by_style in true false; do
    simulate=("$bin/simulate" "$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/simulate.toml" --quiet --threads "$threads" "--by_style=$by_style" -o "$dir/guides_$by_style.h5")
    "${simulate[@]}" 2>/dev/null
    ms[simulate_$by_style]=$(time_ms "${simulate[@]}")
    interpolate=("$bin/interpolate" "$dir/guides_$by_style.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/interpolate.toml" --quiet --threads "$threads" --frames "$frames" -o "$dir/frames.h5")
    ms[interpolate_$by_style]=$(time_ms "${interpolate[@]}")
  done
  styles=$(h5dump -d /clusters/style "$dir/styles.h5" | sed -n '/DATA {/,/}/p' | grep -o '[a-z]\+' | grep -v '^data$' | sort | uniq -c | awk '{printf "%s%s %s", sep, $1, $2; sep=", "}')
  fixed=$(attribute "$dir/guides_true.h5" fixed_strand_count)
  braided=$(attribute "$dir/guides_true.h5" braided_strand_count)
  by=$((ms[simulate_true] + ms[interpolate_true]))
  off=$((ms[simulate_false] + ms[interpolate_false]))
  echo "| $model | $styles | $fixed / $braided | ${ms[simulate_true]} | ${ms[simulate_false]} | $(saved "${ms[simulate_true]}" "${ms[simulate_false]}") | ${ms[interpolate_true]} | ${ms[interpolate_false]} | $(saved "$by" "$off") |"
done
echo
echo "## A still head: settling"
echo
echo "Simulate \`--motion still\` for $still_s s at 30 fps: the simulation stops once no particle moves faster than 0.05 H/s for 10 frames, against the same with settling off (\`--settle_speed_h_s 0\`)."
echo
echo "| model | settled at frame | simulate ms, settling | simulate ms, no settling | saved |"
echo "|---|---:|---:|---:|---:|"
for model in ponytail01 long01; do
  dir=$work/$model
  still=("$bin/simulate" "$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/simulate.toml" --quiet --threads "$threads" --motion still --duration_s "$still_s")
  "${still[@]}" -o "$dir/still.h5"
  settled=$(attribute "$dir/still.h5" settled_at_frame)
  frame_count=$(count "$dir/still.h5" /frames/time_s)
  if ((settled >= 0)); then settled="$settled of $frame_count"; else settled="never ($frame_count frames)"; fi
  with=$(time_ms "${still[@]}" -o "$dir/still.h5")
  without=$(time_ms "${still[@]}" --settle_speed_h_s 0 -o "$dir/still_all.h5")
  echo "| $model | $settled | $with | $without | $(saved "$with" "$without") |"
done
