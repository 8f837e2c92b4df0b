# bench/common.sh: shell functions the bench scripts share; source it, do not run it.
#   source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# copy_binaries SCRIPT DIR TOOL...: copies each BIN/TOOL (BIN: default build/bin) into
# DIR/bin, so that a rebuild while the bench runs does not change them; a missing one
# is an error naming SCRIPT.
copy_binaries() {
  local script=$1 dir=$2 tool
  shift 2
  mkdir -p "$dir/bin"
  for tool in "$@"; do
    [[ -x "${BIN:-build/bin}/$tool" ]] || { echo "$script: ${BIN:-build/bin}/$tool is missing" >&2; exit 1; }
    cp "${BIN:-build/bin}/$tool" "$dir/bin/"
  done
}

# median: the median of the numbers on stdin, one per line.
median() { sort -g | awk '{v[NR]=$1} END {print (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2)}'; }

# time_ms COMMAND...: median wall time of $runs runs of COMMAND, in ms (output discarded).
time_ms() {
  local run start
  for ((run = 0; run < runs; ++run)); do
    start=$(date +%s%N)
    "$@" >/dev/null 2>&1
    echo $(($(date +%s%N) - start))
  done | median | awk '{ printf "%.0f\n", $1 / 1e6 }'
}
