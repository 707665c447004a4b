#!/usr/bin/env bash
# Runs the test suite of a build tree (default build/) under CTest and exits non-zero if any test
# fails. The window tests (label `window`: each starts its own Xvfb and editor, drives it and
# mostly waits for its frames) run one at a time beside the others, which run one per core at
# the lowest priority (nice 19): they take the cores the window tests leave idle, and a window
# test's frames come as fast as when it runs alone. Their output follows the others'.
set -euo pipefail
cd "$(dirname "$0")/.."
cd "${1:-build}"
ctest --output-on-failure -L window >window-tests.log 2>&1 &
window=$!
status=0
nice -n 19 ctest --output-on-failure -j"$(nproc)" -LE window || status=1
wait "$window" || status=1
echo "The window tests:"
cat window-tests.log
exit $status
