#!/usr/bin/env bash
# Installs what is missing, builds softgrain with warnings as errors and the heavy
# validation checks on, and runs the whole test suite (ctest + GoogleTest, the scenario
# fuzzer included).
# Then, in CI (CI=true) or with SOFTGRAIN_SANITIZE_PASS=1, it builds once more with
# AddressSanitizer + UBSan (-DSOFTGRAIN_SANITIZE=ON, in build-asan/) and runs the fuzzer and
# the fast test modules under it: any sanitizer report aborts the process and fails its test.
# SOFTGRAIN_SANITIZE_PASS=0 skips that pass (on an idle 2-core machine it adds about 22 minutes
# of build and 7 of tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build=${SOFTGRAIN_BUILD_DIR:-build-test}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSOFTGRAIN_WERROR=ON -DSOFTGRAIN_VALIDATE=ON
cmake --build "$build" -j"$(nproc)"
OMP_WAIT_POLICY=PASSIVE ctest --test-dir "$build" --output-on-failure -j"$(nproc)" --timeout 900

default_pass=0
[[ "${CI:-}" == true ]] && default_pass=1
if [[ "${SOFTGRAIN_SANITIZE_PASS:-$default_pass}" != 1 ]]; then exit 0; fi
asan=${SOFTGRAIN_ASAN_BUILD_DIR:-build-asan}
# The modules whose tests take seconds (the solver, scenario and render suites run whole
# simulations: minutes under the sanitizers), and the fuzzer.
fast_modules=(test_geometry test_meshfree test_material test_model test_contact test_io
              test_analysis test_campaign)
cmake -S . -B "$asan" -DCMAKE_BUILD_TYPE=Release -DSOFTGRAIN_WERROR=ON -DSOFTGRAIN_SANITIZE=ON
cmake --build "$asan" -j"$(nproc)" --target softgrain scenario_fuzzer "${fast_modules[@]}"
labels=$(IFS='|'; echo "fuzz|${fast_modules[*]}")
ASAN_OPTIONS=abort_on_error=1:detect_leaks=1 \
  UBSAN_OPTIONS=halt_on_error=1:abort_on_error=1:print_stacktrace=1 \
  OMP_WAIT_POLICY=PASSIVE SOFTGRAIN_FUZZ_TIMEOUT=300 \
  ctest --test-dir "$asan" --output-on-failure -j"$(nproc)" --timeout 900 -L "^($labels)\$"
