"""Deploy the distributed fixture on a real RTT / OCL 2.10 built with CORBA and MQueue.

Not in CI (marker ``orocos_toolchain``, like tests/test_orocos_deploy.py): the
toolchain is built from public sources by toolchains/orocos/build.sh (omniORB
from Debian: omniidl, libomniorb4-dev, omniorb-nameserver, omniorb for
nameclt); these tests use the helpers of toolchains/orocos/env.sh.

The fixture ``distributed`` runs the headlamp application on two hosts; its
force sensor is a ROS 1 node, which needs rtt_roscomm (toolchains/orocos/build-ros.sh; tests/test_rtt_ros.py runs it), so the
processes-talking tests deploy the same model with that execution environment
made Orocos: two hosts (both on loopback addresses), four deployer processes,
the shared thread ``controlLoop`` (arm and controller in one SlaveActivity
chain), MQueue streams inside a host (visionValue, wrench), CORBA proxies
between the hosts (channelPosition, toolPose) and local connections. A second
variant's vision component takes 3 s to configure (its realizing class
sleeps), so a start script that waited only for registration would start the
controller first. For each deployment format and variant the two generated
start scripts run the processes in their modelled order, each process only
once the components before it are Running (the scripts' time-stamped lines
say when); a probe (rttlua-corba) then finds every component Running, every
input connected and samples of vision.channelPosition changing (the arm's
toolPose, sent over CORBA, added to the camera's value, sent over MQueue).
SIGTERM to the control host's script, then the vision host's, must stop
everything with no ERROR, CRITICAL or FATAL line in any process's log (one log
per process) or script output. The check scripts run to a verdict and exit;
a start script whose naming service or earlier component never comes fails
in time, naming it. The mixed model's control process must refuse to start
without rtt_roscomm, naming it, rather than drop the ROS link.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import socket
import subprocess
import time
from pathlib import Path

import pytest

from edits import distributed_variant, edit
from robomda.api import generate

ROOT = Path(__file__).resolve().parents[1]
ENV_SH = ROOT / "toolchains" / "orocos" / "env.sh"
INSTALL = Path(os.environ.get("OROCOS_INSTALL", Path.home() / "orocos" / "install"))
CASES = ROOT / "fixtures" / "cases"

pytestmark = [
    pytest.mark.orocos_toolchain,
    pytest.mark.skipif(not (INSTALL / "bin" / "deployer-corba").exists(),
                       reason=f"no deployer-corba in {INSTALL}: build the toolchain with toolchains/orocos/build.sh"),
    pytest.mark.skipif(not (shutil.which("omniNames") and shutil.which("nameclt")),
                       reason="no omniNames / nameclt (Debian omniorb-nameserver, omniorb; toolchains/orocos/build.sh)"),
]

INSTANCES = ["camera", "vision", "forceSensor", "controlLoop", "arm", "controller"]
INPUTS = [("vision", "visionValue"), ("vision", "toolPose"), ("controller", "channelPosition"),
          ("controller", "wrench"), ("controller", "armState"), ("arm", "armCommand")]
BAD = re.compile(r"\[ *(ERROR|CRITICAL|FATAL) *\]|\bERROR\b|CRITICAL|FATAL")
STAMP = re.compile(r"\[(\d+\.\d+)\]: (.*)$")

PROBE = """require("rttlib")
local tc = rtt.getTC()
local depl = tc:getPeer("Deployer")
depl:getProperty("AutoUnload"):set(false)
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
depl:getOperation("shutdown")()
rtt.sleep(0, 500000000)
os.exit(ok and 0 or 1)
"""


def _bash(script: str, cwd: Path, timeout: int = 1200, env: dict[str, str] | None = None
          ) -> subprocess.CompletedProcess[str]:
    env = dict(env or os.environ, OROCOS_INSTALL=str(INSTALL))
    return subprocess.run(["bash", "-c", f"source {ENV_SH} >/dev/null && {script}"], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout)


def _all_orocos(tmp: Path) -> Path:
    """The fixture's model in TMP/cases/distributed, its ROS process an Orocos one too."""
    return distributed_variant(tmp, (' kind="ROS"', "", 1))


