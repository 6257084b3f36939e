#!/usr/bin/env bash
# The recipes of docs/cluster.md, run as written on tiny
# clips (160x90, 30 frames):
#   scripts/render_parallel.sh on this machine, and over SSH to two pretend
#     hosts (tests/cli/fake_ssh.sh as GNU parallel's ssh: each host is a
#     folder of its own, files really go there and back with rsync);
#   scripts/slurm/*.sbatch run by hand with SLURM_ARRAY_TASK_ID/COUNT set as
#     Slurm would (Slurm is not installed), and submit.sh against a pretend
#     sbatch that records the array and the dependency;
#   scripts/sweep_sphere_inside.sh on a small grid, against its closed form.
# Each joined clip is probed with ffprobe: 30 frames, tagged as frames 0-29.
#
#   bash tests/cli/recipes_test.sh BUILD/rollspin WORK_FOLDER
set -euo pipefail

rollspin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
work=$2
src=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work"
export ROLLSPIN=$rollspin
tiny=(--set render.width=160 --set render.height=90 --set animation.fps=30 --set animation.duration=0.6
      --set animation.hold=0.2)
scene=$src/scenes/lollipop.toml
# A failure shows what the pretend hosts saw: who ran which shard, what went over SSH.
fail() {
  echo "FAIL: $*" >&2
  for log in "$work/ran.log" "$work/fake-hosts/ssh.log"; do
    [ -f "$log" ] && { echo "--- $log" >&2; cut -c1-200 "$log" | tail -n 20 >&2; }
  done
  exit 1
}

# A joined clip: 30 decoded frames, tagged as the whole clip, +faststart.
check_clip() {
  local clip=$1
  [ -f "$clip" ] || fail "$clip missing"
  local frames tags
  frames=$(ffprobe -v error -count_frames -select_streams v -show_entries stream=nb_read_frames -of csv=p=0 "$clip")
  [ "$frames" = 30 ] || fail "$clip: $frames frames, expected 30"
  tags=$(ffprobe -v error -show_entries format_tags=rollspin_frames,rollspin_clip_frames -of csv=p=0 "$clip")
  [ "$tags" = "0-29,30" ] || fail "$clip: tags '$tags', expected 0-29,30"
  echo "ok: $clip has 30 frames, tagged 0-29 of 30"
}

echo "== GNU parallel on this machine"
bash "$src/scripts/render_parallel.sh" "$scene" local/clip.mp4 -n 3 -- "${tiny[@]}"
check_clip local/clip.mp4
[ "$(ls local)" = "clip.mp4" ] || fail "parts left beside local/clip.mp4: $(ls local)"

echo "== GNU parallel over SSH (two pretend hosts and this machine)"
export FAKE_SSH_ROOT=$work/fake-hosts FAKE_SSH_BIN=$work/remote-bin PARALLEL_SSH=$src/tests/cli/fake_ssh.sh
mkdir -p "$FAKE_SSH_ROOT" "$FAKE_SSH_BIN"
# The hosts' `rollspin` in PATH: logs which host ran it (its HOME), then runs.
printf '#!/bin/sh\necho "$(basename "$HOME") $*" >> "%s"\nexec "%s" "$@"\n' "$work/ran.log" "$rollspin" \
  > "$FAKE_SSH_BIN/rollspin"
chmod +x "$FAKE_SSH_BIN/rollspin"
printf 'alpha\nbeta\n:\n' > hosts
PATH=$FAKE_SSH_BIN:$PATH bash "$src/scripts/render_parallel.sh" "$scene" ssh/clip.mp4 --hosts hosts -n 5 -j 1 --keep-parts -- "${tiny[@]}"
check_clip ssh/clip.mp4
[ "$(ls ssh | grep -c 'part-.-of-5')" = 5 ] || fail "--keep-parts: $(ls ssh)"
for host in alpha beta; do
  grep -q "^$host render .rollspin-shards-clip.*/scene.toml --shard ./5 " ran.log || fail "no shard ran on $host"
  grep -q "^fake-ssh: $host rsync --server" "$FAKE_SSH_ROOT/ssh.log" || fail "nothing transferred to $host"
  [ -z "$(find "$FAKE_SSH_ROOT/$host" -type f)" ] || fail "--cleanup left $(find "$FAKE_SSH_ROOT/$host" -type f)"
done
[ -z "$(ls -A . | grep rollspin-shards)" ] || fail "staging folder left behind"
unset PARALLEL_SSH

echo "== Slurm array job, the variables set by hand"
mkdir slurm
(
  cd slurm
  for k in 1 2 3; do
    SLURM_ARRAY_TASK_ID=$k SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=3 \
      bash "$src/scripts/slurm/render_shard.sbatch" "$scene" out/clip.mp4 "${tiny[@]}"
  done
  [ "$(ls out | tr '\n' ' ')" = "clip.part-1-of-3.mp4 clip.part-2-of-3.mp4 clip.part-3-of-3.mp4 " ] ||
    fail "array parts: $(ls out)"
  bash "$src/scripts/slurm/join.sbatch" out/clip.mp4 3
  check_clip out/clip.mp4
  [ "$(ls out)" = "clip.mp4" ] || fail "parts left after the join: $(ls out)"
  # Not an array task, or an array that is not 1-N: refused before rendering.
  if bash "$src/scripts/slurm/render_shard.sbatch" "$scene" out/x.mp4 2>/dev/null; then fail "ran outside an array"; fi
  set +e
  SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=2 \
    bash "$src/scripts/slurm/render_shard.sbatch" "$scene" out/x.mp4 2>/dev/null
  [ $? = 2 ] || fail "--array=0-2 accepted"
  set -e
  # submit.sh against a pretend sbatch: the array, then a join after it.
  mkdir -p bin
  cat > bin/sbatch <<'EOF'
#!/usr/bin/env bash
echo "$*" >> sbatch.log
if [[ "$*" == *--array=* ]]; then echo "4242;cluster"; else echo 4243; fi
EOF
  chmod +x bin/sbatch
  PATH=$PWD/bin:$PATH bash "$src/scripts/slurm/submit.sh" "$scene" out/clip.mp4 8 --quality high
  grep -q -- "--parsable --array=1-8 .*render_shard.sbatch $scene out/clip.mp4 --quality high$" sbatch.log ||
    fail "array submission: $(cat sbatch.log)"
  grep -q -- "--parsable --dependency=afterok:4242 .*join.sbatch out/clip.mp4 8$" sbatch.log ||
    fail "join submission: $(cat sbatch.log)"
  echo "ok: submit.sh submits --array=1-8 and a join with --dependency=afterok on it"
)

echo "== solve --json sweep with GNU parallel"
RADII="0.5 1.5" COLATITUDES="45 60 90" bash "$src/scripts/sweep_sphere_inside.sh" sweep/sweep.csv
[ "$(wc -l < sweep/sweep.csv)" = 7 ] || fail "sweep rows: $(cat sweep/sweep.csv)"
[[ "$(head -1 sweep/sweep.csv)" == ball_radius,colatitude_deg,angle,closed_form_angle,difference,* ]] || fail "header"
awk -F, 'NR > 1 { d = $5 < 0 ? -$5 : $5; if (d > 1e-9) { print "row " NR ": " $0; bad = 1 } } END { exit bad }' \
  sweep/sweep.csv || fail "the solver's angle is not the closed form"
echo "ok: 6 grid points, each within 1e-9 rad of the closed form"
echo "all recipes ran"
