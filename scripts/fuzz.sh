#!/usr/bin/env bash
# Builds the libFuzzer targets in fuzz/ with clang (-fsanitize=fuzzer,address,
# undefined) and runs each for the given number of seconds (default 60),
# starting from the seed corpus in fuzz/corpus/<target> plus the shipped
# scenarios and scenes, up to COLLISION2D_JOBS (default 2) targets at a
# time. Prints executions and crashes per target and fails when any target
# crashed (the reproducer is kept in <repo>/.build/fuzz/artifacts/<target>/;
# turn it into a regression test in test/unit/). Idempotent: reuses
# <repo>/.build/fuzz and its grown corpora.
#
# Usage: scripts/fuzz.sh [--with-ros devel-space] [seconds-per-target]
#        --with-ros also builds and runs the ROS conversion's target
#        (scripts/fuzz_ros.sh) in the same pool, against that catkin devel space
#        scripts/fuzz.sh --library   (only builds the instrumented core
#        library, <build>/build/libfuzz_collision2d.a, for scripts/fuzz_ros.sh)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
LIBRARY_ONLY=0
ROS_DEVEL=""
ROS_TARGET=fuzz_ros_conversion
if [[ ${1:-} == --library ]]; then
  LIBRARY_ONLY=1
  shift
elif [[ ${1:-} == --with-ros ]]; then
  ROS_DEVEL="${2:?--with-ros needs a devel space}"
  shift 2
fi
SECONDS_PER_TARGET="${1:-60}"
BUILD_DIR="${COLLISION2D_BUILD_ROOT:-$ROOT/.build}/fuzz"
JOBS="${COLLISION2D_JOBS:-2}"
TARGETS=(fuzz_scenario fuzz_scene_yaml fuzz_solve)
# Per-input limits: a single input running longer or using more memory than
# this is reported by libFuzzer as a crash (timeout / out of memory).
INPUT_TIMEOUT_S=20
RSS_LIMIT_MB=2048
MAX_INPUT_BYTES=4096
# A fixed seed makes a run repeatable: the same mutations in the same order, so
# a machine that runs the same seconds or fewer (CI on a clean clone) explores
# no input that a clean run here did not. COLLISION2D_FUZZ_SEED=0 draws a fresh
# seed each run, for longer bug hunts.
SEED="${COLLISION2D_FUZZ_SEED:-1}"

log() { printf '[fuzz] %s\n' "$*" >&2; }

[[ $SECONDS_PER_TARGET =~ ^[0-9]+$ && $SECONDS_PER_TARGET -gt 0 ]] ||
  { log "usage: $0 [seconds-per-target > 0]"; exit 2; }
command -v clang++ >/dev/null || { log "clang++ not found (install clang and libclang-rt-dev)"; exit 2; }

log "configuring $BUILD_DIR with clang++"
cmake -S "$ROOT/fuzz" -B "$BUILD_DIR/build" -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
if [[ $LIBRARY_ONLY -eq 1 ]]; then
  log "building the core library (-j$JOBS)"
  cmake --build "$BUILD_DIR/build" -j"$JOBS" --target fuzz_collision2d >/dev/null
  exit 0
fi
log "building (-j$JOBS)"
cmake --build "$BUILD_DIR/build" -j"$JOBS" --target "${TARGETS[@]}"
POOL=("${TARGETS[@]}")
if [[ -n $ROS_DEVEL ]]; then
  "$ROOT/scripts/fuzz_ros.sh" --build-only "$SECONDS_PER_TARGET" "$ROS_DEVEL"
  POOL+=("$ROS_TARGET")
fi

# Extra read-only seed folders per target (libFuzzer adds new inputs to the
# first corpus folder only).
extra_seeds() {
  case "$1" in
    fuzz_scenario) echo "$ROOT/config/scenarios" ;;
    fuzz_scene_yaml) echo "$ROOT/config/scenes" ;;
  esac
}

export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# Runs one target; its one-line summary ("<target>: ok ..." or "<target>:
# FAILED ...") goes to $BUILD_DIR/<target>.summary.
run_target() {
  local target=$1
  if [[ $target == "$ROS_TARGET" ]]; then
    "$ROOT/scripts/fuzz_ros.sh" --run-only "$SECONDS_PER_TARGET" "$ROS_DEVEL" \
      >"$BUILD_DIR/$target.summary" 2>"$BUILD_DIR/$target.log" || true
    return
  fi
  local corpus="$BUILD_DIR/corpus/$target" artifacts="$BUILD_DIR/artifacts/$target"
  local output="$BUILD_DIR/$target.log" status=0 seeds extra executions crashes
  mkdir -p "$corpus" "$artifacts"
  seeds=("$ROOT/fuzz/corpus/$target")
  extra="$(extra_seeds "$target")"
  [[ -n $extra && -d $extra ]] && seeds+=("$extra")
  "$BUILD_DIR/build/$target" -seed="$SEED" -max_total_time="$SECONDS_PER_TARGET" -timeout="$INPUT_TIMEOUT_S" \
    -rss_limit_mb="$RSS_LIMIT_MB" -max_len="$MAX_INPUT_BYTES" -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$corpus" "${seeds[@]}" >"$output" 2>&1 || status=$?
  executions="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$output" | grep -o '[0-9]*$' | tail -1)"
  # Only this run's reproducers count: older ones stay for inspection.
  crashes="$(grep -c '^artifact_prefix=\|Test unit written to' "$output" || true)"
  if [[ $status -ne 0 ]]; then
    echo "$target: FAILED (exit $status), ${executions:-?} executions, ${crashes} crash input(s) in $artifacts" \
      >"$BUILD_DIR/$target.summary"
  else
    echo "$target: ok (seed $SEED), ${executions:-?} executions, 0 crashes, corpus $(find "$corpus" -type f | wc -l) inputs" \
      >"$BUILD_DIR/$target.summary"
  fi
}

# The targets share nothing, so up to $JOBS run at once (each is one process
# on one core): the run takes about ceil(targets / jobs) times the seconds.
for target in "${POOL[@]}"; do
  rm -f "$BUILD_DIR/$target.summary"
  while [[ $(jobs -rp | wc -l) -ge $JOBS ]]; do
    wait -n || true
  done
  log "running $target for ${SECONDS_PER_TARGET}s"
  run_target "$target" &
done
wait

failed=0
for target in "${POOL[@]}"; do
  # A run that died before writing its summary failed too.
  if ! grep -q "^$target: ok" "$BUILD_DIR/$target.summary" 2>/dev/null; then
    failed=1
    tail -n 60 "$BUILD_DIR/$target.log" >&2
  fi
done
for target in "${POOL[@]}"; do
  cat "$BUILD_DIR/$target.summary" 2>/dev/null || echo "$target: FAILED (no summary)"
done
if [[ $failed -ne 0 ]]; then
  log "FAILED: a target crashed (see the reproducers above)"
  exit 1
fi
log "no crashes"