def _build(tmp: Path, model: Path) -> Path:
    out = tmp / "distributed"
    generate(model, out, "orocos")
    done = _bash(f"oro_build_pkg {out}", tmp)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return out


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    tmp = tmp_path_factory.mktemp("distributed")
    return _build(tmp, _all_orocos(tmp))


@pytest.fixture(scope="module")
def built_slow(tmp_path_factory) -> Path:
    """The same, with a copy of the headlamp library whose GumChannelDetector (vision's realizing
    class) takes 3 s in configure()."""
    tmp = tmp_path_factory.mktemp("slow")
    (tmp / "cases").mkdir()
    shutil.copytree(CASES / "headlamp", tmp / "cases" / "headlamp")
    edit(tmp / "cases" / "headlamp" / "atomic" / "src" / "GumChannelDetector.cpp", "bool GumChannelDetector::configure() {",
         "bool GumChannelDetector::configure() {\n  std::this_thread::sleep_for(std::chrono::seconds(3));")
    source = tmp / "cases" / "headlamp" / "atomic" / "src" / "GumChannelDetector.cpp"
    source.write_text("#include <chrono>\n#include <thread>\n" + source.read_text(encoding="utf-8"), encoding="utf-8")
    return _build(tmp, _all_orocos(tmp))


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Hosts:
    """The two start scripts of a built package, on a naming service of their own (127.0.0.1:PORT)."""

    def __init__(self, built: Path, tmp: Path, fmt: str) -> None:
        self.deploy, self.tmp, self.fmt = built / "deploy", tmp, fmt
        self.port = _free_port()
        self.env = dict(os.environ, NAMESERVICE=f"127.0.0.1:{self.port}", LOGDIR=str(tmp / "logs"), TMPDIR=str(tmp),
                        OROCOS_INSTALL=str(INSTALL))
        self.prefix = f"source {ENV_SH} >/dev/null && oro_add_prefix {built}/install && "
        self.scripts: dict[str, subprocess.Popen] = {}
        self.outputs: dict[str, Path] = {}

    def start(self, *hosts: str) -> None:
        """Start deploy/start_HOST.sh of each host, in this order, and wait until each says every
        process of its host started (the processes of the two hosts alternate in the start order)."""
        for host in hosts:
            out = self.tmp / f"start_{host}.out"
            self.outputs[host] = out
            with out.open("w") as f:
                self.scripts[host] = subprocess.Popen(["bash", "-c", self.prefix + f"exec ./start_{host}.sh {self.fmt}"],
                                                      cwd=self.deploy, env=self.env, stdout=f, stderr=subprocess.STDOUT,
                                                      stdin=subprocess.DEVNULL)
            time.sleep(1)
        deadline = time.monotonic() + 180
        while not all("started; Ctrl-C stops them" in self.outputs[h].read_text(errors="replace") for h in hosts):
            assert all(self.scripts[h].poll() is None for h in hosts), self.report()
            assert time.monotonic() < deadline, self.report()
            time.sleep(0.2)

    def stop(self, host: str) -> int:
        script = self.scripts.pop(host)
        script.send_signal(signal.SIGTERM)
        return script.wait(timeout=90)

    def stop_all(self) -> None:
        for host in reversed(list(self.scripts)):
            self.stop(host)

    def lines(self, host: str) -> list[tuple[float, str]]:
        """The time-stamped lines of the start script of HOST: (time, text)."""
        found = (STAMP.search(line) for line in self.outputs[host].read_text(errors="replace").splitlines())
        return [(float(m.group(1)), m.group(2)) for m in found if m]

    def logs(self) -> dict[str, str]:
        """Every text a process or a script wrote: the per-process logs, the scripts' outputs."""
        files = sorted((self.tmp / "logs").glob("*.log")) + list(self.outputs.values())
        return {f.name: f.read_text(errors="replace") for f in files}

    def report(self) -> str:
        return "\n".join(f"== {name}\n{text[-2500:]}" for name, text in self.logs().items())


def _when(lines: list[tuple[float, str]], text: str) -> float:
    times = [t for t, line in lines if line.startswith(text)]
    assert times, f"no line {text!r} in {lines}"
    return times[0]


