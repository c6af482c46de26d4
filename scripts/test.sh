#!/usr/bin/env bash
# Installs what is missing, builds softgrain with warnings as errors and the heavy
# validation checks on, and runs the whole test suite (ctest + GoogleTest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build=${SOFTGRAIN_BUILD_DIR:-build-test}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSOFTGRAIN_WERROR=ON -DSOFTGRAIN_VALIDATE=ON
cmake --build "$build" -j"$(nproc)"
OMP_WAIT_POLICY=PASSIVE ctest --test-dir "$build" --output-on-failure -j"$(nproc)" --timeout 900
