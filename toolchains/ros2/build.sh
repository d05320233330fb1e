#!/usr/bin/env bash
# Builds the minimal ROS 2 Jazzy that robomda's ros2_toolchain tests use, from public sources, into
# $ROS2_PREFIX (default ~/ros2), on Debian 12 (bookworm) with Python 3.11:
#
#   $ROS2_PREFIX/src, src_py      the repositories of sources.tsv (git clone --depth 1 --branch REF)
#   $ROS2_PREFIX/venv             colcon, empy 3.3.4 and the other PyPI tools, pinned (requirements.txt)
#   $ROS2_PREFIX/install          stage 1: the C++ core (rclcpp, rclcpp_components, rclcpp_lifecycle,
#                                 std_msgs, std_srvs, lifecycle_msgs, rmw_cyclonedds_cpp), merged install
#   $ROS2_PREFIX/install_py       stage 2, an overlay: rclpy, launch, launch_ros, launch_testing, a ros2cli
#                                 subset, and the interface packages again with their Python bindings
#   $ROS2_PREFIX/tools            uncrustify at the version ament_uncrustify's configuration is for (plain
#                                 CMake; what uncrustify_vendor would fetch), for colcon test's linters
#
# Usage: build.sh [--check] [--no-apt] [--sources-only] [--stage1-only] [--cmake-clean-cache]
#   --check              build nothing: report what is present and what is missing (Debian packages,
#                        sources and their commits, venv pins, every package of both stages installed),
#                        and uncrustify, then run the tree once: import the Python type support of rcl_interfaces,
#                        lifecycle_msgs and std_msgs, and `ros2 launch` a tiny launch file; exit
#                        status 1 if anything is missing or a run fails (a tree that cannot launch)
#   --no-apt             do not install Debian packages (only check they are there)
#   --sources-only       stop after fetching the sources (to build later, offline)
#   --stage1-only        stop after the C++ core (enough to build generated packages, not to launch them)
#   --cmake-clean-cache  passed to colcon in both stages (after changing interface packages, so they
#                        find the overlay's service_msgs etc.); stage 2's second pass always uses it
# Environment: ROS2_PREFIX; MIRROR, a folder of fetched bare mirrors (MIRROR/ros2+rclcpp/repo, ...), cloned
# instead of the public URL when set; JOBS (make jobs and colcon workers, default 2); NICE (default 19).
# Source env.sh beside this script to use the result. Takes ~30 min on 2 cores.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
PREFIX=${ROS2_PREFIX:-$HOME/ros2}
JOBS=${JOBS:-2}
NICE=${NICE:-19}
CHECK=0 APT=1 STAGE2=1 SOURCES_ONLY=0 CLEAN=()
for arg in "$@"; do
  case $arg in
    --check) CHECK=1 ;;
    --no-apt) APT=0 ;;
    --sources-only) SOURCES_ONLY=1 ;;
    --stage1-only) STAGE2=0 ;;
    --cmake-clean-cache) CLEAN=(--cmake-clean-cache) ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "build.sh: unknown option $arg (see --help)" >&2; exit 2 ;;
  esac
done

# Debian packages: compilers and tools, then the system libraries the vendor packages wrap
APT_PACKAGES=(build-essential cmake git ca-certificates python3-venv python3-dev cppcheck libxml2-utils
              libyaml-dev libspdlog-dev libconsole-bridge-dev libacl1-dev libssl-dev libtinyxml2-dev pybind11-dev)
# what each stage is built up to (colcon --packages-up-to), and what it leaves out of its graph
# (--packages-ignore: with --packages-skip the package stays in the graph and rcl waits for test_msgs)
STAGE1_UP_TO=(rclcpp_components rclcpp_lifecycle std_msgs std_srvs lifecycle_msgs
              rosidl_default_generators rosidl_default_runtime rmw_cyclonedds_cpp rmw_implementation
              ament_lint_auto ament_lint_common)
STAGE1_IGNORE=(test_msgs)
STAGE2_PATHS=(src_py src/rcl_interfaces src/common_interfaces src/unique_identifier_msgs src/rpyutils src/rcl/rcl_action
              src/rosidl_defaults)
