#!/usr/bin/env bash
# The README's picture of the web viewer: the command the README shows, then
# the page in headless Chromium (web/node_modules/playwright-core, Debian's
# /usr/bin/chromium, no network) at 1280×720, a little over half way along
# the path, saved as docs/viewer.png.
#   bash scripts/viewer_screenshot.sh [SCENE]   (default: storyboard)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-storyboard}
build/rollspin render "$scene" -o "output/$scene.html"
node scripts/viewer_screenshot.mjs "output/$scene.html" docs/viewer.png 0.62
