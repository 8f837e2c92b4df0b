#!/usr/bin/env bash
# The chain to styles.h5 on every mesh of the corpus (bench/corpus/README.md), and
# docs/measured/corpus.md: per mesh and per half (tune, check), how the input and the
# grown strands follow the painted flow, coverage and fidelity, kinks, curls kept, the
# styles by strands; and one contact sheet per half (the mesh with its texture beside the
# grown strands, a row per mesh), docs/measured/corpus_{tune,check}.png.
#
#   bench/corpus.sh [-j JOBS] [CORPUS_DIR]
#
# CORPUS_DIR (default build/corpus) is what scripts/corpus-prepare.sh wrote. Meshes run
# JOBS at a time (default 1), each stage on THREADS threads (default 1 when JOBS > 1).
# Environment: BIN (default build/bin), PARAMS (default pipelines/default), MODEL
# (default models/style_extended.yml), REPORT (default docs/measured/corpus.md; the
# pictures go beside it), ONLY (a regular expression: run only the meshes whose name
# matches; the report then holds just them), BLENDER (default blender: the mesh
# pictures; without it the sheets show the grown strands only), KEEP (a folder to keep
# every mesh's outputs and pictures in, instead of a temporary one).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

jobs=1
if [[ "${1:-}" == "-j" ]]; then jobs=$2; shift 2; elif [[ "${1:-}" == -j* ]]; then jobs=${1#-j}; shift; fi
corpus=${1:-build/corpus}
params=${PARAMS:-pipelines/default}
model_file=${MODEL:-models/style_extended.yml}
report=${REPORT:-docs/measured/corpus.md}
only=${ONLY:-.}
blender=${BLENDER:-blender}
threads=${THREADS:-$((jobs > 1 ? 1 : 0))}
manifest=$corpus/manifest.tsv
[[ -f "$manifest" ]] || { echo "corpus.sh: $manifest is missing: run scripts/corpus-prepare.sh first" >&2; exit 2; }

if [[ -n "${KEEP:-}" ]]; then
  work=$KEEP && mkdir -p "$work"  # every mesh's outputs and pictures stay there
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/corpus.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
source bench/common.sh
copy_binaries corpus "$work" extract typeify cluster-middle cluster-all grow classify hair-grow-report hair-render
bin=$work/bin
# The parameters and the model as they are now, so that an edit while the bench runs
# does not reach half of the meshes.
rm -rf "$work/params" && cp -r "$params" "$work/params" && params=$work/params
cp "$model_file" "$work/model.yml" && model_file=$work/model.yml
machine="$(nproc) cores, $(cpu_name)"  # before OMP_NUM_THREADS, which nproc obeys
export bin params model_file work corpus blender threads
export OMP_NUM_THREADS=$((threads > 0 ? threads : $(nproc)))

# one NAME: the chain, the report's row, the pictures; a failure is written down, not fatal.
one() {
  local name=$1 dir=$work/$1 mesh=$corpus/$1/hair/$1.obj body=$corpus/$1/body.obj
  mkdir -p "$dir"
  local start=$(date +%s%N)
  if ! ( pipeline_to_styles "$mesh" "$body" "$dir" ) 2>"$dir/error.txt"; then
    local first=$(grep -m 1 'error' "$dir/error.txt" || tail -n 1 "$dir/error.txt")
    echo "failed: $first" >"$dir/row.txt"
    echo "corpus: $name failed: $first" >&2
    return 0
  fi
  echo $(( ($(date +%s%N) - start) / 1000000 )) >"$dir/ms.txt"
  "$bin/hair-grow-report" "$dir/extract.h5" "$dir/strands.h5" --name "$name" >"$dir/row.txt"
  "$bin/hair-render" "$dir/strands.h5" --extract "$dir/extract.h5" --size 160 \
    --title "$name: grown strands by cluster" -o "$dir/strands.png"
  if command -v "$blender" >/dev/null; then
    "$blender" --background --factory-startup --python scripts/corpus/blender_mesh_views.py -- \
      "$mesh" "$body" "$dir/mesh.png" --size 160 >/dev/null 2>"$dir/blender.txt" || true
  fi
  echo "corpus: $name done" >&2
}
export -f one pipeline_to_styles pipeline_to_clusters

names=$(awk -F'\t' 'NR > 1 { print $1 }' "$manifest" | grep -E -- "$only" || true)
[[ -n "$names" ]] || { echo "corpus.sh: no mesh of $manifest matches '$only'" >&2; exit 2; }
echo "corpus: $(echo "$names" | wc -l) meshes, $jobs at a time" >&2
echo "$names" | xargs -P "$jobs" -I{} bash -c 'one "$@"' _ {}

mkdir -p "$(dirname "$report")"
/usr/bin/python3 bench/corpus_report.py "$manifest" "$work" "$report" \
  --command "bench/corpus.sh -j $jobs $corpus" --machine "$machine" \
  --commit "$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- common stages tools pipelines models || echo '+changes')"
echo "corpus: wrote $report" >&2
