#!/usr/bin/env bash
# Refactoring check: renders a still of every scene in scenes/ with a
# reference binary and with build/rollspin and compares the PNG bytes.
#   bash scripts/same_stills.sh /tmp/rollspin-before [WIDTHxHEIGHT]
# Exit 0 when every still is byte-identical; lists the scenes that differ.
set -euo pipefail
cd "$(dirname "$0")/.."
reference=${1:?usage: same_stills.sh REFERENCE_BINARY [WxH]}
size=${2:-640x360}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
differ=0
for scene in scenes/*.toml; do
  name=$(basename "$scene" .toml)
  "$reference" render "$scene" --still -o "$work/$name.before.png" --width "${size%x*}" --height "${size#*x}" 2>/dev/null
  build/rollspin render "$scene" --still -o "$work/$name.after.png" --width "${size%x*}" --height "${size#*x}" 2>/dev/null
  if cmp -s "$work/$name.before.png" "$work/$name.after.png"; then
    echo "same    $name"
  else
    echo "DIFFERS $name"
    differ=1
  fi
done
exit $differ
