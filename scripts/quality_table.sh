#!/usr/bin/env bash
# The antialiasing quality table ("Quality" under
# docs/speed-history.md#render-speed-bench_render-as-the-readme-had-it): for
# each scene, the mean absolute difference (0-255 levels, mean of R, G, B) of
# a 640x360 still against a 16-sample reference, the same still at 2560x1440
# with render.msaa = 1, box-filtered down (ffmpeg scale, flags=area).
# render.labels and render.trails are off in both: text and trails are not
# what the table measures.
#
#   scripts/quality_table.sh                       # the default settings
#   scripts/quality_table.sh render.msaa=1 ...     # and a candidate column
#   BASELINE=/tmp/old/rollspin scripts/quality_table.sh
#                     # first a column of another build's default stills,
#                     # against this build's references
#
# A pixel-moving change to the renderer shows its column beside the default
# one before any golden is regenerated (BASELINE: the commit before it, built
# in a worktree). Needs ./build/rollspin and ffmpeg.
set -euo pipefail
cd "$(dirname "$0")/.."
rollspin=${ROLLSPIN:-./build/rollspin}
scenes=${QUALITY_SCENES:-"lollipop sphere-inside saddle-geodesic torus cylinder-helix"}
[ -x "$rollspin" ] || { echo "quality_table.sh: $rollspin not found: build first (cmake --build build -j2)" >&2; exit 2; }
baseline=${BASELINE:-}
[ -z "$baseline" ] || [ -x "$baseline" ] || { echo "quality_table.sh: BASELINE=$baseline is not an executable" >&2; exit 2; }
command -v ffmpeg >/dev/null || { echo "quality_table.sh: needs the ffmpeg tool (scripts/install-deps.sh)" >&2; exit 2; }

candidate=()
for kv in "$@"; do
  [[ "$kv" == *=* ]] || { echo "quality_table.sh: expected key=value, got '$kv'" >&2; exit 2; }
  candidate+=(--set "$kv")
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--still --quiet --set render.labels=false --set render.trails=false)

# A render by BIN, quiet unless it fails: its stderr then, and exit 2.
renderWith() {
  local bin=$1
  shift
  "$bin" render "$@" >/dev/null 2>"$work/stderr" || { cat "$work/stderr" >&2; exit 2; }
}
render() { renderWith "$rollspin" "$@"; }

# The mean of compare's R, G and B mean deltas (compare exits 1 when the
# images differ, as they do; 2 is an error).
meanRgb() {
  local json status=0
  json=$("$rollspin" compare --json "$1" "$2") || status=$?
  [ "$status" -le 1 ] || { echo "quality_table.sh: compare failed on $1" >&2; exit 2; }
  python3 -c '
import json, sys
r = json.load(sys.stdin)["references"][0]
assert r["size_matches"], "sizes differ"
print("%.3f" % (sum(r["mean_delta"][:3]) / 3))' <<<"$json"
}

header="| scene |"
rule="| --- |"
[ -z "$baseline" ] || { header="$header baseline default |"; rule="$rule --- |"; }
header="$header default |"
rule="$rule --- |"
[ ${#candidate[@]} -eq 0 ] || { header="$header $* |"; rule="$rule --- |"; }
echo "$header"
echo "$rule"
for s in $scenes; do
  file=scenes/$s.toml
  [ -f "$file" ] || { echo "quality_table.sh: no $file" >&2; exit 2; }
  render "$file" "${common[@]}" --width 2560 --height 1440 --set render.msaa=1 -o "$work/$s-big.png"
  ffmpeg -v error -y -i "$work/$s-big.png" -vf scale=640:360:flags=area "$work/$s-ref.png"
  row="| $s |"
  if [ -n "$baseline" ]; then
    renderWith "$baseline" "$file" "${common[@]}" --width 640 --height 360 -o "$work/$s-baseline.png"
    row="$row $(meanRgb "$work/$s-baseline.png" "$work/$s-ref.png") |"
  fi
  render "$file" "${common[@]}" --width 640 --height 360 -o "$work/$s-default.png"
  row="$row $(meanRgb "$work/$s-default.png" "$work/$s-ref.png") |"
  if [ ${#candidate[@]} -gt 0 ]; then
    render "$file" "${common[@]}" --width 640 --height 360 "${candidate[@]}" -o "$work/$s-candidate.png"
    row="$row $(meanRgb "$work/$s-candidate.png" "$work/$s-ref.png") |"
  fi
  echo "$row"
done
