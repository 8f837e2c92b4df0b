#!/usr/bin/env bash
# Numerical stability of the simulate stage under stress (issue 9), the slow cases, on
# MakeHuman models and one synthetic braided model (hair-synth's two_braids, seed 1, which
# gets a wisp): the largest stable time step per model, the stiffness from x1 to x1000,
# head motions from the shake to past the violent shake, and a 10,000-frame run tracking
# the energy. Markdown tables on stdout. The fast cases are the unit tests
# (tests/unit/sim/test_simulation_stress.cpp).
#
#   bench/stability.sh [MAKEHUMAN_DIR]
#
# Environment: BIN (default build/bin), MODELS (default "braid01 ponytail01 long01"),
# SYNTH (default 1: add the synthetic braided model), THREADS (default 2), PARAMS (default
# pipelines/default), MODEL (style model, default models/style_extended.yml), LONG_MODEL
# (the 10,000-frame run's, default ponytail01), LONG_FRAMES (default 10000), QUICK=1 (only
# ponytail01, no synthetic model, fewer steps and motions, 1,000 frames; about a minute).
#
# A run is *stable* when (hair-sim-report --stability, common/hair/sim/run_stability.h):
#   - it finishes (simulate aborts on a non-finite position or velocity, or one beyond
#     1000 H) and every guide point and per-frame energy in guides.h5 is finite;
#   - the largest hair stretch is within 0.011 (the 1% limit, and a tenth of it);
#   - at most 5% of the hair particles are left inside the body at any frame's end;
#   - the springs' deformation, sqrt(2 E / (k M)) for the largest elastic energy E, the
#     hair segments' stiffness per kg k and the simulated hair's mass M (wisps by the strands they
#     carry), stays within 0.05 H: a root mean square of how far the springs are from
#     their rest lengths, whatever their stiffness (the elastic energy grows with the
#     stiffness at the same deformation);
#   - the energy does not grow: the largest kinetic energy of the last third of the
#     frames is at most twice the middle third's (or under 1 uJ); a driven run levels
#     off within +-30% from second to second once its swing has built up (the first
#     third: the ramp, and seconds for a braid's heavy wisp).
# Every run simulates 6 s (nine cycles of the shake) unless its table says otherwise.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

makehuman=${1:-../shared/data/makehuman}
quick=${QUICK:-0}
if [[ $quick == 1 ]]; then
  models=${MODELS:-ponytail01}
  synth=${SYNTH:-0}
  long_frames=${LONG_FRAMES:-1000}
else
  models=${MODELS:-braid01 ponytail01 long01}
  synth=${SYNTH:-1}
  long_frames=${LONG_FRAMES:-10000}
fi
threads=${THREADS:-2}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
long_model=${LONG_MODEL:-ponytail01}
work=$(mktemp -d "${TMPDIR:-/tmp}/stability.XXXXXX")
trap 'rm -rf "$work"' EXIT

source bench/common.sh
copy_binaries stability "$work" extract typeify cluster-middle cluster-all grow classify simulate hair-synth hair-sim-report
bin=$work/bin
bench_start=$(date +%s)

# prepare NAME MESH BODY: the pipeline up to styles.h5 in $work/NAME.
prepare() { pipeline_to_styles "$2" "$3" "$work/$1"; }
names=()
for model in $models; do
  prepare "$model" "$makehuman/hair/$model.obj" "$makehuman/body.obj"
  names+=("$model")
done
if [[ $synth == 1 ]]; then
  "$bin/hair-synth" --preset two_braids --seed 1 -o "$work/synth" --reproducible > /dev/null 2>&1
  prepare synth_two_braids "$work/synth/two_braids.obj" data/samples/body.obj
  names+=(synth_two_braids)
fi
[[ " ${names[*]} " == *" $long_model "* ]] || prepare "$long_model" "$makehuman/hair/$long_model.obj" "$makehuman/body.obj"

