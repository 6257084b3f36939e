#!/usr/bin/env bash
# On a lent GPU machine (after scripts/device_unpack.sh): times video renders
# of the lollipop with rollspin's bundled binary against a reference binary,
# in turn, and says where the pipeline waits. What the README's "Video speed"
# (On a GPU) table came from.
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

# label, command…: wall, CPU (user + system of the tree), peak RSS, and the
# --verbose lines about the pipeline and the encoder.
measure() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys, time
start = time.monotonic()
r = subprocess.run(sys.argv[2:], stderr=subprocess.PIPE, text=True)
wall = time.monotonic() - start
u = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{sys.argv[1]}: {wall:.2f} s wall, {u.ru_utime + u.ru_stime:.2f} s CPU, {u.ru_maxrss // 1024} MiB, rc {r.returncode}")
for line in r.stderr.splitlines():
    if "pipeline:" in line or "encoder:" in line or "rror" in line:
        print("    " + line)
PY
}
scene=scenes/lollipop.toml
hd=(--set render.width=1920 --set render.height=1080 --set animation.fps=30 --set animation.hold=0
    --set animation.crf=18 --set animation.preset=medium --set animation.duration=10)
echo "== 1080p fixed camera, 10 s, in turn"
for _ in 1 2 3; do
  measure "reference        " "$ref" render $scene "${hd[@]}" -o "$w/ref.mp4" --quiet
  measure "bundle           " "$new" render $scene "${hd[@]}" -o "$w/new.mp4" --quiet
  ROLLSPIN_CONVERT_THREADS=1 measure "bundle, 1 thread " "$new" render $scene "${hd[@]}" -o "$w/new1.mp4" --quiet
done
cmp "$w/new.mp4" "$w/new1.mp4" && echo "bundle: default and 1 conversion thread byte-identical"
measure "reference --verbose" "$ref" --verbose render $scene "${hd[@]}" -o "$w/refv.mp4"
measure "bundle --verbose" "$new" --verbose render $scene "${hd[@]}" -o "$w/newv.mp4"

echo "== (b) the ffmpeg tool, raw RGBA → MP4"
ffmpeg -v error -y -i "$w/new.mp4" -f rawvideo -pix_fmt rgba "$w/frames.rgba"
cat "$w/frames.rgba" >/dev/null
x264=(-c:v libx264 -preset medium -crf 18 -pix_fmt yuv420p -vf scale=out_color_matrix=bt709:out_range=tv:flags=bilinear
      -colorspace bt709 -color_primaries bt709 -color_trc bt709 -color_range tv -movflags +faststart)
for _ in 1 2; do
  measure "(b)" ffmpeg -v error -y -f rawvideo -pix_fmt rgba -s 1920x1080 -framerate 30 -i "$w/frames.rgba" "${x264[@]}" "$w/b.mp4"
done
rm -f "$w/frames.rgba"
for f in new ref b; do
  echo "$f.mp4 x264: $(strings "$w/$f.mp4" | grep -m1 -o 'options: .*' | tr ' ' '\n' | grep -E '^(threads|lookahead_threads)=' | tr '\n' ' ')"
done

uhd=(--set render.width=3840 --set render.height=2160 --set animation.fps=30 --set animation.hold=0 --set animation.duration=5)
echo "== 4K follow camera, 5 s"
measure "reference" "$ref" --verbose render $scene "${uhd[@]}" --set render.follow=true -o "$w/ref4f.mp4"
measure "bundle" "$new" --verbose render $scene "${uhd[@]}" --set render.follow=true -o "$w/new4f.mp4"
for threads in 1 8; do
  ROLLSPIN_CONVERT_THREADS=$threads measure "bundle, $threads threads" "$new" --verbose render $scene "${uhd[@]}" \
    --set render.follow=true -o "$w/new4f-$threads.mp4"
  cmp "$w/new4f.mp4" "$w/new4f-$threads.mp4" && echo "    byte-identical to the default thread count"
done
echo "== 4K fixed camera, 5 s"
measure "reference" "$ref" --verbose render $scene "${uhd[@]}" -o "$w/ref4.mp4"
measure "bundle" "$new" --verbose render $scene "${uhd[@]}" -o "$w/new4.mp4"

if command -v bench_media >/dev/null; then
  echo "== bench_media (1080p, then 4K)"
  args=(--benchmark_min_time=0.3 --benchmark_repetitions=3 --benchmark_report_aggregates_only=true)
  bench_media "${args[@]}" 2>&1 | grep median
  ROLLSPIN_BENCH_SIZE=3840x2160 bench_media "${args[@]}" 2>&1 | grep median
fi
rm -rf "$w"
date -u; echo "load $(cut -d' ' -f1-3 /proc/loadavg)"
