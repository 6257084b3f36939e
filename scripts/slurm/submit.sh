#!/usr/bin/env bash
# Submits a clip to Slurm as an array of N shards and a join that waits for
# all of them (docs/cluster.md, "Render across machines"):
#
#   bash scripts/slurm/submit.sh SCENE OUT.mp4 N [render options]
#
# Run it from a folder every node sees (paths are relative to it). Prints the
# two job ids. SBATCH_* variables and #SBATCH lines in the two job scripts set
# the partition, time and account. Run again after a shard failed: parts
# already rendered are kept, and only the missing shards are submitted.
set -euo pipefail

[ $# -ge 3 ] || { sed -n '2,11p' "$0" >&2; exit 2; }
scene=$1 out=$2 shards=$3
shift 3
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "submit.sh: N must be a positive count, got $shards" >&2; exit 2; }
jobs=$(dirname "$0")

# Which parts are missing: rollspin writes a part under a temporary name and
# renames it when complete, so a part that is there is whole. Its name pads
# K to N's width (OUT.part-K-of-N.EXT).
dir=$(dirname "$out") file=$(basename "$out")
stem=${file%.*} ext=${file##*.}
missing=()
for ((k = 1; k <= shards; k++)); do
  printf -v part '%s/%s.part-%0*d-of-%s.%s' "$dir" "$stem" "${#shards}" "$k" "$shards" "$ext"
  [ -e "$part" ] || missing+=("$k")
done

# The join runs only once every shard succeeded (afterok); if one fails, the
# join is cancelled rather than left pending (--kill-on-invalid-dep), and
# that shard's log names it.
if [ ${#missing[@]} -eq 0 ]; then
  echo "submit.sh: all $shards parts of $out are there: submitting the join only"
  join=$(sbatch --parsable "$jobs/join.sbatch" "$out" "$shards")
  echo "join: job ${join%%;*}"
  exit 0
fi
if [ ${#missing[@]} -eq "$shards" ]; then
  array="1-$shards"
else
  array=$(IFS=,; echo "${missing[*]}")
  echo "submit.sh: $((shards - ${#missing[@]})) of $shards parts are there; rendering shards $array only"
fi
# ROLLSPIN_SHARDS tells each task N: a resubmitted array holds only some of 1-N.
shard_job=$(sbatch --parsable --array="$array" --export="ALL,ROLLSPIN_SHARDS=$shards" \
  "$jobs/render_shard.sbatch" "$scene" "$out" "$@")
shard_job=${shard_job%%;*}  # "jobid;cluster" on federated clusters
join=$(sbatch --parsable --dependency="afterok:$shard_job" --kill-on-invalid-dep=yes "$jobs/join.sbatch" "$out" "$shards")
echo "shards: job $shard_job (array $array); join: job ${join%%;*} (after all shards succeed)"
