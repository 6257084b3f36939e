# Sourced by build.sh, sanitize.sh and fuzz.sh: compile through ccache when it
# is installed (scripts/install-deps.sh installs it). CCACHE_BASEDIR is the
# checkout, so ccache hashes paths relative to it and a fresh clone in any
# folder hits the objects an earlier clone (or an earlier configuration of
# the same sources) left in ~/.cache/ccache. Sets `cache_flags` for cmake.
cache_flags=()
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="$PWD"
  # Release, ASan and fuzz builds share one cache; 5 GiB keeps all three.
  export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-5G}"
  # The test programs share a precompiled header (tests/CMakeLists.txt):
  # ccache caches a file compiled with one only when told that the header's
  # macros and __DATE__/__TIME__ (which rollspin never uses) may be ignored.
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros}"
  cache_flags=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
