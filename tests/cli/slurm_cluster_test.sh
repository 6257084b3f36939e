#!/usr/bin/env bash
# A real Slurm cluster (label cluster): one node on this machine, started
# here, runs the project's recipe (scripts/slurm/submit.sh, unchanged, as
# docs/cluster.md gives it): an array job renders 3 shards of a 160x90, 2 s
# clip, a join job waits on it (--dependency=afterok). Then:
#   - the joined clip has every frame, continuous timestamps, decodes with no
#     error, and its frames equal a single-machine render's within the
#     encoder's noise (PSNR);
#   - a shard that fails is named in its log and the join is cancelled, not
#     left pending; submitting again renders only the missing shard.
# The cluster: its own munge key and socket, slurm.conf in a temporary
# folder, slurmctld and slurmd on 127.0.0.1 at ports 16817/16818; both
# daemons and munged are stopped, and the folder removed, on any exit.
# Needs root and Debian's slurm-wlm + munge (scripts/install-deps.sh);
# elsewhere it prints "skipped: WHY" and exits 77 (ctest: skipped).
# Usage: slurm_cluster_test.sh ROLLSPIN (run by ctest).
set -uo pipefail
rollspin=$(realpath "$1")
src=$(realpath "$(dirname "$0")/../..")
source "$(dirname "$0")/fault_support.sh"

