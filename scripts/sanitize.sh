#!/usr/bin/env bash
# Builds everything, the test suite included, with clang 16, AddressSanitizer (with its leak
# checker) and UndefinedBehaviorSanitizer into build-asan/, and runs every test under CTest.
# Tests that run `patina` run the sanitized program. Any report fails the test it happens in.
# The fuzz targets (scripts/fuzz.sh) are built in the same tree, on the same engine.
# docs/FUZZING.md.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/stages.sh
source scripts/stages.sh
trap stage_summary EXIT
# shellcheck source=scripts/sanitized_tree.sh
source scripts/sanitized_tree.sh
stage "sanitizer setup" bash scripts/setup.sh --sanitizers
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
# LLVM 16's __tls_get_addr interceptor can take a heap block of a dlopen'ed library's dynamic
# TLS (Mesa's) for a glibc 2.19 TLS header when it lands at a certain page offset, and the leak
# checker's tracer then crashes reading the bogus range ("Tracer caught signal 11"), depending
# only on memory layout (google/sanitizers#1322). Off, the leak checker still scans static TLS.
# Both exported before the build: test discovery runs the test programs.
export ASAN_OPTIONS="intercept_tls_get_addr=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
stage "sanitizer configure" configure_sanitized_tree
stage "sanitizer build" cmake --build "$sanitized_dir" -j"$(nproc)"
stage "sanitizer suite" bash scripts/suite.sh "$sanitized_dir"
