"""The mixed Orocos <-> ROS 1 system on real middleware: messages cross each way.

Not in CI (marker ``rtt_ros_toolchain``): it needs the Orocos toolchain of
toolchains/orocos/build.sh, the rtt_ros_integration packages of
toolchains/orocos/build-ros.sh (rtt_rosnode, rtt_roscomm, rtt_std_msgs) and
Debian's ROS 1 (catkin, roscpp, roscore, roslaunch, rostopic); it uses
toolchains/orocos/env-ros.sh.

The fixture ``distributed`` streams one connection between the two
middlewares (the ROS 1 force sensor to the Orocos controller, /wrenchConn).
For a message in each direction its variant here also puts the vision host's
``rttVision`` process on ROS 1, so that the ROS 1 node ``vision`` reads the
Orocos camera (/visionValueConn) and the Orocos arm (/toolPoseConn) and feeds
the Orocos controller (/channelPositionConn). The generated Orocos package
is built (oro_build_pkg) and the ROS 1 package with catkin_make; a roscore
on 127.0.0.1, the vision host's start script (omniNames, the camera process),
roslaunch of the generated launch file (vision and forceSensor), the
control host's start script (controller and arm in the shared thread), in
each deployment format (lua, xml, ops). Then:

- ROS 1 node -> Orocos: the arm's toolPose (armState + 150, published by the
  Orocos arm through rtt_roscomm) leaves 150: the arm only moves when the
  controller's command does, and the controller's inputs other than the arm
  (channelPosition, wrench) come from the ROS 1 nodes only; without them its
  command stays at the arm's state, 0.
- Orocos -> ROS 1 node: the channel position the ROS 1 node vision publishes
  is not 0: its inputs (visionValue, toolPose) come from the Orocos camera and
  arm only, and are 0 until a message arrives.
- rostopic info names the Orocos process's ROS node (rtt_rosnode's anonymous
  ``/rtt_...``) and the generated node at the two ends of each topic.

Everything then stops (the control host, roslaunch, the vision host, roscore)
with no ERROR, CRITICAL or FATAL line in any process's log or output.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import time
from pathlib import Path

import pytest

from edits import distributed_variant
from robomda.api import generate
from test_orocos_distributed import BAD, Hosts, _free_port

ROOT = Path(__file__).resolve().parents[1]
ENV_ROS_SH = ROOT / "toolchains" / "orocos" / "env-ros.sh"
INSTALL = Path(os.environ.get("OROCOS_INSTALL", Path.home() / "orocos" / "install"))
RTT_ROS = Path(os.environ.get("RTT_ROS_INSTALL", Path(os.environ.get("RTT_ROS_HOME", Path.home() / "rtt_ros")) / "install"))
ROSCOMM = RTT_ROS / "lib" / "orocos" / "gnulinux" / "rtt_roscomm"
# what the generated deployments import besides rtt_roscomm: rtt_std_msgs as build-ros.sh builds it (the
# std_msgs message typekit, its ROS transport, the primitives transport the fixture's int ports use)
STD_MSGS = [RTT_ROS / "lib" / "orocos" / "gnulinux" / "rtt_std_msgs" / f for f in
            ("types/librtt-std_msgs-typekit-gnulinux.so", "types/librtt-std_msgs-ros-transport-gnulinux.so",
             "plugins/librtt-ros-primitives-transport-gnulinux.so")]
SYS_PATH = "/usr/bin:/bin:/usr/sbin:/sbin"

pytestmark = [
    pytest.mark.rtt_ros_toolchain,
    pytest.mark.skipif(not (INSTALL / "bin" / "deployer-corba").exists(),
                       reason=f"no deployer-corba in {INSTALL}: build the toolchain with toolchains/orocos/build.sh"),
    pytest.mark.skipif(not ROSCOMM.is_dir(),
                       reason=f"no rtt_roscomm in {RTT_ROS}: build it with toolchains/orocos/build-ros.sh"),
    pytest.mark.skipif(not all(f.is_file() for f in STD_MSGS),
                       reason=f"rtt_std_msgs incomplete in {RTT_ROS}: build it with toolchains/orocos/build-ros.sh"),
    pytest.mark.skipif(not all(shutil.which(p, path=SYS_PATH) for p in ("roscore", "roslaunch", "rostopic", "catkin_make")),
                       reason="no roscore / roslaunch / rostopic / catkin_make (Debian ROS 1: toolchains/orocos/build-ros.sh)"),
    pytest.mark.skipif(not (shutil.which("omniNames") and shutil.which("nameclt")),
                       reason="no omniNames / nameclt (Debian omniorb-nameserver, omniorb; toolchains/orocos/build.sh)"),
]

# the vision host's second process on ROS 1 (its Middleware says version="2.10", i.e. Orocos RTT)
VISION_ON_ROS = ('base_ExecutionEnvironment="_dstRttVisionEEb6C7d8E9f" version="2.10"',
                 'base_ExecutionEnvironment="_dstRttVisionEEb6C7d8E9f" kind="ROS"', 1)
DATA = re.compile(r"^data: (-?\d+)$", re.M)


def _ros_env(tmp: Path, port: int) -> dict[str, str]:
    """Debian's ROS 1 on 127.0.0.1:PORT, its logs under TMP; no pyenv or venv Python in the way."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYENV", "VIRTUAL_ENV", "PYTHON", "ROS_"))}
    env.update(PATH=SYS_PATH, ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_IP="127.0.0.1",
               ROS_HOME=str(tmp / "ros"), ROS_LOG_DIR=str(tmp / "logs" / "ros"), OROCOS_INSTALL=str(INSTALL))
    return env