STAGE2_FIRST=(rosidl_generator_py python_cmake_module)
STAGE2_UP_TO=(rclpy launch launch_xml launch_yaml launch_ros ros2launch ros2lifecycle ros2topic ros2node ros2run
              ros2pkg ros2component ros2param ros2service launch_testing launch_testing_ros launch_testing_ament_cmake
              std_msgs std_srvs lifecycle_msgs composition_interfaces type_description_interfaces)
STAGE2_IGNORE=(test_msgs ros2cli_test_interfaces test_launch_ros)

# say, missing, apt_step (toolchains/common.sh)
source "$HERE/../common.sh"

# --- Debian packages ------------------------------------------------------------------------------
apt_step

# --- sources ----------------------------------------------------------------------------------------
# From MIRROR/<owner>+<name>/repo when that exists (fetched bare mirrors: a full history, so the verified
# commit is checked out directly), else a shallow clone of the public URL's branch, after which the
# verified commit is fetched on its own (GitHub serves any reachable commit); if that fails, the script
# says which commit it got. An existing clone is only compared with the verified commit.
mirror_of() {  # url -> the mirror's git dir, or nothing
  local slug
  slug=${1#https://github.com/}; slug=${slug%.git}
  if [ -n "${MIRROR:-}" ] && [ -d "$MIRROR/${slug/\//+}/repo" ]; then echo "$MIRROR/${slug/\//+}/repo"; fi
}
while IFS=$'\t' read -r dir name url ref commit; do
  case $dir in ''|'#'*) continue ;; esac
  dest=$PREFIX/$dir/$name
  if [ -d "$dest" ]; then
    if [ -d "$dest/.git" ]; then
      got=$(git -C "$dest" rev-parse HEAD)
      [ "$got" = "$commit" ] || say "$dir/$name: at $got, not the verified $commit"
    fi
    continue
  fi
  if [ $CHECK = 1 ]; then missing "source $dir/$name ($url $ref)"; continue; fi
  mkdir -p "$PREFIX/$dir"
  from=$(mirror_of "$url")
  if [ -n "$from" ]; then
    git clone -q --no-checkout "$from" "$dest"
    git -C "$dest" -c advice.detachedHead=false checkout -q "$commit"
    continue
  fi
  git -c advice.detachedHead=false clone -q --depth 1 --branch "$ref" "$url" "$dest"
  got=$(git -C "$dest" rev-parse HEAD)
  if [ "$got" != "$commit" ]; then
    if git -C "$dest" fetch -q --depth 1 origin "$commit" && git -C "$dest" -c advice.detachedHead=false checkout -q "$commit"; then
      say "$dir/$name: $ref has moved to $got; checked out the verified $commit"
    else
      say "WARNING: $dir/$name: could not fetch the verified $commit; building $ref at $got"
    fi
  fi
done < "$HERE/sources.tsv"
if [ $CHECK = 1 ] && [ $MISSING = 0 ]; then
  say "sources: all present in $PREFIX/src, $PREFIX/src_py, $PREFIX/tools (exported trees without .git cannot show their commit)"
fi
if [ $SOURCES_ONLY = 1 ] && [ $CHECK = 0 ]; then say "sources fetched into $PREFIX"; exit 0; fi

# --- venv with the PyPI tools -------------------------------------------------------------------------
VENV=$PREFIX/venv
pins_missing() {
  local frozen pin
  frozen=$("$VENV/bin/python" -m pip freeze --all 2>/dev/null | tr '[:upper:]_' '[:lower:]-')
  while read -r pin; do
    case $pin in ''|'#'*) continue ;; esac
    pin=$(echo "$pin" | tr '[:upper:]_' '[:lower:]-')
    grep -qx "$pin" <<<"$frozen" || echo "$pin"
  done < "$HERE/requirements.txt"
}
if [ ! -x "$VENV/bin/python" ]; then
  if [ $CHECK = 1 ]; then missing "venv $VENV"; else python3 -m venv "$VENV"; fi
