#!/bin/bash
# Renders the shards of one image with GNU parallel, on this machine or over ssh, and merges them
# (docs/distributed.md).
#
#   examples/parallel/render.sh SCENE K OUTDIR IMAGE [radiant render flags...]
#
# Environment:
#   SSHLOGINFILE  hosts for parallel's --sshloginfile (each needs radiant and the scene at the same
#                 path, e.g. on a shared file system); unset: local jobs only
#   JOBS          jobs at once per host (default: 1, each shard using every core)
#   RETRIES       attempts per shard (default 3): a shard that fails is run again
#   RESUME=1      after an interrupted run: --resume-failed reruns only shards the job log
#                 ($OUTDIR/joblog) records as failed or not run
#   RADIANT       the radiant executable (default: radiant)
set -euo pipefail
(($# >= 4)) || { echo "usage: $0 SCENE K OUTDIR IMAGE [render flags...]" >&2; exit 2; }
command -v parallel >/dev/null || { echo "$0: GNU parallel is not installed (apt-get install parallel)" >&2; exit 2; }
scene=$1 count=$2 outdir=$3 image=$4
shift 4
radiant=${RADIANT:-radiant}
mkdir -p "$outdir"
options=(--will-cite --retries "${RETRIES:-3}" --joblog "$outdir/joblog" --jobs "${JOBS:-1}" --halt never)
[[ ${RESUME:-0} == 1 ]] && options+=(--resume-failed)
[[ -n ${SSHLOGINFILE:-} ]] && options+=(--sshloginfile "$SSHLOGINFILE" --workdir "$PWD")
# -q quotes the command, so flags with spaces or shell characters reach radiant as given.
status=0
seq 0 $((count - 1)) | parallel -q "${options[@]}" \
  "$radiant" render "$scene" -o "$outdir/shard-{}.exr" --shard "{}/$count" --skip-existing --quiet "$@" || status=$?
if ((status != 0)); then
  echo "$status shard(s) failed after ${RETRIES:-3} attempts; see $outdir/joblog, then rerun with RESUME=1" >&2
  exit 1
fi
exec "$radiant" merge "$outdir"/shard-*.exr -o "$image" --quiet
