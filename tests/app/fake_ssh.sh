#!/usr/bin/env bash
# A pretend remote host for the recipe test (GNU parallel's PARALLEL_SSH, and
# rsync's -e): "ssh [opts] HOST CMD..." runs CMD in $FAKE_SSH_ROOT/HOST (the
# host's login folder), with $FAKE_SSH_BIN first in PATH, as sshd would.
echo "fake-ssh: $*" >> "$FAKE_SSH_ROOT/ssh.log"
while [ $# -gt 0 ]; do
  case "$1" in
    -l|-p|-o|-i|-S|-F|-E) shift 2 ;;
    --) shift; break ;;
    -*) shift ;;
    *) break ;;
  esac
done
host=$1; shift
[ "${1:-}" = "--" ] && shift
mkdir -p "$FAKE_SSH_ROOT/$host"
cd "$FAKE_SSH_ROOT/$host"
export HOME="$FAKE_SSH_ROOT/$host" PATH="$FAKE_SSH_BIN:$PATH"
exec bash -c "$*"
