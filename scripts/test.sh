#!/usr/bin/env bash
# Builds everything and runs every test (GoogleTest under CTest). Needs no GPU and no display:
# the GL tests use Mesa's llvmpipe through an EGL surfaceless context.
#
# With CI=true (as .ci/run is run), or when asked locally, also the slower checks of
# docs/FUZZING.md, each after the one before passes:
#   TEST_SANITIZERS=1       the whole suite again, built with ASan and UBSan (scripts/sanitize.sh)
#   TEST_FUZZ_SECONDS=N     every fuzz target for N seconds (scripts/fuzz.sh)
# CI=true means TEST_SANITIZERS=1 TEST_FUZZ_SECONDS=60; set either to 0 to leave it out.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${CI:-}" = true ]; then
  sanitizers=${TEST_SANITIZERS:-1} fuzz_seconds=${TEST_FUZZ_SECONDS:-60}
else
  sanitizers=${TEST_SANITIZERS:-0} fuzz_seconds=${TEST_FUZZ_SECONDS:-0}
fi
bash scripts/build.sh
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j"$(nproc)")
if [ "$sanitizers" != 0 ]; then
  start=$SECONDS
  bash scripts/sanitize.sh
  echo "test.sh: sanitizer build and suite took $((SECONDS - start)) s"
fi
if [ "$fuzz_seconds" != 0 ]; then
  start=$SECONDS
  bash scripts/fuzz.sh "$fuzz_seconds"
  echo "test.sh: fuzz build and runs took $((SECONDS - start)) s"
fi
