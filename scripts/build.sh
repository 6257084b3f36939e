#!/usr/bin/env bash
# Configure and build Release into build/ (2 parallel jobs: the reference
# machine has 2 cores).
#   bash scripts/build.sh            # everything: rollspin, tests, benchmarks
#   bash scripts/build.sh rollspin   # only these targets (the quick start)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${cache_flags[@]}"
if [ $# -gt 0 ]; then
  cmake --build build -j2 --target "$@"
else
  cmake --build build -j2
fi
