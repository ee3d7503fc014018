#!/usr/bin/env bash
# The Slurm recipe (examples/slurm/) on a real single-node cluster: a 4-task array renders tile
# and sample-range shards (--split both) of the bundled Cornell box, one task fails once, the
# dependent merge is cancelled, the failed index is resubmitted with a new merge, and the merged
# EXR (every AOV) equals a single render bit for bit. Run by .ci/run, not by ctest. Needs root.
#
# Usage: tests/distributed/slurm_shards.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
radiant=$(realpath "${1:-build}")/radiant
work=$(mktemp -d /tmp/radiant-slurm.XXXXXX)
trap 'scripts/slurm-cluster.sh stop "$work/cluster"; rm -rf "$work"' EXIT
start=$(date +%s)
eval "$(scripts/slurm-cluster.sh start "$work/cluster")"
echo "slurm up in $(($(date +%s) - start)) s"

scene=$PWD/assets/cornell.gltf
flags=(--width 32 --height 24 --spp 8 --max-depth 3 --mode path --aov albedo,normal,depth,variance,spp)
"$radiant" render "$scene" -o "$work/single.exr" "${flags[@]}" --quiet

# radiant, failing the first run of task 2 as a node or a preempted job would.
cat >"$work/flaky-radiant" <<FLAKY
#!/bin/bash
if [[ \${SLURM_ARRAY_TASK_ID:-} == 2 && ! -e "$work/failed-once" ]]; then
  touch "$work/failed-once"
  echo "task 2: failing once on purpose" >&2
  exit 1
fi
exec "$radiant" "\$@"
FLAKY
chmod +x "$work/flaky-radiant"
export RADIANT=$work/flaky-radiant

# wait_for JOB: until the job (every task of an array) has left the queue, at most 60 s.
wait_for() {
  for ((i = 0; i < 240; i++)); do
    [[ -z $(squeue -h -j "$1" 2>/dev/null) ]] && return 0
    sleep 0.25
  done
  echo "job $1 still queued after 60 s:" >&2
  squeue >&2
  exit 1
}

submit=(sbatch --parsable --chdir="$work" --output="$work/%x-%A_%a.log")
array=$("${submit[@]}" --array=0-3 examples/slurm/render-array.sbatch "$scene" 4 "$work" "${flags[@]}" --split both)
merge=$("${submit[@]}" --dependency="afterok:$array" --kill-on-invalid-dep=yes examples/slurm/merge.sbatch "$work" "$work/merged.exr")
wait_for "$array"
wait_for "$merge"
[[ ! -e $work/merged.exr ]] || { echo "the merge ran although task 2 failed" >&2; exit 1; }
[[ -e $work/shard-0.exr && -e $work/shard-1.exr && -e $work/shard-3.exr && ! -e $work/shard-2.exr ]] ||
  { echo "expected shards 0, 1 and 3 only:" >&2; ls "$work" >&2; exit 1; }

# Resubmit the failed index only, K given explicitly, and a new merge.
array=$("${submit[@]}" --array=2 examples/slurm/render-array.sbatch "$scene" 4 "$work" "${flags[@]}" --split both)
merge=$("${submit[@]}" --dependency="afterok:$array" --kill-on-invalid-dep=yes examples/slurm/merge.sbatch "$work" "$work/merged.exr")
wait_for "$array"
wait_for "$merge"
[[ -e $work/merged.exr ]] || { echo "no merged image; logs:" >&2; tail -n 5 "$work"/*.log >&2; exit 1; }
idiff -q -fail 0 -failpercent 0 -warn 0 -warnpercent 0 "$work/single.exr" "$work/merged.exr" ||
  { echo "the merged image differs from the single render" >&2; exit 1; }
echo "slurm: merged shards equal the single render bit for bit ($(($(date +%s) - start)) s with the cluster's start)"
