#!/usr/bin/env bash
# The clustering stages (cluster-middle, cluster-all) on every MakeHuman mesh and on
# synthetic braided models: counts, median wall time of each stage (the issue asks
# for under 1 s on every MakeHuman mesh), determinism of --reproducible reruns, and
# our spectral clustering against scikit-learn's on the same graphs
# (bench/sklearn_spectral.py), as Markdown tables on stdout.
#
#   bench/cluster_compare.sh [MAKEHUMAN_DIR]
#
# Each model goes extract -> typeify -> cluster-middle -> cluster-all in a temporary
# folder. Synthetic models: hair-synth --preset braid|two_braids|normal_braid --vary
# for each seed of SEEDS. Stage times use hyperfine when installed (apt-get install
# hyperfine), else a loop of date +%s%N. Deterministic means three --reproducible
# runs of each stage (two with THREADS, one with --threads 1) give identical bytes.
# Environment: BIN (default build/bin), RUNS (default 5), THREADS (stage --threads,
# default 0 = all), SEEDS (default "1 2 3"), PYTHON (default python3; needs numpy,
# scipy, h5py and scikit-learn).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/common.sh

makehuman=${1:-../shared/data/makehuman}
body=data/samples/body.obj
runs=${RUNS:-5}
threads=${THREADS:-0}
seeds=${SEEDS:-1 2 3}
python=${PYTHON:-python3}
work=$(mktemp -d "${TMPDIR:-/tmp}/cluster_compare.XXXXXX")
trap 'rm -rf "$work"' EXIT

# A copy of the binaries, so that a rebuild while this runs does not change them.
mkdir -p "$work/bin"
for tool in extract typeify cluster-middle cluster-all hair-synth; do
  [[ -x "${BIN:-build/bin}/$tool" ]] || { echo "cluster_compare: ${BIN:-build/bin}/$tool is missing" >&2; exit 1; }
  cp "${BIN:-build/bin}/$tool" "$work/bin/"
done
bin=$work/bin
[[ -e "$body" ]] || { echo "cluster_compare: $body is missing" >&2; exit 1; }
"$python" -c 'import h5py, numpy, scipy, sklearn' 2>/dev/null ||
  { echo "cluster_compare: $python lacks numpy, scipy, h5py or scikit-learn (set PYTHON)" >&2; exit 1; }

# time_ms COMMAND...: median wall time of RUNS runs of the command, in ms, to 0.1 ms
# (common.sh's to 1 ms), with hyperfine where it is installed.
time_ms() {
  if command -v hyperfine >/dev/null; then
    local quoted
    printf -v quoted '%q ' "$@"
    hyperfine --style none --warmup 1 --runs "$runs" --export-json "$work/hyperfine.json" \
      "$quoted" >/dev/null 2>&1
    grep -o '"median": *[0-9.eE+-]*' "$work/hyperfine.json" | head -n 1 | sed 's/.*: *//' |
      awk '{ printf "%.1f\n", $1 * 1000 }'
  else
    local run start
    for ((run = 0; run < runs; ++run)); do
      start=$(date +%s%N)
      "$@" >/dev/null 2>&1
      echo $(($(date +%s%N) - start))
    done | median | awk '{ printf "%.1f\n", $1 / 1e6 }'
  fi
}

# The first error line of a log, for a failed stage.
error_line() { grep -m 1 -i 'error' "$1" || tail -n 1 "$1" || true; }

# counts DIR: groups | middle groups | middle clusters | nodes | clusters before split | clusters
counts() {
  "$python" - "$1/middle.h5" "$1/clusters.h5" <<'EOF'
import sys, h5py
with h5py.File(sys.argv[1], "r") as middle, h5py.File(sys.argv[2], "r") as clusters:
    mc = middle["/groups/middle_cluster"][()]
    source = middle.attrs["cluster_count_source"]
    source = source.decode() if isinstance(source, bytes) else source
    print(f"{len(mc)} | {int((mc >= 0).sum())} | {int(middle.attrs['cluster_count'])} ({source}) | "
          f"{len(clusters['/nodes/set'])} | {int(clusters.attrs['cluster_count'])} | "
          f"{len(clusters['/clusters/group_count'])}")
EOF
}

# same FILE...: "yes" when every file has the bytes of the first, else "no".
same() {
  local first=$1 file
  shift
  for file; do cmp -s "$first" "$file" || { echo no; return; }; done
  echo yes
}

