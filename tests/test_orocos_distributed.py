"""Deploy the distributed fixture on a real RTT / OCL 2.10 built with CORBA and MQueue.

Not in CI (marker ``orocos_toolchain``, like tests/test_orocos_deploy.py): the
toolchain comes from fetched sources (../shared/orocos-reference/toolchain),
here rebuilt with ``-DENABLE_CORBA=ON -DENABLE_MQ=ON`` (omniORB from Debian:
omniidl, libomniorb4-dev, omniorb-nameserver, omniorb for nameclt).

The fixture ``distributed`` runs the headlamp application on two hosts; its
force sensor is a ROS 1 node, which needs rtt_roscomm (not built here), so the
processes-talking test deploys the same model with that execution environment
made Orocos: two hosts (both on the loopback address), four deployer processes,
the shared thread ``controlLoop`` (arm and controller in one SlaveActivity
chain), MQueue streams inside a host (visionValue, wrench), CORBA proxies
between the hosts (channelPosition, toolPose) and local connections. For each
deployment format the two generated start scripts run the processes in their
modelled order; a probe (rttlua-corba) then finds every component in the naming
service, requires it Running and every input port connected, and reads samples
of vision.channelPosition (which adds the arm's toolPose, sent over CORBA, to
the camera's value, sent over MQueue). The mixed model's control process must
refuse to start without rtt_roscomm, naming it, rather than drop the ROS link.
"""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import time
from pathlib import Path

import pytest

from edits import distributed_variant
from robomda.api import generate

ROOT = Path(__file__).resolve().parents[1]
SHARED = Path(os.environ.get("ROBOMDA_SHARED", ROOT.parent / "shared"))
ENV_SH = SHARED / "orocos-reference" / "toolchain" / "env.sh"
INSTALL = Path(os.environ.get("OROCOS_INSTALL", Path.home() / "orocos" / "install"))

pytestmark = [
    pytest.mark.orocos_toolchain,
    pytest.mark.skipif(not ENV_SH.is_file(), reason=f"no {ENV_SH} (../shared beside the checkout)"),
    pytest.mark.skipif(not (INSTALL / "bin" / "deployer-corba").exists(),
                       reason=f"no deployer-corba in {INSTALL}: rebuild RTT and OCL with CORBA and MQueue"),
    pytest.mark.skipif(not (shutil.which("omniNames") and shutil.which("nameclt")),
                       reason="no omniNames / nameclt (Debian omniorb-nameserver, omniorb)"),
]

INSTANCES = ["camera", "vision", "forceSensor", "controlLoop", "arm", "controller"]
INPUTS = [("vision", "visionValue"), ("vision", "toolPose"), ("controller", "channelPosition"),
          ("controller", "wrench"), ("controller", "armState"), ("arm", "armCommand")]
# what a deployer logs when the process at the other end of a CORBA link stops first
SHUTDOWN_NOISE = ("Could not unload Component", "invalidated during write", "caught CORBA exception while marshalling",
                  "unbinding failed")

PROBE = """require("rttlib")
local tc = rtt.getTC()
local depl = tc:getPeer("Deployer")
local ok = true
local function check(cond, what) print((cond and "PROBE ok " or "PROBE FAILED ") .. what); ok = ok and cond end
for _, n in ipairs({%(instances)s}) do
  check(depl:loadComponent(n, "CORBA"), "proxy " .. n)
  check(depl:getPeer(n):getState() == "Running", n .. " Running")
end
for _, e in ipairs({%(inputs)s}) do
  check(depl:getPeer(e[1]):getPort(e[2]):info().connected, e[1] .. "." .. e[2] .. " connected")
end
local ip = rtt.InputPort("int")
tc:addPort(ip, "probe")
check(depl:connect("vision.channelPosition", "lua.probe", rtt.Variable("ConnPolicy")), "probe connected")
local seen, last = 0, nil
for k = 1, 40 do
  local fs, v = ip:read()
  if fs == "NewData" then
    if last ~= nil and v ~= last then seen = seen + 1 end
    last = v
  end
  rtt.sleep(0, 25000000)
end
check(seen >= 3, "vision.channelPosition changes (" .. seen .. " new values)")
ip:disconnect()
print(ok and "PROBE-RESULT: OK" or "PROBE-RESULT: FAILED")
"""


def _bash(script: str, cwd: Path, timeout: int = 1200, **kw) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, OROCOS_INSTALL=str(INSTALL))
    return subprocess.run(["bash", "-c", f"source {ENV_SH} >/dev/null && {script}"], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout, **kw)


