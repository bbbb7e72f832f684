#!/usr/bin/env bash
# Photographs the collision2d demo as a real rviz draws it, on a virtual
# display (Xvfb, software OpenGL), so it works on machines without a screen.
#
#   rviz_screenshot.sh [--frames N | --live SECONDS] OUTPUT.png
#
#   --frames N      (default 45) the world steps only on request: N frames are
#                   stepped, then that frame is photographed and checked with
#                   check_screenshot.py (body-coloured pixels where the world
#                   says the bodies are, none where there is no body). Exits
#                   non-zero when the check fails.
#   --live SECONDS  the world runs in real time; once rviz draws it, the scene
#                   restarts and is photographed SECONDS later (only checked
#                   for being drawn at all).
#
# Needs the package's ROS environment (source devel/setup.bash) and the
# Debian packages rviz, xvfb and imagemagick. Runs its own ROS master on a free
# port, so it neither needs nor disturbs a running roscore.
set -euo pipefail

readonly SCREEN_SIZE=1280x800x24       # matches config/collision2d.rviz's window
readonly START_TIMEOUT_S=60            # master, world node and Xvfb coming up
readonly DRAW_TIMEOUT_S=60             # rviz (software GL) drawing the first frame
readonly POLL_INTERVAL_S=2
readonly NS=/collision2d

frames=45
live_seconds=""
output=""

usage() { sed -n '2,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; exit 2; }
log() { printf '[rviz_screenshot] %s\n' "$*" >&2; }
die() { log "error: $*"; exit 1; }

while [[ $# -gt 0 ]]; do
  case $1 in
    --frames) frames=${2:?}; shift 2 ;;
    --live) live_seconds=${2:?}; shift 2 ;;
    -h|--help) usage ;;
    -*) usage ;;
    *) output=$1; shift ;;
  esac
done
[[ -n $output ]] || usage

for tool in Xvfb rviz import convert roslaunch rosservice rospack; do
  command -v "$tool" >/dev/null ||
    die "'$tool' not found: install the Debian packages rviz, xvfb and imagemagick and source the workspace"
done
package_dir=$(rospack find collision2d) || die "package collision2d not found: source devel/setup.bash"
checker="$package_dir/scripts/check_screenshot.py"
rviz_config="$package_dir/config/collision2d.rviz"

work=$(mktemp -d)
xvfb_pid=""
launch_pid=""
cleanup() {
  # roslaunch shuts its nodes (and its master) down on SIGINT.
  if [[ -n $launch_pid ]] && kill -0 "$launch_pid" 2>/dev/null; then
    kill -INT "$launch_pid" 2>/dev/null || true
    timeout 20 tail --pid="$launch_pid" -f /dev/null 2>/dev/null || kill -KILL "$launch_pid" 2>/dev/null || true
  fi
  if [[ -n $xvfb_pid ]]; then
    kill "$xvfb_pid" 2>/dev/null || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT
# Make a terminating signal run the EXIT trap, so no Xvfb or rviz is left over.
trap 'exit 143' TERM
trap 'exit 130' INT

free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

start_display() {
  # -displayfd: Xvfb picks a free display and writes its number once ready.
  Xvfb -displayfd 3 -screen 0 "$SCREEN_SIZE" -nolisten tcp 3>"$work/display" >"$work/xvfb.log" 2>&1 &
  xvfb_pid=$!
  local waited=0
  until [[ -s $work/display ]]; do
    ((waited++ < START_TIMEOUT_S * 10)) || die "Xvfb did not start: $(cat "$work/xvfb.log")"
    sleep 0.1
  done
  DISPLAY=":$(cat "$work/display")"
  export DISPLAY
  log "virtual display $DISPLAY"
}

start_demo() {
  local port rate
  port=$(free_port)
  export ROS_MASTER_URI="http://127.0.0.1:$port"
  export LIBGL_ALWAYS_SOFTWARE=1
  rate=$([[ -n $live_seconds ]] && echo 60 || echo 0)
  # rviz on Mesa's software GL now and then segfaults while it starts (seen
  # in one CI run: exit -11 a second after "Forcing OpenGl version 0"; none
  # in 8 runs here): roslaunch restarts it, and report_rviz_restarts says so.
  roslaunch -p "$port" collision2d demo.launch rate:="$rate" output:=log rviz_respawn:=true \
    >"$work/roslaunch.log" 2>&1 &
  launch_pid=$!
  local waited=0
  until rosservice list 2>/dev/null | grep -qx "$NS/step_world"; do
    ((waited++ < START_TIMEOUT_S * 2)) ||
      die "the world node did not come up; roslaunch said: $(tail -20 "$work/roslaunch.log")"
    sleep 0.5
  done
}

report_rviz_restarts() {
  local deaths
  deaths=$(grep -c 'rviz-[0-9]*\] process has died' "$work/roslaunch.log" || true)
  if ((deaths > 0)); then
    log "rviz died $deaths time(s) and was restarted by roslaunch"
  fi
}

take_screenshot() {
  import -display "$DISPLAY" -window root "$1"
}

# Steps the frozen world, then photographs it until the checker sees it drawn
# (rviz with software GL takes a few seconds to come up).
photograph_frames() {
  rosservice call "$NS/step_world" "{frames: $frames, dt: 0.0}" >/dev/null
  rosservice call "$NS/get_world" >"$work/state.yaml"
  local deadline=$((SECONDS + DRAW_TIMEOUT_S))
  until take_screenshot "$output" &&
        /usr/bin/python3 "$checker" "$output" "$rviz_config" --state "$work/state.yaml" >"$work/check.txt"; do
    if ((SECONDS >= deadline)); then
      cat "$work/check.txt" >&2
      report_rviz_restarts
      die "rviz did not draw the world within ${DRAW_TIMEOUT_S} s (screenshot: $output)"
    fi
    sleep "$POLL_INTERVAL_S"
  done
  cat "$work/check.txt"
  report_rviz_restarts
}

# Waits for rviz to draw, restarts the scene (the world ran while rviz was
# starting), lets it run live_seconds, then photographs it.
photograph_live() {
  local deadline=$((SECONDS + DRAW_TIMEOUT_S))
  until take_screenshot "$output" &&
        /usr/bin/python3 "$checker" "$output" "$rviz_config" >"$work/check.txt"; do
    ((SECONDS < deadline)) || { cat "$work/check.txt" >&2; die "rviz did not come up within ${DRAW_TIMEOUT_S} s"; }
    sleep "$POLL_INTERVAL_S"
  done
  rosservice call "$NS/reset_world" >/dev/null
  sleep "$live_seconds"
  take_screenshot "$output"
}

mkdir -p "$(dirname "$output")"
start_display
start_demo
if [[ -n $live_seconds ]]; then
  photograph_live
else
  photograph_frames
fi
log "screenshot: $(cd "$(dirname "$output")" && pwd)/$(basename "$output")"
