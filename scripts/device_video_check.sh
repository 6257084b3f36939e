#!/usr/bin/env bash
# On a lent GPU machine (after scripts/device_unpack.sh): times video renders
# of the lollipop with rollspin's bundled binary against a reference binary,
# in turn, and says where the pipeline waits. Where the "On a GPU" table came
# from (docs/speed-history.md#video-speed-scriptsbench_videosh-as-the-readme-had-it).
#   bash scripts/device_video_check.sh REFERENCE_ROLLSPIN [LOG]
# REFERENCE_ROLLSPIN: an older build (same libraries), carried beside the
# bundle. (b) is the ffmpeg tool with bench_video.sh's (b) command, on frames
# decoded from (a)'s MP4 (PNG frames take minutes there). Needs the bundle
# made with --with-ffmpeg (and bench_media in it) and python3. About 90 s.
set -uo pipefail
ref=${1:?usage: device_video_check.sh REFERENCE_ROLLSPIN [LOG]}
log=${2:-${OUT:-/tmp}/device_video_check.txt}
exec > >(tee -a "$log") 2>&1
cd "$(dirname "$0")/.." || exit 2
source /opt/rollspin/env.sh
new=/opt/rollspin/bin/rollspin
chmod +x "$ref"
w=$(mktemp -d)
date -u; echo "$(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"; nvidia-smi -L 2>/dev/null
"$new" info 2>&1 | tail -3

# shellcheck source=scripts/bench_common.sh
source scripts/bench_common.sh
x264_args medium 18
# label, command…: wall, CPU (user + system of the tree), peak RSS, and the
# --verbose lines about the pipeline and the encoder.
report() {
  local label=$1 err wall rss cpu rc
  shift
  err=$(mktemp)
  read -r wall rss cpu rc < <(measure "$@" 2>"$err")
  echo "$label: $wall s wall, $cpu s CPU, $((rss / 1024)) MiB, rc $rc"
  grep -E "pipeline:|encoder:|rror" "$err" | sed 's/^/    /'
  rm -f "$err"
}
scene=scenes/lollipop.toml
hd=(--set render.width=1920 --set render.height=1080 --set animation.fps=30 --set animation.hold=0
    --set animation.crf=18 --set animation.preset=medium --set animation.duration=10)
echo "== 1080p fixed camera, 10 s, in turn"
for _ in 1 2 3; do
  report "reference        " "$ref" render $scene "${hd[@]}" -o "$w/ref.mp4" --quiet
  report "bundle           " "$new" render $scene "${hd[@]}" -o "$w/new.mp4" --quiet
  ROLLSPIN_CONVERT_THREADS=1 report "bundle, 1 thread " "$new" render $scene "${hd[@]}" -o "$w/new1.mp4" --quiet
done
cmp "$w/new.mp4" "$w/new1.mp4" && echo "bundle: default and 1 conversion thread byte-identical"
report "reference --verbose" "$ref" --verbose render $scene "${hd[@]}" -o "$w/refv.mp4"
report "bundle --verbose" "$new" --verbose render $scene "${hd[@]}" -o "$w/newv.mp4"

echo "== (b) the ffmpeg tool, raw RGBA → MP4"
ffmpeg -v error -y -i "$w/new.mp4" -f rawvideo -pix_fmt rgba "$w/frames.rgba"
cat "$w/frames.rgba" >/dev/null
for _ in 1 2; do
  report "(b)" ffmpeg -v error -y -f rawvideo -pix_fmt rgba -s 1920x1080 -framerate 30 -i "$w/frames.rgba" "${X264_ARGS[@]}" "$w/b.mp4"
done
rm -f "$w/frames.rgba"
for f in new ref b; do
  echo "$f.mp4 x264: $(x264_options "$w/$f.mp4" | grep -E '^(threads|lookahead_threads)=' | tr '\n' ' ')"
done

uhd=(--set render.width=3840 --set render.height=2160 --set animation.fps=30 --set animation.hold=0 --set animation.duration=5)
echo "== 4K follow camera, 5 s"
report "reference" "$ref" --verbose render $scene "${uhd[@]}" --set render.follow=true -o "$w/ref4f.mp4"
report "bundle" "$new" --verbose render $scene "${uhd[@]}" --set render.follow=true -o "$w/new4f.mp4"
for threads in 1 8; do
  ROLLSPIN_CONVERT_THREADS=$threads report "bundle, $threads threads" "$new" --verbose render $scene "${uhd[@]}" \
    --set render.follow=true -o "$w/new4f-$threads.mp4"
  cmp "$w/new4f.mp4" "$w/new4f-$threads.mp4" && echo "    byte-identical to the default thread count"
done
echo "== 4K fixed camera, 5 s"
report "reference" "$ref" --verbose render $scene "${uhd[@]}" -o "$w/ref4.mp4"
report "bundle" "$new" --verbose render $scene "${uhd[@]}" -o "$w/new4.mp4"

if command -v bench_media >/dev/null; then
  echo "== bench_media (1080p, then 4K)"
  args=(--benchmark_min_time=0.3 --benchmark_repetitions=3 --benchmark_report_aggregates_only=true)
  bench_media "${args[@]}" 2>&1 | grep median
  ROLLSPIN_BENCH_SIZE=3840x2160 bench_media "${args[@]}" 2>&1 | grep median
fi
rm -rf "$w"
date -u; echo "load $(cut -d' ' -f1-3 /proc/loadavg)"
