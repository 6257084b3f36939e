#!/usr/bin/env python3
"""Paired before/after CPU time of whole rollspin processes: for each case,
runs the old and the new binary in turn RUNS times (old, new, old, new, ...),
so that a change of load hits both alike, and prints the mean and median
user+sys CPU seconds per process (from wait4's rusage) and the saving.

  bench/process_pairs.py OLD_BINARY NEW_BINARY [--runs 20] [--scenes a,b] [--sizes 160x90,640x360] [--clip SECONDS]

(docs/speed-history.md, 2026-11-28: per-process cost of small stills.)"""
import argparse, os, statistics, subprocess, tempfile

def cpu_seconds(argv):
    pid = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).pid
    _, status, usage = os.wait4(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"failed ({os.waitstatus_to_exitcode(status)}): {' '.join(argv)}")
    return usage.ru_utime + usage.ru_stime

def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old"); ap.add_argument("new")
    ap.add_argument("--runs", type=int, default=20)
    ap.add_argument("--scenes", default="lollipop,storyboard,sphere-story,tennis-ball")
    ap.add_argument("--sizes", default="160x90,640x360")
    ap.add_argument("--clip", type=float, default=0.0, help="also a clip of this many seconds at the first size")
    ap.add_argument("--clip-scenes", default="lollipop", help="the scenes that get a clip (no storyboards)")
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    work = tempfile.mkdtemp()
    cases = []
    for scene in args.scenes.split(","):
        for size in args.sizes.split(","):
            w, h = size.split("x")
            cases.append((f"{scene} {size} still", ["render", f"{root}/scenes/{scene}.toml", "--still", "--width", w,
                                                    "--height", h, "--quiet"], "png"))
        if args.clip > 0 and scene in args.clip_scenes.split(","):
            w, h = args.sizes.split(",")[0].split("x")
            cases.append((f"{scene} {w}x{h} clip {args.clip:g} s",
                          ["render", f"{root}/scenes/{scene}.toml", "--width", w, "--height", h, "--quiet",
                           "--set", f"animation.duration={args.clip:g}"], "mp4"))
    print(f"{'case':36} {'old mean':>9} {'new mean':>9} {'old med':>8} {'new med':>8} {'saved':>7}")
    total = {"old": 0.0, "new": 0.0}
    for name, argv, ext in cases:
        times = {"old": [], "new": []}
        for _ in range(args.runs):
            for side in ("old", "new"):
                binary = getattr(args, side)
                times[side].append(cpu_seconds([binary] + argv + ["-o", f"{work}/{side}.{ext}"]))
        old, new = statistics.mean(times["old"]), statistics.mean(times["new"])
        total["old"] += old
        total["new"] += new
        print(f"{name:36} {old:9.3f} {new:9.3f} {statistics.median(times['old']):8.3f} "
              f"{statistics.median(times['new']):8.3f} {100 * (old - new) / old:6.1f}%")
    print(f"{'all cases (sum of means)':36} {total['old']:9.3f} {total['new']:9.3f} {'':8} {'':8} "
          f"{100 * (total['old'] - total['new']) / total['old']:6.1f}%")

if __name__ == "__main__":
    main()
