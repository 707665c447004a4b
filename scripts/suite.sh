#!/usr/bin/env bash
# Runs the test suite of a build tree (default build/) under CTest and exits non-zero if any test
# fails. The window tests (label `window`: each starts its own Xvfb and editor, drives it and
# mostly waits for its frames) run one at a time beside the others, which run one per core,
# instead of after them. The window tests run at a higher priority (nice -10) where that is
# allowed (root): their frames then come about as fast as when they run alone, even on a busy
# machine. Elsewhere nice says it cannot and they run at the usual priority. Their output follows
# the others'.
set -euo pipefail
cd "$(dirname "$0")/.."
cd "${1:-build}"
nice -n -10 ctest --output-on-failure -L window >window-tests.log 2>&1 &
window=$!
status=0
ctest --output-on-failure -j"$(nproc)" -LE window || status=1
wait "$window" || status=1
echo "The window tests:"
cat window-tests.log
exit $status
