# shellcheck shell=bash
# Sourced by bench_video.sh (here) and device_video_check.sh (on a lent GPU
# machine): how a run is measured, and the ffmpeg tool's encoder settings
# that must match rollspin's for (a)/(b) to be a fair ratio. One copy, so
# that the two cannot drift apart.

# measure COMMAND…: runs it (its stderr passes through) and prints
# "WALL_SECONDS PEAK_RSS_KIB CPU_SECONDS EXIT_CODE" (RSS of the largest
# child; CPU = user + system of all its threads). On a machine shared with
# other jobs the CPU seconds are the steadier measure of the work done.
measure() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys, time
start = time.monotonic()
code = subprocess.run(sys.argv[1:]).returncode
wall = time.monotonic() - start
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{wall:.3f} {usage.ru_maxrss} {usage.ru_utime + usage.ru_stime:.3f} {code}")
PY
}

# x264_args PRESET CRF: sets X264_ARGS, the ffmpeg tool's output options that
# match rollspin's MP4 (libx264, yuv420p through swscale's bilinear BT.709
# matrix into limited range, BT.709 tags, +faststart).
x264_args() {
  # shellcheck disable=SC2034  # used by the scripts that source this file
  X264_ARGS=(-c:v libx264 -preset "$1" -crf "$2" -pix_fmt yuv420p
             -vf "scale=out_color_matrix=bt709:out_range=tv:flags=bilinear"
             -colorspace bt709 -color_primaries bt709 -color_trc bt709 -color_range tv -movflags +faststart)
}

# x264_options FILE: the settings libx264 wrote into the stream (an SEI),
# one a line, threads included.
# sed -n 1p, not grep -m1: a reader that stops early kills strings (SIGPIPE, 141 under pipefail).
x264_options() { strings "$1" | grep -o 'options: .*' | sed -n 1p | tr ' ' '\n'; }
