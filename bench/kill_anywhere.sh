#!/usr/bin/env bash
# Kill anywhere: runs `make -f Makefile.pipeline -j2 all` on the samples, kills a random
# stage process (or make itself) with SIGKILL at a random moment, KILLS times with a fixed
# seed, reruns make after each kill, and checks that:
#  - no output up to date before a rerun (make -q) is made again by it (its modification
#    time stays),
#  - the finished outputs are byte-identical to a clean REPRODUCIBLE=yes run's
#    (every dataset and attribute: the same paths, so the same provenance),
#  - no temporary file is left.
# Writes a report (markdown) to REPORT (default docs/bench/kill_anywhere.md). Takes about
# 40 s a kill on 2 cores with nothing else running (30 kills: about 25 minutes; twice that
# beside other work): a nightly bench, not a ctest test.
#
#   bash bench/kill_anywhere.sh [KILLS (30)] [SEED (1)]
#
# Environment: BIN (default build/bin), DATA (default data/samples), MAX_DELAY_MS (the
# latest moment of a kill after make starts, default 8000), REPORT.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
kills=${1:-30}
seed=${2:-1}
bin=${BIN:-build/bin}
data=${DATA:-data/samples}
max_delay_ms=${MAX_DELAY_MS:-8000}
report=${REPORT:-docs/bench/kill_anywhere.md}
source bench/common.sh
work=$(mktemp -d "${TMPDIR:-/tmp}/kill_anywhere.XXXXXX")
trap 'rm -rf "$work"' EXIT
copy_binaries kill_anywhere "$work" extract typeify cluster-middle cluster-all grow classify simulate interpolate hair-inspect
bin=$work/bin
out=$work/out
params=$work/params
cp -r pipelines/default "$params"
stage_files=(extract typeify cluster-middle cluster-all grow classify simulate interpolate)

run_make() {
  make -f Makefile.pipeline DATA="$data" OUT="$out" BIN="$bin" PARAMS="$params" \
    REPRODUCIBLE=yes STAGE_FLAGS=--quiet -j2 "${@:-all}" >>"$work/make.log" 2>&1
}
# The outputs make finds up to date (make -q).
up_to_date() {
  local file
  find "$out" -name '*.h5' | sort | while read -r file; do
    make -q -f Makefile.pipeline DATA="$data" OUT="$out" BIN="$bin" PARAMS="$params" "$file" \
      2>/dev/null && echo "${file#$out/}"
  done
}
outputs() { find "$out" -name '*.h5' -printf '%P %T@\n' 2>/dev/null | sort; }

RANDOM=$seed
rows=""
reruns_of_complete=0
run_make  # everything once; each kill then interrupts the rerun of a random stage onwards
for ((i = 1; i <= kills; ++i)); do
  touch "$params/${stage_files[$((RANDOM % ${#stage_files[@]}))]}.toml"
  run_make &
  make_pid=$!
  delay_ms=$(((RANDOM * 32768 + RANDOM) % max_delay_ms))
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  # The victim: a running stage, or make itself one time in five.
  mapfile -t stages < <(pgrep -f "^$bin/" || true)
  if ((${#stages[@]} > 0 && RANDOM % 5 != 0)); then
    victim=${stages[$((RANDOM % ${#stages[@]}))]}
    what=$(ps -o args= -p "$victim" 2>/dev/null | awk '{ n = split($1, p, "/"); print p[n] }') || what="a stage"
  else
    victim=$make_pid
    what=make
  fi
  kill -KILL "$victim" 2>/dev/null || what="$what (had ended)"
  wait "$make_pid" 2>/dev/null || true
  # make killed leaves its running stages to finish or die on their own: wait for them.
  while pgrep -f "^$bin/" >/dev/null; do sleep 0.2; done
  before=$(outputs)
  fresh=$(up_to_date | awk '{ print $1 }')
  run_make || { echo "kill_anywhere: the rerun after kill $i failed" >&2; tail "$work/make.log" >&2; exit 1; }
  after=$(outputs)
  before=$(echo "$before" | grep -F -f <(echo "${fresh:-@none@}") || true)
  remade=$(join <(echo "$before") <(echo "$after") | awk '$2 != $3 { print $1 }' | tr '\n' ' ')
  [[ -z $remade ]] || reruns_of_complete=$((reruns_of_complete + 1))
  complete=$(echo "$before" | grep -c . || true)
  rows+="| $i | ${delay_ms} | ${what} | ${complete} | ${remade:-none} |"$'\n'
  echo "kill $i: ${delay_ms} ms, $what; $complete outputs up to date before the rerun; remade: ${remade:-none}" >&2
done

# The last run, killed and rerun, against a clean one of the same paths.
rm -rf "$out"
run_make &
make_pid=$!
sleep 3
pkill -KILL -f "^$bin/" || true
wait "$make_pid" 2>/dev/null || true
run_make
mkdir -p "$work/killed" && cp -r "$out"/. "$work/killed/"
temporaries=$(find "$out" -name '.*.tmp.*' | wc -l)
rm -rf "$out"
run_make
differ=0
while read -r file; do
  cmp -s "$work/killed/$file" "$out/$file" || { echo "differs: $file" >&2; differ=$((differ + 1)); }
done < <(cd "$out" && find . -name '*.h5' | sort)
files=$(cd "$out" && find . -name '*.h5' | wc -l)

mkdir -p "$(dirname "$report")"
{
  echo "# Kill anywhere"
  echo
  echo "Measured $(date +%F) at commit $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- common stages || echo '+changes') on $(nproc) cores, $(cpu_name), by"
  echo "\`bash bench/kill_anywhere.sh $kills $seed\` (MAX_DELAY_MS=$max_delay_ms): make -j2 on $data, a random"
  echo "stage process (or make, one time in five) killed with SIGKILL at a random moment,"
  echo "then make again."
  echo
  echo "- kills: $kills; reruns that made again an output complete before them: $reruns_of_complete"
  echo "- a last run killed and rerun against a clean run: $differ of $files outputs differ; temporary files left: $temporaries"
  echo
  echo "| kill | after (ms) | killed | outputs up to date before the rerun | made again by the rerun |"
  echo "|---:|---:|---|---:|---|"
  printf '%s' "$rows"
} >"$report"
echo "kill_anywhere: wrote $report" >&2
((reruns_of_complete == 0 && differ == 0 && temporaries == 0))
