#!/usr/bin/env bash
# Install robomda with its test dependencies into .venv and run the whole test
# suite. The README's quick start and .ci/run both call exactly this.
# Extra arguments go to pytest (e.g. tests/run.sh -k orocos).
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian packages the real-tool tests use (compiler and CMake for the fixture
# libraries). Installed when we are root on Debian; otherwise the tests that
# need a missing tool skip and say why.
need=()
command -v cmake >/dev/null 2>&1 || need+=(cmake)
command -v g++ >/dev/null 2>&1 || need+=(g++)
command -v make >/dev/null 2>&1 || need+=(make)
python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || need+=(python3-venv)
if [ "${#need[@]}" -gt 0 ]; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "tests/run.sh: installing Debian packages: ${need[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
  else
    echo "tests/run.sh: not installing ${need[*]} (not root on Debian); tests needing them will skip"
  fi
fi

python3 -m venv .venv
.venv/bin/python -m pip install -q --disable-pip-version-check -e '.[test]'
exec .venv/bin/python -m pytest "$@"
