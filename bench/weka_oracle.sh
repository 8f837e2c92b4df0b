#!/usr/bin/env bash
# Weka as an oracle for our style classifiers (issue 6): the feature tables that
# hair-train-style --tables writes (features_paper.arff, features_extended.arff,
# features_raw.arff) run through Weka's own 10-fold cross-validation (-x 10 -s 1), the
# paper's likely toolchain, as a Markdown table on stdout (and in OUT.md when given).
#
#   bench/weka_oracle.sh TABLES_DIR [OUT.md]
#
# Needs Weka 3.6 (Debian: apt-get install -y --no-install-recommends weka, which pulls
# a JRE) and bash >= 4.3. Not a CI test: a bench, a few minutes on two cores.
#
# Runs, for each feature set whose ARFF is in TABLES_DIR:
#   SVM, nested grid (feature sets of GRID_SETS): weka.classifiers.meta.MultiScheme -X 5
#     over one SMO (-N 1: standardise, PUK kernel) per point of our grid, sigma in
#     SIGMAS x omega in OMEGAS x C in CS. MultiScheme scores every candidate by a 5-fold
#     CV of the training rows it is given and keeps the one of least error, the first
#     among equals, so inside Weka's outer CV it is our grid search in each training fold;
#     the candidates are listed in our order of preference among equals (C ascending,
#     sigma descending, omega ascending). Weka 3.6's GridSearch only searches two
#     properties (it reaches the kernel, e.g. classifier.kernel.sigma and classifier.c)
#     and scores the grid by 2-fold CV then hill-climbs with 10-fold CV, and
#     CVParameterSelection only reaches the top-level options of SMO (-C, not the
#     kernel's -S and -O, which sit inside -K) on a linear scale: neither is our search.
#   SVM, Weka's GridSearch (feature sets of GRIDSEARCH_SETS): sigma x C on our grid
#     values, omega 1, accuracy as the measure: what a Weka user would reach for.
#   SVM, fixed settings: Weka's defaults (sigma 1, omega 1, C 1; with -N 1, where Weka's
#     default is -N 0, normalise to [0, 1]) and, when REPORT has the feature set, the
#     setting our grid search chose most often in its folds.
#   Random forest, 100 trees, seed 1: Weka's default features per split (-K 0:
#     int(log2(d) + 1)) and -K round(sqrt(d)), ours (OpenCV's default).
# Weka's folds are not ours (another random generator), so the figures compare as
# estimates, not fold by fold.
#
# Environment: WEKA_JAR (default /usr/share/java/weka.jar), JAVA (default java),
# WEKA_HEAP (java -Xmx, default 2g), JOBS (Weka runs at a time, default 2),
# GRID_SETS (default "paper extended"; raw adds ~21 CPU minutes: one MultiScheme build of
# the grid on 718 raw rows took 115 s, and the CV does eleven),
# GRIDSEARCH_SETS (default "paper"), SIGMAS (default "0.5 1 2 4 8 16"), OMEGAS (default
# "0.5 1 2 5"), CS (default "0.1 1 10 100"), INNER_FOLDS (default 5), REPORT (our
# hair-train-style --report, default TABLES_DIR/../report.md; compared when present),
# WEKA_LOGS (a folder to keep Weka's raw outputs in), LENGTH_LOG_OFFSET (default 0.1, as
# hair-train-style's --length-log-offset) and LINEAR (1: every feature as it is, as
# --linear-features): how the lengths and the node count reach the classifiers.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 || ! -d $1 ]]; then
  echo "usage: $0 TABLES_DIR [OUT.md]" >&2
  exit 2
