#!/usr/bin/env bash
# Two makes started at once on one output folder (Makefile.pipeline, a sample's chain to
# styles.h5): both succeed, every stage runs once (the other run waits on the model's lock
# and leaves what the first made), no temporary file is left, and the outputs are
# byte-identical to a single run's.
#
#   tests/faults/two_runs_one_folder.sh SOURCE_DIR BIN_DIR
set -euo pipefail
source_dir=$1 bin=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/data/hair/textures"
cp "$source_dir"/data/samples/hair/braid01.{obj,mtl} "$work/data/hair/"
cp "$source_dir"/data/samples/hair/textures/braid01* "$work/data/hair/textures/"
cp "$source_dir/data/samples/body.obj" "$work/data/"
out=$work/out
target=$out/braid01/styles.h5
run_make() {
  make -f "$source_dir/Makefile.pipeline" -C "$source_dir" DATA="$work/data" OUT="$out" BIN="$bin" \
    REPRODUCIBLE=yes STAGE_FLAGS=--quiet THREADS=1 "$target"
}
run_make >"$work/first.log" 2>&1 &
first=$!
run_make >"$work/second.log" 2>&1 &
second=$!
status=0
wait "$first" || { echo "first make failed:"; cat "$work/first.log"; status=1; }
wait "$second" || { echo "second make failed:"; cat "$work/second.log"; status=1; }
((status == 0)) || exit 1

stages="extract types middle clusters strands styles"
# make prints every recipe it starts; the ones the lock found made print that too.
recipes=$(cat "$work/first.log" "$work/second.log" | grep -c -- " -o $out/braid01/" || true)
left=$(cat "$work/first.log" "$work/second.log" | grep -c "made by another run" || true)
runs=$((recipes - left))
echo "stage recipes started: $recipes, left to the other run: $left"
[[ $runs == 6 ]] || { echo "expected each of the 6 stages to run once, got $runs runs"; exit 1; }
for stage in $stages; do
  "$bin/hair-inspect" "$out/braid01/$stage.h5" >/dev/null || { echo "$stage.h5 is invalid"; exit 1; }
done
if ls -A "$out/braid01" | grep -q '\.tmp\.'; then echo "temporary files left:"; ls -A "$out/braid01"; exit 1; fi

mkdir -p "$work/both"
cp "$out"/braid01/*.h5 "$work/both/"
rm -rf "$out"
run_make >"$work/single.log" 2>&1 || { cat "$work/single.log"; exit 1; }
for stage in $stages; do
  cmp -s "$work/both/$stage.h5" "$out/braid01/$stage.h5" || { echo "$stage.h5 differs from a single run's"; exit 1; }
done
echo "two runs on one folder: each stage ran once, outputs as a single run's"