skip_all() { echo "skipped: $1"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip_all "a Slurm cluster is started as root (uid $(id -u))"
for tool in munged slurmctld slurmd sbatch scontrol squeue ffprobe ffmpeg; do
  command -v "$tool" >/dev/null || skip_all "$tool is not installed (scripts/install-deps.sh installs slurm-wlm and munge)"
done

tmp=$(mktemp -d /tmp/rollspin-slurm.XXXXXX)
chmod 755 "$tmp"
stop_cluster() {
  local pidfile pid
  kill "${watchdog:-}" 2>/dev/null
  for pidfile in "$tmp/slurmd.pid" "$tmp/slurmctld.pid" "$tmp/munged.pid"; do
    [ -s "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
  done
  rm -rf "$tmp"
}
trap stop_cluster EXIT
trap 'echo "slurm_cluster_test: stopped (signal or the 240 s limit)"; exit 1' INT TERM
# A hard limit below ctest's 300 s, so that the daemons are always stopped
# by the trap above rather than left running by ctest's kill.
( trap 'kill $nap 2>/dev/null; exit 0' TERM; sleep 240 & nap=$!; wait $nap && kill -TERM $$ ) 2>/dev/null &
watchdog=$!

# --- munge: a key of its own and a socket in the folder
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge.key"
mkdir -p "$tmp/munge"
chmod 700 "$tmp/munge"
# The daemons start without any LD_PRELOAD of the caller's (a sanitizer
# runtime or a GL driver is rollspin's business, not theirs).
daemon() { env -u LD_PRELOAD "$@"; }
daemon munged --force --key-file="$tmp/munge.key" --socket="$tmp/munge/munge.socket" --pid-file="$tmp/munged.pid" \
  --seed-file="$tmp/munge/seed" --log-file="$tmp/munged.log" --num-threads=2 ||
  skip_all "munged would not start here: $(tail -n 2 "$tmp/munged.log" 2>/dev/null)"

# --- slurm.conf: one node, localhost, non-default ports, everything in $tmp
mkdir -p "$tmp/state" "$tmp/spool"
cpus=$(nproc)
cat >"$tmp/slurm.conf" <<EOF
ClusterName=rollspin-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmdParameters=config_overrides
MinJobAge=600
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$((2 * cpus)) State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$tmp/slurm.conf
daemon slurmctld -i -f "$SLURM_CONF" || skip_all "slurmctld would not start here: $(tail -n 3 "$tmp/slurmctld.log")"
daemon slurmd -f "$SLURM_CONF" -N localhost || skip_all "slurmd would not start here: $(tail -n 3 "$tmp/slurmd.log")"
if ! wait_for "sinfo -h -o %t 2>/dev/null | grep -E '^(idle|mix|alloc)' >/dev/null" 30; then
  echo "slurmctld.log:"; tail -n 15 "$tmp/slurmctld.log"; echo "slurmd.log:"; tail -n 15 "$tmp/slurmd.log"
  fail cluster-up "the node did not come up: $(sinfo 2>&1 | tail -n 2)"
  finish; exit 1
fi
pass cluster-up

# Waits for job $1 to end; prints its state (COMPLETED, FAILED, CANCELLED…).
job_state() { scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort -u | tr '\n' ' '; }
wait_job() {
  local id=$1 limit=${2:-120} deadline=$((SECONDS + ${2:-120}))
  while [ -n "$(squeue -h -j "$id" 2>/dev/null)" ]; do
    [ $SECONDS -lt $deadline ] || { echo "TIMEOUT"; scancel "$id"; return; }
    sleep 0.5
  done
  job_state "$id"
}
# The job ids submit.sh printed: "shards: job A (…); join: job B (…)".
shard_job() { sed -n 's/^shards: job \([0-9]*\).*/\1/p' "$1"; }
join_job() { sed -n 's/.*join: job \([0-9]*\).*/\1/p' "$1"; }

# --- the recipe as docs/cluster.md gives it: 3 shards, then the join
work=$tmp/shared  # "a folder every node sees"
mkdir -p "$work"
cd "$work" || exit 1
cp "$src/scenes/lollipop.toml" scene.toml
options=(--set render.width=160 --set render.height=90 --set animation.duration=2)
export ROLLSPIN=$rollspin
bash "$src/scripts/slurm/submit.sh" scene.toml out/clip.mp4 3 "${options[@]}" >submit.log 2>&1 ||
  fail submit "$(cat submit.log)"
cat submit.log
state=$(wait_job "$(join_job submit.log)" 120)
if [ "$state" = "COMPLETED " ] && [ -f out/clip.mp4 ] && [ "$(ls out)" = clip.mp4 ]; then
  pass "array + join (afterok): out/clip.mp4"
else
  fail "array + join" "join job: $state; out: $(ls out 2>/dev/null | tr '\n' ' '); $(cat slurm-*.out 2>/dev/null | tail -n 5)"
fi

# --- the joined clip against a render on this machine
"$rollspin" render scene.toml "${options[@]}" --quiet -o single.mp4
frames=$(video_frames out/clip.mp4 2>/dev/null)
expected=$(video_frames single.mp4)
if [ -n "$frames" ] && [ "$frames" = "$expected" ] && [ "$expected" -ge 2 ]; then
  pass "every frame ($frames)"
else
  fail "every frame" "joined ${frames:-?}, single-machine $expected"
fi
if ffprobe -v error -select_streams v:0 -show_entries packet=pts_time -of csv=p=0 out/clip.mp4 | sort -g |
   awk 'NR > 1 { d = $1 - p; if (NR == 2) step = d; else if (d < step - 1e-4 || d > step + 1e-4) bad = 1 } { p = $1 }
        END { exit bad || NR < 2 }'; then
  pass "continuous timestamps"
else
  fail "continuous timestamps" "$(ffprobe -v error -show_entries packet=pts_time -of csv=p=0 out/clip.mp4 | sort -g | tr '\n' ' ' | cut -c 1-300)"
fi
decode=$(ffmpeg -v error -i out/clip.mp4 -f null - 2>&1)
if [ -z "$decode" ]; then pass "clean decode"; else fail "clean decode" "$decode"; fi
# Shards are encoded apart (each starts with a key frame), so frames differ
# from the single render's by x264's noise at crf 18: PSNR 40+ dB where a
# wrong or shifted frame scores below 25 dB. The least frame must pass 35.
psnr=$(ffmpeg -v info -i out/clip.mp4 -i single.mp4 -lavfi "[0:v][1:v]psnr=stats_file=$tmp/psnr.log" -f null - 2>&1 |
  sed -n 's/.* min:\([0-9.a-z]*\).*/\1/p')
if [ -n "$psnr" ] && { [ "$psnr" = inf ] || awk -v p="$psnr" 'BEGIN { exit !(p >= 35) }'; }; then
  pass "frames equal the single-machine render's (least PSNR $psnr dB)"
else
  fail "frames equal the single-machine render's" "least PSNR ${psnr:-?} dB"
fi

# --- a shard that fails: named, the join cancelled; resubmitting renders only it
rm -rf out slurm-*.out
cat >failing-rollspin <<EOF
#!/usr/bin/env bash
# Shard 2 fails once (a node that lost its disk), then works.
if [[ " \$* " == *" --shard 2/3 "* ]] && [ ! -e "$work/failed-once" ]; then
  touch "$work/failed-once"; echo "rollspin: error: (the test's) shard 2 fails" >&2; exit 1
fi
echo "\$*" >>"$work/rendered.log"
exec "$rollspin" "\$@"
EOF
chmod +x failing-rollspin
export ROLLSPIN=$work/failing-rollspin
bash "$src/scripts/slurm/submit.sh" scene.toml out/clip.mp4 3 "${options[@]}" >submit1.log 2>&1
shards=$(wait_job "$(shard_job submit1.log)" 120)
join1=$(join_job submit1.log)
for _ in $(seq 20); do [ -z "$(squeue -h -j "$join1" 2>/dev/null)" ] && break; sleep 0.5; done
state=$(job_state "$join1")
named=$(cat slurm-rollspin-shard-*_2.out 2>/dev/null | grep -c 'shard 2/3 of out/clip.mp4 failed')
if [[ "$shards" == *FAILED* ]] && [ "$state" = "CANCELLED " ] && [ "$named" = 1 ] &&
   [ "$(ls out | tr '\n' ' ')" = "clip.part-1-of-3.mp4 clip.part-3-of-3.mp4 " ]; then
  pass "a failed shard is named in its log; the join is cancelled, not left pending"
else
  fail "a failed shard" "shards: $shards; join: $state; named: $named; out: $(ls out | tr '\n' ' ')"
fi
rm -f rendered.log
bash "$src/scripts/slurm/submit.sh" scene.toml out/clip.mp4 3 "${options[@]}" >submit2.log 2>&1
cat submit2.log
state=$(wait_job "$(join_job submit2.log)" 120)
if [ "$state" = "COMPLETED " ] && grep -q 'rendering shards 2 only' submit2.log && [ "$(grep -c '^render ' rendered.log)" = 1 ] &&
   grep -q -- '^render .*--shard 2/3' rendered.log && [ "$(video_frames out/clip.mp4)" = "$expected" ]; then
  pass "resubmitted: only the missing shard rendered, then joined"
else
  fail "resubmitted" "join: $state; rendered: $(tr '\n' ';' <rendered.log 2>/dev/null); $(cat submit2.log)"
fi
cd / || true
finish
