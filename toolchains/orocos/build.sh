#!/usr/bin/env bash
# Builds the Orocos toolchain 2.10 (log4cpp, RTT, OCL) that robomda's orocos_toolchain tests use, from
# public sources, into $OROCOS_HOME (default ~/orocos), on Debian 12 (bookworm; GCC 12, Boost 1.74):
#
#   $OROCOS_HOME/src/{log4cpp,rtt,ocl}   the repositories of sources.tsv, at their verified commits
#   $OROCOS_HOME/build/...               the CMake build folders
#   $OROCOS_HOME/install                 the toolchain: RTT with the CORBA (omniORB) and MQueue transports,
#                                        OCL with deployer, deployer-corba, rttlua and rttlua-corba
#
# Usage: build.sh [--check] [--no-apt] [--sources-only]
#   --check          build nothing: report what is present and what is missing (Debian packages, sources
#                    and their commits, the programs and transports installed) and run the toolchain once:
#                    deployer --version, a tiny rttlua script (RTT typekit, a component loaded), and
#                    rttlua-corba against a naming service of its own on 127.0.0.1; exit status 1 if
#                    anything is missing or a run fails (a tree that cannot deploy)
#   --no-apt         do not install Debian packages (only check they are there)
#   --sources-only   stop after fetching the sources (to build later, offline)
# Environment: OROCOS_HOME; MIRROR, a folder of fetched bare mirrors (MIRROR/orocos-toolchain+rtt/repo,
# ...), cloned instead of the public URL when set; JOBS (make jobs, default 2); NICE (default 19).
# Source env.sh beside this script to use the result. Takes ~20 min on 2 cores.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ORO=${OROCOS_HOME:-$HOME/orocos}
PREFIX=$ORO/install
SRC=$ORO/src
BLD=$ORO/build
JOBS=${JOBS:-2}
NICE=${NICE:-19}
# say, missing, parse_options, apt_step, fetch_sources, _run (toolchains/common.sh)
# shellcheck disable=SC1091
source "$HERE/../common.sh"
parse_options "$@"

# Debian packages: compilers, Boost, Lua 5.1 (rttlua), omniORB (CORBA transport, omniNames, nameclt)
APT_PACKAGES=(build-essential cmake git ca-certificates pkg-config libboost-all-dev libxml-xpath-perl
              liblua5.1-0-dev lua5.1 libreadline-dev libncurses-dev libexpat1-dev libxml2-dev
              omniorb omniidl omniorb-nameserver libomniorb4-dev)
# what an install that can deploy holds (relative to $PREFIX)
PROGRAMS=(bin/deployer bin/deployer-corba bin/rttlua bin/rttlua-corba)
LIBRARIES=(lib/liborocos-rtt-gnulinux.so lib/liborocos-rtt-corba-gnulinux.so lib/liborocos-rtt-mqueue-gnulinux.so
           lib/liborocos-ocl-deployment-corba-gnulinux.so)


# --- Debian packages ------------------------------------------------------------------------------
apt_step

# --- sources ----------------------------------------------------------------------------------------
# From MIRROR/orocos-toolchain+<name>/repo when that exists (fetched bare mirrors), else from the public
# URL; then the verified commit is checked out (an existing clone is only compared with it).
fetch_sources "$HERE/sources.tsv" orocos-toolchain

