#!/bin/sh
# Runs one stage of Makefile.pipeline holding its model's lock, so that two makes on one
# output folder never run a stage of the same model at once:
#
#   scripts/run-locked.sh TARGET [PREREQUISITE ...] -- COMMAND [ARGUMENT ...]
#
# takes an exclusive flock(1) on TARGET's folder's .lock (waiting for it), then runs
# COMMAND, unless TARGET exists and is newer than every PREREQUISITE: another run made it
# while this one waited, and it is left as it is ("<target>: made by another run").
set -eu
if [ "${HAIRSTYLE_LOCK_HELD:-}" != "$1" ]; then
  mkdir -p "$(dirname "$1")"
  HAIRSTYLE_LOCK_HELD=$1 exec flock "$(dirname "$1")/.lock" "$0" "$@"
fi
target=$1
shift
stale=no
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do
  if [ ! -e "$target" ] || [ "$1" -nt "$target" ]; then stale=yes; fi
  shift
done
[ "$#" -gt 0 ] || { echo "run-locked.sh: no '--' before the command" >&2; exit 2; }
shift
if [ "$stale" = no ] && [ -e "$target" ]; then
  echo "$target: made by another run"
  exit 0
fi
exec "$@"