# run NAME OUT ARGS...: simulate NAME's model into OUT with ARGS; prints the figures of
# hair-sim-report --stability, or "aborted" when simulate failed.
run() {
  local name=$1 out=$2 dir=$work/$1
  shift 2
  if "$bin/simulate" "$dir/extract.h5" "$dir/strands.h5" "$dir/styles.h5" --params "$params/simulate.toml" \
    --quiet --threads "$threads" -o "$out" "$@" 2> "$out.log"; then
    "$bin/hair-sim-report" --stability "$out"
  else
    echo "- - - - - - - - - - - - - aborted"
  fi
}
# row FIGURES: the table cells of a run's figures.
row() {
  local frames finite stretch depth inside speed e0 e1 emax k1 k2 growth elastic verdict
  read -r frames finite stretch depth inside speed e0 e1 emax k1 k2 growth elastic verdict <<< "$1"
  echo "$stretch | $inside% | $depth | $speed | $emax | $elastic | $growth | $verdict"
}
header="largest stretch | most left inside | deepest before the push (mm) | fastest particle (m/s) | largest total energy (J) | spring deformation (mm) | kinetic growth | verdict"
rule="---:|---:|---:|---:|---:|---:|---:|---"

echo "Machine: $(nproc) cores, $(cpu_name); $threads threads; parameters $params; style model $model_file; $(date -u +%Y-%m-%d)."
echo

