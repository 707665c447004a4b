#!/usr/bin/env bash
# Builds everything and runs every test (GoogleTest under CTest, scripts/suite.sh). Needs no GPU
# and no display: the GL tests use Mesa's llvmpipe through an EGL surfaceless context.
#
# With CI=true (as .ci/run is run), or when asked locally, also the slower checks of
# docs/FUZZING.md, each after the one before passes:
#   TEST_SANITIZERS=1       the whole suite again, built with ASan and UBSan (scripts/sanitize.sh)
#   TEST_FUZZ_SECONDS=N     the fuzz targets for N seconds each on average (scripts/fuzz.sh), in
#                           the sanitizer suite's tree
# CI=true means TEST_SANITIZERS=1 TEST_FUZZ_SECONDS=60; set either to 0 to leave it out.
# Each stage's time is printed as it ends, and all of them at the end (scripts/stages.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/stages.sh
source scripts/stages.sh
trap stage_summary EXIT
if [ "${CI:-}" = true ]; then
  sanitizers=${TEST_SANITIZERS:-1} fuzz_seconds=${TEST_FUZZ_SECONDS:-60}
else
  sanitizers=${TEST_SANITIZERS:-0} fuzz_seconds=${TEST_FUZZ_SECONDS:-0}
fi
bash scripts/build.sh
stage suite bash scripts/suite.sh "${BUILD_DIR:-build}"
if [ "$sanitizers" != 0 ]; then
  bash scripts/sanitize.sh
fi
if [ "$fuzz_seconds" != 0 ]; then
  bash scripts/fuzz.sh "$fuzz_seconds"
fi