fi
tables=$(cd "$1" && pwd)
out=${2:-}
jar=${WEKA_JAR:-/usr/share/java/weka.jar}
java=${JAVA:-java}
heap=${WEKA_HEAP:-2g}
max_jobs=${JOBS:-2}
grid_sets=" ${GRID_SETS-paper extended} "
gridsearch_sets=" ${GRIDSEARCH_SETS-paper} "
read -r -a sigmas <<<"${SIGMAS:-0.5 1 2 4 8 16}"
read -r -a omegas <<<"${OMEGAS:-0.5 1 2 5}"
read -r -a cs <<<"${CS:-0.1 1 10 100}"
inner_folds=${INNER_FOLDS:-5}
report=${REPORT:-$(dirname "$tables")/report.md}
[[ -f $jar ]] || { echo "$0: no Weka jar at $jar (apt-get install weka, or set WEKA_JAR)" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/weka_oracle.XXXXXX")
trap 'rm -rf "$work"' EXIT

weka_version=$("$java" -cp "$jar" weka.core.Version 2>/dev/null | head -1)
java_version=$("$java" -version 2>&1 | head -1)
puk=weka.classifiers.functions.supportVector.Puk
smo=weka.classifiers.functions.SMO

# Grid points in our order of preference among equals (puk_svm_candidates): C ascending,
# sigma descending, omega ascending.
mapfile -t sorted_sigmas < <(printf '%s\n' "${sigmas[@]}" | sort -g -r)
mapfile -t sorted_omegas < <(printf '%s\n' "${omegas[@]}" | sort -g)
mapfile -t sorted_cs < <(printf '%s\n' "${cs[@]}" | sort -g)
grid_points=()
grid_options=()
for c in "${sorted_cs[@]}"; do
  for s in "${sorted_sigmas[@]}"; do
    for o in "${sorted_omegas[@]}"; do
      grid_points+=("$s $o $c")
      grid_options+=(-B "$smo -C $c -N 1 -K \"$puk -O $o -S $s\"")
    done
  done
done
printf '%s\n' "${grid_points[@]}" >"$work/grid_points"

# log2 of the smallest and largest value of a list of powers of `base` (for GridSearch).
exponent_range() {  # base values...
  local base=$1; shift
  printf '%s\n' "$@" | awk -v b="$base" '{ e = log($1) / log(b); r = (e < 0 ? -int(-e + 0.5) : int(e + 0.5));
    if (r - e > 1e-9 || e - r > 1e-9) bad = 1; if (NR == 1 || r < lo) lo = r; if (NR == 1 || r > hi) hi = r }
    END { if (bad) exit 1; print lo, hi }'
}

