# shellcheck shell=bash
# Source this (bash): the runtime and build environment of the minimal ROS 2 Jazzy that build.sh
# installs into $ROS2_PREFIX (default ~/ros2): its venv (colcon, empy, ...), the C++ core
# (install/), the Python overlay when built (install_py/: rclpy, launch_ros, ros2cli), and a
# private, loopback-only DDS set-up. ROS_DOMAIN_ID (default 42) and ROS_HOME (default: a new
# temporary folder) are kept when already set.
ROS2_PREFIX=${ROS2_PREFIX:-$HOME/ros2}
if [ ! -f "$ROS2_PREFIX/install/setup.bash" ] || [ ! -f "$ROS2_PREFIX/venv/bin/activate" ]; then
  echo "env.sh: no ROS 2 built in $ROS2_PREFIX (run build.sh beside this file)" >&2
  return 1
fi
export ROS2_PREFIX
# shellcheck disable=SC1091
source "$ROS2_PREFIX/venv/bin/activate"
# shellcheck disable=SC1091
source "$ROS2_PREFIX/install/setup.bash"
if [ -f "$ROS2_PREFIX/install_py/local_setup.bash" ]; then
  # shellcheck disable=SC1091
  source "$ROS2_PREFIX/install_py/local_setup.bash"
fi
# uncrustify at the version ament_uncrustify's configuration is for (build.sh builds it)
if [ -x "$ROS2_PREFIX/tools/bin/uncrustify" ]; then
  export PATH="$ROS2_PREFIX/tools/bin:$PATH"
fi
export RMW_IMPLEMENTATION=rmw_cyclonedds_cpp
export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST
export ROS_DOMAIN_ID=${ROS_DOMAIN_ID:-42}
ROS_HOME=${ROS_HOME:-$(mktemp -d "${TMPDIR:-/tmp}/ros2-home.XXXXXX")}
export ROS_HOME
export RCUTILS_COLORIZED_OUTPUT=0
