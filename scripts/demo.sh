#!/usr/bin/env bash
# First README command: install what the package needs, build it, run the main job.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

DEMO_SCENARIO="$COLLISION2D_ROOT/config/scenarios/cluster.collision"

# The main job: resolve a shipped multi-contact scenario and print the report.
# Called by path rather than through rosrun, whose `find -L` over the package
# would wander into .build/ws/src/collision2d, a symlink back to the clone.
run_main_job() {
  "$COLLISION2D_WS/devel/lib/collision2d/collision2d_cli" "$DEMO_SCENARIO"
}

install_and_build
run_main_job
