#!/usr/bin/env bash
# Builds everything, the test suite included, with clang 16, AddressSanitizer (with its leak
# checker) and UndefinedBehaviorSanitizer into build-asan/, and runs every test under CTest.
# Tests that run `patina` run the sanitized program. Any report fails the test it happens in.
# docs/FUZZING.md.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --sanitizers
build_dir=build-asan
# Exported before the build too: test discovery runs the test programs.
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-/usr/lib/llvm-16/bin/llvm-symbolizer}
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-16 -DPATINA_SANITIZE=ON
cmake --build "$build_dir" -j"$(nproc)"
cd "$build_dir"
ctest --output-on-failure -j"$(nproc)"