# 1. Time steps: the default (30 fps, 2 substeps), then one step per frame (--substeps 1)
#    at fps 30 down to 1, under the shake.
if [[ $quick == 1 ]]; then steps="30:2 15:1 4:1 1:1"; else steps="30:2 30:1 15:1 8:1 4:1 2:1 1:1"; fi
echo "### Time step (shake, 6 s)"
echo
echo "| model | fps x substeps | step (ms) | $header |"
echo "|---|---|---:|$rule|"
declare -A largest_stable=() first_failure=() default_figures=()
for name in "${names[@]}"; do
  largest_stable[$name]=none
  first_failure[$name]=""
  for setting in $steps; do
    fps=${setting%:*} substeps=${setting#*:}
    figures=$(run "$name" "$work/step.h5" --motion shake --duration_s 6 --fps "$fps" --substeps "$substeps")
    [[ $setting == 30:2 ]] && default_figures[$name]=$figures
    step_ms=$(awk -v f="$fps" -v s="$substeps" 'BEGIN { printf "%.0f", 1000 / (f * s) }')
    verdict=${figures##* }
    echo "| $name | $fps x $substeps | $step_ms | $(row "$figures") |"
    # Steps grow down the list: the largest stable one is the last before the first failure.
    if [[ -z ${first_failure[$name]} ]]; then
      if [[ $verdict == stable ]]; then largest_stable[$name]="$step_ms ms"; else first_failure[$name]="$step_ms ms: $verdict"; fi
    fi
  done
done
echo
echo "| model | largest stable step (every smaller one stable too) | first unstable step: why |"
echo "|---|---:|---|"
for name in "${names[@]}"; do
  echo "| $name | ${largest_stable[$name]} | ${first_failure[$name]:-none up to 1000 ms} |"
done
echo

# 2. Stiffness: the edge, bend, torsion and altitude springs scaled together, at the
#    default step (30 fps x 2), under the shake.
if [[ $quick == 1 ]]; then scales="1 1000"; else scales="1 10 100 1000"; fi
echo "### Stiffness (shake, 6 s, 30 fps x 2; x1 is the time step table's 30 x 2 run)"
echo
echo "| model | stiffness | $header |"
echo "|---|---:|$rule|"
for name in "${names[@]}"; do
  for scale in $scales; do
    if [[ $scale == 1 ]]; then
      echo "| $name | x1 | $(row "${default_figures[$name]}") |"
      continue
    fi
    figures=$(run "$name" "$work/stiff.h5" --motion shake --duration_s 6 --stiffness_scale "$scale")
    echo "| $name | x$scale | $(row "$figures") |"
  done
done
echo

# 3. Head motions: the shake (30 deg at 1.5 Hz), yaw shakes of 45 deg at 2 and 3 Hz
#    (keyframes every 1/240 s), the violent shake (45 deg at 4 Hz) and past it (60 deg at
#    6 Hz), ramped in over half a period as the presets are; the peak angular
#    acceleration A (2 pi f)^2.
# keyframes FILE AMPLITUDE_DEG FREQUENCY_HZ: a ramped yaw shake over 6 s.
keyframes() {
  awk -v a="$2" -v f="$3" 'BEGIN {
    pi = atan2(0, -1); print "time_s,yaw_deg"; T = 0.5 / f
    for (i = 0; i <= 1440; ++i) { t = i / 240; u = t / T; if (u > 1) u = 1
      r = u * u * u * (10 + u * (-15 + 6 * u)); printf "%.6f,%.6f\n", t, a * r * sin(2 * pi * f * t) } }' > "$1"
}
if [[ $quick == 1 ]]; then
  motions="shake violent_shake"
else
  motions="shake yaw45_2hz yaw45_3hz violent_shake yaw60_6hz"
fi
echo "### Head motion (6 s, 30 fps x 2; the shake is the time step table's 30 x 2 run)"
echo
echo "| model | motion | peak angular acceleration (rad/s^2) | $header |"
echo "|---|---|---:|$rule|"
for name in "${names[@]}"; do
  for motion in $motions; do
    case $motion in
      shake) motion_args=(--motion shake) amplitude=30 frequency=1.5 ;;
      violent_shake) motion_args=(--motion violent_shake) amplitude=45 frequency=4 ;;
      yaw*) amplitude=${motion#yaw} amplitude=${amplitude%%_*} frequency=${motion##*_} frequency=${frequency%hz}
        keyframes "$work/$motion.csv" "$amplitude" "$frequency"
        motion_args=(--keyframes "$work/$motion.csv") ;;
    esac
    acceleration=$(awk -v a="$amplitude" -v f="$frequency" 'BEGIN { pi = atan2(0, -1); printf "%.0f", a * pi / 180 * (2 * pi * f)^2 }')
    if [[ $motion == shake ]]; then
      figures=${default_figures[$name]}
    else
      figures=$(run "$name" "$work/motion.h5" "${motion_args[@]}" --duration_s 6)
    fi
    echo "| $name | $motion | $acceleration | $(row "$figures") |"
  done
done
echo

# 4. A long run: LONG_FRAMES frames of the shake at 30 fps x 2, the energy per frame.
duration=$(awk -v n="$long_frames" 'BEGIN { printf "%.6f", n / 30 }')
start=$(date +%s)
figures=$(run "$long_model" "$work/long.h5" --motion shake --duration_s "$duration")
seconds=$(($(date +%s) - start))
echo "### $long_frames frames ($long_model, shake, 30 fps x 2, $seconds s of wall time)"
echo
echo "| model | frames | $header |"
echo "|---|---:|$rule|"
echo "| $long_model | ${figures%% *} | $(row "$figures") |"
echo
fps=$(h5dump -a /fps "$work/long.h5" | sed -n 's/^ *(0): *//p' | head -n 1)
"$bin/hair-sim-report" --energies "$work/long.h5" | awk -v fps="$fps" '
  { kinetic[NR - 1] = $2; total[NR - 1] = $5; n = NR }
  function window(label, from, to,   i, sum, most, ksum, kmost) {
    sum = 0; most = -1e300; ksum = 0; kmost = -1e300
    for (i = from; i < to; ++i) { sum += total[i]; ksum += kinetic[i]
      if (total[i] > most) most = total[i]; if (kinetic[i] > kmost) kmost = kinetic[i] }
    printf "| %s | %.4f | %.4f | %.4f | %.4f |\n", label, sum / (to - from), most, ksum / (to - from), kmost
    return sum / (to - from)
  }
  END {
    cycle = int(2 * fps + 0.5)  # the shake natural duration: three of its cycles
    print "| window (2 s) | mean total energy (J) | largest total energy (J) | mean kinetic energy (J) | largest kinetic energy (J) |"
    print "|---|---:|---:|---:|---:|"
    first = window("first cycle after the ramp (frames " cycle "-" 2 * cycle - 1 ")", cycle, 2 * cycle)
    split("0.25 0.5 0.75", shares, " ")
    for (s = 1; s <= 3; ++s) { at = int(int(n * shares[s]) / cycle) * cycle
      window("frames " at "-" at + cycle - 1, at, at + cycle) }
    end_at = int((n - 1) / cycle) * cycle
    last = window("last full cycle (frames " end_at - cycle "-" end_at - 1 ")", end_at - cycle, end_at)
    most = -1e300; arg = 0
    for (i = 0; i < n; ++i) if (total[i] > most) { most = total[i]; arg = i }
    printf "\nTotal energy: first frame %.4f J, last %.4f J, largest %.4f J (frame %d); mean over the last full cycle / over the first after the ramp: %.3f (drift %+.1f%%).\n", total[0], total[n - 1], most, arg, last / first, 100 * (last - first) / (first < 0 ? -first : first)
  }'
echo
times > "$work/times"
cpu=$(tail -n 1 "$work/times" | awk '{ gsub(/[ms]/, " "); print $1 * 60 + $2 + $3 * 60 + $4 }')
echo "Bench wall time: $(($(date +%s) - bench_start)) s; CPU time of its processes: ${cpu%.*} s."
