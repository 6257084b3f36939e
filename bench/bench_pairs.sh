#!/usr/bin/env bash
# Paired before/after timing of two Google Benchmark binaries: runs them in
# turn, PAIRS times (old, new, old, new, …), so that a change of load hits
# both alike, and prints each benchmark's median CPU time over the runs.
#   bench/bench_pairs.sh OLD_BINARY NEW_BINARY FILTER [PAIRS=5] [MIN_TIME=0.5]
# e.g. (docs/speed-history.md, 2026-11-27, issue 43):
#   bench/bench_pairs.sh old/build/bench/bench_solver build/bench/bench_solver 'Scene_Solve' 5
set -euo pipefail
old=$1 new=$2 filter=$3 pairs=${4:-5} minTime=${5:-0.5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((i = 0; i < pairs; ++i)); do
  for side in old new; do
    binary=${!side}
    "$binary" --benchmark_filter="$filter" --benchmark_min_time="$minTime" --benchmark_format=json \
      > "$work/$side-$i.json" 2> /dev/null
  done
done
python3 - "$work" "$pairs" <<'PY'
import json, statistics, sys, glob, os
work, pairs = sys.argv[1], int(sys.argv[2])
times = {}
for side in ("old", "new"):
    for i in range(pairs):
        for b in json.load(open(os.path.join(work, f"{side}-{i}.json")))["benchmarks"]:
            times.setdefault((b["name"], side), []).append((b["cpu_time"], b["time_unit"], b.get("steps")))
names = sorted({n for n, _ in times})
print(f"{'benchmark':45} {'old (median CPU)':>18} {'new (median CPU)':>18} {'new/old':>8}")
for n in names:
    cell = {}
    for side in ("old", "new"):
        if (n, side) in times:
            t = times[(n, side)]
            cell[side] = (statistics.median(x[0] for x in t), t[0][1], t[0][2])
    fmt = lambda c: f"{c[0]:10.1f} {c[1]}" + (f" ({int(c[2])})" if c[2] else "") if c else "-"
    ratio = f"{cell['new'][0] / cell['old'][0]:.2f}" if len(cell) == 2 else "-"
    print(f"{n:45} {fmt(cell.get('old')):>18} {fmt(cell.get('new')):>18} {ratio:>8}")
PY