fi
if [ -x "$VENV/bin/python" ]; then
  mapfile -t unpinned < <(pins_missing)
  if [ ${#unpinned[@]} -eq 0 ]; then
    say "venv: every pin of requirements.txt installed"
  elif [ $CHECK = 1 ]; then
    missing "venv pins ${unpinned[*]}"
  else
    "$VENV/bin/python" -m pip install -q -r "$HERE/requirements.txt"
  fi
fi

# --- uncrustify ----------------------------------------------------------------------------------------
# ament_uncrustify's configuration is for uncrustify 0.78 (Debian ships 0.72, which formats otherwise):
# built from tools/uncrustify (sources.tsv) into $PREFIX/tools; env.sh puts its bin/ on PATH
UNCRUSTIFY=$PREFIX/tools/bin/uncrustify
if [ -x "$UNCRUSTIFY" ]; then
  say "uncrustify: $("$UNCRUSTIFY" --version)"
elif [ $CHECK = 1 ]; then
  missing "uncrustify in $PREFIX/tools/bin"
elif [ -d "$PREFIX/tools/uncrustify" ]; then
  say "uncrustify into $PREFIX/tools"
  cmake -S "$PREFIX/tools/uncrustify" -B "$PREFIX/tools/uncrustify-build" -DCMAKE_BUILD_TYPE=Release \
    -DNoGitVersionString=ON "-DCMAKE_INSTALL_PREFIX=$PREFIX/tools" >/dev/null
  nice -n "$NICE" cmake --build "$PREFIX/tools/uncrustify-build" -j "$JOBS" >/dev/null
  cmake --install "$PREFIX/tools/uncrustify-build" >/dev/null
fi

# --- colcon stages --------------------------------------------------------------------------------
# -O0 (CMAKE_BUILD_TYPE=None), no tests, no LTTng tracepoints, Cyclone DDS without shared memory, LTO,
# security or SSL; the Python of the venv everywhere (empy 3 for rosidl).
CMAKE_ARGS=(-DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=None
            "-DPython3_EXECUTABLE=$VENV/bin/python3" "-DPYTHON_EXECUTABLE=$VENV/bin/python3"
            -DRMW_IMPLEMENTATION=rmw_cyclonedds_cpp)
STAGE1_CMAKE_ARGS=(-DBUILD_DDSPERF=OFF -DENABLE_SHM=OFF -DENABLE_LTO=OFF -DENABLE_SECURITY=OFF -DENABLE_SSL=OFF
                   -DTRACETOOLS_TRACEPOINTS_EXCLUDED=ON)
COLCON_COMMON=(--merge-install --parallel-workers "$JOBS" --event-handlers console_direct- console_cohesion+)

# every package a stage must install: colcon's own answer for the stage's package selection
stage_check() {  # stage-name install-base colcon-list-args...
  local stage=$1 base=$2 pkg n=0 absent=()
  shift 2
  while read -r pkg; do
    n=$((n + 1))
    [ -e "$PREFIX/$base/share/colcon-core/packages/$pkg" ] || absent+=("$pkg")  # colcon's mark, plain CMake too
  done < <(cd "$PREFIX" && "$VENV/bin/colcon" list --names-only "$@")
  if [ "$n" = 0 ]; then missing "$stage: colcon lists no package"; return; fi
  if [ ${#absent[@]} -eq 0 ]; then say "$stage: all $n packages installed in $PREFIX/$base"
  else missing "$stage: ${#absent[@]} of $n packages not installed in $PREFIX/$base: ${absent[*]}"; fi
}

STAGE1_SELECT=(--base-paths src --packages-up-to "${STAGE1_UP_TO[@]}" --packages-ignore "${STAGE1_IGNORE[@]}")
STAGE2_SELECT=(--base-paths "${STAGE2_PATHS[@]}" --packages-up-to "${STAGE2_UP_TO[@]}" --packages-ignore "${STAGE2_IGNORE[@]}")

# one run of what a generated package needs, in a fresh shell with env.sh sourced: the Python type support
# of rcl_interfaces (what launch_ros's own node needs: a tree whose interfaces were configured before the
# overlay's service_msgs installs them without it, and then every `ros2 launch` fails) and of the
# interfaces generated packages use, and a tiny `ros2 launch`
check_runs() {
  local tmp
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/ros2-check.XXXXXX")
  mkdir "$tmp/home"
  cat > "$tmp/typesupport.py" <<'PY'
from rclpy.type_support import check_for_type_support
from rcl_interfaces.msg import ParameterEvent
from rcl_interfaces.srv import GetParameters, SetParameters
from lifecycle_msgs.srv import ChangeState
from std_msgs.msg import Float64
for kind in (ParameterEvent, GetParameters, SetParameters, ChangeState, Float64):
    check_for_type_support(kind)  # raises when the compiled type support does not import
print("TYPESUPPORT-OK")
PY
  cat > "$tmp/tiny.launch.xml" <<'XML'
<launch>
  <executable cmd="echo LAUNCH-OK" output="screen"/>
</launch>
XML
  local env=(env "ROS2_PREFIX=$PREFIX" "ROS_HOME=$tmp/home" "ROS_DOMAIN_ID=${ROS_DOMAIN_ID:-42}")
  local sourced="set +u; source '$HERE/env.sh' >/dev/null"
  _run "import of the Python type support (rcl_interfaces, lifecycle_msgs, std_msgs)" TYPESUPPORT-OK \
    "${env[@]}" bash -c "$sourced && python3 '$tmp/typesupport.py'"
  RUN_TIMEOUT=120 _run "ros2 launch of a tiny launch file" "LAUNCH-OK" \
    "${env[@]}" bash -c "$sourced && ros2 launch '$tmp/tiny.launch.xml' 2>&1; s=\$?; [ \$s = 0 ] || echo EXIT \$s; exit \$s"
  rm -rf "$tmp"
}

if [ $CHECK = 1 ]; then
  if [ -x "$VENV/bin/colcon" ]; then
    stage_check "stage 1" install "${STAGE1_SELECT[@]}"
    [ $STAGE2 = 1 ] && stage_check "stage 2" install_py "${STAGE2_SELECT[@]}"
  else
    missing "colcon in $VENV (stages not checked)"
  fi
  if [ $MISSING = 1 ]; then say "runs skipped: the install is incomplete"
  elif [ $STAGE2 = 1 ]; then check_runs; fi
  if [ $MISSING = 0 ]; then say "check: OK ($PREFIX)"; else say "check: incomplete ($PREFIX)"; fi
  exit $MISSING
fi

cd "$PREFIX"
# shellcheck disable=SC1091
source "$VENV/bin/activate"
export MAKEFLAGS=-j$JOBS

say "stage 1 (C++ core) into $PREFIX/install"
nice -n "$NICE" colcon build "${STAGE1_SELECT[@]}" --install-base install --build-base build "${COLCON_COMMON[@]}" \
  "${CLEAN[@]}" --cmake-args "${CMAKE_ARGS[@]}" "${STAGE1_CMAKE_ARGS[@]}"
[ $STAGE2 = 1 ] || { say "done (stage 1 only)"; exit 0; }

# colcon's setup scripts read unset variables (COLCON_TRACE, ...): sourced with set -u off
set +u
# shellcheck disable=SC1091
source install/setup.bash
set -u
# Stage 2 in two passes: the interface packages build their Python bindings with rosidl_generator_py,
# which their CMake only finds if it is on PYTHONPATH when they are configured. So first the generator,
# then, with the overlay sourced, everything, from a clean CMake cache.
say "stage 2, pass 1 (rosidl_generator_py) into $PREFIX/install_py"
nice -n "$NICE" colcon build --base-paths "${STAGE2_PATHS[@]}" --packages-up-to "${STAGE2_FIRST[@]}" \
  --packages-ignore "${STAGE2_IGNORE[@]}" --install-base install_py --build-base build_py "${COLCON_COMMON[@]}" \
  "${CLEAN[@]}" --cmake-args "${CMAKE_ARGS[@]}"
set +u
# shellcheck disable=SC1091
source install_py/local_setup.bash
set -u
say "stage 2, pass 2 (rclpy, launch_ros, ros2cli, interfaces with Python) into $PREFIX/install_py"
nice -n "$NICE" colcon build "${STAGE2_SELECT[@]}" --install-base install_py --build-base build_py "${COLCON_COMMON[@]}" \
  --cmake-clean-cache --cmake-args "${CMAKE_ARGS[@]}"
say "done: source $HERE/env.sh (ROS2_PREFIX=$PREFIX)"
