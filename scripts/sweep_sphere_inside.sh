#!/usr/bin/env bash
# A parameter sweep with GNU parallel (README, "A parameter sweep"):
# `solve --json` for a ball of radius R rolling once round a parallel at
# colatitude θ inside a sphere of radius r = 3, over a grid of R and θ,
# collected into one CSV beside the closed form (docs/solver.md#notes-on-the-paper)
#   δ = 2π √(ρ²/R² + cos²θ),  ρ = r sin θ,
# folded like the solver's net angle into [0, π].
#
#   bash scripts/sweep_sphere_inside.sh [OUT.csv]     (default output/sweep-sphere-inside.csv)
#
# RADII and COLATITUDES (space-separated, degrees) replace the grid;
# PARALLEL_OPTS adds GNU parallel options (e.g. "-j 8"). rollspin: $ROLLSPIN,
# else this clone's build/rollspin, else `rollspin` in PATH. Needs jq.
set -euo pipefail

out=${1:-output/sweep-sphere-inside.csv}
here=$(cd "$(dirname "$0")/.." && pwd)
rollspin=${ROLLSPIN:-}
if [ -z "$rollspin" ]; then
  if [ -x "$here/build/rollspin" ]; then rollspin=$here/build/rollspin; else rollspin=rollspin; fi
fi
for tool in parallel jq; do
  command -v "$tool" >/dev/null || { echo "sweep_sphere_inside.sh: needs $tool (Debian: apt-get install $tool)" >&2; exit 1; }
done
read -r -a radii <<< "${RADII:-0.1 0.25 0.5 0.75 1 1.25 1.5 1.75 2 2.25 2.5 2.75}"
read -r -a colatitudes <<< "${COLATITUDES:-30 45 60 75 90}"
sphere=3

# One grid point → one CSV row. The solver's JSON keys are listed in
# docs/getting-started.md#commands; jq adds the closed form.
solve_one() {
  local R=$1 theta=$2
  "$ROLLSPIN_SWEEP" solve "$SCENE_SWEEP" --json --set "ball.radius=$R" --set "path.colatitude_deg=$theta" \
    --set "surface.radius=$SPHERE_SWEEP" |
    jq -r --argjson R "$R" --argjson deg "$theta" --argjson r "$SPHERE_SWEEP" '
      ($deg * (1 | atan) / 45) as $t | (2 * (1 | atan) * 4) as $twoPi |
      ($twoPi * (((($r * ($t | sin)) / $R) | . * .) + (($t | cos) | . * .) | sqrt)) as $delta |
      ($delta | fmod(.; $twoPi)) as $a | (if $a > $twoPi / 2 then $twoPi - $a else $a end) as $closed |
      [$R, $deg, .angle, $closed, (.angle - $closed), .spinor_angle, .steps, .unitarity_error] | @csv'
}
export -f solve_one
export ROLLSPIN_SWEEP=$rollspin SCENE_SWEEP=$here/scenes/sphere-inside.toml SPHERE_SWEEP=$sphere

mkdir -p "$(dirname "$out")"
tmp=$(mktemp "$out.XXXXXX.tmp")  # renamed when complete: no half-written CSV
trap 'rm -f "$tmp"' EXIT
echo "ball_radius,colatitude_deg,angle,closed_form_angle,difference,spinor_angle,steps,unitarity_error" > "$tmp"
# -k: rows in grid order whatever finishes first; a failed solve stops the sweep.
# shellcheck disable=SC2086
parallel --will-cite -k --halt now,fail=1 ${PARALLEL_OPTS:-} solve_one ::: "${radii[@]}" ::: "${colatitudes[@]}" >> "$tmp"
mv "$tmp" "$out"
trap - EXIT
echo "sweep_sphere_inside.sh: wrote $out ($(( $(wc -l < "$out") - 1 )) rows)" >&2
