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
# LLVM 16's __tls_get_addr interceptor can take a heap block of a dlopen'ed library's dynamic
# TLS (Mesa's) for a glibc 2.19 TLS header when it lands at a certain page offset, and the leak
# checker's tracer then crashes reading the bogus range ("Tracer caught signal 11"), depending
# only on memory layout (google/sanitizers#1322). Off, the leak checker still scans static TLS.
export ASAN_OPTIONS="intercept_tls_get_addr=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-16 -DPATINA_SANITIZE=ON
cmake --build "$build_dir" -j"$(nproc)"
cd "$build_dir"
ctest --output-on-failure -j"$(nproc)"
