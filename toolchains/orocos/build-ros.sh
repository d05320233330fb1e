#!/usr/bin/env bash
# Builds the Orocos <-> ROS 1 integration robomda's rtt_ros_toolchain tests use: the packages of
# rtt_ros_integration an Orocos deployment with a stream to a ROS topic imports (rtt_ros, rtt_rospack,
# rtt_rosnode, rtt_roscomm and the std_msgs typekits, rtt_std_msgs), from public sources, against the
# Orocos toolchain that build.sh beside this file installs and Debian 12's ROS 1 (catkin, roscpp,
# std_msgs, genmsg: the Noetic-era packages of bookworm), into $RTT_ROS_HOME (default ~/rtt_ros):
#
#   $RTT_ROS_HOME/src/rtt_ros_integration    the repository of sources-ros.tsv, at its verified commit
#   $RTT_ROS_HOME/build_isolated, devel_isolated   catkin_make_isolated's folders
#   $RTT_ROS_HOME/install                    the packages (lib/orocos/gnulinux/<package>: what the
#                                            deployer's Import finds through RTT_COMPONENT_PATH)
#
# Usage: build-ros.sh [--check] [--no-apt] [--sources-only]
#   --check          build nothing: report what is present and what is missing (Debian packages, the
#                    Orocos toolchain, the source and its commit, the plugins and typekits installed), then
#                    run them once: a roscore of its own on a free port of 127.0.0.1, an rttlua script
#                    that imports rtt_ros, rtt_rosnode, rtt_roscomm and rtt_std_msgs and streams an int
#                    port and a /std_msgs/String port (the std_msgs message typekit) to ROS topics and
#                    another of each from topics, rostopic reading the first and publishing the second;
#                    exit status 1 if anything is missing or no message crosses either way on either type
#   --no-apt         do not install Debian packages (only check they are there)
#   --sources-only   stop after fetching the source (to build later, offline)
# Environment: OROCOS_HOME / OROCOS_INSTALL (the Orocos toolchain, as for env.sh); RTT_ROS_HOME; MIRROR,
# a folder of fetched bare mirrors (MIRROR/orocos+rtt_ros_integration/repo), cloned instead of the public
# URL when set; JOBS (make jobs, default 2); NICE (default 19).
# Source env-ros.sh beside this script to use the result. Took 79 min from empty (JOBS=4) on 2 cores
# shared with other builds (rtt_ros's primitives typekit and the 32-message std_msgs typekit are most of it).
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
WS=${RTT_ROS_HOME:-$HOME/rtt_ros}
PREFIX=$WS/install
SRC=$WS/src
JOBS=${JOBS:-2}
NICE=${NICE:-19}
# say, missing, parse_options, apt_step, fetch_sources, _run (toolchains/common.sh)
# shellcheck disable=SC1091
source "$HERE/../common.sh"
parse_options "$@"

# Debian packages: catkin and the ROS 1 libraries rtt_ros_integration builds on (roscpp, rostime,
# rospack, roslib), the message generators and std_msgs (the typekit), libxml2 (rtt_ros), and the tools
# that run a ROS 1 system (roscore, rosout, roslaunch, rostopic); std_srvs for the nodes robomda generates
APT_PACKAGES=(build-essential cmake git ca-certificates catkin python3-catkin-pkg python3-empy
              libroscpp-dev libroscpp-core-dev librospack-dev libroslib-dev libxml2-dev
              python3-genmsg python3-gencpp ros-message-generation ros-std-msgs libstd-msgs-dev
              ros-std-srvs libstd-srvs-dev python3-roslaunch python3-rostopic python3-rosnode rosout)
# the packages built (with what they depend on: rtt_ros, rtt_rospack)
PACKAGES=(rtt_rosnode rtt_roscomm rtt_std_msgs)
# what an install that can stream to ROS holds (relative to $PREFIX/lib/orocos/gnulinux)
PLUGINS=(rtt_ros/plugins/librtt_ros_service-gnulinux.so rtt_rosnode/plugins/librtt_rosnode-gnulinux.so
         rtt_roscomm/plugins/librtt_rostopic_service-gnulinux.so
         rtt_std_msgs/types/librtt-std_msgs-typekit-gnulinux.so
         rtt_std_msgs/types/librtt-std_msgs-ros-transport-gnulinux.so
         rtt_std_msgs/plugins/librtt-ros-primitives-transport-gnulinux.so)