def _bash(script: str, cwd: Path, env: dict[str, str], timeout: int = 1800) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["bash", "-c", f"source {ENV_ROS_SH} >/dev/null && {script}"], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def mixed(tmp_path_factory) -> Path:
    """TMP/orocos (the Orocos package, built and installed) and TMP/ws (a catkin workspace with the ROS 1
    package, built) of the variant."""
    tmp = tmp_path_factory.mktemp("mixed")
    model = distributed_variant(tmp, VISION_ON_ROS)
    env = _ros_env(tmp, 11311)
    generate(model, tmp / "orocos", "orocos")
    done = _bash(f"oro_build_pkg {tmp / 'orocos'}", tmp, env)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    generate(model, tmp / "ws" / "src" / "distributed", "ros1")
    done = subprocess.run(["catkin_make", "-C", str(tmp / "ws"), "-DPYTHON_EXECUTABLE=/usr/bin/python3"],
                          cwd=tmp / "ws", env=dict(env, PWD=str(tmp / "ws")), capture_output=True, text=True, timeout=1800)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return tmp


class MixedHosts(Hosts):
    """The Orocos start scripts of the two hosts (test_orocos_distributed.Hosts), with rtt_ros_integration
    and the ROS 1 master in their environment."""

    def __init__(self, built: Path, tmp: Path, fmt: str, ros: dict[str, str]) -> None:
        super().__init__(built, tmp, fmt)
        self.env = dict(ros, NAMESERVICE=f"127.0.0.1:{self.port}", LOGDIR=str(tmp / "logs"), TMPDIR=str(tmp))
        self.prefix = f"source {ENV_ROS_SH} >/dev/null && oro_add_prefix {built}/install && "


def _start(cmd: list[str], env: dict[str, str], out: Path, cwd: Path | None = None) -> subprocess.Popen:
    with out.open("w") as f:
        return subprocess.Popen(cmd, env=env, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                start_new_session=True)


def _stop(proc: subprocess.Popen, sig: int = signal.SIGINT) -> None:
    if proc.poll() is None:
        os.killpg(proc.pid, sig)
        try:
            proc.wait(timeout=60)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(timeout=30)


def _wait_master(env: dict[str, str], roscore: subprocess.Popen) -> None:
    deadline = time.monotonic() + 60
    while subprocess.run(["rosnode", "list"], env=env, capture_output=True, timeout=30).returncode != 0:
        assert roscore.poll() is None and time.monotonic() < deadline, "roscore did not come up"
        time.sleep(0.5)


def _samples(topic: str, env: dict[str, str], n: int = 20) -> list[int]:
    """N messages of TOPIC (std_msgs/Int32) as rostopic echo prints them."""
    run = subprocess.run(["rostopic", "echo", "-n", str(n), topic], env=env, capture_output=True, text=True, timeout=60)
    return [int(v) for v in DATA.findall(run.stdout)]


def _ends(topic: str, env: dict[str, str]) -> tuple[list[str], list[str]]:
    """The nodes that publish and subscribe TOPIC (rostopic info)."""
    text = subprocess.run(["rostopic", "info", topic], env=env, capture_output=True, text=True, timeout=60).stdout
    pubs, _, subs = text.partition("Subscribers:")
    node = re.compile(r"^ \* (/\S+)", re.M)
    return node.findall(pubs), node.findall(subs)


@pytest.mark.parametrize("fmt", ["lua", "xml", "ops"])
def test_messages_cross_between_orocos_and_ros1_both_ways(fmt: str, mixed: Path, tmp_path: Path) -> None:
    (tmp_path / "logs").mkdir()
    ros = _ros_env(tmp_path, _free_port())
    roscore = _start(["roscore", "-p", ros["ROS_MASTER_URI"].rsplit(":", 1)[1]], ros, tmp_path / "roscore.out")
    hosts = MixedHosts(mixed / "orocos", tmp_path, fmt, ros)
    launch = None
    try:
        _wait_master(ros, roscore)
        hosts.start("vision_pc")
        launch = _start(["bash", "-c", f"source {mixed}/ws/devel/setup.bash && exec roslaunch distributed distributed.launch"],
                        ros, tmp_path / "roslaunch.out")
        hosts.start("control_pc")
        time.sleep(3)
        tool_pose, channel = _samples("/toolPoseConn", ros), _samples("/channelPositionConn", ros)
        ends = {t: _ends(t, ros) for t in ("/visionValueConn", "/toolPoseConn", "/channelPositionConn", "/wrenchConn")}
        assert len(tool_pose) == 20 and any(v != 150 for v in tool_pose), (tool_pose, hosts.report())
        assert len(channel) == 20 and any(v != 0 for v in channel), (channel, hosts.report())
        for topic, (pubs, subs) in ends.items():
            orocos_publishes = topic in ("/visionValueConn", "/toolPoseConn")
            rtt, ros_node = (pubs, subs) if orocos_publishes else (subs, pubs)
            assert any(n.startswith("/rtt_") for n in rtt), (topic, ends)
            assert ("/vision" if topic != "/wrenchConn" else "/forceSensor") in ros_node, (topic, ends)
        assert hosts.stop("control_pc") == 0, hosts.report()
        _stop(launch)
        assert launch.returncode == 0, (tmp_path / "roslaunch.out").read_text()
        assert hosts.stop("vision_pc") == 0, hosts.report()
    finally:
        hosts.stop_all()
        if launch is not None:
            _stop(launch)
        _stop(roscore)
    logs = dict(hosts.logs(), roslaunch=(tmp_path / "roslaunch.out").read_text(errors="replace"))
    assert {"vision_pc_rtt_camera.log", "control_pc_rtt_control.log"} <= set(logs)
    bad = [f"{name}: {line}" for name, text in logs.items() for line in text.splitlines() if BAD.search(line)]
    assert not bad, "\n".join(bad[:20])
