#!/usr/bin/env bash
# Builds and runs the libFuzzer target for the ROS face, fuzz/fuzz_ros_conversion.cpp:
# bytes -> ResolveContacts request -> the service's validation, conversion and
# solve. Compiled with clang++ -fsanitize=fuzzer,address,undefined against the
# ROS headers in /usr/include and the message headers catkin generated in a
# devel space (build the package once first, e.g. with scripts/test.sh), and
# linked to the core library the core's fuzz build makes (fuzz/CMakeLists.txt,
# through `scripts/fuzz.sh --library`, which reuses a build already made).
# Prints executions and crashes; fails when the target crashed (the
# reproducer is kept in <build>/artifacts/; turn it into a regression test in
# test/ros/test_conversions.cpp). Idempotent: objects and the grown corpus are
# reused from <repo>/.build/fuzz_ros (or $COLLISION2D_BUILD_ROOT/fuzz_ros), the
# core library from <repo>/.build/fuzz/build.
#
# Usage: scripts/fuzz_ros.sh [--build-only|--run-only] [seconds] [devel-space]
#   --build-only only builds the target; --run-only runs the one built
#                (scripts/fuzz.sh --with-ros runs it beside the core's targets)
#   seconds      run time (default 60)
#   devel-space  catkin devel folder holding include/collision2d/*.h
#                (default $COLLISION2D_DEVEL, else <repo>/.build/ws/devel)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MODE=all
if [[ ${1:-} == --build-only || ${1:-} == --run-only ]]; then
  MODE="${1#--}"
  shift
fi
SECONDS_TO_RUN="${1:-60}"
DEVEL="${2:-${COLLISION2D_DEVEL:-$ROOT/.build/ws/devel}}"
BUILD_DIR="${COLLISION2D_BUILD_ROOT:-$ROOT/.build}/fuzz_ros"
CORE_LIBRARY="${COLLISION2D_BUILD_ROOT:-$ROOT/.build}/fuzz/build/libfuzz_collision2d.a"  # scripts/fuzz.sh --library
JOBS="${COLLISION2D_JOBS:-2}"
TARGET=fuzz_ros_conversion
# Per-input limits: an input running longer or using more memory than this
# is reported by libFuzzer as a crash (timeout / out of memory).
INPUT_TIMEOUT_S=20
RSS_LIMIT_MB=2048
MAX_INPUT_BYTES=4096
# A fixed seed makes a run repeatable: the same mutations in the same order, so
# a machine that runs the same seconds or fewer (CI on a clean clone) explores
# no input that a clean run here did not. COLLISION2D_FUZZ_SEED=0 draws a fresh
# seed each run, for longer bug hunts.
SEED="${COLLISION2D_FUZZ_SEED:-1}"
# The message conversion, validation and ResolveContacts handler (which logs
# a refusal through rosconsole), and the core they call; nothing that needs a
# node or a master.
ROS_SOURCES=(conversions validation settings_conversions reports printable resolve_contacts)
ROS_LIBS=(-lrosconsole -lroscpp_serialization -lrostime -lcpp_common -lyaml-cpp)

log() { printf '[fuzz_ros] %s\n' "$*" >&2; }

[[ $SECONDS_TO_RUN =~ ^[0-9]+$ && $SECONDS_TO_RUN -gt 0 ]] || { log "usage: $0 [seconds > 0] [devel-space]"; exit 2; }
command -v clang++ >/dev/null || { log "clang++ not found (install clang and libclang-rt-dev)"; exit 2; }
[[ -f $DEVEL/include/collision2d/ResolveContacts.h ]] ||
  { log "no generated messages in $DEVEL/include/collision2d: build the package first or pass its devel space"; exit 2; }

# Builds the target (and the core library it links).
build() {
  # The core as the core's fuzz targets link it (same sanitizers and coverage
  # hooks): one build of it, configured in one place, serves both scripts.
  "$ROOT/scripts/fuzz.sh" --library

  sources=()
  for name in "${ROS_SOURCES[@]}"; do
    sources+=("$ROOT/src/ros/$name.cpp")
  done

  # A generated Makefile: make rebuilds only what changed (-MMD tracks headers)
  # and builds the objects in parallel.
  mkdir -p "$BUILD_DIR/obj" "$BUILD_DIR/corpus" "$BUILD_DIR/artifacts"
  makefile="$BUILD_DIR/Makefile"
  {
    echo "CXX := clang++"
    echo "CXXFLAGS := -std=c++17 -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined" \
      "-fno-sanitize-recover=all -I$ROOT/include -I$ROOT/fuzz -I$DEVEL/include -I/usr/include/eigen3"
    objects=()
    for src in "${sources[@]}" "$ROOT/fuzz/$TARGET.cpp"; do
      obj="obj/$(basename "$(dirname "$src")")_$(basename "${src%.cpp}").o"
      objects+=("$obj")
      # The target itself links libFuzzer's main; everything else only its coverage hooks.
      extra="-fsanitize=fuzzer-no-link"
      [[ $src == *"/$TARGET.cpp" ]] && extra="-fsanitize=fuzzer"
      printf '%s: %s\n\t$(CXX) $(CXXFLAGS) %s -MMD -MP -c $< -o $@\n' "$obj" "$src" "$extra"
    done
    printf '%s: %s %s\n\t$(CXX) $(CXXFLAGS) -fsanitize=fuzzer $^ -o $@ %s\n' "$TARGET" "${objects[*]}" "$CORE_LIBRARY" \
      "${ROS_LIBS[*]}"
    echo "-include obj/*.d"
  } >"$makefile.new"
  mv "$makefile.new" "$makefile"
  log "building $BUILD_DIR/$TARGET (-j$JOBS, devel space $DEVEL)"
  make -s -C "$BUILD_DIR" -j"$JOBS" "$TARGET"
}

[[ $MODE == run-only ]] || build
if [[ $MODE == build-only ]]; then
  exit 0
fi

export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
output="$BUILD_DIR/$TARGET.log"
log "running $TARGET for ${SECONDS_TO_RUN}s (log: $output)"
status=0
"$BUILD_DIR/$TARGET" -seed="$SEED" -max_total_time="$SECONDS_TO_RUN" -timeout="$INPUT_TIMEOUT_S" -rss_limit_mb="$RSS_LIMIT_MB" \
  -max_len="$MAX_INPUT_BYTES" -print_final_stats=1 -artifact_prefix="$BUILD_DIR/artifacts/" \
  "$BUILD_DIR/corpus" "$ROOT/fuzz/corpus/$TARGET" >"$output" 2>&1 || status=$?
executions="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$output" | grep -o '[0-9]*$' | tail -1)"
crashes="$(grep -c 'Test unit written to' "$output" || true)"
if [[ $status -ne 0 ]]; then
  tail -n 60 "$output" >&2
  echo "$TARGET: FAILED (exit $status), ${executions:-?} executions, $crashes crash input(s) in $BUILD_DIR/artifacts"
  exit 1
fi
echo "$TARGET: ok (seed $SEED), ${executions:-?} executions, 0 crashes, corpus $(find "$BUILD_DIR/corpus" -type f | wc -l) inputs"