# --- Debian packages ------------------------------------------------------------------------------
apt_step

# --- the Orocos toolchain (build.sh) --------------------------------------------------------------
# shellcheck disable=SC1091
source "$HERE/env.sh" >/dev/null
for f in bin/deployer bin/rttlua lib/liborocos-rtt-gnulinux.so; do
  [ -e "$OROCOS_INSTALL/$f" ] || missing "the Orocos toolchain: no $OROCOS_INSTALL/$f (build it with build.sh)"
done
if [ $MISSING = 1 ] && [ $CHECK = 0 ]; then say "build the Orocos toolchain first"; exit 1; fi

# --- source -----------------------------------------------------------------------------------------
fetch_sources "$HERE/sources-ros.tsv" orocos

# --- check: files, then one run both ways ------------------------------------------------------------
check_runs() {
  # shellcheck disable=SC1091
  source "$HERE/env-ros.sh" >/dev/null
  local tmp port master rc=0 out pids=() p
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtt-ros-check.XXXXXX")
  port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  export ROS_MASTER_URI=http://127.0.0.1:$port ROS_IP=127.0.0.1 ROS_HOME=$tmp/ros
  setsid roscore -p "$port" >"$tmp/roscore.log" 2>&1 &
  master=$!
  if ! ros_wait_master 90; then
    missing "run: roscore -p $port did not answer in 90 s: $(tail -n 3 "$tmp/roscore.log" | tr '\n' ' ')"
  else
    # two streams each way: an int port (rtt_std_msgs's primitives transport: std_msgs/Int32) and a
    # /std_msgs/String port (the std_msgs message typekit and its ROS transport); rtt.Variable of a
    # std_msgs type fails unless the typekit is loaded
    cat > "$tmp/both.lua" <<'LUA'
require("rttlib")
local tc = rtt.getTC()
local depl = tc:getPeer("Deployer")
for _, p in ipairs({"rtt_ros", "rtt_rosnode", "rtt_roscomm", "rtt_std_msgs"}) do assert(depl:import(p), "import " .. p) end
local topic = rtt.provides("ros"):getOperation("topic")
local ports = {
  {"out", rtt.OutputPort("int"), "/robomda_check_out"}, {"inp", rtt.InputPort("int"), "/robomda_check_in"},
  {"sout", rtt.OutputPort("/std_msgs/String"), "/robomda_check_str_out"},
  {"sinp", rtt.InputPort("/std_msgs/String"), "/robomda_check_str_in"}}
for _, p in ipairs(ports) do
  tc:addPort(p[2], p[1])
  assert(depl:stream("lua." .. p[1], topic(p[3])), "stream lua." .. p[1] .. " with " .. p[3])
end
local out, inp, sout, sinp = ports[1][2], ports[2][2], ports[3][2], ports[4][2]
local msg = rtt.Variable("/std_msgs/String")
local got, sgot = nil, nil
for k = 1, 300 do
  out:write(k)
  msg.data = "from-orocos " .. k
  sout:write(msg)
  local fs, v = inp:read()
  if fs == "NewData" then got = v end
  local sfs, sv = sinp:read()
  if sfs == "NewData" then sgot = sv.data end
  if got and sgot then break end
  rtt.sleep(0, 100000000)
end
print("FROM-ROS " .. tostring(got))
print("FROM-ROS-STRING " .. tostring(sgot))
for k = 1, 20 do out:write(1000 + k); msg.data = "from-orocos " .. (1000 + k); sout:write(msg); rtt.sleep(0, 100000000) end
LUA
    timeout -k 5 120 rostopic echo -n 1 /robomda_check_out >"$tmp/echo.out" 2>&1 & pids+=($!)
    timeout -k 5 120 rostopic echo -n 1 /robomda_check_str_out >"$tmp/echo-str.out" 2>&1 & pids+=($!)
    timeout -k 5 120 rostopic pub -r 5 /robomda_check_in std_msgs/Int32 "data: 4242" >/dev/null 2>&1 & pids+=($!)
    timeout -k 5 120 rostopic pub -r 5 /robomda_check_str_in std_msgs/String "data: from-ros" >/dev/null 2>&1 & pids+=($!)
    out=$(cd "$tmp" && timeout -k 5 150 rttlua both.lua </dev/null 2>&1) || rc=$?
    for p in "${pids[@]:2}"; do kill "$p" 2>/dev/null || true; done
    for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
    if [ $rc = 0 ] && grep -q '^FROM-ROS 4242$' <<<"$out"; then say "run: ROS 1 -> Orocos (rostopic pub std_msgs/Int32 -> rtt_roscomm stream -> int port): OK"
    else missing "run: ROS 1 -> Orocos (int) failed (rttlua exit $rc): $(tail -n 5 <<<"$out" | tr '\n' ' ')"; fi
    if [ $rc = 0 ] && grep -q '^FROM-ROS-STRING from-ros$' <<<"$out"; then say "run: ROS 1 -> Orocos (rostopic pub std_msgs/String -> rtt_std_msgs typekit + ROS transport -> /std_msgs/String port): OK"
    else missing "run: ROS 1 -> Orocos (std_msgs/String) failed (rttlua exit $rc): $(tail -n 5 <<<"$out" | tr '\n' ' ')"; fi
    if grep -q '^data: [0-9]' "$tmp/echo.out"; then say "run: Orocos -> ROS 1 (int port -> rtt_roscomm stream -> rostopic echo std_msgs/Int32): OK"
    else missing "run: Orocos -> ROS 1 (int) failed: rostopic echo read $(tr '\n' ' ' < "$tmp/echo.out" | cut -c1-300)"; fi
    if grep -q '^data: "\{0,1\}from-orocos [0-9]' "$tmp/echo-str.out"; then say "run: Orocos -> ROS 1 (/std_msgs/String port -> rtt_std_msgs ROS transport -> rostopic echo std_msgs/String): OK"
    else missing "run: Orocos -> ROS 1 (std_msgs/String) failed: rostopic echo read $(tr '\n' ' ' < "$tmp/echo-str.out" | cut -c1-300)"; fi
  fi
  kill -INT -- -"$master" 2>/dev/null || true
  wait $master 2>/dev/null || true
  rm -rf "$tmp"
}

