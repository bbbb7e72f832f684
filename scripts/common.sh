# shellcheck shell=bash
# Shared by demo.sh and test.sh: dependency install, ROS environment, build.
# Source it from a script that has `set -euo pipefail`.

COLLISION2D_ROOT="$(cd -P "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Everything generated lives here (git-ignored); override to build elsewhere.
COLLISION2D_BUILD_ROOT="${COLLISION2D_BUILD_ROOT:-$COLLISION2D_ROOT/.build}"
COLLISION2D_WS="$COLLISION2D_BUILD_ROOT/ws"
# Scripts run from the workspace's package folder (rostest) find the same build root.
export COLLISION2D_BUILD_ROOT
COLLISION2D_JOBS="${COLLISION2D_JOBS:-$(nproc)}"
NOETIC_SETUP=/opt/ros/noetic/setup.bash
# ROS python modules are installed for the system interpreter only; a python3
# from pyenv/conda earlier on PATH would not find them.
SYSTEM_PYTHON=/usr/bin/python3
# apt waits this long for another apt/dpkg to release its lock.
APT_LOCK_TIMEOUT_S=600

# ---------------------------------------------------------------------------
# Packages: the one place to add a dependency.
# Needed on every system (not ROS packages). xvfb, imagemagick and Mesa's
# software GL let the rviz test draw and capture a screen on a headless machine.
SYSTEM_PACKAGES=(
  cmake g++ libeigen3-dev libgtest-dev libyaml-cpp-dev
  xvfb imagemagick libgl1-mesa-dri x11-utils
  # clang's libFuzzer and sanitizer runtimes for scripts/fuzz*.sh
  clang libclang-rt-14-dev
  # the peers the benchmarks measure against (built only when present)
  libbox2d-dev libchipmunk-dev)
# ROS from Debian's own archive (Debian 12 and similar: ROS lives in /usr).
DEBIAN_ROS_PACKAGES=(
  catkin ros-core-dev ros-message-generation ros-message-runtime
  libstd-msgs-dev libstd-srvs-dev libgeometry-msgs-dev libvisualization-msgs-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  libros-rosgraph-msgs-dev python3-rosgraph-msgs libtf2-ros-dev python3-tf2-ros
  libinteractive-markers-dev python3-interactive-markers
  python3-rospy python3-rosservice python3-rostopic python3-rostest librostest-dev rviz
  catkin-lint)
# The same for ROS Noetic in /opt/ros/noetic, used when rosdep cannot resolve
# package.xml (rosdep missing or never initialised).
NOETIC_ROS_PACKAGES=(
  ros-noetic-catkin ros-noetic-roscpp ros-noetic-message-generation
  ros-noetic-message-runtime ros-noetic-std-msgs ros-noetic-std-srvs
  ros-noetic-geometry-msgs ros-noetic-visualization-msgs
  ros-noetic-dynamic-reconfigure ros-noetic-rosgraph-msgs ros-noetic-tf2-ros
  ros-noetic-interactive-markers ros-noetic-rospy ros-noetic-rosservice ros-noetic-rostopic
  ros-noetic-rostest ros-noetic-rviz python3-catkin-lint)

# ---------------------------------------------------------------------------
log() { printf '[collision2d] %s\n' "$*" >&2; }
die() { log "error: $*"; exit 1; }

run_as_root() {
  if [[ $EUID -eq 0 ]]; then
    "$@"
  elif command -v sudo >/dev/null; then
    sudo "$@"
  else
    die "root or sudo is needed to run: $*"
  fi
}

using_noetic() { [[ -f $NOETIC_SETUP ]]; }

missing_packages() {
  local package
  for package in "$@"; do
    dpkg-query -W -f='${db:Status-Abbrev}' "$package" 2>/dev/null | grep -q '^ii' ||
      printf '%s\n' "$package"
  done
}

apt_get() {
  run_as_root env DEBIAN_FRONTEND=noninteractive \
    apt-get -q -o DPkg::Lock::Timeout="$APT_LOCK_TIMEOUT_S" "$@"
}

