"""toolchains/orocos/build.sh --check: it passes only on an install that can deploy.

On an empty prefix it names what is missing and exits 1 (no toolchain needed,
so this runs everywhere); on the real install (``$OROCOS_HOME``, default
``~/orocos``; marker ``orocos_toolchain``) it runs deployer, rttlua and
rttlua-corba once and exits 0.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BUILD = ROOT / "toolchains" / "orocos" / "build.sh"
HOME = Path(os.environ.get("OROCOS_HOME", Path.home() / "orocos"))


def _check(home: Path) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if k != "OROCOS_INSTALL"}
    return subprocess.run(["bash", str(BUILD), "--check"], env=dict(env, OROCOS_HOME=str(home)),
                          capture_output=True, text=True, timeout=300)


def test_check_fails_on_an_empty_prefix(tmp_path: Path) -> None:
    done = _check(tmp_path)
    assert done.returncode == 1, done.stdout + done.stderr
    assert f"MISSING: {tmp_path}/install/bin/deployer-corba" in done.stdout
    assert f"MISSING: source rtt (https://github.com/orocos-toolchain/rtt.git toolchain-2.10) in {tmp_path}/src" \
        in done.stdout
    assert "check: FAILED" in done.stdout and "runs skipped" in done.stdout


@pytest.mark.orocos_toolchain
@pytest.mark.skipif(not (HOME / "install" / "bin" / "deployer-corba").exists(),
                    reason=f"no Orocos toolchain in {HOME}/install: build it with toolchains/orocos/build.sh")
def test_check_runs_the_tools_of_a_real_install() -> None:
    done = _check(HOME)
    assert done.returncode == 0, done.stdout + done.stderr
    for run in ("deployer --version: OK", "rttlua tiny.lua (typekit, component load): OK",
                "rttlua-corba corba.lua (naming service on 127.0.0.1:"):
        assert run in done.stdout
    assert "check: OK" in done.stdout
