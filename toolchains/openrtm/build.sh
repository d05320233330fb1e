#!/usr/bin/env bash
# Builds OpenRTM-aist 2.0 (C++) that robomda's openrtm_toolchain tests use, from its public sources,
# with omniORB from Debian, into $OPENRTM_HOME (default ~/openrtm), on Debian 12 (GCC 12):
#
#   $OPENRTM_HOME/src/OpenRTM-aist     the repository of sources.tsv, at its verified commit
#   $OPENRTM_HOME/build/OpenRTM-aist   the CMake build folder
#   $OPENRTM_HOME/install              the toolchain: libRTC, libcoil, rtcd2, rtm2-config, rtm2-naming,
#                                      libRTC2 (coil inside), the IDL files (BasicDataType.idl ...),
#                                      lib/openrtm-2.0/cmake/OpenRTMConfig.cmake
#
# Usage: build.sh [--check] [--no-apt] [--sources-only]
#   --check          build nothing: report what is present and what is missing (Debian packages, sources
#                    and their commit, programs, libraries, the CMake package) and run the toolchain once:
#                    rtm2-config --version, and rtcd2 started against a naming service of its own on
#                    127.0.0.1 (its manager must register there); exit status 1 if anything is missing or
#                    a run fails
#   --no-apt         do not install Debian packages (only check they are there)
#   --sources-only   stop after fetching the sources (to build later, offline)
# Environment: OPENRTM_HOME; MIRROR, a folder of fetched bare mirrors (MIRROR/OpenRTM+OpenRTM-aist/repo),
# cloned instead of the public URL when set; JOBS (make jobs, default 2); NICE (default 19);
# RTM_BUILD_TYPE (CMake build type, default None: unoptimised, see below).
# Source env.sh beside this script to use the result.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
RTM=${OPENRTM_HOME:-$HOME/openrtm}
PREFIX=$RTM/install
SRC=$RTM/src
BLD=$RTM/build
JOBS=${JOBS:-2}
NICE=${NICE:-19}
# say, missing, parse_options, apt_step, fetch_sources, _run (toolchains/common.sh)
# shellcheck disable=SC1091
source "$HERE/../common.sh"
parse_options "$@"

# Debian packages: compilers, CMake, omniORB (ORB, IDL compiler, naming service and its client)
APT_PACKAGES=(build-essential cmake git ca-certificates pkg-config uuid-dev
              omniorb omniidl omniorb-nameserver libomniorb4-dev)
PROGRAMS=(bin/rtcd2 bin/rtm2-config)
LIBRARIES=(lib/libRTC2.so)  # coil is linked into libRTC2

apt_step

# --- sources ----------------------------------------------------------------------------------------
fetch_sources "$HERE/sources.tsv" OpenRTM

# --- check --------------------------------------------------------------------------------------------
# _run LABEL EXPECTED CMD... (toolchains/common.sh)

check_runs() {
  # shellcheck disable=SC1091
  source "$HERE/env.sh" >/dev/null
  local tmp port ns mgr
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/rtm-check.XXXXXX")
  _run "rtm2-config --version" "^2\.0" rtm2-config --version
  port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  omniNames -start "$port" -logdir "$tmp" >/dev/null 2>&1 &
  ns=$!
  sleep 1
  printf 'corba.nameservers: 127.0.0.1:%s\ncorba.endpoints: 127.0.0.1:\nmanager.is_master: YES\nmanager.instance_name: rtmcheck\nmanager.naming_formats: %%n.mgr\nlogger.enable: NO\n' \
    "$port" > "$tmp/rtc.conf"
  ( cd "$tmp" && exec rtcd2 -f rtc.conf </dev/null >"$tmp/rtcd.out" 2>&1 ) &
  mgr=$!
  sleep 3
  _run "rtcd2 registered its manager (rtmcheck.mgr) with the naming service on 127.0.0.1:$port" "rtmcheck" \
    nameclt -ORBInitRef "NameService=corbaname::127.0.0.1:$port" list
  kill -INT $mgr 2>/dev/null || true; sleep 1; kill $mgr 2>/dev/null || true; wait $mgr 2>/dev/null || true
  kill $ns 2>/dev/null || true; wait $ns 2>/dev/null || true
  rm -rf "$tmp"
}

if [ $CHECK = 1 ]; then
  for f in "${PROGRAMS[@]}" "${LIBRARIES[@]}"; do [ -e "$PREFIX/$f" ] || missing "$PREFIX/$f"; done
  find "$PREFIX" -name 'OpenRTMConfig.cmake' 2>/dev/null | grep -q . || missing "OpenRTMConfig.cmake under $PREFIX"
  find "$PREFIX" -name 'BasicDataType.idl' 2>/dev/null | grep -q . || missing "BasicDataType.idl under $PREFIX"
  for p in omniNames nameclt omniidl; do command -v $p >/dev/null || missing "$p (Debian omniorb-nameserver, omniorb, omniidl)"; done
  if [ $MISSING = 0 ]; then check_runs; else say "runs skipped: the install is incomplete"; fi
  if [ $MISSING = 0 ]; then say "check: OK ($PREFIX)"; else say "check: FAILED ($PREFIX cannot run components)"; fi
  exit $MISSING
fi

# --- build --------------------------------------------------------------------------------------------
# omniORB from Debian; no examples, documents, SSL/HTTP transports, observer or extension modules
# (src/ext: SDO services, local services, extra ECs and transports, fluent-bit logger); utils kept (rtcd2,
# rtm2-config, rtm2-naming, the CMake package files). Build type None (no optimisation) unless
# RTM_BUILD_TYPE says otherwise: OpenRTM's Release adds -O3 with inlining limits raised to 1000 and
# -Werror with some 80 warnings, which at nice 19 on 2 shared cores compiled 30 % in 20 min and then
# one file in 15 min; the tests need components that run, not fast ones.
say "build OpenRTM-aist into $PREFIX"
cmake -S "$SRC/OpenRTM-aist" -B "$BLD/OpenRTM-aist" -DCMAKE_INSTALL_PREFIX="$PREFIX" -DCMAKE_BUILD_TYPE="${RTM_BUILD_TYPE:-None}" \
      -DCORBA=omniORB -DEXAMPLES_ENABLE=OFF -DDOCUMENTS_ENABLE=OFF -DSSL_ENABLE=OFF -DHTTP_ENABLE=OFF \
      -DOBSERVER_ENABLE=OFF -DEXTLIB_ENABLE=OFF -DUTILS_ENABLE=ON
nice -n "$NICE" cmake --build "$BLD/OpenRTM-aist" -j "$JOBS"
cmake --build "$BLD/OpenRTM-aist" --target install
say "OpenRTM-aist installed under $PREFIX; checking it"
exec "$0" --check
