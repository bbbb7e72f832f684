#!/usr/bin/env bash
# Sanitizer builds of the ROS-free core and its unit tests. Any report aborts
# the test that made it, so the script fails on the first one.
#
#  address (default): AddressSanitizer + UndefinedBehaviorSanitizer, every
#    unit test through ctest (-fno-sanitize-recover=all, halt_on_error). The
#    standard library checks every index too (_GLIBCXX_ASSERTIONS): a read one
#    past a vector's end within its capacity is no heap overflow to ASan.
#  thread: ThreadSanitizer, the tests that step a world on 2 and 4 workers
#    and those of the worker pool itself. A race between workers (two
#    writing one body, a read against a write) changes no bit of a
#    trajectory, so no golden hash can show it.
#
# Usage: scripts/sanitize.sh [address|thread]   (from anywhere; needs cmake,
#        g++, gtest, eigen, yaml-cpp; no ROS). Re-running reuses the build in
# <repo>/.build/asan or .build/tsan (or under $COLLISION2D_BUILD_ROOT).
# Tests that would run too long under the sanitizers read
# COLLISION2D_SANITIZER_BUILD=1 (set here) and shrink, printing the reduced size.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MODE="${1:-address}"
JOBS="${COLLISION2D_JOBS:-2}"
# Each test binary the thread mode builds, with the tests in it that run
# more than one worker.
THREAD_TESTS=(
  "collision2d_test_world_golden:WorldGoldenRuns.WorkersDoNotChangeTrajectories:WorldGoldenRuns.SharedSoftPassesDoNotChangeTrajectories"
  "collision2d_test_world_sleeping:WorldSleeping.PilesWokenOneByOneMatchFullPasses"
  "collision2d_test_world_resume:WorldResume.ContactsInAnyOrderResumeBitForBitOnSeveralWorkers"
  "collision2d_test_world_out_of_memory:WorldOutOfMemory.FirstStepOnTwoWorkersPutsTheWorldBack"
  "collision2d_test_worker_pool:WorkerPool.*"
)

log() { printf '[sanitize %s] %s\n' "$MODE" "$*" >&2; }

# configure BUILD_DIR COMPILE_FLAGS LINK_FLAGS
configure() {
  log "configuring $1"
  # -O1 -g1: about half the compile time of RelWithDebInfo's -O2 -g, and the
  # reports still name each frame's function, file and line.
  cmake -S "$ROOT" -B "$1" \
    -DCOLLISION2D_WITH_ROS=OFF \
    -DCOLLISION2D_WITH_BENCH=OFF \
    -DCOLLISION2D_UNITY_CORE=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS="$2" \
    -DCMAKE_EXE_LINKER_FLAGS="$3" >/dev/null
}

export COLLISION2D_SANITIZER_BUILD=1

address() {
  local build_dir="${COLLISION2D_BUILD_ROOT:-$ROOT/.build}/asan"
  configure "$build_dir" \
    "-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all -D_GLIBCXX_ASSERTIONS" \
    "-fsanitize=address,undefined"
  log "building (-j$JOBS)"
  cmake --build "$build_dir" -j"$JOBS"
  # halt_on_error/abort_on_error turn every report into a failing test;
  # leak checking is on so a leak fails the same way.
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  log "running the unit tests"
  if ! ctest --test-dir "$build_dir" --output-on-failure -j"$JOBS"; then
    log "FAILED: a unit test failed or a sanitizer reported (see above)"
    exit 1
  fi
  log "clean: every unit test passed under AddressSanitizer and UndefinedBehaviorSanitizer"
}

thread() {
  local build_dir="${COLLISION2D_BUILD_ROOT:-$ROOT/.build}/tsan" entry targets=()
  configure "$build_dir" "-fsanitize=thread" "-fsanitize=thread"
  for entry in "${THREAD_TESTS[@]}"; do
    targets+=("${entry%%:*}")
  done
  log "building ${targets[*]} (-j$JOBS)"
  cmake --build "$build_dir" -j"$JOBS" --target "${targets[@]}"
  export TSAN_OPTIONS="halt_on_error=1:abort_on_error=1:second_deadlock_stack=1"
  for entry in "${THREAD_TESTS[@]}"; do
    local binary="${entry%%:*}" filter="${entry#*:}"
    log "running $binary --gtest_filter=$filter"
    # From the repository root, as ctest runs them (tests read config/).
    if ! (cd "$ROOT" && "$build_dir/$binary" --gtest_filter="$filter" --gtest_brief=1); then
      log "FAILED: $binary (a test failed or ThreadSanitizer reported; see above)"
      exit 1
    fi
  done
  log "clean: the multi-worker tests passed under ThreadSanitizer"
}

case "$MODE" in
  address | thread) "$MODE" ;;
  *) log "usage: $0 [address|thread]"; exit 2 ;;
esac
