#!/usr/bin/env bash
# The main job: build the patina program (only it: the test suite is scripts/test.sh's), then
# open the editor on the embedded default scene. Without a display (no DISPLAY), render the
# default scene to patina-default.png instead.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh patina
patina=./"${BUILD_DIR:-build}"/app/patina
if [ -n "${DISPLAY:-}" ]; then
  exec "$patina"
fi
echo "run: no DISPLAY, so no editor window; rendering the default scene instead"
"$patina" render --width 800 --height 800 --out patina-default.png
echo "wrote $(pwd)/patina-default.png"
