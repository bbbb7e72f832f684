#!/usr/bin/env bash
# Regenerates the performance report in one command: builds the benchmarks
# (ROS-free, Release), runs the speed/accuracy sweep with the peers (and
# times the runs its time target compares again, in paired rounds), the
# solver residual sweep, the stack scenes against every peer and the
# scaling runs and the throughput runs (pyramid and rain, 1 and 2 workers;
# one process per size, for the peak memory; then stepped on a clock, as a
# ROS timer steps a world, and beside a process that keeps a core busy),
# then writes
# docs/perf/*.csv, docs/perf/*.png (gnuplot) and docs/performance.md.
# Ours runs in both pipelines (soft step and Fx2D, each set explicitly) in
# the sweep and the stacks; the report follows whichever is the default.
#
#   scripts/performance_report.sh [--quick] [--no-build]
#
# --quick thins every grid and shortens the long runs (about five minutes
# instead of about twenty-five on two cores, most of it the stacks' 60 s runs
# in every engine). Environment: COLLISION2D_PERF_BUILD (build folder, default
# .build/perf), COLLISION2D_JOBS (default 2), COLLISION2D_BOX2D_V3_DIR
# (optional: a Box2D v3 checkout with its Release static library built under
# it, in build/src/, lib/ or src/, made by you in a scratch folder outside
# this repository; Box2D v3 then joins the peer sweep, the stacks and the
# scaling runs as a third peer, and the report says so) and
# COLLISION2D_BOX2D_V3_LIBRARY (that library's path, if it is elsewhere).
# Without them the report is made without Box2D v3.
# Installs what it needs when missing (apt: the package's build dependencies,
# Box2D and Chipmunk as peers, gnuplot); needs root or sudo for that.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${COLLISION2D_PERF_BUILD:-$ROOT/.build/perf}"
JOBS="${COLLISION2D_JOBS:-2}"
OUT="$ROOT/docs/perf"
QUICK=()
BUILD_FIRST=1
SCALING_SIZES=(100 1000 10000 100000)
THROUGHPUT_SIZES=(100 1000 10000 100000)
# Settled pyramids (sleeping on) up to base 100: larger ones do not fall asleep in 10 s.
RESTING_SIZES=(1000 5050)
THROUGHPUT_ROUNDS=7  # the report reads the count back from scaling.csv
SCALING_ENGINES=(collision2d box2d chipmunk)
BOX2D_V3_DIR="${COLLISION2D_BOX2D_V3_DIR:-}"
BOX2D_V3_LIBRARY="${COLLISION2D_BOX2D_V3_LIBRARY:-}"
STACK_SECONDS=10,60
STACK_REPS=5
# Worlds stepped on a clock: one frame every 1/60, 1/30 and 1/10 s.
PACED_PERIODS_MS=(16.667 33.333 100)
PACED_ROUNDS=3
# Worlds stepped beside another process that keeps a core busy (a shell loop).
BUSY_ROUNDS=3

for arg in "$@"; do
  case "$arg" in
    --quick) QUICK=(--quick); STACK_SECONDS=10; STACK_REPS=3; THROUGHPUT_SIZES=(100 1000 10000); PACED_ROUNDS=1; BUSY_ROUNDS=1 ;;
    --no-build) BUILD_FIRST=0 ;;
    *) echo "usage: $0 [--quick] [--no-build]" >&2; exit 2 ;;
  esac
done

# shellcheck source=scripts/common.sh
source "$ROOT/scripts/common.sh"
log() { printf '[performance] %s\n' "$*" >&2; }

# What the report needs beyond the package's own build dependencies: the
# plotter and the two peers (installed only when missing).
install_apt_packages "${SYSTEM_PACKAGES[@]}" gnuplot-nox python3
for tool in cmake gnuplot "$SYSTEM_PYTHON"; do
  command -v "$tool" > /dev/null || { log "error: $tool is required"; exit 1; }
done

if [[ $BUILD_FIRST == 1 ]]; then
  log "building in $BUILD"
  # A fresh clone has no build folder yet, and the configure log goes beside it.
  mkdir -p "$BUILD"
  # Passed even when empty, so a folder configured with Box2D v3 before drops it.
  cmake -S "$ROOT" -B "$BUILD" -DCOLLISION2D_WITH_ROS=OFF -DCMAKE_BUILD_TYPE=Release \
    -DCOLLISION2D_BOX2D_V3_DIR="$BOX2D_V3_DIR" -DCOLLISION2D_BOX2D_V3_LIBRARY="$BOX2D_V3_LIBRARY" \
    > "$BUILD.cmake.log" 2>&1 || { cat "$BUILD.cmake.log" >&2; exit 1; }
  grep "Box2D v3" "$BUILD.cmake.log" >&2 || true
  cmake --build "$BUILD" -j"$JOBS" --target collision2d_sweep_bench collision2d_scaling_bench collision2d_stack_bench
