# Shared by the fault tests of tests/cli/ (sourced, not run): counting
# results, waiting for a run to be mid-work, mounting a small tmpfs, and
# reading what a video holds with ffprobe.
#
# Every case ends in pass NAME, fail NAME WHY or skip NAME WHY; finish prints
# "N passed, N failed, N skipped" and exits 1 on any failure.

# Each result line ends with the seconds since the previous one, so that a
# slow case shows in the log (the sanitizer pass times them all).
passed=0 failed=0 skipped=0 case_start=$SECONDS took=
case_took() { took="$((SECONDS - case_start)) s" case_start=$SECONDS; }
pass() { passed=$((passed + 1)); case_took; echo "ok      $1 ($took)"; }
fail() { failed=$((failed + 1)); case_took; echo "FAILED  $1: $2 ($took)"; }
skip() { skipped=$((skipped + 1)); case_took; echo "skipped: $1: $2 ($took)"; }
finish() {
  echo "$passed passed, $failed failed, $skipped skipped"
  [ "$failed" -eq 0 ]
}

# Sleeps $1 milliseconds inside bash: an external `sleep 0.005` is a fork
# and an exec, which took 280 ms on a loaded 2-core machine.
exec {sleep_fd}<> <(:)
sleep_ms() {
  local seconds
  printf -v seconds '%d.%03d' $(($1 / 1000)) $(($1 % 1000))
  read -r -t "$seconds" -u "$sleep_fd" || true
}

# Waits (5 ms polls, at most $2 seconds, default 60) until the command in $1
# succeeds; false on time-out.
wait_for() {
  local deadline=$((SECONDS + ${2:-60}))
  until eval "$1"; do
    [ $SECONDS -lt "$deadline" ] || return 1
    sleep_ms 5
  done
}

# True when a file in folder $1 whose name starts with $2 has more than $3 bytes.
has_file_over() {
  local f
  for f in "$1"/$2*; do
    [ -f "$f" ] && [ "$(stat -c %s "$f")" -gt "$3" ] && return 0
  done
  return 1
}

# Mounts a tmpfs of $2 (e.g. 100k) on folder $1: true when it worked (root
# and a kernel that allows it); the caller unmounts it (umount_small).
mounted=()
mount_small() {
  mkdir -p "$1"
  [ "$(id -u)" -eq 0 ] || return 1
  mount -t tmpfs -o "size=$2" tmpfs "$1" 2>/dev/null || return 1
  mounted+=("$1")
}
umount_small() { umount "$1" 2>/dev/null; }
umount_all() {
  local m
  for m in "${mounted[@]}"; do umount "$m" 2>/dev/null || true; done
}

# Frames (packets) in the video $1, and its rollspin_frames tag.
video_frames() { ffprobe -v error -select_streams v:0 -count_packets -show_entries stream=nb_read_packets -of csv=p=0 "$1"; }
frames_tag() { ffprobe -v error -show_entries format_tags=rollspin_frames -of csv=p=0 "$1"; }

# Files left in folder $1 (names, sorted, one line), hidden ones included,
# the test's own stderr files left out.
left_in() { (cd "$1" && ls -A | grep -v '^stderr' | sort | tr '\n' ' '); }

# The fault tests' start, from their arguments ROLLSPIN WORKDIR: $rollspin,
# $work (emptied), $scenes, $small (a 160x90 render); tmpfs mounts are
# undone on exit.
fault_test_setup() {
  rollspin=$(realpath "$1") work=$2
  scenes=$(realpath "$(dirname "${BASH_SOURCE[0]}")/../../scenes")
  rm -rf "$work" && mkdir -p "$work"
  trap umount_all EXIT
  small=(--set render.width=160 --set render.height=90)
}
