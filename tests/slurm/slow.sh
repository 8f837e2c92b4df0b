#!/usr/bin/env bash
# Waits SECONDS, then runs the rest of its arguments: a stage made slow enough to be
# cancelled while its Slurm job runs (tests/slurm/pipeline_through_slurm.sh).
#   slow.sh SECONDS COMMAND [ARGS...]
seconds=$1
shift
sleep "$seconds"
exec "$@"