def _model(tmp: Path, all_orocos: bool) -> Path:
    """The fixture's model in TMP/cases/distributed (its library is ../headlamp/atomic); all on
    Orocos: its ROS process is an Orocos one too."""
    if all_orocos:
        return distributed_variant(tmp, (' kind="ROS"', "", 1))
    return distributed_variant(tmp, name="mixed.xmi")


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    tmp = tmp_path_factory.mktemp("distributed")
    out = tmp / "distributed"
    generate(_model(tmp, True), out, "orocos")
    done = _bash(f"oro_build_pkg {out}", tmp)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return out


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _named(orb: str) -> set[str]:
    done = subprocess.run(["nameclt", *orb.split(), "list", "TaskContexts"], capture_output=True, text=True, timeout=20)
    return set(done.stdout.split())


def _wait_named(orb: str, names: list[str], scripts: list[subprocess.Popen], logs: list[Path]) -> None:
    deadline = time.monotonic() + 90
    while not set(names) <= _named(orb):
        dead = [s for s in scripts if s.poll() is not None]
        assert not dead and time.monotonic() < deadline, "\n".join(l.read_text(errors="replace")[-3000:] for l in logs)
        time.sleep(0.2)


@pytest.mark.parametrize("fmt", ["lua", "xml", "ops"])
def test_processes_on_two_hosts_talk_to_each_other(fmt: str, built: Path, tmp_path: Path) -> None:
    port = _free_port()
    orb = f"-ORBInitRef NameService=corbaname::127.0.0.1:{port}"
    env = dict(os.environ, NAMESERVICE=f"127.0.0.1:{port}", TMPDIR=str(tmp_path))
    prefix = f"source {ENV_SH} >/dev/null && oro_add_prefix {built}/install && "
    deploy = built / "deploy"
    logs = [tmp_path / "vision.log", tmp_path / "control.log"]
    scripts: list[subprocess.Popen] = []
    try:
        # the vision host first: its start script starts the naming service
        for script, log, names in (("start_vision_pc.sh", logs[0], ["camera", "vision"]),
                                   ("start_control_pc.sh", logs[1], ["forceSensor", "controlLoop", "arm", "controller"])):
            with log.open("w") as out:
                scripts.append(subprocess.Popen(["bash", "-c", prefix + f"exec ./{script} {fmt}"], cwd=deploy, env=env,
                                                stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL))
            _wait_named(orb, names, scripts, logs)
        time.sleep(1)
        probe = tmp_path / "probe.lua"
        probe.write_text(PROBE % {"instances": ", ".join(f'"{n}"' for n in INSTANCES),
                                  "inputs": ", ".join(f'{{"{i}", "{p}"}}' for i, p in INPUTS)})
        run = _bash(f"oro_add_prefix {built}/install && timeout -s KILL 60 rttlua-corba {probe} -- {orb} </dev/null",
                    tmp_path, timeout=120)
        report = [l for l in run.stdout.splitlines() if l.startswith("PROBE")]
        assert "PROBE-RESULT: OK" in report, "\n".join(report) + run.stderr[-3000:]
    finally:
        for s in reversed(scripts):  # the control host stops first, then the vision host and its naming service
            s.terminate()
            s.wait(timeout=60)
    for log in logs:
        errors = [l for l in log.read_text(errors="replace").splitlines()
                  if ("[ ERROR" in l or "[ Warning]" in l) and not any(n in l for n in SHUTDOWN_NOISE)
                  and "doesn't need to be configured (already Running)" not in l]
        assert not errors, errors[:10]


def test_the_ros_link_of_the_mixed_model_needs_rtt_roscomm(built: Path, tmp_path: Path) -> None:
    """The control process of the mixed model streams controller.wrench to the ROS topic
    /wrenchConn: without rtt_roscomm it must not start (naming the missing package)."""
    out = tmp_path / "mixed"
    generate(_model(tmp_path, False), out, "orocos")
    xml = (out / "deploy" / "control_pc_rtt_control.xml").read_text()
    assert "<value>/wrenchConn</value>" in xml and "<value>rtt_roscomm</value>" in xml
    run = _bash(f"oro_add_prefix {built}/install && timeout -s KILL 60 deployer-corba --check "
                f"-s control_pc_rtt_control.xml -- -ORBInitRef NameService=corbaname::127.0.0.1:{_free_port()} </dev/null",
                out / "deploy", timeout=120)
    assert run.returncode != 0
    assert "rtt_rosnode" in run.stdout + run.stderr
