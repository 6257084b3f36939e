#!/usr/bin/env bash
# Configure and build Release into build/ (one job a core, memory allowing:
# scripts/jobs.sh; 2 on the reference machine).
#   bash scripts/build.sh            # everything: rollspin, tests, benchmarks
#   bash scripts/build.sh rollspin   # only these targets (the quick start)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
source scripts/jobs.sh
# ROLLSPIN_CMAKE_FLAGS: more -D flags (scripts/test.sh turns the tests on).
# shellcheck disable=SC2086
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${cache_flags[@]}" ${ROLLSPIN_CMAKE_FLAGS:-}
if [ $# -gt 0 ]; then
  cmake --build build -j"$jobs" --target "$@"
else
  cmake --build build -j"$jobs"
fi
