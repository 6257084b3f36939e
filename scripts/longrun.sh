#!/usr/bin/env bash
# Long runs, on demand (not in CI): memory must stay flat as the job grows.
#   1. the lollipop's timeline over 1e3 and over 1e6 turns (1e6 rows each,
#      automatic magnus4 steps: ~1e7 and ~1e10 steps) streamed to CSV;
#      peak RSS of the long run must be within 10 % (+4 MiB) of the short one.
# Prints one line per run: turns, steps, wall seconds, peak RSS.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/rollspin ] || bash scripts/build.sh >/dev/null
out=output/longrun
mkdir -p "$out"
peak() {  # peak RSS in KiB of the command, its stderr to $out/log
  /usr/bin/time -f "%M" -o "$out/rss" "$@" 2>"$out/log" >/dev/null
  cat "$out/rss"
}
run() {
  local turns=$1
  local t0=$SECONDS
  local rss
  rss=$(peak ./build/rollspin timeline scenes/lollipop.toml --set path.turns="$turns" \
          --set timeline.samples=1000000 -o "$out/turns-$turns.csv")
  echo "turns=$turns rows=1000000 wall_s=$((SECONDS - t0)) peak_rss_kib=$rss $(grep -o '[0-9]* steps' "$out/log")" >&2
  rm -f "$out/turns-$turns.csv"
  echo "$rss"
}
short=$(run 1000)
long=$(run 1000000)
limit=$(( short + short / 10 + 4096 ))
if [ "$long" -le "$limit" ]; then
  echo "longrun: flat memory: ${long} KiB for 1e6 turns vs ${short} KiB for 1e3 turns (limit ${limit})"
else
  echo "longrun: memory grew: ${long} KiB for 1e6 turns vs ${short} KiB for 1e3 turns (limit ${limit})" >&2
  exit 1
fi
