#!/usr/bin/env bash
# Second README command: install what the package needs, build it and run every
# test: sanitizer and fuzz runs, then gtest and rostest through catkin. Closes with "N passed, M failed" and
# fails when a test failed or none ran.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# Each phase prints its wall time as it ends: where a run spends its minutes.
took() { log "$1: $((SECONDS - $2)) s"; }

started=$SECONDS
install_and_build
took "installing and building" "$started"
RESULTS_DIR="$COLLISION2D_WS/build/test_results"
# Results of an earlier run must not be counted again.
rm -rf "$RESULTS_DIR"

# Checks outside catkin's test runner: the performance report's ratio
# arithmetic (scripts/test_*.py), every unit test of the ROS-free core
# under AddressSanitizer and UndefinedBehaviorSanitizer, the multi-worker
# tests under ThreadSanitizer, and a bounded run of
# each libFuzzer target (core parsers and solve, and the ROS message
# conversion). They run first so the last line stays the test summary.
FUZZ_SECONDS="${COLLISION2D_FUZZ_SECONDS:-30}"
extra_failures=()
run_check() {
  local name=$1 started=$SECONDS
  shift
  log "running $name"
  "$@" || extra_failures+=("$name")
  took "$name" "$started"
}
run_check "the performance report's scripts (unit tests)" \
  "$SYSTEM_PYTHON" -m unittest discover -s "$COLLISION2D_ROOT/scripts" -p 'test_*.py'
run_check "sanitizers (ASan + UBSan unit tests)" "$COLLISION2D_ROOT/scripts/sanitize.sh"
run_check "thread sanitizer (the multi-worker tests)" "$COLLISION2D_ROOT/scripts/sanitize.sh" thread
# The ROS conversion's target runs in the core's pool: four targets, two at a time.
run_check "fuzzing the core and the ROS conversion (${FUZZ_SECONDS} s per target)" \
  "$COLLISION2D_ROOT/scripts/fuzz.sh" --with-ros "$COLLISION2D_WS/devel" "$FUZZ_SECONDS"

log "building the tests"
started=$SECONDS
catkin_make_ws tests
took "building the tests" "$started"
# One test at a time: rostests start their own masters and nodes, and the
# timings some tests print are only meaningful on an otherwise idle machine.
log "running the tests"
started=$SECONDS
COLLISION2D_JOBS=1 catkin_make_ws run_tests
took "running the tests" "$started"

status=0
if [[ ${#extra_failures[@]} -gt 0 ]]; then
  log "failed: ${extra_failures[*]}"
  status=1
fi
catkin_test_results "$RESULTS_DIR" >/dev/null || status=$?
"$SYSTEM_PYTHON" "$COLLISION2D_ROOT/scripts/summarize_test_results.py" "$RESULTS_DIR" || status=$?
exit "$status"
