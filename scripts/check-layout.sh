#!/usr/bin/env bash
# Checks libhair's layout: every file lies in a folder of common/hair/README.md, and
# every `#include "hair/..."` in a folder names its own folder or an entry that the
# README's `layers` block allows that folder (a folder, a header, or a pattern such as
# extract/*_io.h).
#
#   scripts/check-layout.sh [LIBHAIR_DIR]     # default: common/hair beside this script
#
# Prints one line per violation (file:line, the include, what the folder may include)
# and exits 1 if there is one; exits 2 if the README's block cannot be read.
set -euo pipefail
set -f  # the entries are patterns to match, not files to expand

root=${1:-"$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/common/hair"}
readme="$root/README.md"
[[ -f "$readme" ]] || { echo "check-layout: no $readme" >&2; exit 2; }

# The block between "```layers" and the next "```": a folder, then what it may include.
declare -A allowed=()
in_block=0
while IFS= read -r line; do
  if [[ "$line" == '```layers'* ]]; then in_block=1; continue; fi
  if ((in_block)) && [[ "$line" == '```'* ]]; then in_block=2; break; fi
  ((in_block)) || continue
  read -r -a words <<<"$line"
  ((${#words[@]})) || continue
  allowed[${words[0]}]="${words[*]:1}"
done <"$readme"
if ((in_block != 2 || ${#allowed[@]} == 0)); then
  echo "check-layout: $readme has no closed \`\`\`layers block" >&2
  exit 2
fi

violations=0
report() { echo "$1"; violations=$((violations + 1)); }

# A file outside the folders, or in a folder the block does not name.
while IFS= read -r -d '' file; do
  relative=${file#"$root"/}
  folder=${relative%%/*}
  if [[ "$relative" != */* ]]; then
    report "$relative: lies outside the folders (common/hair/README.md lists them)"
  elif [[ -z "${allowed[$folder]+set}" ]]; then
    report "$relative: folder $folder/ is not in the layers block of common/hair/README.md"
  fi
done < <(find "$root" -type f \( -name '*.h' -o -name '*.cpp' \) -print0 | sort -z)

# Every include of ours.
while IFS= read -r match; do
  file=${match%%:*}
  rest=${match#*:}
  line_number=${rest%%:*}
  target=${rest#*:}
  target=${target#*\"hair/}
  target=${target%%\"*}
  relative=${file#"$root"/}
  folder=${relative%%/*}
  [[ -n "${allowed[$folder]+set}" ]] || continue  # reported above
  target_folder=${target%%/*}
  if [[ "$target" != */* ]]; then
    report "$relative:$line_number: includes hair/$target, which is in no folder"
    continue
  fi
  [[ "$target_folder" == "$folder" ]] && continue
  ok=0
  for entry in ${allowed[$folder]}; do
    # shellcheck disable=SC2053  # the entry is a glob pattern on purpose
    if [[ "$target_folder" == "$entry" || "$target" == $entry ]]; then ok=1; break; fi
  done
  ((ok)) || report "$relative:$line_number: includes hair/$target; $folder/ may include \
${allowed[$folder]:-nothing of ours} (common/hair/README.md)"
done < <(grep -rnoE '#include "hair/[^"]+"' --include='*.h' --include='*.cpp' "$root" | sort)

if ((violations)); then
  echo "check-layout: $violations violation(s) of the layout in $root" >&2
  exit 1
fi
echo "check-layout: ${#allowed[@]} folders, every include allowed"
