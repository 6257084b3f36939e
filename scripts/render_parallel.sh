#!/usr/bin/env bash
# One clip rendered in N shards by GNU parallel, on this machine or over SSH,
# then joined (README, "A render across machines"; docs/cluster.md).
#
#   bash scripts/render_parallel.sh SCENE OUT.mp4 [options] [-- render options]
#
#   -n N           shards (default: this machine's cores; with --hosts, 2 per host line)
#   -j J           shards at once on each machine (default 50%: one per two cores, as one
#                  render already keeps two busy: the renderer and the encoder)
#   --hosts FILE   GNU parallel's --sshloginfile (one [user@]host per line, ":" = here):
#                  the scene goes to each host resolved (`rollspin scene --print`, so
#                  `extends` needs no other file) with --transferfile, each part comes
#                  back with --return and is removed there (--cleanup). Every host needs
#                  rsync and rollspin (ROLLSPIN_REMOTE, default: `rollspin` in its PATH).
#   --keep-parts   keep OUT's parts (NAME.part-K-of-N.mp4) after the join
#
# Render options (--quality high, --set key=value, ...) go to every shard.
# rollspin here: $ROLLSPIN, else this clone's build/rollspin, else `rollspin` in PATH.
set -euo pipefail

usage() { sed -n '2,18p' "$0"; }
[ $# -ge 2 ] || { usage >&2; exit 2; }
scene=$1 out=$2
shift 2
shards="" jobs="" hosts="" keep=0 render_opts=()
while [ $# -gt 0 ]; do
  case "$1" in
    -n) shards=$2; shift 2 ;;
    -j) jobs=$2; shift 2 ;;
    --hosts) hosts=$2; shift 2 ;;
    --keep-parts) keep=1; shift ;;
    --) shift; render_opts=("$@"); break ;;
    -h|--help) usage; exit 0 ;;
    *) echo "render_parallel.sh: unknown option $1" >&2; exit 2 ;;
  esac
done

here=$(cd "$(dirname "$0")/.." && pwd)
rollspin=${ROLLSPIN:-}
if [ -z "$rollspin" ]; then
  if [ -x "$here/build/rollspin" ]; then rollspin=$here/build/rollspin; else rollspin=rollspin; fi
fi
command -v parallel >/dev/null || { echo "render_parallel.sh: needs GNU parallel (Debian: apt-get install parallel)" >&2; exit 1; }
[ -f "$scene" ] || { echo "render_parallel.sh: no scene file $scene" >&2; exit 2; }
case "$out" in *.mp4|*.mov|*.webm) ;; *) echo "render_parallel.sh: OUT must be a video file (.mp4), got $out" >&2; exit 2 ;; esac
if [ -z "$shards" ]; then
  if [ -n "$hosts" ]; then shards=$((2 * $(grep -cv '^[[:space:]]*\(#\|$\)' "$hosts"))); else shards=$(nproc); fi
fi
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "render_parallel.sh: -n expects a positive count, got $shards" >&2; exit 2; }
jobs_opt=(-j "${jobs:-50%}")

out_dir=$(dirname "$out")
file=$(basename "$out")
stem=${file%.*} ext=${file##*.}
mkdir -p "$out_dir"
# Zero-padded shard numbers (seq -w) are exactly the K in the part names.
mapfile -t ks < <(seq -w 1 "$shards")

if [ -z "$hosts" ]; then
  # One machine: the shards write their parts beside OUT.
  parallel --will-cite -q --halt now,fail=1 "${jobs_opt[@]}" \
    "$rollspin" render "$scene" --shard "{}/$shards" -o "$out" --quiet "${render_opts[@]}" ::: "${ks[@]}"
  parts=("$out_dir/$stem".part-*-of-"$shards.$ext")
else
  # Over SSH: a staging folder here, at a relative path so that it lands in
  # each host's login folder; the parts come back into it.
  stage=$(mktemp -d ".rollspin-shards-$stem.XXXXXX")
  trap 'rm -rf "$stage"' EXIT
  "$rollspin" scene "$scene" --print > "$stage/scene.toml"
  remote=${ROLLSPIN_REMOTE:-rollspin}
  parallel --will-cite -q --halt now,fail=1 "${jobs_opt[@]}" --sshloginfile "$hosts" \
    --transferfile "$stage/scene.toml" --return "$stage/$stem.part-{}-of-$shards.$ext" --cleanup \
    "$remote" render "$stage/scene.toml" --shard "{}/$shards" -o "$stage/$stem.$ext" --quiet "${render_opts[@]}" \
    ::: "${ks[@]}"
  parts=("$stage/$stem".part-*-of-"$shards.$ext")
fi

# A shard whose job ended without its part (a remote host whose rollspin or
# shell is missing can end a job with status 0) is named, not left for the
# join to report as missing frames.
missing=()
for k in "${ks[@]}"; do
  [ -f "${stage:-$out_dir}/$stem.part-$k-of-$shards.$ext" ] || missing+=("$k")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "render_parallel.sh: shard(s) ${missing[*]} of $shards wrote no part; see the messages above" >&2
  exit 1
fi
"$rollspin" join "${parts[@]}" -o "$out"
if [ "$keep" = 1 ]; then
  [ -z "$hosts" ] || mv "${parts[@]}" "$out_dir/"
else
  [ -n "$hosts" ] || rm -f "${parts[@]}"  # the staging folder goes at exit
fi
