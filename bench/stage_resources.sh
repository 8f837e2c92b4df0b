#!/usr/bin/env bash
# What each stage needs per model, to size a cluster's job requests (README, "Processing
# a library on a cluster"): wall time and peak memory (GNU time's maximum resident set)
# of every stage on each model, with THREADS threads, through Makefile.pipeline's own
# commands (LAUNCH is where /usr/bin/time goes). Markdown on stdout.
#
#   bench/stage_resources.sh [DATA]        (default data/samples; DATA/hair/*.obj)
#
# Environment: BIN (default build/bin), THREADS (default 2).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
data=${1:-data/samples}
bin=${BIN:-build/bin}
threads=${THREADS:-2}
work=$(mktemp -d "${TMPDIR:-/tmp}/stage_resources.XXXXXX")
trap 'rm -rf "$work"' EXIT
[[ -x /usr/bin/time ]] || { echo "stage_resources: needs GNU time (apt install time)" >&2; exit 2; }

# Each stage command runs under GNU time, which appends "stage seconds kilobytes" to a log.
cat > "$work/timed.sh" << 'SCRIPT'
#!/usr/bin/env bash
stage=$(basename "$1")
exec /usr/bin/time -a -o "$TIMED_LOG" -f "$stage %e %M" "$@"
SCRIPT
chmod +x "$work/timed.sh"
export TIMED_LOG=$work/times.log
for mesh in "$data"/hair/*.obj; do
  model=$(basename "$mesh" .obj)
  echo "model $model" >> "$TIMED_LOG"
  make -f Makefile.pipeline DATA="$data" OUT="$work/out" BIN="$bin" THREADS="$threads" \
    STAGE_FLAGS=--quiet LAUNCH="$work/timed.sh" "$work/out/$model/frames.h5" > /dev/null
done
echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $threads threads a stage; $(date +%F)."
echo
echo "| model | stage | wall (s) | peak memory (MB) |"
echo "|---|---|---:|---:|"
awk '/^model/ { model = $2; next } { printf "| %s | %s | %.2f | %.0f |\n", model, $1, $2, $3 / 1024 }' "$TIMED_LOG"
echo
echo "| stage | largest wall (s) | largest peak memory (MB) |"
echo "|---|---:|---:|"
awk '!/^model/ { if ($2 > wall[$1]) wall[$1] = $2; if ($3 > mem[$1]) mem[$1] = $3; order[$1] = NR }
     END { for (s in order) printf "%d | %s | %.2f | %.0f |\n", order[s], s, wall[s], mem[s] / 1024 }' "$TIMED_LOG" |
  sort -n | cut -d'|' -f2- | sed 's/^/|/'
awk '/^model/ { n++; next } { total += $2 } END { printf "\nAll stages, all models: %.1f s of wall time, %.1f s a model on average.\n", total, total / n }' "$TIMED_LOG"