# Installs only what is missing, so a second run neither updates nor installs.
install_apt_packages() {
  local missing
  mapfile -t missing < <(missing_packages "$@")
  [[ ${#missing[@]} -eq 0 ]] && return 0
  log "installing: ${missing[*]}"
  apt_get update
  apt_get install -y "${missing[@]}"
}

install_noetic_ros_packages() {
  if command -v rosdep >/dev/null &&
     DEBIAN_FRONTEND=noninteractive rosdep install --from-paths "$COLLISION2D_ROOT" \
       --ignore-src -y --rosdistro noetic; then
    return 0
  fi
  log "rosdep unavailable or failed: installing the explicit ros-noetic list"
  install_apt_packages "${NOETIC_ROS_PACKAGES[@]}"
}

install_dependencies() {
  install_apt_packages "${SYSTEM_PACKAGES[@]}"
  # Never mix Debian's catkin/ros-* packages into a Noetic system.
  if using_noetic; then
    install_noetic_ros_packages
  else
    install_apt_packages "${DEBIAN_ROS_PACKAGES[@]}"
  fi
}

# ---------------------------------------------------------------------------
# ROS setup scripts read unset variables, so they are sourced without `set -u`.
source_without_nounset() {
  set +u
  # shellcheck disable=SC1090
  source "$1"
  set -u
}

setup_ros_environment() {
  # /usr/bin first so ROS tools and `#!/usr/bin/env python3` nodes run with the
  # system python3 even when pyenv or conda shadow it; the Noetic setup then
  # puts /opt/ros/noetic/bin ahead of /usr/bin.
  export PATH="/usr/bin:/bin:$PATH"
  if using_noetic; then
    source_without_nounset "$NOETIC_SETUP"
  fi
  # Keep logs and rostest results of these scripts out of ~/.ros.
  export ROS_HOME="$COLLISION2D_BUILD_ROOT/ros_home"
  mkdir -p "$ROS_HOME"
}

# The package folder of the workspace: one link per top-level entry of the
# clone, leaving out the build trees. rosrun searches the package folder with
# `find -L`; a link to the whole clone would lead it into .build (a loop back
# to the package, and the sanitizer and fuzz builds' copies of every program).
link_package_folder() {
  local package="$COLLISION2D_WS/src/collision2d" entry name
  # Earlier layouts linked the whole clone here.
  [[ -L $package ]] && rm -f "$package"
  mkdir -p "$package"
  for entry in "$package"/* "$package"/.[!.]*; do
    [[ -L $entry && ! -e $entry ]] && rm -f "$entry"  # gone from the clone
  done
  for entry in "$COLLISION2D_ROOT"/* "$COLLISION2D_ROOT"/.[!.]*; do
    [[ -e $entry ]] || continue
    name=$(basename "$entry")
    case "$name" in
      .build | build* | devel | install) continue ;;
    esac
    [[ $entry -ef $COLLISION2D_BUILD_ROOT ]] && continue
    ln -sfn "$entry" "$package/$name"
  done
}

# A catkin workspace whose only package is this repository (linked, so edits
# in the clone are built without copying).
prepare_workspace() {
  mkdir -p "$COLLISION2D_WS/src"
  # catkin caches the test environment (build/catkin_generated/setup_cached.sh,
  # used by run_tests) at the first configure, and leaves the devel python
  # folder out of PYTHONPATH if it does not exist yet: rostest python nodes
  # would then not import the generated collision2d messages.
  mkdir -p "$COLLISION2D_WS/devel/lib/python3/dist-packages"
  link_package_folder
  # A clone that moved leaves a CMake cache pointing at the old place.
  local cache="$COLLISION2D_WS/build/CMakeCache.txt"
  if [[ -f $cache ]] &&
     ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$COLLISION2D_WS/src" "$cache"; then
    log "workspace moved: clearing $COLLISION2D_WS/build and devel"
    rm -rf "$COLLISION2D_WS/build" "$COLLISION2D_WS/devel"
  fi
}

# catkin_make with the project's fixed flags; extra arguments are targets.
catkin_make_ws() {
  catkin_make -C "$COLLISION2D_WS" -j"$COLLISION2D_JOBS" \
    -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE="$SYSTEM_PYTHON" "$@"
}

source_workspace() {
  source_without_nounset "$COLLISION2D_WS/devel/setup.bash"
}

# Everything demo.sh and test.sh need before their own work.
install_and_build() {
  install_dependencies
  setup_ros_environment
  prepare_workspace
  log "building in $COLLISION2D_WS"
  catkin_make_ws all
  source_workspace
}
