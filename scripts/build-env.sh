# Sourced by demo.sh and test.sh (not run): how softgrain's scripts configure a build.
# Sets `cmake_configure_args`, to be given to `cmake -S . -B <build folder>`.
#
# A compiler cache kept outside the clone (ccache's own folder, ~/.cache/ccache unless
# CCACHE_DIR says otherwise), with the clone as base directory: ccache then names every
# file relative to the build folder, so that two clones of the repository (a CI clone and a
# developer's, or two CI runs) share one cache, and a commit that changed ten files
# recompiles ten files. SOFTGRAIN_CCACHE=0 builds without it.
# Ninja when it is installed (a build folder keeps the generator it was first made with).
cmake_configure_args=()
if [[ "${SOFTGRAIN_CCACHE:-1}" == 1 ]] && command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
  # Compressed, both passes of a dozen commits took 260 MB on the machine that measured it
  # (docs/architecture.md): 8 GB is room for many.
  export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-8G}"
  # The tests' precompiled header (tests/CMakeLists.txt): ccache caches it and the units that
  # use it only when told not to hash the header's compile time and its file times (a fresh
  # clone has new ones); softgrain uses neither __TIME__ nor __DATE__.
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
  cmake_configure_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

# Usage: generator_args BUILD_FOLDER: "-G Ninja" for a new build folder when ninja exists.
generator_args() {
  if [[ ! -f "$1/CMakeCache.txt" ]] && command -v ninja >/dev/null; then
    echo "-GNinja"
  fi
}
