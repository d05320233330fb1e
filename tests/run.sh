#!/usr/bin/env bash
# Install robomda with its test dependencies into .venv and run the whole test
# suite. The README's quick start and .ci/run both call exactly this.
# Extra arguments go to pytest (e.g. tests/run.sh -k orocos).
# Tests run on every core (pytest-xdist, -n auto).
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian packages the real-tool tests use: compiler and CMake for the fixture
# libraries, Saxon-HE Java and Node.js (for SaxonJS) for the engine
# portability tests, PlantUML for the diagrams. Installed when we are root on Debian; otherwise the
# tests that need a missing tool skip and say why.
need=()
command -v cmake >/dev/null 2>&1 || need+=(cmake)
command -v g++ >/dev/null 2>&1 || need+=(g++)
command -v make >/dev/null 2>&1 || need+=(make)
command -v java >/dev/null 2>&1 || need+=(default-jre-headless)
[ -f /usr/share/java/Saxon-HE.jar ] || need+=(libsaxonhe-java)
command -v node >/dev/null 2>&1 || need+=(nodejs)
command -v npm >/dev/null 2>&1 || need+=(npm)
python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || need+=(python3-venv)
# PlantUML (and Graphviz, which it lays component and deployment diagrams out
# with) for tests/test_diagrams.py: every fixture's diagrams render to SVG.
command -v plantuml >/dev/null 2>&1 || need+=(plantuml)
command -v dot >/dev/null 2>&1 || need+=(graphviz)
# valgrind for bench/instructions.py, which .ci/run runs as a smoke run: the
# stylesheets' instructions counted, the one measure a shared machine leaves steady
command -v valgrind >/dev/null 2>&1 || need+=(valgrind)
# ROS 1 (Debian's own packages) for tests/test_ros.py: catkin build, catkin_lint,
# roslaunch loader, roscore / rostopic / rosnode / rosservice, rostest (the generated system tests), std_msgs, std_srvs.
[ -x /usr/bin/catkin_make ] || need+=(catkin)
[ -x /usr/bin/catkin_lint ] || need+=(catkin-lint)
[ -x /usr/bin/roscore ] || need+=(ros-core-dev)
[ -x /usr/bin/roslaunch ] || need+=(python3-roslaunch)
[ -x /usr/bin/rostopic ] || need+=(python3-rostopic)
[ -x /usr/bin/rosnode ] || need+=(python3-rosnode)
[ -x /usr/bin/rosservice ] || need+=(python3-rosservice)
[ -x /usr/bin/rostest ] || need+=(python3-rostest)
/usr/bin/python3 -c 'import rosgraph, rospkg, yaml' >/dev/null 2>&1 || need+=(python3-rosgraph python3-rospkg python3-yaml)
ls /usr/lib/*/cmake/rostest/rostestConfig.cmake >/dev/null 2>&1 || need+=(librostest-dev)
[ -f /usr/include/std_msgs/Float64.h ] || need+=(ros-core-dev)
[ -f /usr/include/std_srvs/Empty.h ] || need+=(libstd-srvs-dev)
if [ "${#need[@]}" -gt 0 ]; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "tests/run.sh: installing Debian packages: ${need[*]}"
    # another apt/dpkg run (an unattended upgrade, a toolchain build) holds the
    # lock for a while: wait for it instead of skipping the real-tool tests
    apt=(apt-get -o DPkg::Lock::Timeout=600)
    "${apt[@]}" update -qq
    if ! DEBIAN_FRONTEND=noninteractive "${apt[@]}" install -y -qq "${need[@]}" >/dev/null; then
      # one package that cannot be installed (e.g. npm beside a nodejs that
      # bundles it) must not keep the others out; what is still missing makes
      # its tests skip, or fail under CI, naming it
      for pkg in "${need[@]}"; do
        DEBIAN_FRONTEND=noninteractive "${apt[@]}" install -y -qq "$pkg" >/dev/null \
          || echo "tests/run.sh: could not install $pkg"
      done
    fi
  else
    echo "tests/run.sh: not installing ${need[*]} (not root on Debian); tests needing them will skip"
  fi
fi

# SaxonJS (npm package xslt3, pinned by tests/engines/package-lock.json)
if command -v npm >/dev/null 2>&1 && [ ! -f tests/engines/node_modules/xslt3/xslt3.js ]; then
  npm ci --prefix tests/engines --no-audit --no-fund --loglevel=error >/dev/null \
    || echo "tests/run.sh: npm ci failed; the SaxonJS tests will skip"
fi

python3 -m venv .venv
.venv/bin/python -m pip install -q --disable-pip-version-check -e '.[test]'
# One worker per core (pytest-xdist); ROBOMDA_TEST_JOBS=0 runs in this process
# (pdb, -x), and a later -n of the caller's wins. loadgroup: the tests of a costly
# module fixture (tests/conftest.py) stay on one worker.
exec .venv/bin/python -m pytest -n "${ROBOMDA_TEST_JOBS:-auto}" --dist loadgroup "$@"