# run_model NAME MESH: the pipeline on one mesh, one Markdown row on stdout; the
# stage outputs and their times go to $work/out/NAME and $work/times.tsv.
run_model() {
  local name=$1 mesh=$2 dir=$work/out/$1
  mkdir -p "$dir/det"
  if ! "$bin/extract" "$mesh" --body "$body" --unit_scale 0.1 --quiet --threads "$threads" \
         -o "$dir/extract.h5" 2>"$dir/extract.log"; then
    echo "| $name | extract failed: $(error_line "$dir/extract.log") |"; return
  fi
  if ! "$bin/typeify" "$dir/extract.h5" --quiet --threads "$threads" -o "$dir/types.h5" \
         2>"$dir/typeify.log"; then
    echo "| $name | typeify failed: $(error_line "$dir/typeify.log") |"; return
  fi
  local middle=("$bin/cluster-middle" "$dir/types.h5" --quiet)
  local all=("$bin/cluster-all" "$dir/types.h5" "$dir/middle.h5" --quiet)
  local middle_ms all_ms
  if ! "${middle[@]}" --threads "$threads" -o "$dir/middle.h5" 2>"$dir/middle.log"; then
    echo "| $name | cluster-middle failed: $(error_line "$dir/middle.log") |"; return
  fi
  middle_ms=$(time_ms "${middle[@]}" --threads "$threads" -o "$dir/middle.h5")
  printf '%s\t%s\n' "$dir/middle.h5" "$middle_ms" >>"$work/times.tsv"
  if ! "${all[@]}" --threads "$threads" -o "$dir/clusters.h5" 2>"$dir/all.log"; then
    echo "| $name | cluster-all failed: $(error_line "$dir/all.log") |"; return
  fi
  all_ms=$(time_ms "${all[@]}" --threads "$threads" -o "$dir/clusters.h5")
  printf '%s\t%s\n' "$dir/clusters.h5" "$all_ms" >>"$work/times.tsv"

  # Determinism: two reproducible runs and one on a single thread, byte for byte.
  local run
  for run in 1 2; do
    "${middle[@]}" --reproducible --threads "$threads" -o "$dir/det/middle.$run.h5" 2>/dev/null
  done
  "${middle[@]}" --reproducible --threads 1 -o "$dir/det/middle.3.h5" 2>/dev/null
  local all_det=("$bin/cluster-all" "$dir/types.h5" "$dir/det/middle.1.h5" --quiet --reproducible)
  for run in 1 2; do
    "${all_det[@]}" --threads "$threads" -o "$dir/det/clusters.$run.h5" 2>/dev/null
  done
  "${all_det[@]}" --threads 1 -o "$dir/det/clusters.3.h5" 2>/dev/null
  local middle_same all_same deterministic
  middle_same=$(same "$dir"/det/middle.{1,2,3}.h5)
  all_same=$(same "$dir"/det/clusters.{1,2,3}.h5)
  if [[ $middle_same == yes && $all_same == yes ]]; then
    deterministic=yes
  else
    deterministic="no (cluster-middle $middle_same, cluster-all $all_same)"
  fi
  echo "| $name | $(counts "$dir") | $middle_ms | $all_ms | $deterministic |"
}

header="| model | groups | middle groups | middle clusters (k source) | cluster-all nodes | clusters before split | clusters | cluster-middle (ms) | cluster-all (ms) | deterministic |"
rule="|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"
if command -v hyperfine >/dev/null; then method="hyperfine, median of $runs runs after 1 warm-up run"
else method="shell loop, median of $runs runs"; fi
version=$(cat "${BIN:-build/bin}/hairstyle-version.txt" 2>/dev/null || git describe --always --dirty 2>/dev/null || echo unknown)
echo "Machine: $(nproc) cores, $(cpu_name); load average $(cut -d ' ' -f 1-3 /proc/loadavg)."
echo "Binaries: $version; stages with --threads $threads; stage times are wall clock of the whole binary (read, graph, clustering, write), $method."
echo "scikit-learn $("$python" -c 'import sklearn; print(sklearn.__version__)'), scipy $("$python" -c 'import scipy; print(scipy.__version__)') ($python)."
echo
echo "### MakeHuman meshes ($makehuman/hair, body $body, --unit_scale 0.1)"
echo
echo "$header"
echo "$rule"
: >"$work/times.tsv"
for mesh in "$makehuman"/hair/*.obj; do
  run_model "$(basename "$mesh" .obj)" "$mesh" | tee -a "$work/makehuman.md"
done
echo
awk -F '|' 'NF >= 11 { n++; for (i = 9; i <= 10; i++) if ($i + 0 > max) max = $i + 0; if ($9 + 0 >= 1000 || $10 + 0 >= 1000) slow++ }
  END { printf "Each stage under 1 s on every MakeHuman mesh: %s (%d of %d meshes ran every stage; slowest stage %.1f ms).\n",
        (slow == 0 && n > 0) ? "yes" : "no", n, '"$(ls "$makehuman"/hair/*.obj | wc -l)"', max }' "$work/makehuman.md"
echo
echo "### Synthetic braided models (hair-synth --vary, seeds $seeds)"
echo
echo "$header"
echo "$rule"
for preset in braid two_braids normal_braid; do
  for seed in $seeds; do
    name=$preset-s$seed
    synth=$work/synth/$preset-$seed
    if ! "$bin/hair-synth" --preset "$preset" --seed "$seed" --vary --reproducible --body "$body" \
           -o "$synth" 2>"$work/synth.log"; then
      echo "| $name | hair-synth failed: $(error_line "$work/synth.log") |"; continue
    fi
    run_model "$name" "$synth/$preset.obj"
  done
done
echo
echo "### Our spectral clustering against scikit-learn's (bench/sklearn_spectral.py)"
echo
echo "The same affinity matrix; k is ours; ARI = adjusted Rand index of the two labellings (1: identical partitions);"
echo "sklearn times are the median of $runs fits, ours the median wall time of the whole stage binary."
echo
mapfile -t files < <(cut -f 1 "$work/times.tsv")  # every stage output, in order
if ((${#files[@]})); then
  "$python" bench/sklearn_spectral.py --runs "$runs" --times "$work/times.tsv" "${files[@]}"
else
  echo "No stage outputs to compare."
fi