def _probe(built: Path, hosts: Hosts) -> list[str]:
    probe = hosts.tmp / "probe.lua"
    probe.write_text(PROBE % {"instances": ", ".join(f'"{n}"' for n in INSTANCES),
                              "inputs": ", ".join(f'{{"{i}", "{p}"}}' for i, p in INPUTS)})
    run = _bash(f"oro_add_prefix {built}/install && ORO_LOGFILE={hosts.tmp}/probe.log timeout -s KILL 60 rttlua-corba "
                f"{probe} -- -ORBInitRef NameService=corbaname::127.0.0.1:{hosts.port} "
                "-ORBendPoint giop:tcp:127.0.0.1: </dev/null", hosts.tmp, timeout=120)
    report = [line for line in run.stdout.splitlines() if line.startswith("PROBE")]
    assert run.returncode == 0 and "PROBE-RESULT: OK" in report, "\n".join(report) + run.stderr[-3000:]
    return report


def _run_two_hosts(built: Path, tmp: Path, fmt: str) -> Hosts:
    """Start both hosts (vision first: it starts the naming service), probe, stop them in the reverse
    order; every log clean."""
    hosts = Hosts(built, tmp, fmt)
    try:
        hosts.start("vision_pc", "control_pc")
        _probe(built, hosts)
        assert hosts.stop("control_pc") == 0, hosts.report()
        assert hosts.stop("vision_pc") == 0, hosts.report()
    finally:
        hosts.stop_all()
    logs = hosts.logs()
    assert {"vision_pc_rtt_camera.log", "vision_pc_rtt_vision.log", "control_pc_ros_sensor.log",
            "control_pc_rtt_control.log"} <= set(logs)
    bad = [f"{name}: {line}" for name, text in logs.items() for line in text.splitlines() if BAD.search(line)]
    assert not bad, "\n".join(bad[:20])
    return hosts


def _check_order(hosts: Hosts, slow: bool) -> None:
    """Each process started once the components of the processes before it were Running, in the
    modelled order (1 rttCamera, 2 rosSensor on the control host, 3 rttVision, 4 rttControl), and
    stopped in the reverse order, each process's components first. A component is Running from the
    first time either host's script saw it so."""
    vision, control = hosts.lines("vision_pc"), hosts.lines("control_pc")

    def up(name: str) -> float:
        return min(t for t, line in vision + control if line == f"{name} Running")

    assert _when(control, "starting process 2 'rosSensor'") >= up("camera")
    assert _when(vision, "starting process 3 'rttVision'") >= max(up("camera"), up("forceSensor"))
    assert _when(control, "starting process 4 'rttControl'") >= up("vision")
    assert up("controller") > up("vision")
    if slow:  # vision took its 3 s to configure, and the control process waited for it
        assert up("vision") - _when(vision, "starting process 3 'rttVision'") >= 3.0
    assert _when(control, "stopping control_pc_rtt_control controller arm controlLoop") \
        < _when(control, "stopping control_pc_ros_sensor forceSensor")
    assert _when(vision, "stopping vision_pc_rtt_vision vision") < _when(vision, "stopping vision_pc_rtt_camera camera")


@pytest.mark.parametrize("fmt", ["lua", "xml", "ops"])
def test_two_hosts_start_in_order_talk_and_stop_cleanly(fmt: str, built: Path, tmp_path: Path) -> None:
    _check_order(_run_two_hosts(built, tmp_path, fmt), slow=False)


@pytest.mark.parametrize("fmt", ["lua", "xml", "ops"])
def test_a_slow_configure_keeps_the_order(fmt: str, built_slow: Path, tmp_path: Path) -> None:
    _check_order(_run_two_hosts(built_slow, tmp_path, fmt), slow=True)


