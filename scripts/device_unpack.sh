#!/usr/bin/env bash
# On a lent machine: unpacks the parts of scripts/device_bundle.sh found in
# BUNDLE_DIR (default build/device-bundle) into / (the binaries and
# libraries under /opt/rollspin), and says which parts it has seen so far:
# a call may carry one part at a time, and the machine keeps what the calls
# before unpacked while it stays warm.
#   bash scripts/device_unpack.sh [BUNDLE_DIR] && source /opt/rollspin/env.sh
# Needs only python3 (no xz or dpkg on the machine).
set -euo pipefail
dir=${1:-build/device-bundle}
shopt -s nullglob
parts=("$dir"/part-*.tar.xz)
[ ${#parts[@]} -gt 0 ] || { echo "device_unpack.sh: no part-*.tar.xz in $dir" >&2; exit 2; }
python3 - "${parts[@]}" <<'PY'
import os, sys, tarfile
seen = "/opt/rollspin/parts-unpacked"
os.makedirs("/opt/rollspin", exist_ok=True)
for part in sys.argv[1:]:
    with tarfile.open(part, "r:xz") as tar:
        for member in tar.getmembers():
            if member.name.startswith("/") or ".." in member.name.split("/"):
                sys.exit(f"device_unpack.sh: {part} holds an unsafe path {member.name}")
        tar.extractall("/")
    with open(seen, "a") as f:
        f.write(os.path.basename(part) + "\n")
    print(f"unpacked {part}")
names = sorted(set(open(seen).read().split()))
print(f"unpacked so far: {' '.join(names)}")
PY
command -v ldconfig >/dev/null && ldconfig || true
# grep reads all of ldd's output (grep -q or head would stop early: SIGPIPE, 141 under pipefail).
missingLibs=""
if [ -x /opt/rollspin/bin/rollspin ]; then
  missingLibs=$(LD_LIBRARY_PATH=/opt/rollspin/lib ldd /opt/rollspin/bin/rollspin | grep "not found" || true)
fi
if [ -n "$missingLibs" ]; then
  echo "device_unpack.sh: libraries still missing (more parts to come?):"
  echo "$missingLibs" | sed -n 1,5p
else
  echo "device_unpack.sh: rollspin's libraries are all here; source /opt/rollspin/env.sh"
fi
