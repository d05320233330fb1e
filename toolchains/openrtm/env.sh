# shellcheck shell=bash
# Source this (bash): OpenRTM-aist 2.0 that build.sh beside this file installs into
# $OPENRTM_HOME/install (default ~/openrtm/install; OPENRTM_INSTALL overrides the install folder),
# and the helpers robomda's openrtm_toolchain tests use:
#
#   rtm_build_pkg PKGDIR      configure + build a generated OpenRTM package in PKGDIR/build
#                             (the component modules <Class>.so land there)
#   rtm_build_probe DIR       build the test probe (probe/Probe.cpp: an InPort<TimedLong> that prints
#                             what it reads) into DIR
#
# Tunables (environment): RTM_JOBS (make -j, default 2), RTM_CMAKE_ARGS (extra cmake args).

OPENRTM_INSTALL=${OPENRTM_INSTALL:-${OPENRTM_HOME:-$HOME/openrtm}/install}
export OPENRTM_INSTALL
_RTM_HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

_rtm_prepend() {  # _rtm_prepend VAR DIR: put DIR first in the :-separated VAR, once
  local var=$1 dir=$2 cur
  cur=${!var:-}
  case ":$cur:" in
    *":$dir:"*) cur=$(printf '%s' ":$cur:" | sed "s#:$dir:#:#g; s#^:##; s#:\$##") ;;
  esac
  export "$var=$dir${cur:+:$cur}"
}

_rtm_prepend PATH "$OPENRTM_INSTALL/bin"
_rtm_prepend LD_LIBRARY_PATH "$OPENRTM_INSTALL/lib"
_rtm_prepend PKG_CONFIG_PATH "$OPENRTM_INSTALL/lib/pkgconfig"
_rtm_prepend CMAKE_PREFIX_PATH "$OPENRTM_INSTALL"

_rtm_cmake() {  # _rtm_cmake SRC BUILD: configure and build
  cmake -S "$1" -B "$2" -DCMAKE_PREFIX_PATH="$CMAKE_PREFIX_PATH" ${RTM_CMAKE_ARGS:-} \
    || { echo "rtm: cmake configure of $1 FAILED" >&2; return 1; }
  nice -n 19 cmake --build "$2" -j "${RTM_JOBS:-2}" || { echo "rtm: build of $1 FAILED" >&2; return 1; }
}

rtm_build_pkg() {
  local pkg
  pkg=$(readlink -f "${1:?usage: rtm_build_pkg PKGDIR}") || return 2
  [ -f "$pkg/CMakeLists.txt" ] || { echo "rtm_build_pkg: no CMakeLists.txt in $pkg" >&2; return 2; }
  _rtm_cmake "$pkg" "$pkg/build" || return 1
  find "$pkg/build" -maxdepth 1 -name '*.so' | grep -q . || { echo "rtm_build_pkg: no component module in $pkg/build" >&2; return 1; }
}

rtm_build_probe() {
  local out
  out=$(readlink -f "${1:?usage: rtm_build_probe DIR}") || return 2
  _rtm_cmake "$_RTM_HERE/probe" "$out" && [ -f "$out/Probe.so" ]
}
