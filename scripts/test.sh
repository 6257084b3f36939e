#!/usr/bin/env bash
# Fresh machine → the whole test suite: installs the Debian packages (the
# quick start's and the tests': install-deps.sh --tests), builds Release with
# the tests and benchmarks, runs every test through ctest (the Python tests and the example
# notebooks too: ctest's python_tests, pytest with the build's package).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --tests
# A unity build (CMakeLists.txt, ROLLSPIN_UNITY_BUILD): from scratch it
# compiles in about three fifths of the time; ROLLSPIN_UNITY_BUILD=OFF keeps
# one object per file, for a tree you go on editing.
ROLLSPIN_CMAKE_FLAGS="-DROLLSPIN_BUILD_TESTS=ON -DROLLSPIN_BUILD_BENCHMARKS=ON -DROLLSPIN_UNITY_BUILD=${ROLLSPIN_UNITY_BUILD:-ON}" \
  bash scripts/build.sh
source scripts/jobs.sh
cd build
# ctest starts the longest tests first when it knows their times (else it
# goes in file order and a long test left for last runs alone): a fresh build
# takes them from tests/ctest_cost_data.txt, a Release run's own file
# (refresh it with `cp build/Testing/Temporary/CTestCostData.txt
# tests/ctest_cost_data.txt`); ctest then keeps its own measurements.
if [ ! -f Testing/Temporary/CTestCostData.txt ]; then
  mkdir -p Testing/Temporary
  cp ../tests/ctest_cost_data.txt Testing/Temporary/CTestCostData.txt
fi
# A failed pass is run again, failed tests only, so that their output is the
# last thing printed (CI keeps only the tail of a log), and so that the log
# tells a flaky test (passes the second time) from a broken one.
pass() {
  "$@" --output-on-failure -j"$jobs" && return 0
  echo "test.sh: some tests failed; running those again for their output:" >&2
  "$@" --rerun-failed --output-on-failure -j1 || true
  return 1
}
# ctest runs a test per core already: llvmpipe's own rasterizer threads
# would only oversubscribe them (and sync per tile), so each GL test draws
# in its one thread (LP_NUM_THREADS=0; pixels are the same either way).
# That took a tenth off the GL tests; a test of the threads sets its own.
export LP_NUM_THREADS=${LP_NUM_THREADS:-0}
pass ctest
# `auto` picks OSMesa on a machine without a GPU; the GL tests meet the EGL
# backend (surfaceless, llvmpipe) in scripts/sanitize.sh, which runs the
# suite with ROLLSPIN_GL=egl, and in the tests that force it.
