#!/usr/bin/env bash
# Builds everything and runs every test (GoogleTest under CTest). Needs no GPU and no display:
# the GL tests use Mesa's llvmpipe through an EGL surfaceless context.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd "${BUILD_DIR:-build}"
ctest --output-on-failure -j"$(nproc)"
