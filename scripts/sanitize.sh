#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer build of the ROS-free core and
# every unit test, run with ctest. Any sanitizer report aborts the test that
# made it (-fno-sanitize-recover=all, halt_on_error), so the script fails on
# the first report. The standard library checks every index too
# (_GLIBCXX_ASSERTIONS): a read one past a vector's end within its capacity
# is no heap overflow to AddressSanitizer. Idempotent: re-running reuses and refreshes the build in
# <repo>/.build/asan (or $COLLISION2D_BUILD_ROOT/asan).
#
# Usage: scripts/sanitize.sh            (from anywhere; needs cmake, g++, gtest,
#                                        eigen, yaml-cpp; no ROS)
# Tests that would run too long under the sanitizers read
# COLLISION2D_SANITIZER_BUILD=1 (set here) and shrink, printing the reduced size.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${COLLISION2D_BUILD_ROOT:-$ROOT/.build}/asan"
JOBS="${COLLISION2D_JOBS:-2}"
SANITIZE_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all -D_GLIBCXX_ASSERTIONS"

log() { printf '[sanitize] %s\n' "$*" >&2; }

log "configuring $BUILD_DIR"
# -O1 -g1: about half the compile time of RelWithDebInfo's -O2 -g, and the
# reports still name each frame's function, file and line.
cmake -S "$ROOT" -B "$BUILD_DIR" \
  -DCOLLISION2D_WITH_ROS=OFF \
  -DCOLLISION2D_WITH_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_CXX_FLAGS="$SANITIZE_FLAGS" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null

log "building (-j$JOBS)"
cmake --build "$BUILD_DIR" -j"$JOBS"

# halt_on_error/abort_on_error turn every report into a failing test;
# leak checking is on so a leak fails the same way.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export COLLISION2D_SANITIZER_BUILD=1

log "running the unit tests"
status=0
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$JOBS" || status=$?
if [[ $status -ne 0 ]]; then
  log "FAILED: a unit test failed or a sanitizer reported (see above)"
  exit "$status"
fi
log "clean: every unit test passed under AddressSanitizer and UndefinedBehaviorSanitizer"