# --- what our own cross-validation report says ------------------------------------
# Per feature set: rows, SVM and forest accuracy, the SVM setting chosen most often.
declare -A ours_rows ours_svm ours_forest ours_mode
if [[ -f $report ]]; then
  while IFS=$'\t' read -r set rows svm forest mode; do
    ours_rows[$set]=$rows; ours_svm[$set]=$svm; ours_forest[$set]=$forest; ours_mode[$set]=$mode
  done < <(awk '
    function flush() { if (set != "") {
        best = ""; for (k in count) if (best == "" || count[k] > count[best] || (count[k] == count[best] && k < best)) best = k
        printf "%s\t%s\t%s\t%s\t%s\n", set, rows, svm, forest, best } }
    /^## / { flush(); set = ""; rows = ""; svm = ""; forest = ""; delete count
             h = tolower($0)
             if (h ~ /^## extended/) set = "extended"; else if (h ~ /^## raw/) set = "raw"; else if (h ~ /paper/) set = "paper"
             next }
    set == "" { next }
    /cross-validation, [0-9]+ rows/ { match($0, /[0-9]+ rows/); rows = substr($0, RSTART, RLENGTH - 5) }
    /^\| SVM/ { split($0, f, "|"); svm = f[3]; gsub(/^ +| +$/, "", svm) }
    /^\| random forest/ { split($0, f, "|"); forest = f[3]; gsub(/^ +| +$/, "", forest) }
    /^\| *[0-9]+ *\| *[0-9]+ *\| *[0-9.]+ *\| *[0-9.]+ *\| *[0-9.]+ *\| *[0-9.]+%/ {
      split($0, f, "|"); k = ""; for (i = 4; i <= 6; ++i) { v = f[i]; gsub(/ /, "", v); k = k (i > 4 ? " " : "") v }
      count[k]++ }
    END { flush() }' "$report")
  ours_folds_line=$(grep -m1 '^Folds:' "$report" || true)
fi

# --- the Weka runs --------------------------------------------------------------------
declare -a job_ids=()
declare -A job_set job_classifier job_settings job_kind
run_job() {  # id java-args...
  local id=$1; shift
  local start end
  start=$(date +%s.%N)
  if ! "$java" "-Xmx$heap" -cp "$jar" "$@" >"$work/$id.out" 2>&1; then touch "$work/$id.failed"; fi
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f\n", b - a }' >"$work/$id.time"
}
queue=()
add_job() {  # id set classifier settings kind -- java-args...
  local id=$1 set=$2
  job_ids+=("$id"); job_set[$id]=$set; job_classifier[$id]=$3; job_settings[$id]=$4; job_kind[$id]=$5
  shift 6
  printf '%s\0' "$@" >"$work/$id.args"
  queue+=("$id")
}

sets=()
for set in paper extended raw; do
  if [[ -f $tables/features_$set.arff ]]; then sets+=("$set"); fi
done
[[ ${#sets[@]} -gt 0 ]] || { echo "$0: no features_{paper,extended,raw}.arff in $tables" >&2; exit 1; }

# The classifiers' input, as hair-train-style gives it to ours: lengths in H (attributes
# named *_h) as log(x + LENGTH_LOG_OFFSET), the node count as log(x + 1)
# (feature_log_offsets); LENGTH_LOG_OFFSET=0 leaves the lengths as they are, LINEAR=1
# every attribute (hair-train-style --linear-features).
length_log_offset=${LENGTH_LOG_OFFSET:-0.1}
for set in "${sets[@]}"; do
  awk -v c="$length_log_offset" -v linear="${LINEAR:-0}" '
    toupper($1) == "@ATTRIBUTE" { ++n; name = $2; gsub(/["\047]/, "", name)
      if (linear != 1 && name ~ /_h$/ && c > 0) offset[n] = c
      if (linear != 1 && name == "middle_node_count") offset[n] = 1
      print; next }
    toupper($1) == "@DATA" { data = 1; print; next }
    data && !/^[ \t]*(%|$)/ { k = split($0, v, ",")
      for (i = 1; i <= k; ++i) if (i in offset) v[i] = sprintf("%.17g", log((v[i] > 0 ? v[i] : 0) + offset[i]))
      line = v[1]; for (i = 2; i <= k; ++i) line = line "," v[i]; print line; next }
    { print }' "$tables/features_$set.arff" >"$work/features_$set.arff"
done
tables_in=$tables
tables=$work

declare -A dims rows_of
for set in "${sets[@]}"; do
  arff=$tables/features_$set.arff
  # Attributes less the class (the last one); data rows: not empty, not comments.
  dims[$set]=$(awk 'toupper($1) == "@ATTRIBUTE" { n++ } END { print n - 1 }' "$arff")
  rows_of[$set]=$(awk 'toupper($1) == "@DATA" { d = 1; next } d && !/^[ \t]*(%|$)/ { n++ } END { print n + 0 }' "$arff")
done

# The long runs first, so that JOBS runs keep busy to the end.
for set in "${sets[@]}"; do
  arff=$tables/features_$set.arff
  cv=(-t "$arff" -x 10 -s 1 -v)
  if [[ $grid_sets == *" $set "* ]]; then
    add_job "$set.grid" "$set" "SVM (PUK), nested grid" \
      "MultiScheme -X $inner_folds -S 1 over SMO -N 1 with ${#sigmas[@]} sigma x ${#omegas[@]} omega x ${#cs[@]} C" grid -- \
      weka.classifiers.meta.MultiScheme "${cv[@]}" -D -X "$inner_folds" -S 1 "${grid_options[@]}"
  fi
done
for set in "${sets[@]}"; do
  arff=$tables/features_$set.arff
  cv=(-t "$arff" -x 10 -s 1 -v)
  if [[ $gridsearch_sets == *" $set "* ]]; then
    if xr=$(exponent_range 2 "${sigmas[@]}") && yr=$(exponent_range 10 "${cs[@]}"); then
      read -r xlo xhi <<<"$xr"; read -r ylo yhi <<<"$yr"
      add_job "$set.gridsearch" "$set" "SVM (PUK), Weka GridSearch" \
        "GridSearch -E ACC, sigma 2^$xlo..2^$xhi x C 10^$ylo..10^$yhi, omega 1, SMO -N 1" gridsearch -- \
        weka.classifiers.meta.GridSearch "${cv[@]}" -E ACC -S 1 -filter weka.filters.AllFilter \
        -x-property classifier.kernel.sigma -x-min "$xlo" -x-max "$xhi" -x-step 1 -x-base 2 -x-expression 'pow(BASE,I)' \
        -y-property classifier.c -y-min "$ylo" -y-max "$yhi" -y-step 1 -y-base 10 -y-expression 'pow(BASE,I)' \
        -W "$smo" -- -N 1 -K "$puk -O 1 -S 1"
    else
      echo "$0: GridSearch skipped: SIGMAS are not powers of 2 or CS not powers of 10" >&2
    fi
  fi
done
for set in "${sets[@]}"; do
  arff=$tables/features_$set.arff
  cv=(-t "$arff" -x 10 -s 1 -v)
  d=${dims[$set]}
  add_job "$set.smo_default" "$set" "SVM (PUK), fixed" "SMO -N 1 -C 1, Puk -S 1 -O 1 (Weka's defaults)" fixed -- \
    "$smo" "${cv[@]}" -o -N 1 -C 1 -K "$puk -O 1 -S 1"
  if [[ -n ${ours_mode[$set]:-} ]]; then
    read -r s o c <<<"${ours_mode[$set]}"
    if [[ "$s $o $c" != "1 1 1" ]]; then
      add_job "$set.smo_ours" "$set" "SVM (PUK), fixed" "SMO -N 1 -C $c, Puk -S $s -O $o (our most frequent pick)" fixed -- \
        "$smo" "${cv[@]}" -o -N 1 -C "$c" -K "$puk -O $o -S $s"
    fi
  fi
  k_sqrt=$(awk -v d="$d" 'BEGIN { printf "%d\n", int(sqrt(d) + 0.5) }')
  add_job "$set.rf_default" "$set" "random forest" "RandomForest -I 100 -S 1 -K 0 (Weka's default)" forest -- \
    weka.classifiers.trees.RandomForest "${cv[@]}" -I 100 -S 1 -K 0
  add_job "$set.rf_sqrt" "$set" "random forest" "RandomForest -I 100 -S 1 -K $k_sqrt (round(sqrt(d)), ours)" forest -- \
    weka.classifiers.trees.RandomForest "${cv[@]}" -I 100 -S 1 -K "$k_sqrt"
done

load_before=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
bench_start=$(date +%s.%N)
for id in "${queue[@]}"; do
  while (($(jobs -rp | wc -l) >= max_jobs)); do wait -n || true; done
  echo "weka_oracle: $id" >&2
  mapfile -d '' -t args <"$work/$id.args"
  run_job "$id" "${args[@]}" &
done
wait
bench_end=$(date +%s.%N)
load_after=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
if [[ -n ${WEKA_LOGS:-} ]]; then mkdir -p "$WEKA_LOGS" && cp "$work"/*.out "$WEKA_LOGS"/; fi

# --- parsing Weka's output ----------------------------------------------------------------
# Correct, total and percentage of the cross-validation; the confusion matrix rows
# ("n n n n" per truth class, joined by " / "); the class names in Weka's order.
cv_summary() {  # file -> "correct<TAB>total<TAB>pct<TAB>confusion<TAB>classes"
  awk '
    /=== Stratified cross-validation ===|=== Cross-validation ===/ { cvs = 1 }
    cvs && /^Correctly Classified Instances/ { correct = $4; pct = $5 }
    cvs && /^Total Number of Instances/ { total = $5 }
    cvs && /=== Confusion Matrix ===/ { conf = ""; names = ""; inconf = 1; next }
    inconf && /\|/ { split($0, half, "|"); row = half[1]; gsub(/^ +| +$/, "", row); gsub(/ +/, " ", row)
                     conf = conf (conf == "" ? "" : " / ") row
                     n = half[2]; sub(/^ *[a-z]+ = /, "", n); gsub(/ +$/, "", n); names = names (names == "" ? "" : "/") n; next }
    inconf && /[^ ]/ && !/classified as/ { inconf = 0 }
    END { printf "%s\t%s\t%s\t%s\t%s\n", correct, total, pct, conf, names }' "$1"
}

pct_of() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.1f", 100 * a / b }'; }
# "87.9% (631 / 718)" -> 87.9
pct_value() { sed -E 's/^([0-9.]+)%.*/\1/' <<<"$1"; }

table="| features | classifier | Weka settings | accuracy (Weka) | ours | time (s) | confusion (rows: truth CLASSES) |
|---|---|---|---:|---:|---:|---|"
classes=""
notes=""
for id in "${job_ids[@]}"; do
  set=${job_set[$id]}
  file=$work/$id.out
  seconds=$(cat "$work/$id.time" 2>/dev/null || echo "?")
  settings=${job_settings[$id]}
  if [[ -f $work/$id.failed ]]; then
    table+=$'\n'"| $set (${dims[$set]}) | ${job_classifier[$id]} | $settings | failed: $(grep -m1 -iE 'exception|error' "$file" | cut -c1-80) | | $seconds | |"
    continue
  fi
  IFS=$'\t' read -r correct total _ conf names < <(cv_summary "$file")
  if [[ -n $names ]]; then classes=$names; fi
  case ${job_kind[$id]} in
    forest)
      k=$(sed -nE 's/.*considering ([0-9]+) random features.*/\1/p' "$file" | head -1)
      if [[ -n $k ]]; then settings="$settings: $k features per split"; fi
      ours=${ours_forest[$set]:-} ;;
    gridsearch)
      pick=$(sed -nE 's/^Values: ([0-9.E-]+) \(X coordinate\), ([0-9.E-]+) \(Y coordinate\).*/sigma \1, C \2/p' "$file" | head -1)
      if [[ -n $pick ]]; then settings="$settings; on all rows: $pick"; fi
      ours=${ours_svm[$set]:-} ;;
    *) ours=${ours_svm[$set]:-} ;;
  esac
  ours_cell=""
  if [[ -n $ours ]]; then
    ours_cell="$(pct_value "$ours")%"
    if [[ ${ours_rows[$set]:-} != "${rows_of[$set]}" ]]; then ours_cell+=" (${ours_rows[$set]:-?} rows)"; fi
  fi
  table+=$'\n'"| $set (${dims[$set]}) | ${job_classifier[$id]} | $settings | $(pct_of "$correct" "$total")% ($correct / $total) | $ours_cell | $seconds | $conf |"

  if [[ ${job_kind[$id]} == grid ]]; then
    # MultiScheme -D prints "Error rate: e for classifier ..." for every candidate of every
    # build: first the build on all rows, then one per outer fold, in -B order.
    picks=$(grep '^Error rate:' "$file" | awk -v g="${#grid_points[@]}" -v pts="$work/grid_points" '
      BEGIN { while ((getline l < pts) > 0) p[n++] = l }
      { i = (NR - 1) % g; b = int((NR - 1) / g); e = $3 + 0
        if (i == 0 || e < best) { best = e; arg = i }
        if (i == g - 1) { split(p[arg], v, " ")
          printf "%s|sigma %s, omega %s, C %s|%.1f%%\n", (b == 0 ? "all rows" : "fold " b - 1), v[1], v[2], v[3], 100 * (1 - best) } }')
    selected=$(sed -nE 's/^Selected scheme: [^ ]*SMO -C ([0-9.E-]+) .* -O ([0-9.E-]+) -S ([0-9.E-]+)".*/sigma \3, omega \2, C \1/p' "$file")
    notes+=$'\n\n'"Nested grid on $set: candidates chosen by MultiScheme's inner $inner_folds-fold CV (inner accuracy):"$'\n\n'
    notes+="| build | sigma, omega, C | inner accuracy |"$'\n'"|---|---|---:|"
    while IFS='|' read -r build setting acc; do
      if [[ -n $build ]]; then notes+=$'\n'"| $build | $setting | $acc |"; fi
    done <<<"$picks"
    if [[ -n $selected ]]; then notes+=$'\n\n'"MultiScheme's \"Selected scheme\" on all rows: $selected."; fi
  fi
done
table=${table/CLASSES/${classes:-in Weka\'s order}}

{
  echo "Weka $weka_version ($jar), $java_version, java -Xmx$heap; $(nproc) cores; $max_jobs Weka runs at a time."
  echo "Tables: $tables_in, lengths and node count as hair-train-style gives them to its classifiers (LENGTH_LOG_OFFSET=$length_log_offset, LINEAR=${LINEAR:-0}) ($(for s in "${sets[@]}"; do printf '%s %s rows x %s features; ' "$s" "${rows_of[$s]}" "${dims[$s]}"; done | sed 's/; $//'))."
  echo "10-fold stratified cross-validation in Weka (-x 10 -s 1); SMO with -N 1 standardises on each training set."
  gridded=$(for s in "${sets[@]}"; do if [[ $grid_sets == *" $s "* ]]; then printf ' %s' "$s"; fi; done)
  echo "Nested grid search (GRID_SETS) on:${gridded:- none}; the other feature sets have fixed SVM settings only."
  if [[ -f $report ]]; then
    echo "Ours: $report${ours_folds_line:+ ($ours_folds_line)}; ours is our accuracy on the same feature set (its row count in brackets when the report's tables differ from these)."
  else
    echo "Ours: no report at $report (REPORT=...)."
  fi
  echo "Wall time $(awk -v a="$bench_start" -v b="$bench_end" 'BEGIN { printf "%.0f", b - a }') s; load average $load_before before, $load_after after. Times are wall clock of each Weka run (JVM start and Weka's extra build on all rows included)."
  echo
  echo "$table"
  if [[ -n $notes ]]; then echo "$notes"; fi
} >"$work/result.md"
cat "$work/result.md"
if [[ -n $out ]]; then cp "$work/result.md" "$out"; fi
exit 0