# --- check: files, then one run of each tool ---------------------------------------------------------
# _run LABEL EXPECTED CMD... (toolchains/common.sh)
check_runs() {
  # shellcheck disable=SC1091
  source "$HERE/env.sh" >/dev/null
  local tmp port
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/oro-check.XXXXXX")
  # (OCL's deployer exits 1 after printing its version: only the output counts)
  _run "deployer --version" "OROCOS Toolchain version '2.10" sh -c 'deployer --version; exit 0'
  cat > "$tmp/tiny.lua" <<'LUA'
require("rttlib")
local depl = rtt.getTC():getPeer("Deployer")
local cp = rtt.Variable("ConnPolicy")   -- the RTT typekit
cp.type = rtt.globals.BUFFER
assert(depl:loadComponent("probe", "OCL::LuaComponent"), "loadComponent OCL::LuaComponent")
assert(depl:getPeer("probe"):configure(), "configure")
assert(depl:unloadComponent("probe"), "unloadComponent")
print("TINY-OK")
LUA
  ( cd "$tmp" && _run "rttlua tiny.lua (typekit, component load)" TINY-OK rttlua tiny.lua )
  # CORBA: a naming service of our own on a free loopback port, and rttlua-corba registering with it
  port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  cat > "$tmp/corba.lua" <<'LUA'
require("rttlib")
local depl = rtt.getTC():getPeer("Deployer")
assert(depl:getOperation("server"), "no CORBA deployer (server operation)")
assert(depl:loadComponent("probe", "OCL::LuaComponent"), "loadComponent")
assert(depl:server("probe", true), "server probe")
assert(depl:loadComponent("probe2", "CORBA") == false, "a proxy for a name nobody registered")
print("CORBA-OK")
depl:unloadComponent("probe")
LUA
  omniNames -start "$port" -logdir "$tmp" >/dev/null 2>&1 &
  local ns=$!
  sleep 1
  ( cd "$tmp" && _run "rttlua-corba corba.lua (naming service on 127.0.0.1:$port)" CORBA-OK \
      rttlua-corba corba.lua -- -ORBInitRef "NameService=corbaname::127.0.0.1:$port" -ORBendPoint giop:tcp:127.0.0.1: )
  kill $ns 2>/dev/null || true
  wait $ns 2>/dev/null || true
  rm -rf "$tmp"
}

if [ $CHECK = 1 ]; then
  for f in "${PROGRAMS[@]}" "${LIBRARIES[@]}"; do [ -e "$PREFIX/$f" ] || missing "$PREFIX/$f"; done
  for t in corba mqueue; do
    find "$PREFIX/lib/orocos" -name "librtt-typekit-$t*" -o -name "librtt-transport-$t*" 2>/dev/null | grep -q . \
      || missing "the RTT $t transport plugin under $PREFIX/lib/orocos"
  done
  for p in omniNames nameclt; do command -v $p >/dev/null || missing "$p (Debian omniorb-nameserver, omniorb)"; done
  if [ $MISSING = 0 ]; then check_runs; else say "runs skipped: the install is incomplete"; fi
  if [ $MISSING = 0 ]; then say "check: OK ($PREFIX)"; else say "check: FAILED ($PREFIX cannot deploy)"; fi
  exit $MISSING
fi

# --- build --------------------------------------------------------------------------------------------
mkdir -p "$BLD"
export PATH=$PREFIX/bin:$PATH
export PKG_CONFIG_PATH=$PREFIX/lib/pkgconfig:${PKG_CONFIG_PATH:-}
export CMAKE_PREFIX_PATH=$PREFIX
# A system-wide catkin (ROS 1 tools) would make RTT and OCL install catkin env-hooks and fail without
# catkin_pkg; a Log4cxx some other package brought must not replace OCL's own log4cpp logging.
COMMON=(-DCMAKE_INSTALL_PREFIX="$PREFIX" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$PREFIX"
        -DCMAKE_DISABLE_FIND_PACKAGE_catkin=ON -DCMAKE_DISABLE_FIND_PACKAGE_Log4cxx=ON)
build() {  # build NAME CMAKE-ARGS...
  local name=$1
  shift
  say "build $name into $PREFIX"
  cmake -S "$SRC/$name" -B "$BLD/$name" "${COMMON[@]}" "$@"
  nice -n "$NICE" cmake --build "$BLD/$name" -j "$JOBS"
  cmake --build "$BLD/$name" --target install
}
# log4cpp (the Orocos fork; OCL logging needs it). GCC 12: DailyRollingFileAppender.hh uses struct tm
# without <time.h> ("field '_logsTime' has incomplete type 'tm'"): force-include it.
build log4cpp "-DCMAKE_CXX_FLAGS=-include time.h"
# RTT: gnulinux target, CORBA (omniORB) and MQueue transports, no tests
build rtt -DOROCOS_TARGET=gnulinux -DENABLE_CORBA=ON -DCORBA_IMPLEMENTATION=OMNIORB -DENABLE_MQ=ON -DENABLE_TESTS=OFF
# OCL: deployers, taskbrowser, rttlua with its CORBA binding (rttlua-corba)
build ocl -DOROCOS_TARGET=gnulinux -DBUILD_LUA_RTT=ON -DBUILD_LUA_RTT_CORBA=ON -DBUILD_TESTS=OFF
say "Orocos toolchain installed under $PREFIX; checking it"
exec "$0" --check
