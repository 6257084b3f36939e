#!/usr/bin/env bash
# Submits a clip to Slurm as an array of N shards and a join that waits for
# all of them (README, "Rendering on many machines"):
#
#   bash scripts/slurm/submit.sh SCENE OUT.mp4 N [render options]
#
# Run it from a folder every node sees (paths are relative to it). Prints the
# two job ids. SBATCH_* variables and #SBATCH lines in the two job scripts set
# the partition, time and account.
set -euo pipefail

[ $# -ge 3 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
scene=$1 out=$2 shards=$3
shift 3
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "submit.sh: N must be a positive count, got $shards" >&2; exit 2; }
jobs=$(dirname "$0")
array=$(sbatch --parsable --array="1-$shards" "$jobs/render_shard.sbatch" "$scene" "$out" "$@")
array=${array%%;*}  # "jobid;cluster" on federated clusters
join=$(sbatch --parsable --dependency="afterok:$array" "$jobs/join.sbatch" "$out" "$shards")
echo "shards: job $array (array 1-$shards); join: job ${join%%;*} (after all shards succeed)"
