#!/usr/bin/env bash
# ThreadSanitizer build of the ROS-free core and the unit tests that step a
# world on several workers; runs the tests that compare 1, 2 and 4 workers.
# A data race between workers (two writing one body, a read against a write)
# fails the run even where every trajectory's bits agree, which no golden hash
# can show. Reuses <repo>/.build/tsan (or $COLLISION2D_BUILD_ROOT/tsan).
#
# Usage: scripts/sanitize_threads.sh   (needs cmake, g++, gtest, eigen, yaml-cpp)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${COLLISION2D_BUILD_ROOT:-$ROOT/.build}/tsan"
JOBS="${COLLISION2D_JOBS:-2}"
# Each test binary with the tests in it that run more than one worker.
TESTS=(
  "collision2d_test_world_golden:WorldGoldenRuns.WorkersDoNotChangeTrajectories:WorldGoldenRuns.SharedSoftPassesDoNotChangeTrajectories"
  "collision2d_test_world_sleeping:WorldSleeping.PilesWokenOneByOneMatchFullPasses"
  "collision2d_test_world_resume:WorldResume.ContactsInAnyOrderResumeBitForBitOnSeveralWorkers"
)

log() { printf '[sanitize threads] %s\n' "$*" >&2; }

log "configuring $BUILD_DIR"
cmake -S "$ROOT" -B "$BUILD_DIR" \
  -DCOLLISION2D_WITH_ROS=OFF \
  -DCOLLISION2D_WITH_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_CXX_FLAGS="-fsanitize=thread" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" >/dev/null

targets=()
for entry in "${TESTS[@]}"; do
  targets+=("${entry%%:*}")
done
log "building ${targets[*]} (-j$JOBS)"
cmake --build "$BUILD_DIR" -j"$JOBS" --target "${targets[@]}"

export TSAN_OPTIONS="halt_on_error=1:abort_on_error=1:second_deadlock_stack=1"
export COLLISION2D_SANITIZER_BUILD=1
for entry in "${TESTS[@]}"; do
  binary="${entry%%:*}"
  filter="${entry#*:}"
  log "running $binary --gtest_filter=$filter"
  # Run from the repository root, as ctest does (tests read config/).
  if ! (cd "$ROOT" && "$BUILD_DIR/$binary" --gtest_filter="$filter" --gtest_brief=1); then
    log "FAILED: $binary (a test failed or ThreadSanitizer reported; see above)"
    exit 1
  fi
done
log "clean: the multi-worker tests passed under ThreadSanitizer"
