#!/usr/bin/env bash
# The simulate stage's cost per particle as the guides grow: the samples (data/samples)
# grown to 10,000 strands and classified, then simulated under the shake (body collisions,
# hair-hair repulsion and the tails' cohesion on, as pipelines/default has them) with 169,
# 500, 1,000 and 2,000 guides on 1 and 2 threads: milliseconds per integrated frame
# (median of RUNS), nanoseconds per particle-step (wall time of the frames over particles
# times substeps integrated), and where the time goes, by phase (simulate's own profile,
# --profile_phases=true, in a run of its own: springs, solve, limits, collisions, hair-hair,
# bundles, frames; the per-strand phases in thread-seconds). With BEFORE=DIR (a build/bin of another commit) every row is run with
# that simulate too, alternating, and the ratio before / after is printed. Markdown on
# stdout (docs/bench/simulate_scaling.md).
#
#   bench/simulate_scaling.sh
#
# Environment: BIN (default build/bin), BEFORE (unset: no comparison), RUNS (default 3),
# MODELS (default "braid01 ponytail01 long01"), GUIDES (default "169 500 1000 2000"),
# THREADS (default "1 2"), DURATION_S (default 1: 30 frames of the shake's cycle).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/common.sh

runs=${RUNS:-3}
models=${MODELS:-braid01 ponytail01 long01}
guide_counts=${GUIDES:-169 500 1000 2000}
thread_counts=${THREADS:-1 2}
duration_s=${DURATION_S:-1}
params=pipelines/default
model_file=models/style_extended.yml
work=$(mktemp -d "${TMPDIR:-/tmp}/simulate_scaling.XXXXXX")
trap 'rm -rf "$work"' EXIT
copy_binaries simulate_scaling "$work" extract typeify cluster-middle cluster-all grow classify simulate
bin=$work/bin
if [[ -n ${BEFORE:-} ]]; then
  [[ -x $BEFORE/simulate ]] || { echo "simulate_scaling: $BEFORE/simulate is missing" >&2; exit 2; }
  mkdir -p "$work/before"
  cp "$BEFORE/simulate" "$work/before/"
fi

# simulate_once BIN_DIR DIR GUIDES THREADS [OPTION...]: one run; prints "ms_per_frame
# ns_per_particle_step phases" from simulate's log (a build before the profile:
# "ms_per_frame - ...").
simulate_once() {
  local log
  log=$("$1/simulate" "$2/extract.h5" "$2/strands.h5" "$2/styles.h5" --params "$params/simulate.toml" \
    --motion shake --duration_s "$duration_s" --guide_count "$3" --threads "$4" -o "$2/guides.h5" "${@:5}" 2>&1)
  local ms phases ns
  ms=$(sed -n 's/.* \([0-9.]*\) ms per frame;.*/\1/p' <<<"$log")
  phases=$(sed -n 's/.*time by phase: \(.*\); [0-9.]* ns per particle-step.*/\1/p' <<<"$log")
  ns=$(sed -n 's/.*; \([0-9.]*\) ns per particle-step.*/\1/p' <<<"$log")
  [[ -n $ms ]] || { echo "simulate_scaling: no timing in the log of $1/simulate:" >&2; echo "$log" >&2; exit 1; }
  echo "$ms ${ns:--} ${phases:-(a build without the profile)}"
}

echo "Machine: $(nproc) cores, $(cpu_name); $(date +%F), commit $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- common stages || echo '+changes')."
echo "Motion: shake, ${duration_s} s; median of $runs runs; parameters $params; 10,000 grown strands."
echo
header="| model | guides | particles (hair + ghost) | threads | ms per frame | ns per particle-step | time by phase |"
rule="|---|---:|---:|---:|---:|---:|---|"
if [[ -n ${BEFORE:-} ]]; then
  header="| model | guides | particles (hair + ghost) | threads | ms per frame | ns per particle-step | before: ms per frame | before / after | time by phase |"
  rule="|---|---:|---:|---:|---:|---:|---:|---:|---|"
fi
echo "$header"
echo "$rule"
for model in $models; do
  dir=$work/$model
  echo "simulate_scaling: $model: extract to classify" >&2
  pipeline_to_styles "data/samples/hair/$model.obj" data/samples/body.obj "$dir"
  for guides in $guide_counts; do
    for threads in $thread_counts; do
      echo "simulate_scaling: $model, $guides guides, $threads thread(s)" >&2
      : >"$work/after.txt"
      : >"$work/before.txt"
      for ((run = 0; run < runs; ++run)); do
        simulate_once "$bin" "$dir" "$guides" "$threads" >>"$work/after.txt"
        [[ -z ${BEFORE:-} ]] || simulate_once "$work/before" "$dir" "$guides" "$threads" >>"$work/before.txt"
      done
      ms=$(awk '{ print $1 }' "$work/after.txt" | median)
      ns=$(awk '{ print $2 }' "$work/after.txt" | median)
      # The phases from a run of their own (timing them costs about 0.5 us a strand step).
      phases=$(simulate_once "$bin" "$dir" "$guides" "$threads" --profile_phases=true |
        awk '{ $1 = ""; $2 = ""; sub(/^  /, ""); print }')
      hair=$(h5ls "$dir/guides.h5/guides/rest_points" | sed 's/.*{\([0-9]*\).*/\1/')
      ghosts=$(h5dump -d /guides/ghost_count "$dir/guides.h5" | sed -n '/DATA {/,/}/p' | sed 's/([0-9]*)://' | grep -o '[0-9]\+' | awk '{ s += $1 } END { print s + 0 }')
      made=$(h5ls "$dir/guides.h5/guides/kind" | sed 's/.*{\([0-9]*\).*/\1/')
      row="| $model | $made | $hair + $ghosts | $threads | $(printf '%.2f' "$ms") | $(printf '%.0f' "$ns")"
      if [[ -n ${BEFORE:-} ]]; then
        before_ms=$(awk '{ print $1 }' "$work/before.txt" | median)
        row+=" | $(printf '%.2f' "$before_ms") | $(awk -v b="$before_ms" -v a="$ms" 'BEGIN { printf "%.2f", (a > 0 ? b / a : 0) }')"
      fi
      echo "$row | $phases |"
    done
  done
done
echo
echo "Guides: what simulate made of the asked guide_count (fixed and braided clusters have none of their own; a cluster gets at least its share). Particles: hair particles of all guides + their ghost particles (the altitude springs' tetrahedra). ns per particle-step: wall time of the frames / (particles x substeps integrated), every phase included."
