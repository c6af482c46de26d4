#!/usr/bin/env bash
# Installs what is missing, builds softgrain (Release), and runs the default example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target softgrain
./build/app/softgrain run examples/shear-cell-small.toml
