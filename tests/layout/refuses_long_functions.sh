#!/usr/bin/env bash
# The function-length check must fail on a function over the limit, naming it, and pass
# one at the limit: a free function and a member function of 121 lines, one of 120.
set -euo pipefail
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/hair/sim"

# A function of `lines` lines in all, signature to closing brace.
function_of() {
  echo "$2 {"
  for ((i = 0; i < $1 - 2; ++i)); do echo "  total += $i;"; done
  echo "}"
}
{
  echo "namespace hair {"
  echo "int total = 0;"
  function_of 120 "void at_the_limit()"
  echo "struct Loop { void step(); };"
  function_of 121 "void Loop::step()"
  function_of 121 "void too_long()"
  echo "}  // namespace hair"
} >"$work/hair/sim/long.cpp"

status=0
report=$(bash "$source_dir/scripts/check-function-length.sh" "$work/hair" 120 2>&1) || status=$?
echo "$report"
[[ $status == 1 ]] || { echo "expected exit 1, got $status"; exit 1; }
for expected in "121 lines: step" "121 lines: too_long" "2 of 3 functions"; do
  grep -qF "$expected" <<<"$report" || { echo "missing: $expected"; exit 1; }
done
if grep -qF "at_the_limit" <<<"$report"; then echo "at_the_limit was reported"; exit 1; fi
