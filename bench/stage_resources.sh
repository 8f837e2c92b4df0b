#!/usr/bin/env bash
# What each stage needs per model, to size a cluster's job requests (README, "Processing
# a library on a cluster"): wall time and peak memory (GNU time's maximum resident set)
# of every stage on each model, with THREADS threads, through Makefile.pipeline's own
# commands (LAUNCH is where /usr/bin/time goes). Markdown on stdout.
#
#   bench/stage_resources.sh [DATA]        (default data/samples; DATA/hair/*.obj)
#   bench/stage_resources.sh --big         inputs far larger than the samples: long01
#       subdivided 4 times (bench/subdivide_obj.py; 1,051,648 triangles, its texture
#       kept), grow's strand_count 100,000, simulate's guide_count 2,000, interpolate on
#       the first 30 frames (one second; each frame is one chunk of frames.h5, so its
#       memory does not grow with the frames). About 15 minutes on 2 cores.
#
# Environment: BIN (default build/bin), THREADS (default 2).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bin=${BIN:-build/bin}
threads=${THREADS:-2}
work=$(mktemp -d "${TMPDIR:-/tmp}/stage_resources.XXXXXX")
trap 'rm -rf "$work"' EXIT
[[ -x /usr/bin/time ]] || { echo "stage_resources: needs GNU time (apt install time)" >&2; exit 2; }
params=pipelines/default
frames=
if [[ ${1:-} == --big ]]; then
  data=$work/data
  mkdir -p "$data/hair/textures"
  ln -s "$PWD/data/samples/body.obj" "$data/body.obj"
  cp data/samples/hair/long01.mtl "$data/hair/"
  cp data/samples/hair/textures/long01.png "$data/hair/textures/"
  echo "stage_resources: subdividing long01 4 times" >&2
  /usr/bin/python3 bench/subdivide_obj.py data/samples/hair/long01.obj "$data/hair/long01.obj" 4
  params=$work/params
  cp -r pipelines/default "$params"
  sed -i 's/^strand_count = .*/strand_count = 100000/' "$params/grow.toml"
  sed -i 's/^guide_count = .*/guide_count = 2000/' "$params/simulate.toml"
  frames=0:30
else
  data=${1:-data/samples}
fi

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
  triangles=$(awk '/^f / { t += NF - 3 } END { print t }' "$mesh")
  echo "model $model $triangles" >> "$TIMED_LOG"
  make -f Makefile.pipeline DATA="$data" OUT="$work/out" BIN="$bin" THREADS="$threads" \
    PARAMS="$params" FRAMES="$frames" STAGE_FLAGS=--quiet LAUNCH="$work/timed.sh" \
    "$work/out/$model/frames.h5" > /dev/null
  # Rows of a dataset's first dimension, as hair-inspect lists it ("[N]" or "[N, 3]").
  rows() { "$bin/hair-inspect" "$1" | awk -v name="$2" '$1 == name { gsub(/[\[\],]/, "", $3); print $3; exit }'; }
  echo "sizes | $model | $triangles | $(rows "$work/out/$model/extract.h5" /strands/points) |" \
    "$(($(rows "$work/out/$model/strands.h5" /strands/offsets) - 1)) |" \
    "$(rows "$work/out/$model/strands.h5" /strands/points) |" \
    "$(($(rows "$work/out/$model/guides.h5" /guides/offsets) - 1)) |" \
    "$(rows "$work/out/$model/guides.h5" /guides/rest_points) |" \
    "$(du -m "$work/out/$model/frames.h5" | cut -f1) |" >> "$work/sizes.log"
done
echo "| model | mesh triangles | input strand points | grown strands | grown points | guides | guide points | frames.h5 (MB) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
sed 's/^sizes //' "$work/sizes.log"
echo
echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $threads threads a stage; $(date +%F)."
echo
echo "| model | stage | wall (s) | peak memory (MB) |"
echo "|---|---|---:|---:|"
awk '/^model/ { model = $2 " (" $3 " triangles)"; next } { printf "| %s | %s | %.2f | %.0f |\n", model, $1, $2, $3 / 1024 }' "$TIMED_LOG"
echo
echo "| stage | largest wall (s) | largest peak memory (MB) |"
echo "|---|---:|---:|"
awk '!/^model/ { if ($2 > wall[$1]) wall[$1] = $2; if ($3 > mem[$1]) mem[$1] = $3; order[$1] = NR }
     END { for (s in order) printf "%d | %s | %.2f | %.0f |\n", order[s], s, wall[s], mem[s] / 1024 }' "$TIMED_LOG" |
  sort -n | cut -d'|' -f2- | sed 's/^/|/'
awk '/^model/ { n++; next } { total += $2 } END { printf "\nAll stages, all models: %.1f s of wall time, %.1f s a model on average.\n", total, total / n }' "$TIMED_LOG"
