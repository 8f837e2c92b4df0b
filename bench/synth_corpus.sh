#!/usr/bin/env bash
# The synthetic corpus end to end: hair-synth corpus (wall time, streams per style),
# the pipeline over every model (make -f Makefile.pipeline), and the stages measured
# against the truth (the tables docs/synth.md quotes, printed by the unit tests).
#
#   bench/synth_corpus.sh [COUNT]
#
# Environment: BUILD (default build), JOBS (default nproc).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/common.sh

count=${1:-60}
build=${BUILD:-build}
jobs=${JOBS:-$(nproc)}
work=$(mktemp -d "${TMPDIR:-/tmp}/synth_corpus.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "Machine: $(nproc) cores, $(cpu_name)"
start=$(date +%s%N)
"$build/bin/hair-synth" corpus --count "$count" -o "$work/data/hair" --reproducible 2>/dev/null
echo "hair-synth corpus --count $count: $(( ($(date +%s%N) - start) / 1000000 )) ms, $(du -sh "$work/data/hair" | cut -f1)"

start=$(date +%s%N)
make -s -f Makefile.pipeline BUILD="$build" DATA="$work/data" OUT="$work/out" \
  BODY=data/samples/body.obj THREADS=1 STAGE_FLAGS=--quiet -j "$jobs" all > /dev/null
done_models=$(find "$work/out" -name types.h5 | wc -l)
echo "pipeline (make -j $jobs): $done_models of $count models through every stage, $(( ($(date +%s%N) - start) / 1000000 )) ms"
echo
"$build/tests/hair_unit_tests" --gtest_filter='SynthPresets.Corpus*:*SynthPreset.Extract*:SynthTypeify*:SynthExtract*' |
  grep '^\[ synth' | sed 's/^\[ synth    \] //'
