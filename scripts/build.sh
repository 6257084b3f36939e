#!/usr/bin/env bash
# Configure and build Release into build/ (2 parallel jobs: the reference
# machine has 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
