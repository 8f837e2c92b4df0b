#!/usr/bin/env bash
# A stage writing into a full file system (a tmpfs of a few kilobytes) exits 1 with one
# line that says the disk is full, and leaves nothing there: extract (its output the
# largest of a sample's first stages) and typeify. Needs root to mount the tmpfs; skipped
# (exit 77) with the reason where it cannot be mounted.
#
#   tests/faults/disk_full.sh SOURCE_DIR BIN_DIR
set -euo pipefail
source_dir=$1 bin=$2
work=$(mktemp -d)
full=$work/full
mkdir -p "$full"
cleanup() {
  mountpoint -q "$full" && umount "$full"
  rm -rf "$work"
}
trap cleanup EXIT
if ! mount -t tmpfs -o size=16k tmpfs "$full" 2>"$work/mount.txt"; then
  echo "skipped: cannot mount a small tmpfs here ($(head -n 1 "$work/mount.txt"); needs root)"
  exit 77
fi
samples=$source_dir/data/samples
"$bin/extract" "$samples/hair/braid01.obj" --body "$samples/body.obj" --unit_scale 0.1 \
  -o "$work/extract.h5" --quiet

# expect_disk_full NAME COMMAND...: exit 1, one line naming the full disk, nothing left.
expect_disk_full() {
  local name=$1 status=0
  shift
  "$@" --quiet 2>"$work/$name.err" || status=$?
  echo "$name: exit $status: $(cat "$work/$name.err")"
  [[ $status == 1 ]] || { echo "$name: expected exit 1"; exit 1; }
  [[ $(wc -l <"$work/$name.err") == 1 ]] || { echo "$name: expected one line"; exit 1; }
  grep -q "no space left on device" "$work/$name.err" || { echo "$name: not said"; exit 1; }
  if [[ -n $(ls -A "$full") ]]; then echo "$name: left behind:"; ls -la "$full"; exit 1; fi
}
expect_disk_full extract "$bin/extract" "$samples/hair/braid01.obj" --body "$samples/body.obj" \
  --unit_scale 0.1 -o "$full/extract.h5"
expect_disk_full typeify "$bin/typeify" "$work/extract.h5" -o "$full/types.h5"
echo "a full disk: exit 1, one line, nothing left"
