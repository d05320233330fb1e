# shellcheck shell=bash
# Source this (bash): env.sh beside this file (the Orocos toolchain and its helpers), then the
# rtt_ros_integration packages that build-ros.sh installs into $RTT_ROS_HOME/install (default
# ~/rtt_ros/install; RTT_ROS_INSTALL overrides the install folder) and Debian's ROS 1, so that a
# deployment importing rtt_rosnode, rtt_roscomm and rtt_std_msgs finds them, plus:
#
#   ros_wait_master SECS     wait until the ROS master of ROS_MASTER_URI answers (SECS seconds at most)
#
# ROS_MASTER_URI, ROS_IP / ROS_HOSTNAME are left as they are (roscore's default is
# http://localhost:11311); set them before starting roscore and the deployers.

# shellcheck disable=SC1091
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

RTT_ROS_INSTALL=${RTT_ROS_INSTALL:-${RTT_ROS_HOME:-$HOME/rtt_ros}/install}
export RTT_ROS_INSTALL

# Debian's ROS 1 lives in /usr: its packages are found through ROS_PACKAGE_PATH /usr/share and its
# CMake configurations through CMAKE_PREFIX_PATH /usr; then the rtt_ros_integration install before them.
case ":${ROS_PACKAGE_PATH:-}:" in *":/usr/share:"*) ;; *) export ROS_PACKAGE_PATH=${ROS_PACKAGE_PATH:+$ROS_PACKAGE_PATH:}/usr/share ;; esac
export ROS_DISTRO=${ROS_DISTRO:-debian}
export ROS_PYTHON_VERSION=3
_oro_prepend ROS_PACKAGE_PATH "$RTT_ROS_INSTALL/share"
_oro_prepend CMAKE_PREFIX_PATH "$RTT_ROS_INSTALL"
_oro_prepend LD_LIBRARY_PATH "$RTT_ROS_INSTALL/lib"
_oro_prepend PKG_CONFIG_PATH "$RTT_ROS_INSTALL/lib/pkgconfig"
_oro_prepend RTT_COMPONENT_PATH "$RTT_ROS_INSTALL/lib/orocos"
_oro_prepend PYTHONPATH "$RTT_ROS_INSTALL/lib/python3/dist-packages"

ros_wait_master() {
  local secs=${1:-30} end
  end=$(($(date +%s) + secs))
  until timeout 5 rosnode list >/dev/null 2>&1; do
    [ "$(date +%s)" -lt "$end" ] || { echo "ros_wait_master: no ROS master at ${ROS_MASTER_URI:-http://localhost:11311} after $secs s" >&2; return 1; }
    sleep 0.5
  done
}
