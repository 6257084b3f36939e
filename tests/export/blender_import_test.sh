#!/usr/bin/env bash
# Blender (Debian's, headless) imports `rollspin export` and its ball turns
# as the solver says (tests/export/blender_check.py). Exit 77 (ctest skips)
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
status=0
blender -b --factory-startup --python-exit-code 1 --python "$here/blender_check.py" -- \
  "$work/lollipop.glb" "$work/lollipop.csv" 30 0 37 150 223 299 >"$work/blender.log" 2>&1 || status=$?
# Blender's banner and the importer's progress left out.
grep -E "blender_check|Error|rror:" "$work/blender.log" || cat "$work/blender.log"
exit "$status"
