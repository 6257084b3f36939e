#!/usr/bin/env bash
# Video benchmark (on demand, not in CI): a 10 s 1080p30 clip of the lollipop
# (300 frames, no holds), measured in one run:
#   (a) rollspin render → MP4, end to end (solve, render, convert, encode, mux)
#   (b) the ffmpeg tool encoding the same frames from raw RGBA with the same
#       codec settings (libx264, preset, CRF, yuv420p through the BT.709
#       matrix with swscale's bilinear filter, BT.709 tags, +faststart; rollspin
#       converts with its own BT.709 converter, only the blocks that changed)
#   (c) rollspin writing PNG frames, then the ffmpeg tool encoding them (the
#       way a QuTiP/matplotlib script makes a video)
#   peak RSS of a 40 s clip against the 10 s clip (rollspin, MP4).
# Targets: (a)/(b) ≤ 1.5, (c)/(a) ≥ 3, RSS(40 s)/RSS(10 s) ≤ 1.10.
# Needs a Release build (scripts/build.sh) and Debian's ffmpeg package.
# Usage: bash scripts/bench_video.sh [WORK_DIR]   (default: a fresh temp dir)
# DURATION / LONG_DURATION / SIZE override 10, 40 and 1920x1080 for a quick try.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
bin=$root/build/rollspin
[ -x "$bin" ] || { echo "bench_video: build first (bash scripts/build.sh)" >&2; exit 1; }
command -v ffmpeg >/dev/null || { echo "bench_video: needs the ffmpeg tool (apt-get install ffmpeg)" >&2; exit 1; }

work=${1:-$(mktemp -d /tmp/rollspin-bench-video.XXXXXX)}
mkdir -p "$work"
duration=${DURATION:-10}
long=${LONG_DURATION:-40}
size=${SIZE:-1920x1080}
width=${size%x*}
height=${size#*x}
fps=30
crf=18
preset=medium
scene=$root/scenes/lollipop.toml
common=(--set render.width="$width" --set render.height="$height" --set animation.fps="$fps"
        --set animation.hold=0 --set animation.crf="$crf" --set animation.preset="$preset" --quiet)

# shellcheck source=scripts/bench_common.sh
source "$root/scripts/bench_common.sh"
x264_args "$preset" "$crf"
# A measured run that failed (EXIT_CODE, the 4th field) ends the benchmark.
ran() { [ "$1" = 0 ] || { echo "bench_video: $2 failed (exit $1)" >&2; exit 1; }; }

echo "bench_video: ${duration} s at ${width}x${height}@${fps}, libx264 preset ${preset} crf ${crf}; work dir $work"
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"

# (a) rollspin end to end.
read -r a_wall a_rss a_cpu a_rc < <(measure "$bin" render "$scene" "${common[@]}" --set animation.duration="$duration" \
                                            -o "$work/a.mp4")
ran "$a_rc" "(a)"
echo "(a) rollspin render → MP4:                  ${a_wall} s  (CPU ${a_cpu} s, peak RSS $((a_rss / 1024)) MiB)"

# (c) PNG frames, then the ffmpeg tool (timed together).
rm -rf "$work/frames"
read -r c1_wall _ c1_cpu c1_rc < <(measure "$bin" render "$scene" "${common[@]}" --set animation.duration="$duration" \
                                     --set render.format=png -o "$work/frames")
ran "$c1_rc" "(c), the PNG frames"
read -r c2_wall _ c2_cpu c2_rc < <(measure ffmpeg -v error -y -framerate $fps -i "$work/frames/frame_%05d.png" \
                                     "${X264_ARGS[@]}" "$work/c.mp4")
ran "$c2_rc" "(c), the ffmpeg tool"
c_wall=$(python3 -c "print(f'{$c1_wall + $c2_wall:.3f}')")
c_cpu=$(python3 -c "print(f'{$c1_cpu + $c2_cpu:.3f}')")
echo "(c) PNG frames + ffmpeg tool:               ${c_wall} s  (CPU ${c_cpu} s; frames ${c1_wall} s, encode ${c2_wall} s)"

# (b) the same frames as raw RGBA (prepared untimed, read from the page cache).
ffmpeg -v error -y -i "$work/frames/frame_%05d.png" -f rawvideo -pix_fmt rgba "$work/frames.rgba"
cat "$work/frames.rgba" > /dev/null
read -r b_wall b_rss b_cpu b_rc < <(measure ffmpeg -v error -y -f rawvideo -pix_fmt rgba -s "${width}x${height}" \
                                    -framerate $fps -i "$work/frames.rgba" "${X264_ARGS[@]}" "$work/b.mp4")
ran "$b_rc" "(b)"
rm -f "$work/frames.rgba"
echo "(b) ffmpeg tool, raw RGBA → MP4:            ${b_wall} s  (CPU ${b_cpu} s, peak RSS $((b_rss / 1024)) MiB)"

# Fairness: libx264 writes its full settings into the stream (an SEI); (a),
# (b) and (c) must have encoded with the same ones (threads included).
if ! diff <(x264_options "$work/a.mp4") <(x264_options "$work/b.mp4") >/dev/null ||
   ! diff <(x264_options "$work/a.mp4") <(x264_options "$work/c.mp4") >/dev/null; then
  echo "bench_video: the x264 settings differ between (a), (b) and (c):" >&2
  diff <(x264_options "$work/a.mp4") <(x264_options "$work/b.mp4") >&2 || true
  exit 1
fi
echo "    x264 settings identical in (a), (b), (c): $(x264_options "$work/a.mp4" | grep -E '^(threads|lookahead_threads|crf|subme|ref)=' | tr '\n' ' ')"

# Peak RSS of a clip 4× longer.
read -r l_wall l_rss _ l_rc < <(measure "$bin" render "$scene" "${common[@]}" --set animation.duration="$long" \
                                     -o "$work/long.mp4")
ran "$l_rc" "the ${long} s clip"
echo "    rollspin ${long} s clip:                    ${l_wall} s  (peak RSS $((l_rss / 1024)) MiB)"

python3 - "$a_wall" "$b_wall" "$c_wall" "$a_rss" "$l_rss" "$a_cpu" "$b_cpu" "$c_cpu" <<'EOF'
import sys
a, b, c, rss10, rss40, a_cpu, b_cpu, c_cpu = map(float, sys.argv[1:])
def verdict(ok): return "ok" if ok else "MISSED"
# The targets hold in wall and in CPU time alike.
print(f"(a)/(b) = {a / b:.2f} wall, {a_cpu / b_cpu:.2f} CPU   target <= 1.5   "
      f"{verdict(a / b <= 1.5 and a_cpu / b_cpu <= 1.5)}")
print(f"(c)/(a) = {c / a:.2f} wall, {c_cpu / a_cpu:.2f} CPU   target >= 3     {verdict(c / a >= 3 and c_cpu / a_cpu >= 3)}")
print(f"RSS long/short = {rss40 / rss10:.3f} ({rss40 / 1024:.0f} / {rss10 / 1024:.0f} MiB)   target <= 1.10   "
      f"{verdict(rss40 / rss10 <= 1.10)}")
EOF
