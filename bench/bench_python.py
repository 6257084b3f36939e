#!/usr/bin/env python3
"""bench_python — issue 44's speed figures for the Python package, each timed
against its C++/CLI baseline in the same run (not a test; run on demand):

  1. Scene.solve() on the lollipop vs the same solve from C++
     (bench_solver's BM_LollipopScene_Solve): target ≤ 1.5× + 20 µs.
  2. A 10^6-row timeline reaching numpy: target < 1 s.
  3. A still through Python (a fresh interpreter: import, load, still, save
     PNG) vs `rollspin render --still` (a fresh process): target within 10 %.
  4. A second 960×540 still on a Scene (the kept GL context, model, layout):
     CPU time (all threads) target ≤ 80 ms.

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [--build build]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[1]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=str(SOURCE / "build"), help="the CMake build folder")
    parser.add_argument("--runs", type=int, default=5, help="fresh-process runs for the still comparison")
    args = parser.parse_args()
    build = Path(args.build)
    sys.path.insert(0, str(build / "python"))
    import rollspin

    lollipop_file = SOURCE / "scenes" / "lollipop.toml"
    ok = True

    # 1. solve
    scene = rollspin.load(lollipop_file)
    for _ in range(200):
        scene.solve()
    samples = []
    for _ in range(7):
        n = 2000
        start = time.perf_counter()
        for _ in range(n):
            scene.solve()
        samples.append((time.perf_counter() - start) / n * 1e6)
    python_us = statistics.median(samples)
    bench = subprocess.run([str(build / "bench" / "bench_solver"), "--benchmark_filter=BM_LollipopScene_Solve",
                            "--benchmark_format=json", "--benchmark_repetitions=5",
                            "--benchmark_report_aggregates_only=true"],
                           capture_output=True, text=True, check=True)
    rows = json.loads(bench.stdout)["benchmarks"]
    cpp_us = next(r["real_time"] for r in rows if r.get("aggregate_name") == "median")
    limit = 1.5 * cpp_us + 20.0
    print(f"solve (lollipop)      Python {python_us:8.2f} µs   C++ {cpp_us:8.2f} µs   "
          f"limit 1.5×C++ + 20 µs = {limit:.2f} µs   {'ok' if python_us <= limit else 'OVER'}")
    ok &= python_us <= limit

    # 2. 10^6-row timeline
    times = []
    for _ in range(3):
        start = time.perf_counter()
        t = scene.timeline(samples=1_000_000)
        qw = t["qw"]
        times.append(time.perf_counter() - start)
    assert len(qw) == 1_000_000
    print(f"timeline 10^6 rows    {min(times):8.3f} s (best of 3; median {statistics.median(times):.3f} s)   "
          f"limit 1 s   {'ok' if min(times) < 1.0 else 'OVER'}")
    ok &= min(times) < 1.0
    del t, qw

    # 3. a still through Python vs the CLI, fresh processes, interleaved
    env = dict(os.environ, PYTHONPATH=str(build / "python"))
    with tempfile.TemporaryDirectory() as tmp:
        py_png, cli_png = Path(tmp) / "py.png", Path(tmp) / "cli.png"
        python_cmd = [sys.executable, "-c",
                      f"import rollspin; rollspin.load({str(lollipop_file)!r}).still(width=960, height=540)"
                      f".save({str(py_png)!r})"]
        cli_cmd = [str(build / "rollspin"), "render", str(lollipop_file), "--still", "--width", "960", "--height",
                   "540", "-o", str(cli_png), "--quiet"]
        # The CLI restarts itself with malloc's huge pages (app/huge_pages.hpp);
        # an interpreter cannot, so Python is timed with and without the variable.
        huge = dict(env, GLIBC_TUNABLES="glibc.malloc.hugetlb=1")
        py_times, py_huge_times, cli_times = [], [], []
        for _ in range(args.runs):
            for cmd, store, environment in ((python_cmd, py_times, env), (python_cmd, py_huge_times, huge),
                                            (cli_cmd, cli_times, env)):
                start = time.perf_counter()
                subprocess.run(cmd, check=True, env=environment, capture_output=True)
                store.append(time.perf_counter() - start)
        same = py_png.read_bytes() == cli_png.read_bytes()
    py_med, cli_med = statistics.median(py_times), statistics.median(cli_times)
    huge_med = statistics.median(py_huge_times)
    print(f"still 960x540 (fresh) Python {py_med * 1e3:8.1f} ms   Python with GLIBC_TUNABLES=glibc.malloc.hugetlb=1 "
          f"{huge_med * 1e3:8.1f} ms   CLI {cli_med * 1e3:8.1f} ms   ratios {py_med / cli_med:.3f} / "
          f"{huge_med / cli_med:.3f} (limit 1.10)   same PNG bytes: {same}   "
          f"{'ok' if py_med <= 1.10 * cli_med else 'OVER'}")
    ok &= py_med <= 1.10 * cli_med

    # 4. a second still on a kept Scene: CPU time of the whole process (llvmpipe's threads included)
    scene.still(width=960, height=540)
    cpu = []
    for k in range(5):
        start = time.process_time()
        scene.still(at=0.1 + k, width=960, height=540)
        cpu.append(time.process_time() - start)
    print(f"second still 960x540  CPU {statistics.median(cpu) * 1e3:8.1f} ms (median of 5; min "
          f"{min(cpu) * 1e3:.1f} ms)   limit 80 ms   {'ok' if statistics.median(cpu) <= 0.080 else 'OVER'}")
    ok &= statistics.median(cpu) <= 0.080
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
