#!/usr/bin/env bash
# Fresh machine → rollspin's main job on the default scene: installs the
# Debian packages, builds Release, solves the lollipop, writes its
# orientation timeline to output/ and renders its video, output/lollipop.mp4.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh rollspin  # the program alone: the tests are scripts/test.sh's
./build/rollspin solve scenes/lollipop.toml
./build/rollspin timeline scenes/lollipop.toml -o output/lollipop.csv
./build/rollspin render scenes/lollipop.toml
