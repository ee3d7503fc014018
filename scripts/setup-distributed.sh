#!/usr/bin/env bash
# Installs what the distributed tests (tests/distributed/) need and the plain suite does not:
# Slurm with munge (a real single-node cluster) and GNU parallel. Needs root.
set -euo pipefail
missing=()
command -v slurmctld >/dev/null || missing+=(slurm-wlm)
command -v munged >/dev/null || missing+=(munge)
command -v parallel >/dev/null || missing+=(parallel)
command -v idiff >/dev/null || missing+=(openimageio-tools)
if ((${#missing[@]})); then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi
