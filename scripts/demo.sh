#!/usr/bin/env bash
# Installs what is missing, builds softgrain (Release), and runs the default example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
source scripts/build-env.sh
# shellcheck disable=SC2046 # generator_args prints one word or nothing
cmake -S . -B build $(generator_args build) "${cmake_configure_args[@]}" -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target softgrain
./build/app/softgrain run examples/shear-cell-small.toml