fi
# Every single-threaded run (ours with 1 worker and every peer) goes to the
# same core: on a virtual machine the cores can differ in speed, and a run
# left to the scheduler lands on either (docs/performance.md, *Timing*).
# COLLISION2D_PERF_CPU picks the core; the default is the last one.
ONE_CORE=()
PERF_CPU=""
if command -v taskset > /dev/null && (( $(nproc) > 1 )); then
  PERF_CPU="${COLLISION2D_PERF_CPU:-$(( $(nproc) - 1 ))}"
  ONE_CORE=(taskset -c "$PERF_CPU")
fi
# Runs a command on that core (where it lands when none was chosen).
on_one_core() { ${ONE_CORE[@]+"${ONE_CORE[@]}"} "$@"; }
# A run on $1 workers: one worker on the pinned core, more on every core.
on_workers() {
  local workers=$1
  shift
  if (( workers == 1 )); then on_one_core "$@"; else "$@"; fi
}
SWEEP="$BUILD/bench/collision2d_sweep_bench"
SCALING="$BUILD/bench/collision2d_scaling_bench"
STACK="$BUILD/bench/collision2d_stack_bench"
THROUGHPUT_ENGINES=(collision2d)
if [[ -n $BOX2D_V3_DIR ]]; then
  SCALING_ENGINES+=(box2d_v3)
  THROUGHPUT_ENGINES+=(box2d_v3)
fi
mkdir -p "$OUT"
START=$(date +%s)
PART_START=$START
# Logs how long the part just finished took (for the time budget).
part_done() { local now; now=$(date +%s); log "$1 took $(( now - PART_START )) s"; PART_START=$now; }
# Throughput rounds: at every throughput size ours with 1 worker, then 2,
# then Box2D v3 the same way when it is built in (its own scheduler on 2).
# They are spread over the run (before the sweep, between the long parts
# and at the end), so a spell in which the machine's second core is slow
# reaches only some of them; the rows go into scaling.csv at the end.
THROUGHPUT_ROWS="$BUILD/throughput_rounds.csv"
: > "$THROUGHPUT_ROWS"
ROUNDS_RUN=0
throughput_rounds() {  # $1: how many rounds to run now
  local round scene n workers
  for (( round = 0; round < $1 && ROUNDS_RUN < THROUGHPUT_ROUNDS; round++ )); do
    for scene in pyramid rain; do
      for n in "${THROUGHPUT_SIZES[@]}"; do
        for engine in "${THROUGHPUT_ENGINES[@]}"; do
          for workers in 1 2; do
            on_workers "$workers" "$SCALING" --scene "$scene" --bodies "$n" --engine "$engine" --workers "$workers" \
              2>> "$BUILD/scaling.log" | grep "^$engine," >> "$THROUGHPUT_ROWS" ||
              log "throughput: $engine at $scene $n, $workers workers, not measured"
          done
        done
      done
    done
    ROUNDS_RUN=$(( ROUNDS_RUN + 1 ))
  done
}

log "throughput: ours${BOX2D_V3_DIR:+ and Box2D v3} with 1 and 2 workers, the first rounds (the others follow the long parts)"
throughput_rounds 2
part_done "throughput rounds"

log "sweep: our knobs in both pipelines, the peers and the 60 s stacks (progress in $BUILD/sweep.log)"
on_one_core "$SWEEP" world peers stand "${QUICK[@]}" --out "$OUT/runs.csv" 2> "$BUILD/sweep.log" || { tail "$BUILD/sweep.log" >&2; exit 1; }
part_done sweep

