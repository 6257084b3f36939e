#!/usr/bin/env bash
# The gallery: every scene in scenes/ rendered by rollspin itself.
#
#   bash scripts/gallery.sh NAME ...        output/NAME.mp4 and the still output/NAME.png
#   bash scripts/gallery.sh                 the same for every scene in scenes/
#   bash scripts/gallery.sh --thumbnails    docs/gallery/NAME.png, 480x270 (committed, README "Gallery")
#
# Options: --quality low|medium|high|4k (videos; default: the scene's own
# size and frame rate), --no-video (stills only). When build/rollspin is
# missing (a fresh clone) it runs scripts/install-deps.sh and builds first.
set -euo pipefail
cd "$(dirname "$0")/.."

quality=""
thumbnails=0
video=1
names=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quality) quality="$2"; shift 2 ;;
    --thumbnails) thumbnails=1; video=0; shift ;;
    --no-video) video=0; shift ;;
    -h|--help) sed -n '2,11p' "$0"; exit 0 ;;
    -*) echo "gallery.sh: unknown option $1" >&2; exit 2 ;;
    *) names+=("${1%.toml}"); shift ;;
  esac
done
if [ ${#names[@]} -eq 0 ]; then
  for f in scenes/*.toml; do names+=("$(basename "$f" .toml)"); done
fi
for name in "${names[@]}"; do
  [ -f "scenes/$name.toml" ] || { echo "gallery.sh: no scene scenes/$name.toml" >&2; exit 2; }
done

if [ ! -x build/rollspin ]; then
  bash scripts/install-deps.sh  # only installs what is missing
  bash scripts/build.sh
fi

mkdir -p output docs/gallery
for name in "${names[@]}"; do
  scene="scenes/$name.toml"
  if [ "$thumbnails" = 1 ]; then
    ./build/rollspin render "$scene" --still --width 480 --height 270 -o "docs/gallery/$name.png"
    echo "docs/gallery/$name.png"
    continue
  fi
  ./build/rollspin render "$scene" --still -o "output/$name.png"
  echo "output/$name.png"
  if [ "$video" = 1 ]; then
    ./build/rollspin render "$scene" ${quality:+--quality "$quality"} -o "output/$name.mp4"
  fi
done