if [ $CHECK = 1 ]; then
  for f in "${PLUGINS[@]}"; do [ -e "$PREFIX/lib/orocos/gnulinux/$f" ] || missing "$PREFIX/lib/orocos/gnulinux/$f"; done
  for p in roscore rostopic roslaunch catkin_make; do command -v $p >/dev/null || missing "$p (Debian: see --help)"; done
  if [ $MISSING = 0 ]; then check_runs; else say "runs skipped: the install is incomplete"; fi
  if [ $MISSING = 0 ]; then say "check: OK ($PREFIX)"; else say "check: FAILED ($PREFIX cannot stream to ROS 1)"; fi
  exit $MISSING
fi

# --- build --------------------------------------------------------------------------------------------
# catkin_make_isolated builds each package on its own, in dependency order, and installs into $PREFIX.
# PYTHON_EXECUTABLE: catkin's generators run under Debian's Python (catkin_pkg, genmsg, gencpp), not
# whatever python3 is first on PATH.
# Their scripts run as '#!/usr/bin/env python3' (installed; '#!/usr/bin/env python' in the source) too:
# rtt_roscomm's create_boost_header.py imports roslib, genmsg and gencpp. Debian's python3 goes first on
# PATH under both names, or a pyenv / venv python3 fails with "No module named 'roslib'".
# The build is one { } block: bash reads it whole before running it, so editing this file during a
# build cannot change what the running build does next.
{
  mkdir -p "$WS/bin"
  ln -sf /usr/bin/python3 "$WS/bin/python3"
  ln -sf /usr/bin/python3 "$WS/bin/python"
  export PATH=$WS/bin:$PATH
  say "build ${PACKAGES[*]} (and what they depend on) into $PREFIX"
  (cd "$WS" && nice -n "$NICE" /usr/bin/python3 /usr/bin/catkin_make_isolated --install --install-space "$PREFIX" \
    --only-pkg-with-deps "${PACKAGES[@]}" -j"$JOBS" \
    --cmake-args -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_ENABLE_TESTING=OFF)
  say "rtt_ros_integration installed under $PREFIX; checking it"
  exec "$HERE/build-ros.sh" --check
}
