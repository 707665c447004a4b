#!/usr/bin/env bash
# Installs what is missing (scripts/setup.sh), then configures and builds into build/: every
# target, or only the targets named (`bash scripts/build.sh patina` builds the program without
# the test suite). BUILD_DIR and CMAKE_BUILD_TYPE override the defaults. Prints each step's time
# (scripts/stages.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/stages.sh
source scripts/stages.sh
trap stage_summary EXIT
stage setup bash scripts/setup.sh
build_dir=${BUILD_DIR:-build}
stage configure cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="${CMAKE_BUILD_TYPE:-Release}"
targets=()
for target in "$@"; do
  targets+=(--target "$target")
done
stage build cmake --build "$build_dir" -j"$(nproc)" "${targets[@]}"
