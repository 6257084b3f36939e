#!/usr/bin/env bash
# Packs this machine's build for a machine that lacks Debian 12's libraries
# (a lent GPU machine with another distribution, no package registry): the
# binaries, every shared library they load except glibc's and the C++
# runtime's (the host's newer ones serve), glvnd's libEGL/libGL (rollspin
# opens libEGL with dlopen, so ldd does not list it) and the DejaVu fonts.
#   bash scripts/device_bundle.sh [--with-ffmpeg] [--part-mib N] [OUT_DIR]
# OUT_DIR (default build/device-bundle) then holds part-1.tar.xz, part-2…,
# each at most N MiB (default 56: a call to a lent machine carries 64 MiB
# with the working tree). On the machine, after each part has arrived:
#   bash scripts/device_unpack.sh OUT_DIR      # unpacks the parts present
#   source /opt/rollspin/env.sh                 # once all parts are in
# --with-ffmpeg adds the ffmpeg and ffprobe tools (bench_video.sh needs them;
# their libraries make the bundle about 10 MiB larger).
set -euo pipefail
cd "$(dirname "$0")/.."
withFfmpeg=0
partMib=56
out=build/device-bundle
while [ $# -gt 0 ]; do
  case "$1" in
    --with-ffmpeg) withFfmpeg=1 ;;
    --part-mib) partMib=${2:?--part-mib needs a number}; shift ;;
    -h | --help) sed -n '2,16p' "$0"; exit 0 ;;
    -*) echo "device_bundle.sh: unknown option $1" >&2; exit 2 ;;
    *) out=$1 ;;
  esac
  shift
done
[[ "$partMib" =~ ^[0-9]+$ ]] && [ "$partMib" -ge 8 ] || { echo "device_bundle.sh: --part-mib wants a whole number ≥ 8, got $partMib" >&2; exit 2; }
[ -x build/rollspin ] || { echo "device_bundle.sh: build/rollspin is missing (build first)" >&2; exit 2; }
binaries=(build/rollspin)
for bench in build/bench/bench_render build/bench/bench_media; do
  [ -x "$bench" ] && binaries+=("$bench")
done
if [ "$withFfmpeg" = 1 ]; then
  for tool in ffmpeg ffprobe; do
    path=$(command -v "$tool") || { echo "device_bundle.sh: --with-ffmpeg, but $tool is not installed" >&2; exit 2; }
    binaries+=("$path")
  done
fi

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
root=$stage/root
mkdir -p "$root/opt/rollspin/bin" "$root/opt/rollspin/lib"
for b in "${binaries[@]}"; do cp "$b" "$root/opt/rollspin/bin/"; done

# The libraries: the union of what the binaries load, resolved to files.
# glibc and the C++ runtime stay the host's: a newer host's serve Debian's
# binaries, and an older copy here would break the host's own GPU driver.
# rollspin opens FFmpeg's libraries with dlopen (media/av_library.hpp), so
# ldd of the binary does not list them: they and what they load are added,
# by the names and major versions rollspin loads (its `info` lists them).
sonames=$(build/rollspin info 2>/dev/null | sed -n 's/^video ([^)]*): //p' | grep -oE 'lib[a-z]+ [0-9]+' |
            awk '{print $1 ".so." $2}') || true
[ -n "$sonames" ] || { echo "device_bundle.sh: rollspin info finds no FFmpeg here:" >&2; build/rollspin info | tail -1 >&2; exit 1; }
# Under pipefail no reader may stop before its writer is done: an awk that
# exits at its match kills ldconfig with SIGPIPE and the script with 141
# (tests/scripts_pipefail_test.sh), so the awk reads to the end.
libraryPathOf() { ldconfig -p | awk -v s="$1" '!found && $1 == s && /x86-64/ {print $NF; found = 1}'; }
ffmpegLibs=()
for soname in $sonames; do
  lib=$(libraryPathOf "$soname")
  [ -n "$lib" ] || { echo "device_bundle.sh: $soname, which rollspin loads, is not in ldconfig's cache" >&2; exit 1; }
  ffmpegLibs+=("$lib")
