#!/usr/bin/env bash
# Blender (Debian's, headless) imports `rollspin export` and its ball turns
# as the solver says (tests/export/blender_check.py): a lollipop at five of
# the clip's frames, and torus-to-floor (two surfaces, holds, a fade) at
# keys either side of the change of surface, where only the surface the
# ball is on may be shown. Exit 77 (ctest skips)
# where Blender is not installed: scripts/install-deps.sh --with-blender.
#   blender_import_test.sh ROLLSPIN WORKDIR
set -euo pipefail
rollspin=$1 work=$2
if ! command -v blender >/dev/null; then
  echo "blender_import_test: skipped: Blender is not installed (scripts/install-deps.sh --with-blender)"
  exit 77
fi
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
# Linear easing and no holds: the timeline's 300 samples are then the
# clip's 300 frames (s_k = L k / 299), and Blender's frame k at 30 fps is
# the clip's frame k.
set_args=(--set animation.easing=linear --set animation.hold=0 --set animation.duration=10 --set animation.fps=30)
"$rollspin" export lollipop "${set_args[@]}" -o "$work/lollipop.glb"
"$rollspin" timeline lollipop "${set_args[@]}" --set timeline.samples=300 -o "$work/lollipop.csv"
lollipop_picks=()
for frame in 0 37 150 223 299; do lollipop_picks+=("$(awk -v f="$frame" 'BEGIN { printf "%.17g:%d", f / 30, f }')"); done

# Several surfaces: the picks are keys of the export itself (gltf_keys.py),
# and the solver's rows are taken at their arc lengths.
"$rollspin" export torus-to-floor -o "$work/torus-to-floor.glb"
python3 "$here/gltf_keys.py" "$work/torus-to-floor.glb" 7 "$work/torus-to-floor-s.txt" >"$work/torus-to-floor-keys.txt"
"$rollspin" timeline torus-to-floor --at-s "$work/torus-to-floor-s.txt" -o "$work/torus-to-floor.csv"
surface_picks=()
row=0
while read -r seconds surface; do surface_picks+=("$seconds:$row:$surface"); row=$((row + 1)); done <"$work/torus-to-floor-keys.txt"

status=0
check() {
  local name=$1; shift
  echo "blender_import_test: $name"
  blender -b --factory-startup --python-exit-code 1 --python "$here/blender_check.py" -- \
    "$work/$name.glb" "$work/$name.csv" 30 "$@" >"$work/$name-blender.log" 2>&1 || status=1
  # Blender's banner and the importer's progress left out.
  grep -E "blender_check|Error|rror:" "$work/$name-blender.log" || cat "$work/$name-blender.log"
}
check lollipop "${lollipop_picks[@]}"
check torus-to-floor "${surface_picks[@]}"
exit "$status"
