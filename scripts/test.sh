#!/usr/bin/env bash
# Fresh machine → the whole test suite: installs the Debian packages, builds
# Release, runs every test through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j2
