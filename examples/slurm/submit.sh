#!/bin/bash
# Submits the shards of one render as a Slurm job array and a merge job that runs when all of
# them succeeded. Prints the two job ids.
#
#   examples/slurm/submit.sh SCENE K OUTDIR IMAGE [radiant render flags...]
#   examples/slurm/submit.sh scene.gltf 16 shards image.exr --spp 1024 --split both
#
# After a failure (the merge job is then cancelled), resubmit only the failed indices, with the
# same K and flags, and a new merge:
#   array=$(sbatch --parsable --array=3,7 render-array.sbatch scene.gltf 16 shards --spp 1024 --split both)
#   sbatch --dependency=afterok:$array --kill-on-invalid-dep=yes merge.sbatch shards image.exr
set -euo pipefail
(($# >= 4)) || { echo "usage: $0 SCENE K OUTDIR IMAGE [render flags...]" >&2; exit 2; }
scene=$1 count=$2 outdir=$3 image=$4
shift 4
here=$(dirname "$(realpath "$0")")
mkdir -p "$outdir"
array=$(sbatch --parsable --array="0-$((count - 1))" "$here/render-array.sbatch" "$scene" "$count" "$outdir" "$@")
merge=$(sbatch --parsable --dependency="afterok:${array%%;*}" --kill-on-invalid-dep=yes "$here/merge.sbatch" "$outdir" "$image")
echo "array job ${array%%;*}, merge job ${merge%%;*}"