def test_check_scripts_reach_a_verdict_and_exit(built: Path, tmp_path: Path) -> None:
    """The camera process's check with only the naming service up, the control process's with the
    processes before it up (the vision host, and the control host's rosSensor process run by hand):
    each prints DEPLOY-RESULT: OK and exits 0 under rttlua-corba, and leaves no error behind in the
    processes it talked to; under rttlua (no CORBA) it fails at once, saying what to run."""
    hosts = Hosts(built, tmp_path, "lua")
    orb = f"-ORBInitRef NameService=corbaname::127.0.0.1:{hosts.port} -ORBendPoint giop:tcp:127.0.0.1:"
    prefix = f"oro_add_prefix {built}/install && cd {hosts.deploy} && ORO_LOGFILE={tmp_path}/logs/check.log "
    (tmp_path / "logs").mkdir()
    plain = _bash(prefix + "timeout -s KILL 60 rttlua control_pc_rtt_control-check.lua </dev/null", tmp_path, 120)
    assert plain.returncode == 1 and "no CORBA deployer: run rttlua-corba" in plain.stdout, plain.stdout + plain.stderr
    names = subprocess.Popen(["omniNames", "-start", str(hosts.port), "-ignoreport", "-ORBendPoint",
                              f"giop:tcp:127.0.0.1:{hosts.port}", "-logdir", str(tmp_path)],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(1)
        camera = _bash(prefix + f"timeout -s KILL 60 rttlua-corba vision_pc_rtt_camera-check.lua -- {orb} </dev/null",
                       tmp_path, 120)
        assert camera.returncode == 0 and "DEPLOY-RESULT: OK" in camera.stdout, camera.stdout + camera.stderr
    finally:
        names.terminate()
        names.wait(timeout=30)
    sensor = subprocess.Popen(["bash", "-c", hosts.prefix + f"sleep 3 && ORO_LOGFILE={tmp_path}/logs/sensor.log exec "
                               f"deployer-corba --DeployerName control_pc_ros_sensor -s control_pc_ros_sensor.lua -- {orb}"],
                              cwd=hosts.deploy, env=hosts.env, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT,
                              stdin=subprocess.DEVNULL)
    try:
        hosts.start("vision_pc")
        control = _bash(prefix + f"timeout -s KILL 60 rttlua-corba control_pc_rtt_control-check.lua -- {orb} </dev/null",
                        tmp_path, 120)
        assert control.returncode == 0 and "DEPLOY-RESULT: OK" in control.stdout, control.stdout + control.stderr
        time.sleep(2)  # vision writes on: any channel the check left behind would fail now
    finally:
        sensor.send_signal(signal.SIGINT)
        sensor.wait(timeout=60)
        hosts.stop_all()
    bad = [f"{name}: {line}" for name, text in hosts.logs().items() for line in text.splitlines() if BAD.search(line)]
    assert not bad, bad[:10]


def test_a_start_script_fails_in_time_naming_what_it_waited_for(built: Path, tmp_path: Path) -> None:
    """No naming service: the control host's script gives up after WAIT s, naming its address; a
    naming service without the vision host: it names the component it waited for."""
    hosts = Hosts(built, tmp_path, "lua")
    env = dict(hosts.env, WAIT="3")
    run = _bash(f"oro_add_prefix {built}/install && timeout -s KILL 60 ./start_control_pc.sh", hosts.deploy, 90, env)
    assert run.returncode == 1, run.stdout + run.stderr
    assert f"no naming service answers at 127.0.0.1:{hosts.port} after 3 s" in run.stderr
    names = subprocess.Popen(["omniNames", "-start", str(hosts.port), "-ignoreport", "-ORBendPoint",
                              f"giop:tcp:127.0.0.1:{hosts.port}", "-logdir", str(tmp_path)],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(1)
        run = _bash(f"oro_add_prefix {built}/install && timeout -s KILL 60 ./start_control_pc.sh", hosts.deploy, 90, env)
    finally:
        names.terminate()
        names.wait(timeout=30)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "component camera is not in the naming service at 127.0.0.1:" in run.stderr


def test_the_ros_link_of_the_mixed_model_needs_rtt_roscomm(built: Path, tmp_path: Path) -> None:
    """The control process of the mixed model streams controller.wrench to the ROS topic
    /wrenchConn: without rtt_roscomm it must not start (naming the missing package)."""
    out = tmp_path / "mixed"
    generate(distributed_variant(tmp_path, name="mixed.xmi"), out, "orocos")
    xml = (out / "deploy" / "control_pc_rtt_control.xml").read_text()
    assert "<value>/wrenchConn</value>" in xml and "<value>rtt_roscomm</value>" in xml
    run = _bash(f"oro_add_prefix {built}/install && timeout -s KILL 60 deployer-corba --check "
                f"-s control_pc_rtt_control.xml -- -ORBInitRef NameService=corbaname::127.0.0.1:{_free_port()} </dev/null",
                out / "deploy", timeout=120)
    assert run.returncode != 0
    assert "rtt_ros" in run.stdout + run.stderr  # the first rtt_ros_integration package it imports
