#!/usr/bin/env bash
# The pipeline through a real single-node Slurm (issue 29), run by ctest as
# slurm.pipeline (exit 77: skipped, with the reason, where slurm-wlm and munge are not
# installed or the test does not run as root; .ci/run installs them):
#  1. one of the demo's models (ponytail01: a cap, a band and a tail; the other two
#     run the same jobs, and the demo pipeline runs them in CI) through every stage, each stage a Slurm job (LAUNCH=srun ...),
#     give byte-identical outputs to a local run, both with REPRODUCIBLE=yes, and the jobs
#     visibly ran through Slurm (its job log lists one per stage and model);
#  2. a job cancelled while it runs (scancel) leaves no output and no temporary file,
#     make fails naming the file it could not make, and a rerun makes only what is
#     missing.
#
#   tests/slurm/pipeline_through_slurm.sh SOURCE_DIR BIN_DIR
set -euo pipefail
source_dir=$1
bin_dir=$2
cd "$source_dir"

for program in slurmctld slurmd munged srun scancel squeue; do
  command -v "$program" > /dev/null ||
    { echo "skipped: no $program (apt install slurm-wlm munge; .ci/run installs them)"; exit 77; }
done
[[ $(id -u) == 0 ]] || { echo "skipped: the local Slurm's daemons need root"; exit 77; }

work=$(mktemp -d "${TMPDIR:-/tmp}/slurm_pipeline.XXXXXX")
cleanup() { bash scripts/slurm-local.sh stop "$work/slurm" > /dev/null 2>&1 || true; rm -rf "$work"; }
trap cleanup EXIT
eval "$(bash scripts/slurm-local.sh start "$work/slurm")"
export SLURM_CONF
jobs_log=$work/slurm/jobs.log

# The data: ponytail01 and the body, linked from data/samples.
model=ponytail01
data=$work/data
mkdir -p "$data/hair/textures"
ln -s "$source_dir/data/samples/body.obj" "$data/body.obj"
ln -s "$source_dir/data/samples/hair/$model.obj" "$source_dir/data/samples/hair/$model.mtl" "$data/hair/"
ln -s "$source_dir/data/samples/hair/textures/$model.png" "$data/hair/textures/"

pipeline() {  # OUT [make arguments...]
  local out=$1
  shift
  make -f Makefile.pipeline DATA="$data" OUT="$out" BIN="$bin_dir" REPRODUCIBLE=yes \
    STAGE_FLAGS=--quiet "$@"
}
fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. Local and through Slurm, byte for byte: both into the same OUT (the provenance
# records the inputs' paths), the local run's moved aside.
pipeline "$work/cluster" -j 2 THREADS=1 all > "$work/local.log" 2>&1 || { cat "$work/local.log"; fail "local run"; }
mv "$work/cluster" "$work/local"
launch='srun --ntasks=1 --cpus-per-task=1 --mem=3G --quiet'
pipeline "$work/cluster" -j 4 LAUNCH="$launch" all > "$work/cluster.log" 2>&1 ||
  { cat "$work/cluster.log"; fail "run through Slurm"; }
files=0
for file in "$work"/local/*/*.h5; do
  other=$work/cluster/${file#"$work/local/"}
  cmp -s "$file" "$other" || fail "$other differs from the local run's"
  files=$((files + 1))
done
models=$(ls "$data"/hair/*.obj | wc -l)
((files == models * 8)) || fail "$files files, expected $((models * 8))"
ran=$(grep -c 'JobState=COMPLETED' "$jobs_log")
((ran >= models * 8)) || fail "Slurm's job log lists $ran completed jobs, expected $((models * 8))"
echo "ok: $models models, $files files through $ran Slurm jobs, identical to the local run"

# 2. A cancelled job: simulate of the model, cancelled while it runs.
rm -f "$work/cluster/$model/guides.h5" "$work/cluster/$model/frames.h5"
before=$(grep -c 'JobState=COMPLETED' "$jobs_log")
pipeline "$work/cluster" LAUNCH="$launch --job-name=hair-slow bash tests/slurm/slow.sh 30" all \
  > "$work/cancel.log" 2>&1 &
make_pid=$!
for _ in $(seq 300); do
  [[ -n $(squeue -h -n hair-slow -t RUNNING -o %i) ]] && break
  sleep 0.2
done
job=$(squeue -h -n hair-slow -t RUNNING -o %i)
[[ -n $job ]] || { kill $make_pid; fail "the slow job never ran"; }
scancel "$job"
if wait $make_pid; then fail "make succeeded though its job was cancelled"; fi
grep -q "$work/cluster/$model/guides.h5" "$work/cancel.log" ||
  { cat "$work/cancel.log"; fail "make does not name the file it could not make"; }
[[ ! -e $work/cluster/$model/guides.h5 ]] || fail "a guides.h5 was left"
leftovers=$(find "$work/cluster/$model" -name '*.tmp*' | wc -l)
((leftovers == 0)) || fail "$leftovers temporary files were left"
grep -q "JobId=$job .*JobState=CANCELLED" "$jobs_log" || fail "Slurm did not log job $job as cancelled"
echo "ok: job $job cancelled, make failed naming $model/guides.h5, nothing left behind"

# The rerun makes what is missing, and only that: simulate and interpolate of one model.
pipeline "$work/cluster" LAUNCH="$launch" all > "$work/rerun.log" 2>&1 || { cat "$work/rerun.log"; fail "rerun"; }
after=$(grep -c 'JobState=COMPLETED' "$jobs_log")
((after - before == 2)) || fail "the rerun ran $((after - before)) jobs, expected 2 (simulate, interpolate)"
cmp -s "$work/local/$model/frames.h5" "$work/cluster/$model/frames.h5" || fail "the rerun's frames.h5 differs"
echo "ok: the rerun made $model's guides.h5 and frames.h5 only, identical to the local run's"
