#!/usr/bin/env bash
# Shared by scripts/demo, scripts/test and bench/run: puts Debian's ROS first in PATH, installs what is missing,
# builds the package with plain CMake into _build/.
set -euo pipefail

# The image's pyenv python3 hides the ROS Python modules (catkin_pkg, rospy): Debian's python3 must come first.
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
export PYTHONNOUSERSITE=1

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# Not "build/": rosrun skips executables below <package>/build/.
BUILD_DIR=${PTZ_BUILD_DIR:-$ROOT/_build}
JOBS=${PTZ_JOBS:-$(nproc)}
# The scripts' build type: RelWithDebInfo with line tables only (-g1: a backtrace keeps functions, files and lines, not
# variables), a fifth less compile time than its -g. A build of your own keeps CMake's RelWithDebInfo.
# The test programs' own sources at -O1 (PTZ_TEST_COMPILE_OPTIONS): a quarter less compile time.
# Warnings are errors here (PTZ_WARNINGS_AS_ERRORS), so none reaches main.
PTZ_CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
  -DCATKIN_ENABLE_TESTING=ON -DPTZ_TEST_COMPILE_OPTIONS=-O1 -DPTZ_WARNINGS_AS_ERRORS=ON)

# Everything the package needs to build, test and run, from Debian bookworm's own packages.
PTZ_APT_PACKAGES=(
  build-essential cmake
  ros-base-dev rosbash python3-rostest librostest-dev
  libactionlib-dev python3-actionlib
  libtf2-ros-dev libtf2-eigen-dev libtf2-geometry-msgs-dev
  liburdfdom-dev liburdfdom-tools libeigen3-dev
  libdiagnostic-updater-dev pluginlib-dev
  libsensor-msgs-dev libgeometry-msgs-dev
  libimage-transport-dev libopencv-core-dev libopencv-imgproc-dev libcv-bridge-dev
  ros-robot-state-publisher
  googletest libgtest-dev libbenchmark-dev
  nlohmann-json3-dev
  libcurl4-openssl-dev libssl-dev libtinyxml2-dev
  libyaml-cpp-dev
  librviz-dev rviz xvfb libinteractive-markers-dev libstd-srvs-dev libvisualization-msgs-dev
  libnodelet-dev libnodeletlib-dev libnodeletlib-tools
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  python3-diagnostic-msgs python3-sensor-msgs python3-std-srvs
)

# A step's heading, with the time of day, so a CI log shows where its time went.
log() {
  printf '\033[1m==> %s  [%s]\033[0m\n' "$*" "$(date +%T)"
}

# apt-get install the given packages that are not installed yet.
install_packages() {
  local missing=()
  local package
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  log "installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

install_dependencies() {
  install_packages "${PTZ_APT_PACKAGES[@]}"
}

# Configures and builds everything (and the programs the rostests run when $1 = with-rostest-programs; test_core is
# the target tests' other part).
build_package() {
  log "building into ${BUILD_DIR}"
  mkdir -p "$BUILD_DIR"
  cmake -S "$ROOT" -B "$BUILD_DIR" "${PTZ_CMAKE_ARGS[@]}" >"$BUILD_DIR/configure.log" 2>&1 ||
    { cat "$BUILD_DIR/configure.log"; return 1; }
  cmake --build "$BUILD_DIR" -j "$JOBS"
  if [ "${1:-}" = "with-rostest-programs" ]; then
    cmake --build "$BUILD_DIR" -j "$JOBS" --target rostest_programs
    # run_tests runs in the environment catkin cached at configure time (catkin_generated/setup_cached.sh); on a
    # clean clone devel/lib did not exist then, so the Python rostests could not import the generated messages.
    cmake "$BUILD_DIR" >"$BUILD_DIR/reconfigure.log" 2>&1 || { cat "$BUILD_DIR/reconfigure.log"; return 1; }
  fi
  # shellcheck disable=SC1091
  set +u
  source "$BUILD_DIR/devel/setup.bash"
  set -u
}

# Configures and builds only the given targets (for the scripts that need a few programs, not the tests).
build_targets() {
  log "building $* into ${BUILD_DIR}"
  mkdir -p "$BUILD_DIR"
  cmake -S "$ROOT" -B "$BUILD_DIR" "${PTZ_CMAKE_ARGS[@]}" >"$BUILD_DIR/configure.log" 2>&1 ||
    { cat "$BUILD_DIR/configure.log"; return 1; }
  cmake --build "$BUILD_DIR" -j "$JOBS" --target "$@"
  set +u
  source "$BUILD_DIR/devel/setup.bash"
  set -u
}

# A free TCP port on 127.0.0.1, for a private rosmaster.
free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}
