#!/usr/bin/env bash
# Installs rollspin's dependencies from Debian 12 packages (and the npm
# packages web/package-lock.json pins).
#   bash scripts/install-deps.sh          # build, run and the Python package (the quick start)
#   bash scripts/install-deps.sh --tests  # that, and what only the tests, benchmarks and docs need
#   bash scripts/install-deps.sh [--tests] --list  # print the Debian packages, one a line; install nothing
#   bash scripts/install-deps.sh --with-blender    # also Debian's Blender (large), for the ctest label `blender`
# Checks what is missing first, then installs all of it in one apt-get call.
# No daemon is left enabled or running: slurm-wlm and munge (the cluster
# test starts and stops its own) are installed with service starts denied,
# then disabled where systemd is there.
set -euo pipefail

tests=0 list=0 blender=0
for arg in "$@"; do
  case "$arg" in
    --tests) tests=1 ;;
    --with-blender) blender=1 ;;
    --list) list=1 ;;
    -h | --help) sed -n '2,11p' "$0"; exit 0 ;;
    *) echo "install-deps: unknown option $arg (expected --tests, --with-blender, --list or nothing)" >&2; exit 2 ;;
  esac
done

# Build and run time: the compiler and libraries, GL (OSMesa/EGL, llvmpipe),
# FFmpeg's libraries (rollspin loads them in-process), cairo and the figure
# fonts, gnuplot (`rollspin report errors` draws its plot with it), the man
# page; the Python package (pybind11, numpy; `pip install .` in a venv).
packages=(
  build-essential cmake ninja-build pkg-config git ccache
  libeigen3-dev libglm-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev
  libosmesa6-dev libstb-dev fonts-dejavu-core
  libcairo2-dev fonts-lmodern
  libgl-dev libegl-dev libegl1 libegl-mesa0 libgl1-mesa-dri
  libavcodec-dev libavformat-dev libavfilter-dev libswscale-dev libavutil-dev
  libmuparser-dev
  gnuplot-nox  # `rollspin report errors` runs gnuplot for errors.png
  man-db       # `man rollspin` after the install
  pybind11-dev python3-dev python3-numpy
  libtinygltf-dev nlohmann-json3-dev  # glTF export (tinygltf writes through nlohmann/json)
  python3-setuptools python3-wheel python3-venv  # `pip install .` of the Python package into a virtual environment
)
# Only the tests, benchmarks, sanitizers, docs and recipes (--tests).
test_packages=(
  libgtest-dev libgmock-dev libbenchmark-dev
  poppler-utils librsvg2-bin  # figures' text boxes (pdftotext -bbox), SVG to PNG
  ffmpeg  # ffprobe and ffmpeg in the video tests and benchmarks
  clang libclang-rt-14-dev time  # scripts/sanitize.sh and fuzz.sh; /usr/bin/time in benchmarks
  parallel rsync jq  # the cluster recipes (docs/cluster.md) and their test
  slurm-wlm munge  # tests/cli/slurm_cluster_test.sh starts a one-node cluster of its own
  dpkg-dev  # cpack -G DEB's dpkg-shlibdeps
  python3-pytest
  python3-qutip python3-nbclient python3-ipywidgets python3-ipykernel
  python3-pandas python3-matplotlib jupyter-nbformat
  mkdocs
  chromium  # the web viewer's browser tests (driven by npm playwright-core, no browser download)
  clang-format
)
[ "$tests" = 1 ] && packages+=("${test_packages[@]}")
# Blender imports an exported glTF headless (about 80 packages: on request only).
[ "$blender" = 1 ] && packages+=(blender)
if [ "$list" = 1 ]; then printf '%s\n' "${packages[@]}"; exit 0; fi

missing=()
for p in "${packages[@]}"; do
  if [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]; then
    missing+=("$p")
  fi
done

# The npm packages that web/package-lock.json pins into web/node_modules:
# the build's (three, esbuild: the viewer's bundle) with `npm ci --omit=dev`,
# and with --tests also the tests' (playwright-core, gltf-validator).
# Node.js comes from Debian when the machine has none.
install_npm() {
  if ! command -v npm >/dev/null; then
    "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends nodejs npm
  fi
  local omit=(--omit=dev) stamp=web/node_modules/.rollspin-lock
  [ "$tests" = 1 ] && omit=()
  if [ ! -f web/node_modules/.package-lock.json ] || ! cmp -s web/package-lock.json "$stamp" ||
     { [ "$tests" = 1 ] && [ -f "$stamp.omit-dev" ]; }; then
    (cd web && npm ci "${omit[@]}" --no-audit --no-fund --loglevel=error &&
       cp package-lock.json node_modules/.rollspin-lock &&
       if [ "$tests" = 1 ]; then rm -f node_modules/.rollspin-lock.omit-dev; else touch node_modules/.rollspin-lock.omit-dev; fi)
  fi
}

# Debian starts a service when its package is installed (munged, slurmctld,
# slurmd): a policy-rc.d that denies every start keeps them down during the
# install (invoke-rc.d and deb-systemd-invoke both ask it), then systemd, if
# any, is told not to start them at boot. Only the services of packages this
# run installs: a machine's own munge or Slurm is left as it was.
daemons=()
deny_service_starts() {
  [ -e /usr/sbin/policy-rc.d ] && return 0  # the machine's own policy stays
  printf '#!/bin/sh\n# scripts/install-deps.sh: no service starts during the install\nexit 101\n' |
    "${sudo_cmd[@]}" tee /usr/sbin/policy-rc.d >/dev/null
  "${sudo_cmd[@]}" chmod 755 /usr/sbin/policy-rc.d
  policy_made=1
}
allow_service_starts() {
  if [ "${policy_made:-0}" = 1 ]; then "${sudo_cmd[@]}" rm -f /usr/sbin/policy-rc.d; fi
  if command -v systemctl >/dev/null && [ ${#daemons[@]} -gt 0 ]; then
    for d in "${daemons[@]}"; do
      "${sudo_cmd[@]}" systemctl disable --quiet "$d" 2>/dev/null || true
      "${sudo_cmd[@]}" systemctl stop "$d" 2>/dev/null || true
    done
  fi
}

cd "$(dirname "$0")/.."
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
what=$([ "$tests" = 1 ] && echo "build, run and test" || echo "build and run")

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} $what packages present"
  install_npm
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing $what package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
policy_made=0
for p in "${missing[@]}"; do
  case "$p" in
    munge) daemons+=(munge) ;;
    slurm-wlm) daemons+=(slurmctld slurmd) ;;
  esac
done
trap allow_service_starts EXIT
deny_service_starts
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_npm
