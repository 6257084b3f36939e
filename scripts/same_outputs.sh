#!/usr/bin/env bash
# Refactoring check (issue 51: "byte-identical before and after"): every
# bundled scene through two rollspin binaries, and every output compared
# byte for byte: `scene --print`, `solve --json`, the timeline (CSV and its
# sidecar, JSON), a still (PNG), a figure (SVG), three clip frames (PNG),
# the glTF export, and `keys` (the reference) once.
#   bash scripts/same_outputs.sh BEFORE_BINARY [AFTER_BINARY]   # after: build/rollspin
# Stills, frames and glb are written without metadata (--no-metadata): the
# metadata carries `git describe`, which differs between two commits by
# design; the scene text it would carry is `scene --print`, compared here.
# Exit 0 when everything is identical; lists what differs.
set -euo pipefail
cd "$(dirname "$0")/.."
before=$(realpath "${1:?usage: same_outputs.sh BEFORE_BINARY [AFTER_BINARY]}")
after=$(realpath "${2:-build/rollspin}")
size=${SAME_OUTPUTS_SIZE:-320x180}
work=$(mktemp -d)
[ -n "${SAME_OUTPUTS_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
outputs() {  # BINARY DIR SCENE
  local bin=$1 dir=$2 scene=$3 name
  name=$(basename "$scene" .toml)
  mkdir -p "$dir/$name"
  local w=${size%x*} h=${size#*x}
  {
    "$bin" scene "$scene" --print >"$dir/$name/print.toml"
    "$bin" solve "$scene" --json >"$dir/$name/solve.json"
    "$bin" timeline "$scene" -o "$dir/$name/timeline.csv"
    "$bin" timeline "$scene" -o "$dir/$name/timeline.json"
    "$bin" render "$scene" --still --no-metadata --quiet -o "$dir/$name/still.png" --width "$w" --height "$h"
    "$bin" render "$scene" --still --no-metadata --quiet -o "$dir/$name/figure.svg"
    "$bin" render "$scene" --no-metadata --quiet --frames 0:2 -o "$dir/$name/frames" --width "$w" --height "$h"
    "$bin" export "$scene" --no-metadata -o "$dir/$name/model.glb"
  } >"$dir/$name/stdout.txt" 2>"$dir/$name/stderr.txt" || echo "exit $?" >>"$dir/$name/stderr.txt"
  # Messages name the output files (the work folder differs between the
  # two); run times differ from run to run: both are masked.
  sed -i -E "s|$dir|DIR|g; s/, [0-9.e-]+ s\)/, T s)/" "$dir/$name/stdout.txt" "$dir/$name/stderr.txt"
  sed -i -E 's/"(solve|error_estimate)_seconds": [0-9.e+-]+/"\1_seconds": T/' "$dir/$name"/*.json
}
export -f outputs
export size
for side in before after; do
  bin=${!side}
  mkdir -p "$work/$side"
  "$bin" keys >"$work/$side/keys.txt"
  printf '%s\n' scenes/*.toml | xargs -P "$(nproc)" -I{} bash -c 'outputs "$@"' _ "$bin" "$work/$side" {}
done
if diff -rq "$work/before" "$work/after"; then
  echo "same: $(find "$work/before" -type f | wc -l) files for $(ls scenes/*.toml | wc -l) scenes"
else
  echo "DIFFERS (above; SAME_OUTPUTS_KEEP=1 keeps $work)"
  exit 1
fi
