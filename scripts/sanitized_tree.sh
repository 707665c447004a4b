# shellcheck shell=bash
# The one sanitized build tree, build-asan/, that scripts/sanitize.sh (the whole suite) and
# scripts/fuzz.sh (the libFuzzer targets) share (sourced, not run): clang 16 with ASan and UBSan,
# and PATINA_FUZZ, so the engine's layers carry libFuzzer's coverage and are compiled once for
# both. docs/FUZZING.md.
sanitized_dir=build-asan
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-/usr/lib/llvm-16/bin/llvm-symbolizer}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}

configure_sanitized_tree() {
  cmake -S . -B "$sanitized_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-16 \
    -DPATINA_FUZZ=ON -DPATINA_PRECOMPILE_HEADERS=ON >/dev/null
}
