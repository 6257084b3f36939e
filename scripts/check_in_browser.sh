#!/usr/bin/env bash
# Plays rollspin's transparent WebM in headless Chromium and reports what the
# browser decoded (on demand, not in CI): renders the lollipop with
# --transparent to WebM (VP9 + alpha), loads it in a page with a magenta
# background, seeks to one frame, draws that frame onto a canvas and reads
# the pixels back: how many are transparent / opaque, and the colour of a
# backdrop pixel composited over magenta. The same frame decoded by libvpx
# (the ffmpeg tool) is printed beside it, so the two can be compared.
#
#   bash scripts/check_in_browser.sh [BUILD_DIR]     (default: build)
#
# Needs Debian's `chromium` (installed here if missing; deliberately not in
# install-deps.sh: only this script uses it) and the ffmpeg tool.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
rollspin=$build/rollspin
[ -x "$rollspin" ] || { echo "check_in_browser: build rollspin first ($rollspin)" >&2; exit 1; }
if ! command -v chromium >/dev/null; then
  echo "check_in_browser: installing chromium (Debian package)" >&2
  apt-get install -y --no-install-recommends chromium >/dev/null
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
width=320 height=180 seek=1.0
"$rollspin" render "$root/scenes/lollipop.toml" --transparent --quiet --width $width --height $height \
  --set animation.duration=2 --set animation.fps=30 -o "$work/clip.webm"

cat > "$work/page.html" <<EOF
<!doctype html>
<html><body style="background:#ff00ff;margin:0">
<video id="v" src="clip.webm" muted playsinline preload="auto"></video>
<pre id="out">pending</pre>
<script>
const v = document.getElementById('v'), out = document.getElementById('out');
const report = (text) => { out.textContent = text; };
v.addEventListener('error', () => report('ERROR: the browser could not play the WebM (code ' + (v.error && v.error.code) + ')'));
v.addEventListener('loadeddata', () => { v.currentTime = $seek; });
v.addEventListener('seeked', () => {
  const w = v.videoWidth, h = v.videoHeight;
  const c = document.createElement('canvas'); c.width = w; c.height = h;
  const g = c.getContext('2d');
  g.drawImage(v, 0, 0);
  const px = g.getImageData(0, 0, w, h).data;
  let clear = 0, opaque = 0;
  for (let i = 3; i < px.length; i += 4) { if (px[i] < 16) ++clear; else if (px[i] > 240) ++opaque; }
  const corner = Array.from(px.slice(0, 4));
  // The same frame over the page's magenta, as a viewer sees it.
  const m = document.createElement('canvas'); m.width = w; m.height = h;
  const mg = m.getContext('2d');
  mg.fillStyle = '#ff00ff'; mg.fillRect(0, 0, w, h); mg.drawImage(v, 0, 0);
  const over = Array.from(mg.getImageData(0, 0, 1, 1).data.slice(0, 3));
  report(['canPlayType vp9: ' + v.canPlayType('video/webm; codecs="vp9"'),
          'size: ' + w + 'x' + h + ', duration ' + v.duration.toFixed(3) + ' s, frame at ' + v.currentTime + ' s',
          'alpha<16: ' + (100 * clear / (w * h)).toFixed(1) + '% of pixels, alpha>240: ' + (100 * opaque / (w * h)).toFixed(1) + '%',
          'top-left pixel RGBA: ' + corner.join(','),
          'top-left over magenta: ' + over.join(',')].join('\n'));
});
</script></body></html>
EOF

echo "== Chromium $(chromium --version 2>/dev/null | awk '{print $2}') decoded:"
# Headless Chromium runs the page on virtual time; decoding is real work, so
# on a busy machine the page may still be pending when the budget ends: try
# again with a larger budget.
for budget in 15000 40000 90000; do
  chromium --headless --no-sandbox --disable-gpu --mute-audio --autoplay-policy=no-user-gesture-required \
    --allow-file-access-from-files --virtual-time-budget=$budget --dump-dom "file://$work/page.html" 2>/dev/null \
    > "$work/dom.html" || true
  grep -q '<pre id="out">pending</pre>' "$work/dom.html" || break
done
python3 - "$work/dom.html" <<'EOF'
import html, re, sys
found = re.search(r'<pre id="out">(.*?)</pre>', open(sys.argv[1]).read(), re.S)
print(html.unescape(found.group(1)) if found else "ERROR: the page reported nothing")
EOF

echo "== libvpx (ffmpeg -c:v libvpx-vp9) decoded, same frame:"
ffmpeg -v error -c:v libvpx-vp9 -ss $seek -i "$work/clip.webm" -frames:v 1 -pix_fmt rgba -f rawvideo "$work/frame.rgba"
python3 - "$work/frame.rgba" $width $height <<'EOF'
import sys
data = open(sys.argv[1], 'rb').read()
w, h = int(sys.argv[2]), int(sys.argv[3])
alpha = data[3::4]
clear = sum(1 for a in alpha if a < 16)
opaque = sum(1 for a in alpha if a > 240)
print(f"alpha<16: {100 * clear / (w * h):.1f}% of pixels, alpha>240: {100 * opaque / (w * h):.1f}%")
print("top-left pixel RGBA: " + ",".join(str(b) for b in data[0:4]))
EOF
