#!/usr/bin/env bash
# The main job: build, then render the embedded default scene to patina-default.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./"${BUILD_DIR:-build}"/app/patina render --width 800 --height 800 --out patina-default.png
echo "wrote $(pwd)/patina-default.png"
