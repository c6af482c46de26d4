#!/usr/bin/env bash
# Installs what is missing, builds softgrain with warnings as errors and the heavy
# validation checks on, and runs the whole test suite (ctest + GoogleTest, the scenario
# fuzzer included).
# Then, in CI (CI=true) or with SOFTGRAIN_SANITIZE_PASS=1, the sanitizer pass: a second build
# (build-asan/, at -O1) with AddressSanitizer + UBSan of the program, the fuzzer and the fast
# test modules, which it runs (any sanitizer report aborts the process and fails its test);
# the same build links softgrain_odr_check, whose link fails on any one-definition-rule
# violation (GCC's -Wodr under link-time optimization). SOFTGRAIN_SANITIZE_PASS=0 skips it.
# Both builds go through a compiler cache kept outside the clone (scripts/build-env.sh).
# Times on a 2-core machine: docs/architecture.md, "Developing softgrain".
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
source scripts/build-env.sh
started=$SECONDS
phase() { echo "softgrain test.sh: $1 ($((SECONDS - started)) s since start)"; }

build=${SOFTGRAIN_BUILD_DIR:-build-test}
# shellcheck disable=SC2046 # generator_args prints one word or nothing
cmake -S . -B "$build" $(generator_args "$build") "${cmake_configure_args[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DSOFTGRAIN_WERROR=ON -DSOFTGRAIN_VALIDATE=ON
cmake --build "$build" -j"$(nproc)"
phase "normal build done"
OMP_WAIT_POLICY=PASSIVE ctest --test-dir "$build" --output-on-failure -j"$(nproc)" --timeout 900
phase "normal tests done"

default_pass=0
[[ "${CI:-}" == true ]] && default_pass=1
if [[ "${SOFTGRAIN_SANITIZE_PASS:-$default_pass}" != 1 ]]; then exit 0; fi
asan=${SOFTGRAIN_ASAN_BUILD_DIR:-build-asan}
# The modules whose tests take seconds (the solver, scenario and render suites run whole
# simulations: minutes under the sanitizers), and the fuzzer.
fast_modules=(test_geometry test_meshfree test_material test_model test_contact test_io test_run
              test_analysis test_campaign)
# shellcheck disable=SC2046
cmake -S . -B "$asan" $(generator_args "$asan") "${cmake_configure_args[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DSOFTGRAIN_WERROR=ON -DSOFTGRAIN_SANITIZE=ON -DSOFTGRAIN_ODR_CHECK=ON
cmake --build "$asan" -j"$(nproc)" --target softgrain scenario_fuzzer softgrain_odr_check \
  "${fast_modules[@]}"
phase "sanitizer build and one-definition-rule check done"
labels=$(IFS='|'; echo "fuzz|odr|${fast_modules[*]}")
# Tests of those modules left to the normal pass: they measure (the planner's projected wall
# time against a run's own), or repeat under the sanitizers code that faster tests of the pass
# already cover (whole campaigns with their figures, the largest packing); each took minutes
# under ASan, together about 4 of the pass's 11 CPU minutes.
# The brute-force check of the periodic broad phase and the Fourier-grain packing (51 and 48 s
# under ASan) repeat code that the non-periodic brute-force check and the other packings of the
# pass run in seconds.
slow_under_sanitizers=('CampaignPlan\.ProjectedWallTime' 'PaperCampaign\.ATinyCampaign'
                       'CampaignFigures\.TheExampleCampaign'
                       'Packing\.Paper003Mixture' 'PressureExamples\.TheServoLoads'
                       'PressureExamples\.TheExampleCampaignsPlan'
                       'BroadPhase\.NoMissedPairVersusBruteForcePeriodic'
                       'Packing\.FourierGrainsInABoxWithAGap')
excluded=$(IFS='|'; echo "${slow_under_sanitizers[*]}")
ASAN_OPTIONS=abort_on_error=1:detect_leaks=1 \
  UBSAN_OPTIONS=halt_on_error=1:abort_on_error=1:print_stacktrace=1 \
  OMP_WAIT_POLICY=PASSIVE SOFTGRAIN_FUZZ_TIMEOUT=300 \
  ctest --test-dir "$asan" --output-on-failure -j"$(nproc)" --timeout 900 -L "^($labels)\$" \
  -E "$excluded"
phase "sanitizer tests done"
