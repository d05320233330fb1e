"""Seed 004's jobs on the real ROS 2 Jazzy (docs/jobs.md): the teleop fixture's coordinator.

Where ROS 2 is built (``ROS2_PREFIX``, toolchains/ros2/build.sh; marker ``ros2_toolchain``, deselected
in CI), the teleop package alone is generated and built with colcon, ``ros2 launch teleop
teleop.launch.xml`` runs it, and events on /arm/event switch between its jobs at run time:

- the initial job (trackball, invkin, robot) is active, the player unconfigured;
- ``play``: the trackball is deactivated and cleaned up, invkin (active throughout) gets gain 2.0,
  the player is configured and activated, and the pose reaches invkin again;
- ``teleoperate``: back;
- the shared robot interface never leaves Active: no transition event of its own after start-up,
  its cycle counter counts on across both switches;
- SIGINT stops the launch with no process left and no ERROR line.
"""

from __future__ import annotations

import json
import re
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from robomda.api import generate
from test_ros2_toolchain import ENV_SH, Launch, Workspace, _count, colcon_build, _env, _error_lines, _lifecycle_get, needs_launch
from test_ros2_toolchain import pytestmark  # noqa: F401 (marker ros2_toolchain; skipped where no ROS 2 is built)

ROOT = Path(__file__).resolve().parents[1]
TELEOP = ROOT / "fixtures" / "cases" / "teleop" / "model.xmi"

# watches /robot/transition_event and /cycles until it is sent SIGINT (or 600 s pass);
# prints {"transitions": [...], "cycles": [first, last], "decreased": bool}
_WATCHER = r'''
import json, signal, time
import rclpy
from lifecycle_msgs.msg import TransitionEvent
from std_msgs.msg import Int32
rclpy.init()
node = rclpy.create_node("robomda_job_watcher")
seen = {"transitions": [], "cycles": [], "decreased": False}
def on_transition(m):
    seen["transitions"].append(m.goal_state.label)
def on_cycles(m):
    if seen["cycles"] and m.data < seen["cycles"][-1]:
        seen["decreased"] = True
    seen["cycles"] = (seen["cycles"][:1] + [m.data])
node.create_subscription(TransitionEvent, "/robot/transition_event", on_transition, 10)
node.create_subscription(Int32, "/cycles", on_cycles, 10)
stop = []
signal.signal(signal.SIGINT, lambda *a: stop.append(1))
end = time.monotonic() + 600
while not stop and time.monotonic() < end:
    rclpy.spin_once(node, timeout_sec=0.1)
print(json.dumps(seen), flush=True)
'''


@pytest.fixture(scope="module")
def teleop_ws(tmp_path_factory) -> Workspace:
    """The teleop package alone, generated and built with colcon (nice 19)."""
    ws = tmp_path_factory.mktemp("ros2jobs")
    (ws / "home").mkdir()
    generate(TELEOP, ws / "src" / "teleop", "ros2")
    build = colcon_build(ws)
    assert (ws / "install" / "teleop").is_dir(), build.stdout[-3000:] + build.stderr[-3000:]
    return Workspace(ws, {"teleop": "teleop"}, build)


def _states(ws: Workspace, nodes: list[str]) -> dict[str, str]:
    return {node: _lifecycle_get(ws, node).split(" ")[0] for node in nodes}


@needs_launch
def test_teleop_switches_jobs_and_never_deactivates_the_shared_robot(teleop_ws: Workspace) -> None:
    ws = teleop_ws
    composable = sorted({"/" + n.get("name") for n in ET.parse(
        ws.root / "install/teleop/share/teleop/launch/teleop_localhost.launch.xml").iter("composable_node")})
    assert composable == ["/invkin", "/player", "/robot", "/trackball"], composable
    launch = Launch(ws, "teleop", "teleop.launch.xml", ws.root / "teleop.launch.log")
    watcher = None
    try:
        launch.start_loaded(composable)
        assert launch.wait_for(lambda t: "job teleoperation active" in t), launch.text()[-5000:]
        assert _states(ws, ["/robot", "/trackball", "/invkin", "/player"]) == {
            "/robot": "active", "/trackball": "active", "/invkin": "active", "/player": "unconfigured"}
        (ws.root / "watch.py").write_text(_WATCHER)
        watcher = subprocess.Popen(["bash", "-c", f"source {ENV_SH} >/dev/null && source {ws.root}/install/local_setup.bash"
                                    f" && exec python3 {ws.root / 'watch.py'}"], cwd=ws.root, env=_env(ws.root / "home"),
                                   stdout=subprocess.PIPE, text=True)
        assert all(c > 0 for c in _count(ws, ["/trackballPose", "/command", "/cycles"]).values())
        for event, job, came, gone, gain in (("play", "playback", "/player", "/trackball", "2.0"),
                                             ("teleoperate", "teleoperation", "/trackball", "/player", "1.0")):
            pub = ws.run(f"ros2 topic pub --once /arm/event std_msgs/msg/String '{{data: {event}}}'")
            assert pub.returncode == 0, pub.stdout + pub.stderr
            assert launch.wait_for(lambda t: f"job {job} active (event {event})" in t, 120), launch.text()[-5000:]
            assert _states(ws, ["/robot", came, gone, "/invkin"]) == {
                "/robot": "active", came: "active", gone: "unconfigured", "/invkin": "active"}
            param = ws.run("ros2 param get --no-daemon /invkin gain")
            assert f"Double value is: {gain}" in param.stdout, param.stdout + param.stderr
            # the new source reaches invkin, which commands the robot
            assert all(c > 0 for c in _count(ws, ["/trackballPose", "/command", "/cycles"]).values())
        watcher.send_signal(2)
        seen = json.loads(watcher.communicate(timeout=60)[0].strip().splitlines()[-1])
        watcher = None
        assert seen["transitions"] == [], seen  # the shared robot never left Active
        assert not seen["decreased"] and len(seen["cycles"]) == 2 and seen["cycles"][1] > seen["cycles"][0], seen
        text = launch.text()
        assert "/invkin: 1 values set" in text and re.search(r"/trackball: cleanup", text), text[-5000:]
        left = launch.stop()
        assert not left, f"outlived SIGINT by 90 s (killed): {left}"
        assert not _error_lines(launch.text()), launch.text()[-5000:]
        assert "process has died" not in launch.text(), launch.text()[-5000:]
    finally:
        if watcher is not None:
            watcher.kill()
        launch.stop()
