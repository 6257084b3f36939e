#!/usr/bin/env bash
# A pretend remote host for the recipe test (GNU parallel's PARALLEL_SSH, and
# rsync's -e): "ssh [opts] HOST CMD..." runs CMD in $FAKE_SSH_ROOT/HOST (the
# host's login folder), with $FAKE_SSH_BIN first in PATH, as sshd would.
# Like sshd, it sets SHELL to the user's login shell rather than passing on
# the caller's: GNU parallel's remote wrapper runs each job with the remote
# $SHELL, and a caller whose SHELL names a shell this machine lacks (CI runners
# inherit one) made every remote job end at once with status 0 and no part.
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
login_shell=$(getent passwd "$(id -u)" | cut -d: -f7)
case "$login_shell" in */nologin|*/false|"") login_shell=/bin/sh ;; esac
[ -x "$login_shell" ] || login_shell=/bin/sh
export HOME="$FAKE_SSH_ROOT/$host" PATH="$FAKE_SSH_BIN:$PATH" SHELL="$login_shell"
exec bash -c "$*"