done
{ ldd "${binaries[@]}" "${ffmpegLibs[@]}" 2>/dev/null | awk '/=> \// {print $3}'; printf '%s\n' "${ffmpegLibs[@]}"; } | sort -u |
  grep -v -E '/(libc|libm|libdl|libpthread|librt|libresolv|libutil|ld-linux-x86-64|libstdc\+\+|libgcc_s)\.so' \
    >"$stage/libs.txt"
missingLibs=$(ldd "${binaries[@]}" "${ffmpegLibs[@]}" 2>/dev/null | grep "not found" || true)
if [ -n "$missingLibs" ]; then
  echo "device_bundle.sh: a binary's library is missing here:" >&2
  echo "$missingLibs" >&2
  exit 1
fi
while read -r lib; do cp -L "$lib" "$root/opt/rollspin/lib/$(basename "$lib")"; done <"$stage/libs.txt"

# glvnd's dispatch libraries at their system paths (the GPU driver's vendor
# library, e.g. libEGL_nvidia, is the machine's own), and the label fonts.
for pkg in libegl1 libglvnd0 libgl1 libglx0; do
  dpkg -L "$pkg" | while read -r f; do
    if [ -f "$f" ] && [[ "$f" == /usr/lib/* ]]; then
      mkdir -p "$root$(dirname "$f")"
      cp -P "$f" "$root$f"
    fi
  done
done
mkdir -p "$root/usr/share/fonts/truetype/dejavu"
cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf /usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf \
  "$root/usr/share/fonts/truetype/dejavu/"

cat >"$root/opt/rollspin/env.sh" <<'EOF'
# Source after scripts/device_unpack.sh: rollspin's libraries and binaries
# first, and NVIDIA's EGL vendor file where the image keeps it outside glvnd's
# search path.
export LD_LIBRARY_PATH=/opt/rollspin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export PATH=/opt/rollspin/bin:$PATH
if [ ! -e /usr/share/glvnd/egl_vendor.d/10_nvidia.json ] && [ -e /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json ]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
fi
EOF

# Parts: files in a stable order, a new part when the next file would pass
# the limit compressed (xz shrinks these libraries to about a third; the
# estimate is checked against each part's real size below).
python3 - "$root" "$out" "$partMib" <<'PY'
import lzma, os, sys, tarfile
root, out, part_mib = sys.argv[1], sys.argv[2], int(sys.argv[3])
limit = part_mib * 1024 * 1024
os.makedirs(out, exist_ok=True)
for old in os.listdir(out):
    if old.startswith("part-") and old.endswith(".tar.xz"):
        os.remove(os.path.join(out, old))
entries = []
for dirpath, dirnames, filenames in os.walk(root):
    dirnames.sort()
    for name in sorted(filenames):
        path = os.path.join(dirpath, name)
        entries.append((os.path.relpath(path, root), path))
# Measure each file's compressed size, then fill parts first-fit by it.
sized = []
for rel, path in entries:
    if os.path.islink(path):
        sized.append((rel, path, 512))
    else:
        with open(path, "rb") as f:
            sized.append((rel, path, len(lzma.compress(f.read(), preset=6)) + 512))
parts = []
for rel, path, size in sorted(sized, key=lambda e: -e[2]):
    if size > limit:
        sys.exit(f"device_bundle.sh: {rel} alone is {size / 2**20:.1f} MiB compressed, over --part-mib {part_mib}")
    for p in parts:
        if p[0] + size <= limit:
            p[0] += size
            p[1].append(rel)
            break
    else:
        parts.append([size, [rel]])
total = 0
for k, (_, names) in enumerate(parts, 1):
    name = os.path.join(out, f"part-{k}.tar.xz")
    tmp = name + ".tmp"
    with tarfile.open(tmp, "w:xz", preset=6) as tar:
        for rel in sorted(names):
            tar.add(os.path.join(root, rel), arcname=rel, recursive=False)
    size = os.path.getsize(tmp)
    if size > limit:
        sys.exit(f"device_bundle.sh: {name} came out at {size / 2**20:.1f} MiB, over {part_mib}")
    os.rename(tmp, name)
    total += size
    print(f"{name}: {len(names)} files, {size / 2**20:.1f} MiB")
print(f"{len(parts)} parts, {total / 2**20:.1f} MiB; on the machine: bash scripts/device_unpack.sh {out}")
PY
