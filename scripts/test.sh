#!/usr/bin/env bash
# Second README command: install what the package needs, build it and run every
# test (gtest and rostest through catkin). Closes with "N passed, M failed" and
# fails when a test failed or none ran.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_and_build
RESULTS_DIR="$COLLISION2D_WS/build/test_results"
# Results of an earlier run must not be counted again.
rm -rf "$RESULTS_DIR"

log "building the tests"
catkin_make_ws tests
# One test at a time: rostests start their own masters and nodes, and the
# timings some tests print are only meaningful on an otherwise idle machine.
log "running the tests"
COLLISION2D_JOBS=1 catkin_make_ws run_tests

status=0
catkin_test_results "$RESULTS_DIR" >/dev/null || status=$?
"$SYSTEM_PYTHON" "$COLLISION2D_ROOT/scripts/summarize_test_results.py" "$RESULTS_DIR" || status=$?
exit "$status"
