# shellcheck shell=bash
# Source this (bash): OpenRTM-aist 2.0 that build.sh beside this file installs into
# $OPENRTM_HOME/install (default ~/openrtm/install; OPENRTM_INSTALL overrides the install folder),
# and the helpers robomda's openrtm_toolchain tests use:
#
#   rtm_build_pkg PKGDIR      configure + build a generated OpenRTM package in PKGDIR/build
#                             (the component modules <Class>.so land there)
#   rtm_build_events DIR      build the test event source (events/EventSource.cpp: an OutPort
#                             RTC::TimedString that writes each line of its manager's stdin) into DIR
#   rtm_build_probe DIR [CMAKE_ARG...]  build the test probe (probe/Probe.cpp: an InPort that prints
#                             the time stamp of what it reads, and a TimedLong's or TimedDouble's datum;
#                             -DPROBE_TYPE=..., -DPROBE_HEADER=...,
#                             -DPROBE_PACKAGE_BUILD=... for a generated package's type) into DIR
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

_rtm_cmake() {  # _rtm_cmake SRC BUILD [CMAKE_ARG...]: configure and build
  local src=$1 build=$2
  shift 2
  cmake -S "$src" -B "$build" -DCMAKE_PREFIX_PATH="$CMAKE_PREFIX_PATH" ${RTM_CMAKE_ARGS:-} "$@" \
    || { echo "rtm: cmake configure of $src FAILED" >&2; return 1; }
  nice -n 19 cmake --build "$build" -j "${RTM_JOBS:-2}" || { echo "rtm: build of $src FAILED" >&2; return 1; }
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
  out=$(readlink -f "${1:?usage: rtm_build_probe DIR [CMAKE_ARG...]}") || return 2
  shift
  _rtm_cmake "$_RTM_HERE/probe" "$out" "$@" && [ -f "$out/Probe.so" ]
}

rtm_build_events() {  # rtm_build_events DIR: the test event source (events/EventSource.cpp) into DIR
  local out
  out=$(readlink -f "${1:?usage: rtm_build_events DIR}") || return 2
  _rtm_cmake "$_RTM_HERE/events" "$out" && [ -f "$out/EventSource.so" ]
}
