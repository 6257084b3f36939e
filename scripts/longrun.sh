#!/usr/bin/env bash
# Long runs, on demand (not in CI): memory must stay flat as the job grows.
#   1. the lollipop's timeline over 1e3 and over 1e6 turns (1e6 rows each,
#      automatic magnus4 steps: ~1e7 and ~1e10 steps) streamed to CSV;
#      peak RSS of the long run must be within 10 % (+4 MiB) of the short one.
#   2. a 5-minute 720p30 MP4 of the lollipop (9000 frames) against a 30 s
#      one: peak RSS within 10 % (+16 MiB).
# LONGRUN_SKIP_TIMELINE=1 or LONGRUN_SKIP_VIDEO=1 runs one half.
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
check() {  # name long short slack_kib
  local limit=$(( $3 + $3 / 10 + $4 ))
  if [ "$2" -le "$limit" ]; then
    echo "longrun: $1: flat memory: ${2} KiB long vs ${3} KiB short (limit ${limit})"
  else
    echo "longrun: $1: memory grew: ${2} KiB long vs ${3} KiB short (limit ${limit})" >&2
    status=1
  fi
}
video() {
  local seconds=$1
  local t0=$SECONDS
  local rss
  rss=$(peak ./build/rollspin render scenes/lollipop.toml --quality medium --quiet \
          --set animation.duration="$seconds" -o "$out/clip-$seconds.mp4")
  echo "video=${seconds}s 1280x720@30 wall_s=$((SECONDS - t0)) peak_rss_kib=$rss" >&2
  rm -f "$out/clip-$seconds.mp4"
  echo "$rss"
}
status=0
if [ -z "${LONGRUN_SKIP_TIMELINE:-}" ]; then
  short=$(run 1000)
  long=$(run 1000000)
  check "timeline 1e6 vs 1e3 turns" "$long" "$short" 4096
fi
if [ -z "${LONGRUN_SKIP_VIDEO:-}" ]; then
  short=$(video 30)
  long=$(video 300)
  check "720p video 300 s vs 30 s" "$long" "$short" 16384
fi
exit $status
