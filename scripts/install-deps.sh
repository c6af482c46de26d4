#!/usr/bin/env bash
# Installs the Debian packages softgrain needs, only those missing.
# Works as root or through sudo. Each package is here for one reason:
#   cmake, g++          build (C++20, OpenMP comes with g++)
#   ccache, ninja-build a compiler cache shared between clones, and a faster build tool
#                       (scripts/build-env.sh; CI's time: docs/architecture.md)
#   libeigen3-dev       small dense algebra (2x2 tensors, 3x3 MLS moment matrices, eigen solves in tests)
#   libcgal-dev         constrained Delaunay triangulation + mesher of grain domains (meshfree/)
#   libxsimd-dev        SIMD batches and vector log of the force kernel (material/simd.h), header-only
#   libtomlplusplus-dev TOML scenario files
#   libcli11-dev        the command line
#   libgtest-dev        tests; libbenchmark-dev: bench/
#   libcairo2-dev       PNG rendering of grains (render/)
#   nlohmann-json3-dev  analysis summaries (summary.json)
#   python3-matplotlib  plots drawn by /usr/bin/python3 (analysis pictures)
#   python3-scipy       campaign maps (scattered-data interpolation) and correlations
#   ffmpeg              the MP4 movies `softgrain render` makes (ffprobe checks them in tests)
#   pybind11-dev        the Python module softgrain (python/), bindings to the C++ engine
#   python3-dev         the headers of /usr/bin/python3, the interpreter the module is built for
#   python3-pytest      the Python module's tests (python/tests, run by ctest)
#   slurm-wlm           a one-node Slurm started by the tests of `softgrain sweep --slurm` (tests/slurm/)
#   munge               the authentication those Slurm daemons need (a key made per test)
#   zlib1g-dev          compression of the binary .vtu files and their reader (io/vtu_document.h)
#   python3-vtk9        VTK's own XML reader (the one ParaView uses), which the tests check
#                       reads both .vtu encodings (python/tests/test_vtu_formats.py)
set -euo pipefail
packages=(cmake g++ make ccache ninja-build libeigen3-dev libcgal-dev libxsimd-dev libtomlplusplus-dev
          libcli11-dev libboost-dev libgtest-dev libbenchmark-dev libcairo2-dev nlohmann-json3-dev python3-matplotlib
          python3-numpy python3-scipy ffmpeg pybind11-dev python3-dev python3-pytest slurm-wlm munge
          zlib1g-dev python3-vtk9)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
echo "softgrain: installing missing Debian packages: ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