log "paired rounds: our cheapest runs at each peer run's error and that run, timed again in turns"
# The sweep times each run once, minutes apart; the time target takes each
# round's own ratio (scripts/report_pairs.py says which runs and why).
PAIRED_ROUNDS=7
if (( ${#QUICK[@]} > 0 )); then PAIRED_ROUNDS=3; fi
"$SYSTEM_PYTHON" "$ROOT/scripts/report_pairs.py" "$OUT/runs.csv" > "$BUILD/paired_keys.tsv"
echo "scene,round,key,ms_per_step,cpu_ms_per_step" > "$OUT/paired.csv"
while IFS=$'\t' read -r -a line; do
  keys=()
  for key in "${line[@]:1}"; do keys+=(--key "$key"); done
  on_one_core "$SWEEP" paired --scene "${line[0]}" "${keys[@]}" --rounds "$PAIRED_ROUNDS" ${QUICK[@]+"${QUICK[@]}"} \
    --out "$BUILD/paired_scene.csv" 2>> "$BUILD/paired.log" || { tail "$BUILD/paired.log" >&2; exit 1; }
  tail -n +2 "$BUILD/paired_scene.csv" >> "$OUT/paired.csv"
done < "$BUILD/paired_keys.tsv"
part_done "paired rounds"
throughput_rounds 2
part_done "throughput rounds"

log "solver residuals on random islands"
on_one_core "$SWEEP" solver "${QUICK[@]}" --out "$OUT/solver.csv" 2> "$BUILD/solver.log" || { tail "$BUILD/solver.log" >&2; exit 1; }
part_done solver

log "stacks: ours (both pipelines) and every peer built in, ${STACK_SECONDS} s"
on_one_core "$STACK" --seconds "$STACK_SECONDS" --reps "$STACK_REPS" --soft-step both --csv "$OUT/stacks.csv" > "$BUILD/stacks.md" \
  2> "$BUILD/stacks.log" || { tail "$BUILD/stacks.log" >&2; exit 1; }
part_done stacks
throughput_rounds 2
part_done "throughput rounds"

log "scaling: one process per engine and size"
"$SCALING" --header > "$OUT/scaling.csv"
for n in "${SCALING_SIZES[@]}"; do
  for engine in "${SCALING_ENGINES[@]}"; do
    # The packaged Chipmunk prints a banner on stdout: keep the CSV rows only.
    on_one_core "$SCALING" --bodies "$n" --engine "$engine" 2>> "$BUILD/scaling.log" | grep "^$engine," >> "$OUT/scaling.csv" ||
      log "scaling: $engine at $n bodies not measured (not built in?)"
  done
done
part_done scaling

log "throughput: pyramid and rain, ours${BOX2D_V3_DIR:+ and Box2D v3} with 1 and 2 workers (the last rounds)"
throughput_rounds "$THROUGHPUT_ROUNDS"  # the rounds left
cat "$THROUGHPUT_ROWS" >> "$OUT/scaling.csv"

log "resting: settled pyramids, alone and with one moving body, sleeping on${BOX2D_V3_DIR:+, and Box2D v3}"
for n in "${RESTING_SIZES[@]}"; do
  # The same pyramid awake, where the throughput sizes do not have it.
  scenes=(resting stirred)
  [[ " ${THROUGHPUT_SIZES[*]} " == *" $n "* ]] || scenes+=(pyramid)
  for scene in "${scenes[@]}"; do
    for engine in collision2d ${BOX2D_V3_DIR:+box2d_v3}; do
      on_one_core "$SCALING" --scene "$scene" --bodies "$n" --engine "$engine" 2>> "$BUILD/scaling.log" |
        grep "^$engine," >> "$OUT/scaling.csv" || log "resting: $engine $scene at $n not measured"
    done
  done
done
part_done throughput

log "paced: ours with 1 and 2 workers at 1e4 bodies, one frame every ${PACED_PERIODS_MS[*]} ms"
"$SCALING" --header > "$OUT/paced.csv"
for (( round = 0; round < PACED_ROUNDS; round++ )); do
  for period in "${PACED_PERIODS_MS[@]}"; do
    for scene in pyramid rain; do
      for workers in 1 2; do
        on_workers "$workers" "$SCALING" --scene "$scene" --bodies 10000 --workers "$workers" --period-ms "$period" \
          2>> "$BUILD/scaling.log" | grep "^collision2d," >> "$OUT/paced.csv" ||
          log "paced: $scene, $workers workers, every $period ms, not measured"
      done
    done
  done
done
part_done paced

# Another process keeping the core the pinned runs do not use busy, as
# another node on the robot's computer would: 1 worker on the pinned core
# (untouched by it), 2 workers on both. The busy core is a column of the rows.
BUSY_CPU=""
if [[ -n $PERF_CPU ]]; then
  for (( cpu = 0; cpu < $(nproc); cpu++ )); do
    if (( cpu != PERF_CPU )); then BUSY_CPU=$cpu; break; fi
  done
fi
if [[ -n $BUSY_CPU ]]; then
  log "busy core: pyramid and rain at 1e4 bodies, 1 and 2 workers, a shell loop busy on core $BUSY_CPU"
  echo "$("$SCALING" --header),busy_cpu" > "$OUT/busy.csv"
  taskset -c "$BUSY_CPU" sh -c 'while :; do :; done' &
  BUSY_PID=$!
  trap 'kill "$BUSY_PID" 2> /dev/null || true' EXIT
  for (( round = 0; round < BUSY_ROUNDS; round++ )); do
    for scene in pyramid rain; do
      for engine in "${THROUGHPUT_ENGINES[@]}"; do
        for workers in 1 2; do
          on_workers "$workers" "$SCALING" --scene "$scene" --bodies 10000 --engine "$engine" --workers "$workers" \
            2>> "$BUILD/scaling.log" | grep "^$engine," | sed "s/\$/,$BUSY_CPU/" >> "$OUT/busy.csv" ||
            log "busy core: $engine $scene, $workers workers, not measured"
        done
      done
    done
  done
  kill "$BUSY_PID" 2> /dev/null || true
  wait "$BUSY_PID" 2> /dev/null || true
  trap - EXIT
  part_done "busy core"
else
  rm -f "$OUT/busy.csv"  # no second core: no rows from an earlier run either
fi

ELAPSED=$(( $(date +%s) - START ))
log "measured in ${ELAPSED} s; writing plots and docs/performance.md"
# The renderer needs only the standard library; the system interpreter, not
# whichever python3 comes first on PATH.
"$SYSTEM_PYTHON" "$ROOT/scripts/performance_report.py" --perf-dir "$OUT" --doc "$ROOT/docs/performance.md" \
  --elapsed "$ELAPSED" ${PERF_CPU:+--pinned-cpu "$PERF_CPU"} ${QUICK[@]+"${QUICK[@]}"}
log "done: docs/performance.md"
