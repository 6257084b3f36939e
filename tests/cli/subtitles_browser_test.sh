#!/bin/bash
# Chromium plays a WebM that rollspin wrote, with its captions as a <track>
# (labels gl, browser): renders scenes/storyboard.toml small (96x64, 2 fps,
# 31 frames), then subtitles_browser.mjs checks the cues Chromium reads
# against the scene. Exit 77 (skipped) where Chromium, node or
# web/node_modules are missing.
#   subtitles_browser_test.sh ROLLSPIN SOURCE_DIR WORK_DIR
set -u
rollspin=$1 source=$2 work=$3
modules=$source/web/node_modules
for need in /usr/bin/chromium "$modules/playwright-core/index.mjs"; do
  [ -e "$need" ] || { echo "skipped: $need is missing (scripts/install-deps.sh installs Chromium and web/'s npm packages)"; exit 77; }
done
command -v node >/dev/null || { echo "skipped: node is missing"; exit 77; }
rm -rf "$work" && mkdir -p "$work" || exit 1
"$rollspin" render "$source/scenes/storyboard.toml" -o "$work/clip.webm" --quiet \
  --set render.width=96 --set render.height=64 --set animation.fps=2 || { echo "FAILED: render"; exit 1; }
node "$source/tests/cli/subtitles_browser.mjs" "$modules" "$work" "$source/scenes/storyboard.toml"
