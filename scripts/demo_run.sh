#!/usr/bin/env bash
# Runs the rviz demo once the package is built and its workspace sourced
# (scripts/demo.sh calls it after the build).
#  - With a display ($DISPLAY set and reachable): roslaunch collision2d
#    demo.launch, rviz in a window, until Ctrl-C.
#  - Without one: the demo runs on a virtual display (Xvfb) for a few seconds,
#    a screenshot of rviz is saved and its path printed.
# COLLISION2D_DEMO_SCREENSHOT names the screenshot file; COLLISION2D_DEMO_SECONDS
# how long the headless world runs before it is taken.
set -euo pipefail

SCRIPTS_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO_ROOT="$(dirname "$SCRIPTS_DIR")"
SCREENSHOT="${COLLISION2D_DEMO_SCREENSHOT:-${COLLISION2D_BUILD_ROOT:-$REPO_ROOT/.build}/demo_screenshot.png}"
# Seconds of the scene before the screenshot: the thrown box (11 m from the
# pyramid at 12 m/s) has hit it and the disks are mid-bounce.
HEADLESS_SECONDS="${COLLISION2D_DEMO_SECONDS:-1.5}"

# xdpyinfo (x11-utils) tells a stale $DISPLAY (e.g. ssh without X forwarding)
# from a live one; without it a set $DISPLAY is trusted.
has_display() {
  [[ -n ${DISPLAY:-} ]] || return 1
  command -v xdpyinfo >/dev/null || return 0
  xdpyinfo >/dev/null 2>&1
}

if has_display; then
  echo "[collision2d] opening rviz on $DISPLAY (Ctrl-C to stop)" >&2
  exec roslaunch collision2d demo.launch
fi

echo "[collision2d] no display: running the demo under Xvfb for ${HEADLESS_SECONDS} s" >&2
"$SCRIPTS_DIR/rviz_screenshot.sh" --live "$HEADLESS_SECONDS" "$SCREENSHOT"
echo "Screenshot of the demo in rviz: $(cd "$(dirname "$SCREENSHOT")" && pwd)/$(basename "$SCREENSHOT")"
