#!/usr/bin/env bash
# First README command: install what the package needs, build it, run the main job.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The main job: the rviz demo (world node, marker node, rviz). With a display
# rviz opens; without one it runs under Xvfb and saves a screenshot whose path
# it prints.
run_main_job() {
  "$COLLISION2D_ROOT/scripts/demo_run.sh"
}

install_and_build
run_main_job
