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

# pipeline_to_clusters MESH BODY DIR: extract, typeify, cluster-middle and cluster-all
# of MESH on BODY into DIR/{extract,types,middle,clusters}.h5, with $bin's binaries and
# $params's parameter files.
pipeline_to_clusters() {
  local mesh=$1 body=$2 dir=$3
  mkdir -p "$dir"
  "$bin/extract" "$mesh" --body "$body" -o "$dir/extract.h5" --params "$params/extract.toml" --quiet
  "$bin/typeify" "$dir/extract.h5" -o "$dir/types.h5" --params "$params/typeify.toml" --quiet
  "$bin/cluster-middle" "$dir/types.h5" -o "$dir/middle.h5" --params "$params/cluster-middle.toml" --quiet
  "$bin/cluster-all" "$dir/types.h5" "$dir/middle.h5" -o "$dir/clusters.h5" --params "$params/cluster-all.toml" --quiet
}

# pipeline_to_styles MESH BODY DIR [GROW_OPTION...]: pipeline_to_clusters, then grow (with
# GROW_OPTIONs) and classify (with $model_file) into DIR/{strands,styles}.h5.
pipeline_to_styles() {
  local mesh=$1 body=$2 dir=$3
  shift 3
  pipeline_to_clusters "$mesh" "$body" "$dir"
  "$bin/grow" "$dir/extract.h5" "$dir/types.h5" "$dir/clusters.h5" -o "$dir/strands.h5" --params "$params/grow.toml" --quiet "$@"
  "$bin/classify" "$dir/extract.h5" "$dir/clusters.h5" "$dir/strands.h5" --model "$model_file" -o "$dir/styles.h5" --params "$params/classify.toml" --quiet
}

# cpu_name: the processor as /proc/cpuinfo names it, with its family and model (a cloud
# "AMD EPYC" is several generations: family 25 is Zen 3 and 4, family 26 Zen 5) and
# whether it has AVX-512, so that figures from different machines are not compared as
# if from one.
cpu_name() {
  awk -F': *' '
    $1 ~ /^model name/ && !name { name = $2 }
    $1 ~ /^cpu family/ && !family { family = $2 }
    $1 ~ /^model[ \t]*$/ && !model { model = $2 }
    $1 ~ /^flags/ && !flags { flags = " " $2 " " }
    END {
      printf "%s (family %s, model %s%s)\n", name, family, model,
        (index(flags, " avx512f ") ? ", AVX-512" : (index(flags, " avx2 ") ? ", AVX2" : ""))
    }' /proc/cpuinfo
}
