#!/usr/bin/env bash
# Installs rollspin's build and test dependencies from Debian 12 packages.
# Checks what is missing first, then installs all of it in one apt-get call.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git ccache
  libeigen3-dev libglm-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libosmesa6-dev libstb-dev fonts-dejavu-core
  libcairo2-dev poppler-utils librsvg2-bin fonts-lmodern
  libgl-dev libegl-dev libegl1 libegl-mesa0 libgl1-mesa-dri
  libavcodec-dev libavformat-dev libavfilter-dev libswscale-dev libavutil-dev
  ffmpeg
  libmuparser-dev
  gnuplot-nox
  clang libclang-rt-14-dev time
  parallel rsync jq
  slurm-wlm munge  # tests/cli/slurm_cluster_test.sh starts a one-node cluster of its own
  man-db dpkg-dev  # `man rollspin` after the install; cpack -G DEB's dpkg-shlibdeps
  pybind11-dev python3-dev python3-pytest python3-numpy
  python3-qutip python3-nbclient python3-ipywidgets python3-ipykernel
  python3-pandas python3-matplotlib jupyter-nbformat
  mkdocs
  libtinygltf-dev nlohmann-json3-dev  # glTF export (tinygltf writes through nlohmann/json)
  chromium  # the web viewer's browser tests (driven by npm playwright-core, no browser download)
  python3-setuptools python3-venv  # `pip install .` of the Python package into a virtual environment
  clang-format
)

missing=()
for p in "${packages[@]}"; do
  if [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]; then
    missing+=("$p")
  fi
done

# The npm packages that web/package-lock.json pins (three and esbuild for the
# viewer's bundle; playwright-core and gltf-validator for the tests), into
# web/node_modules. Node.js comes from Debian when the machine has none.
install_npm() {
  if ! command -v npm >/dev/null; then missing_node=(nodejs npm); else missing_node=(); fi
  if [ ${#missing_node[@]} -gt 0 ]; then
    "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing_node[@]}"
  fi
  if [ ! -f web/node_modules/.package-lock.json ] ||
     ! cmp -s web/package-lock.json web/node_modules/.rollspin-lock; then
    (cd web && npm ci --no-audit --no-fund --loglevel=error &&
       cp package-lock.json node_modules/.rollspin-lock)
  fi
}
cd "$(dirname "$0")/.."
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  install_npm
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_npm
