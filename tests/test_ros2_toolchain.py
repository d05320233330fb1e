"""Build and run generated ROS 2 packages on a real ROS 2 Jazzy.

Not in CI (marker ``ros2_toolchain``, deselected there by conftest.py): ROS 2
is in no registry CI reaches; it is built from fetched public sources with
toolchains/ros2/build.sh into ``$ROS2_PREFIX`` (default ``~/ros2``), whose
``install/`` (C++ core) and ``install_py/`` (rclpy, launch_ros, ros2cli)
overlays these tests use through toolchains/ros2/env.sh.

- every fixture's ROS 2 package (fixtures/cases/*/model.xmi,
  fixtures/ros/*/model.xmi) is generated (with a maintainer and a license,
  as a package to release) and built with colcon in one workspace, with
  ``-Wall -Wextra -Wpedantic``, and no compiler warning points into a
  generated package;
- ``colcon test`` of every one passes: ament_lint_common's linters
  (copyright, cppcheck, cpplint, flake8, lint_cmake, pep257, uncrustify,
  xmllint; cppcheck run although Debian's is a version ament calls slow) and
  the generated launch test of the system, each with its results on file;
- with one remap taken out of an installed launch file, the generated launch
  test fails and names the connection it broke;
- fixtures/ros/managed: ``ros2 launch managed managed.launch.xml`` loads every
  composable node, both lifecycle managers exit 0, /arm, /controller and
  /vision report ``active`` (``ros2 lifecycle get``), messages flow on every
  connection topic (``*Conn``), ``ros2 lifecycle set /controller deactivate``
  stops /armCommandConn and ``activate`` restarts it;
- fixtures/cases/pid: ``ros2 launch pid pid.launch.xml`` loads its three nodes
  and messages flow on its three topics; included with ``use_sim_time`` set,
  its timers follow /clock (a test publishes it): nothing without /clock,
  messages while it advances, none while it stands still;
- the managed launch stops on SIGINT with no ERROR line, three times in a row;
- fixtures/cases/learning included under ``<push-ros-namespace>``: the
  topics of its root-namespace nodes and of its namespaced ones
  (``atf/driver``) meet under the pushed namespace and messages flow there;
- ``toolchains/ros2/build.sh --check`` says OK on the tree and fails on a
  copy whose rcl_interfaces Python type support is gone.

Each launch runs in its own process group on a private ROS_DOMAIN_ID and is
stopped with SIGINT; no process of the group may outlive it. Waits poll with
generous bounds: the machines these run on are slow and shared.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import subprocess
import time
import warnings
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from robomda.api import PackageInfo, generate

ROOT = Path(__file__).resolve().parents[1]
TOOLCHAIN = ROOT / "toolchains" / "ros2"
ENV_SH = TOOLCHAIN / "env.sh"
PREFIX = Path(os.environ.get("ROS2_PREFIX", Path.home() / "ros2")).expanduser()
MODELS = sorted((ROOT / "fixtures" / "cases").glob("*/model.xmi")) + sorted((ROOT / "fixtures" / "ros").glob("*/model.xmi"))
# ROBOMDA_ROS2_FIXTURES=managed,learning: build and run those fixtures only (a quick run; the tests
# of the others are not collected, those that need a fixture left out skip and say which)
ONLY = [n for n in os.environ.get("ROBOMDA_ROS2_FIXTURES", "").split(",") if n]
MODELS = [m for m in MODELS if not ONLY or m.parent.name in ONLY]
# what a package to release has (a copyright notice ament_copyright accepts needs all three)
RELEASE = PackageInfo("1.0.0", "robomda tests <robomda-tests@example.com>", "Apache-2.0", "2026")
# a domain of our own, so that another ROS 2 on the machine neither sees nor disturbs these nodes
DOMAIN = os.environ.get("ROS_DOMAIN_ID") or str(50 + os.getpid() % 50)

pytestmark = [
    pytest.mark.ros2_toolchain,
    pytest.mark.skipif(not (PREFIX / "install" / "setup.bash").is_file() or not (PREFIX / "venv" / "bin" / "colcon").exists(),
                       reason=f"no ROS 2 built in {PREFIX} (set ROS2_PREFIX, or build it with {TOOLCHAIN}/build.sh)"),
]
needs_launch = pytest.mark.skipif(not (PREFIX / "install_py" / "bin" / "ros2").exists(),
                                  reason=f"no ros2 launch in {PREFIX}/install_py (stage 2 of {TOOLCHAIN}/build.sh)")


def _env(home: Path) -> dict[str, str]:
    # cppcheck runs although ament skips Debian's 2.10 as slow: the generated code is checked by it
    return dict(os.environ, ROS2_PREFIX=str(PREFIX), ROS_DOMAIN_ID=DOMAIN, ROS_HOME=str(home), MAKEFLAGS="-j2",
                AMENT_CPPCHECK_ALLOW_SLOW_VERSIONS="1")


def _script(ws: Path, command: str) -> list[str]:
    return ["bash", "-c", f"source {ENV_SH} >/dev/null && source {ws}/install/local_setup.bash && {command}"]


@dataclass
class Workspace:
    root: Path
    packages: dict[str, str]  # fixture name -> package name
    build: subprocess.CompletedProcess[str] = field(repr=False)

    def run(self, command: str, timeout: float = 180) -> subprocess.CompletedProcess[str]:
        return subprocess.run(_script(self.root, command), cwd=self.root, env=_env(self.root / "home"),
                              capture_output=True, text=True, timeout=timeout)


def _fixture_name(model: Path) -> str:
    return model.parent.name


def _package(ws: Workspace, fixture: str) -> str:
    """The package of ``fixture``, built; skips when ROBOMDA_ROS2_FIXTURES leaves it out."""
    if fixture not in ws.packages:
        pytest.skip(f"{fixture} is not in ROBOMDA_ROS2_FIXTURES={','.join(ONLY)}")
    pkg = ws.packages[fixture]
    assert (ws.root / "install" / pkg).is_dir(), f"the {fixture} package did not build"
    return pkg


@pytest.fixture(scope="module")
def workspace(tmp_path_factory) -> Workspace:
    """Every fixture's ROS 2 package generated into one colcon workspace and built (nice 19, -j2);
    ROBOMDA_ROS2_WS=DIR: in DIR, kept, so that a second run builds only what changed."""
    ws = Path(os.environ["ROBOMDA_ROS2_WS"]) if os.environ.get("ROBOMDA_ROS2_WS") else tmp_path_factory.mktemp("ros2ws")
    (ws / "home").mkdir(parents=True, exist_ok=True)
    packages = {}
    for model in MODELS:
        out = ws / "src" / _fixture_name(model)
        generate(model, out, "ros2", package=RELEASE)
        packages[_fixture_name(model)] = ET.parse(out / "package.xml").getroot().findtext("name")
    select = f"--packages-select {' '.join(packages.values())} " if ONLY else ""  # a kept workspace may hold others
    return Workspace(ws, packages, colcon_build(ws, f"{select}--continue-on-error "))


def colcon_build(ws: Path, options: str = "") -> subprocess.CompletedProcess:
    """colcon build of the packages under ``ws``/src, warnings on, at nice 19 (``options``: more of colcon's)."""
    return subprocess.run(
        ["bash", "-c", f"source {ENV_SH} >/dev/null && nice -n 19 colcon --log-base log build --base-paths src {options}"
         "--install-base install --build-base build --parallel-workers 1 "
         "--event-handlers console_direct- console_cohesion- --cmake-args -DBUILD_TESTING=ON "
         "-DCMAKE_BUILD_TYPE=None '-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wpedantic' -DPython3_EXECUTABLE=$(command -v python3)"],
        cwd=ws, env=_env(ws / "home"), capture_output=True, text=True, timeout=4 * 3600)


@pytest.mark.parametrize("model", MODELS, ids=_fixture_name)
def test_package_builds_without_a_warning(model: Path, workspace: Workspace) -> None:
    pkg = workspace.packages[_fixture_name(model)]
    log = workspace.root / "log" / "latest_build" / pkg / "stdout_stderr.log"
    said = log.read_text(errors="replace") if log.is_file() else workspace.build.stdout + workspace.build.stderr
    if os.environ.get("ROBOMDA_ROS2_WS") and not re.search(r"Building CXX", said):
        # a kept workspace whose sources did not change: the last build that compiled them
        compiled = [p.read_text(errors="replace") for p in sorted((workspace.root / "log").glob(f"build_*/{pkg}/stdout_stderr.log"))]
        said = next((text for text in reversed(compiled) if "Building CXX" in text), said)
    assert (workspace.root / "install" / pkg / "share" / pkg / "package.xml").is_file(), said[-5000:]
    cache = (workspace.root / "build" / pkg / "CMakeCache.txt").read_text()
    assert re.search(r"^CMAKE_CXX_FLAGS:STRING=.*-Wall -Wextra -Wpedantic", cache, re.M), "the warning flags did not reach the build"
    assert re.search(r"^ROBOMDA_WARNINGS:BOOL=ON", cache, re.M), "the package's own warning option is not on"
    assert re.search(r"\.cpp\.o\b|Building CXX", said), said[-3000:]  # something was compiled
    generated = str(workspace.root / "src" / _fixture_name(model))
    ours = [line for line in said.splitlines() if "warning:" in line and generated in line]
    assert not ours, "\n".join(ours[:20])


# what colcon test must have run for a generated package: ament_lint_common's linters and the launch test
LINTERS = ("copyright", "cppcheck", "cpplint", "flake8", "lint_cmake", "pep257", "uncrustify", "xmllint")


def _colcon_test(ws: Workspace, pkg: str) -> subprocess.CompletedProcess[str]:
    return ws.run(f"nice -n 19 colcon --log-base log test --base-paths src --packages-select {pkg} "
                  "--install-base install --build-base build --event-handlers console_direct- console_cohesion+ "
                  f"&& colcon test-result --test-result-base build/{pkg} --verbose", timeout=900)


@pytest.mark.parametrize("model", MODELS, ids=_fixture_name)
def test_package_passes_colcon_test(model: Path, workspace: Workspace) -> None:
    """colcon test runs ROS 2's linters and the system's launch test on the package, and all pass."""
    fixture = _fixture_name(model)
    pkg = _package(workspace, fixture)
    done = _colcon_test(workspace, pkg)
    said = done.stdout + done.stderr
    assert done.returncode == 0, said[-6000:]
    results = workspace.root / "build" / pkg / "test_results" / pkg
    ran = {}
    for path in sorted(results.glob("*.xml")):
        suite = ET.parse(path).getroot()
        suites = [suite] if suite.tag == "testsuite" else suite.findall("testsuite")
        ran[path.name.removesuffix(".xunit.xml").removesuffix(".xml")] = (
            sum(int(s.get("tests", "0")) for s in suites), sum(int(s.get("failures", "0")) + int(s.get("errors", "0")) for s in suites),
            sum(int(s.get("skipped", "0")) for s in suites))
    launch_test = f"test_{next((workspace.root / 'src' / fixture / 'test').glob('*_launch.py')).name}"
    for name in (*LINTERS, launch_test):
        assert name in ran, f"{name} did not run (results: {sorted(ran)})\n{said[-3000:]}"
        tests, failed, skipped = ran[name]
        assert tests > 0 and failed == 0 and skipped == 0, f"{name}: {tests} tests, {failed} failed, {skipped} skipped"


def test_the_launch_test_names_a_connection_a_launch_file_breaks(workspace: Workspace) -> None:
    """One remap taken out of the installed launch file: the generated test fails, naming that connection."""
    pkg = _package(workspace, "pid")
    launch = workspace.root / "install" / pkg / "share" / pkg / "launch" / "pid_localhost.launch.xml"
    if not launch.is_file():  # the fixture's host launch file, whatever the host is called
        launch = next(p for p in (launch.parent).glob("pid_*.launch.xml"))
    kept = launch.read_text(encoding="utf-8")
    remap = re.search(r'<remap from="(\w+)" to="(\w+)"/>', kept)
    assert remap, kept
    try:
        launch.write_text(kept.replace(remap.group(0), "", 1), encoding="utf-8")
        test = next((workspace.root / "src" / "pid" / "test").glob("*_launch.py"))
        done = workspace.run(f"launch_test {test}", timeout=600)
    finally:
        launch.write_text(kept, encoding="utf-8")
    said = done.stdout + done.stderr
    assert done.returncode != 0, said[-3000:]
    assert re.search(rf"FAIL: test_connections_are_wired .*connection='[^']*{remap.group(1)}", said), said[-4000:]


# counts the messages of each topic given, for SECONDS once every topic has a publisher matched;
# prints {"topic": count, ...}; a topic without a publisher within 60 s counts -1
_COUNTER = r'''
import json, sys, time
import rclpy
from rclpy.qos import qos_profile_sensor_data
from rosidl_runtime_py.utilities import get_message
seconds, topics = float(sys.argv[1]), sys.argv[2:]
rclpy.init()
node = rclpy.create_node("robomda_topic_counter")
types, deadline = {}, time.monotonic() + 60
while len(types) < len(topics) and time.monotonic() < deadline:
    for name, kinds in node.get_topic_names_and_types():
        if name in topics and kinds and node.count_publishers(name) > 0:
            types[name] = kinds[0]
    rclpy.spin_once(node, timeout_sec=0.2)
counts = {t: 0 for t in topics}
def counter(t):
    def cb(_):
        counts[t] += 1
    return cb
subs = [node.create_subscription(get_message(types[t]), t, counter(t), qos_profile_sensor_data) for t in types]
deadline = time.monotonic() + 30
while any(s.get_publisher_count() == 0 for s in subs) and time.monotonic() < deadline:
    rclpy.spin_once(node, timeout_sec=0.1)
for t in topics:
    counts[t] = 0 if t in types else -1
end = time.monotonic() + seconds
while time.monotonic() < end:
    rclpy.spin_once(node, timeout_sec=0.05)
    for t in topics:
        if t not in types:
            counts[t] = -1
print(json.dumps(counts))
'''


def _count(ws: Workspace, topics: list[str], seconds: float = 2.0) -> dict[str, int]:
    (ws.root / "count.py").write_text(_COUNTER)
    run = ws.run(f"exec python3 {ws.root / 'count.py'} {seconds} {' '.join(topics)}", timeout=240)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-3000:]
    return json.loads(run.stdout.strip().splitlines()[-1])


@dataclass
class Launch:
    """``ros2 launch PKG FILE`` in its own process group, output in ``log``."""
    ws: Workspace
    pkg: str
    file: str
    log: Path
    proc: subprocess.Popen[bytes] | None = None
    offset: int = 0  # where this run's output starts in the log
    notes: list[str] = field(default_factory=list)

    def start(self) -> None:
        self.offset = self.log.stat().st_size if self.log.exists() else 0
        with self.log.open("ab") as out:
            # (pkg "": file is a launch file's path)
            self.proc = subprocess.Popen(_script(self.ws.root, f"exec ros2 launch {self.pkg} {self.file}"),
                                         cwd=self.ws.root, env=_env(self.ws.root / "home"), stdout=out,
                                         stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)

    def text(self) -> str:
        """The output of the current (last) run."""
        return self.log.read_bytes()[self.offset:].decode(errors="replace")

    def wait_for(self, done, timeout: float = 240) -> bool:
        """Polls the launch output until ``done(text)`` or the launch ends or ``timeout`` passes."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if done(self.text()):
                return True
            if self.proc is not None and self.proc.poll() is not None:
                return done(self.text())
            time.sleep(1)
        return False

    def group(self) -> list[int]:
        """Pids still in the launch's process group."""
        if self.proc is None:
            return []
        self.proc.poll()  # reaps the launch process once it ended
        pgid = self.proc.pid
        found = subprocess.run(["ps", "-eo", "pid=,pgid=,stat="], capture_output=True, text=True).stdout.split("\n")
        return [int(p) for p, g, stat in (line.split() for line in found if line.strip())
                if int(g) == pgid and not stat.startswith("Z")]

    def stop(self) -> list[int]:
        """SIGINT to the group, 90 s to end; returns the pids that outlived it (then killed)."""
        if self.proc is None:
            return []
        try:
            os.killpg(self.proc.pid, signal.SIGINT)
        except ProcessLookupError:
            pass
        deadline = time.monotonic() + 90
        while self.group() and time.monotonic() < deadline:
            time.sleep(1)
        left = self.group()
        if left:
            os.killpg(self.proc.pid, signal.SIGKILL)
        self.proc.wait(timeout=60)
        self.proc = None
        return left

    def loaded(self, nodes: list[str]) -> bool:
        text = self.text()
        return all(f"Loaded node '{n}'" in text for n in nodes)

    def start_loaded(self, nodes: list[str], timeout: float = 240) -> None:
        """Starts the launch and waits until every composable node is loaded. launch_ros sometimes
        loses a LoadNode request (ros2/launch_ros#572): the node never loads though its container
        runs. Then the launch is stopped and started once more, and the retry is reported."""
        self.start()
        if self.wait_for(lambda _: self.loaded(nodes), timeout):
            return
        missing = [n for n in nodes if f"Loaded node '{n}'" not in self.text()]
        left = self.stop()
        assert not left, f"processes outlived the first launch: {left}"
        note = f"{self.pkg}: {missing} not loaded in {timeout:.0f} s; launch retried once (ros2/launch_ros#572)"
        self.notes.append(note)
        warnings.warn(note)
        with self.log.open("a") as out:
            out.write(f"\n--- {note}\n")
        self.start()
        assert self.wait_for(lambda _: self.loaded(nodes), timeout), self.text()[-5000:]


def _launch_files(ws: Workspace, pkg: str) -> list[Path]:
    return sorted((ws.root / "install" / pkg / "share" / pkg / "launch").glob("*.launch.xml"))


def _composable_nodes(ws: Workspace, pkg: str) -> list[str]:
    """The fully qualified names of the launch files' composable nodes (a part of a composite in its
    namespace: /processing/filter)."""
    return sorted({"/" + "/".join(x.strip("/") for x in (n.get("namespace", ""), n.get("name")) if x.strip("/"))
                   for f in _launch_files(ws, pkg) for n in ET.parse(f).iter("composable_node")})


def _connection_topics(ws: Workspace, pkg: str) -> list[str]:
    return sorted({"/" + r.get("to") for f in _launch_files(ws, pkg) for r in ET.parse(f).iter("remap")
                   if r.get("to", "").endswith("Conn")})


MANAGED_NODES = ["/arm", "/controller", "/vision"]


@pytest.fixture(scope="module")
def managed(workspace: Workspace):
    pkg = _package(workspace, "managed")
    launch = Launch(workspace, pkg, "managed.launch.xml", workspace.root / "managed.launch.log")
    try:
        launch.start_loaded(_composable_nodes(workspace, pkg))
        yield launch
    finally:
        launch.stop()


def _lifecycle_get(ws: Workspace, node: str) -> str:
    run = ws.run(f"ros2 lifecycle get --no-daemon {node}")
    return (run.stdout + run.stderr).strip()


@needs_launch
def test_managed_launch_loads_every_composable_node(managed: Launch) -> None:
    nodes = _composable_nodes(managed.ws, managed.pkg)
    assert set(MANAGED_NODES) <= set(nodes) and len(nodes) == 5, nodes
    assert managed.loaded(nodes), managed.text()[-5000:]
    assert "Failed to load" not in managed.text(), managed.text()[-5000:]


@needs_launch
def test_managed_lifecycle_managers_exit_0(managed: Launch) -> None:
    managers = lambda text: set(re.findall(r"\[INFO\] \[(lifecycle_manager-\d+)\]: process started", text))
    cleanly = lambda text: set(re.findall(r"\[INFO\] \[(lifecycle_manager-\d+)\]: process has finished cleanly", text))
    assert managed.wait_for(lambda t: len(managers(t)) == 2 and cleanly(t) >= managers(t)), managed.text()[-5000:]
    assert not re.search(r"\[(lifecycle_manager-\d+)\]: process has died", managed.text()), managed.text()[-5000:]


@needs_launch
def test_managed_nodes_are_active(managed: Launch) -> None:
    deadline = time.monotonic() + 240
    states = {}
    for node in MANAGED_NODES:
        while True:
            states[node] = _lifecycle_get(managed.ws, node)
            if states[node].startswith("active") or time.monotonic() > deadline:
                break
            time.sleep(2)
    assert all(s.startswith("active [3]") for s in states.values()), states


@needs_launch
def test_managed_connection_topics_flow(managed: Launch) -> None:
    topics = _connection_topics(managed.ws, managed.pkg)
    assert len(topics) == 6 and "/armCommandConn" in topics, topics
    counts = _count(managed.ws, topics, 3.0)
    assert all(c > 0 for c in counts.values()), counts


@needs_launch
def test_managed_deactivate_stops_and_activate_restarts_the_controller(managed: Launch) -> None:
    ws = managed.ws
    assert _count(ws, ["/armCommandConn"])["/armCommandConn"] > 0
    try:
        run = ws.run("ros2 lifecycle set --no-daemon /controller deactivate")
        assert "Transitioning successful" in run.stdout, run.stdout + run.stderr
        assert _lifecycle_get(ws, "/controller").startswith("inactive [2]")
        assert _count(ws, ["/armCommandConn"])["/armCommandConn"] == 0  # the publisher stays, silent
    finally:
        run = ws.run("ros2 lifecycle set --no-daemon /controller activate")
    assert "Transitioning successful" in run.stdout, run.stdout + run.stderr
    assert _lifecycle_get(ws, "/controller").startswith("active [3]")
    assert _count(ws, ["/armCommandConn"])["/armCommandConn"] > 0


@needs_launch
def test_managed_launch_stops_on_sigint_and_leaves_nothing(managed: Launch) -> None:
    assert managed.proc is not None and managed.proc.poll() is None, managed.text()[-5000:]  # still up
    left = managed.stop()
    assert not left, f"outlived SIGINT by 90 s (killed): {left}"
    assert "process has died" not in managed.text(), managed.text()[-5000:]
    assert not _error_lines(managed.text()), managed.text()[-5000:]


# what a clean stop must not log: a node's or launch's ERROR / FATAL line
def _error_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if re.search(r"\[(ERROR|FATAL|CRITICAL)\]", line)]


@needs_launch
def test_managed_launch_stops_on_sigint_without_an_error_line_again_and_again(workspace: Workspace) -> None:
    # after the module fixture's run (the test above), twice more: a clean Ctrl-C of a managed
    # launch logs no ERROR line (the lifecycle destructors no longer transition a shut-down context)
    pkg = _package(workspace, "managed")
    launch = Launch(workspace, pkg, "managed.launch.xml", workspace.root / "managed.again.launch.log")
    finished = lambda text: len(re.findall(r"\[lifecycle_manager-\d+\]: process has finished cleanly", text)) == 2
    for round_ in range(2):
        try:
            launch.start_loaded(_composable_nodes(workspace, pkg))
            assert launch.wait_for(finished), launch.text()[-5000:]
            assert _count(workspace, ["/armCommandConn"])["/armCommandConn"] > 0
        finally:
            left = launch.stop()
        assert not left, f"round {round_}: outlived SIGINT by 90 s (killed): {left}"
        assert not _error_lines(launch.text()), f"round {round_}:\n" + launch.text()[-5000:]
        assert "process has died" not in launch.text(), launch.text()[-5000:]


@needs_launch
def test_pid_launch_runs_its_three_nodes_and_topics(workspace: Workspace) -> None:
    pkg = _package(workspace, "pid")
    nodes = _composable_nodes(workspace, pkg)
    topics = _connection_topics(workspace, pkg)
    assert nodes == ["/PIDController", "/RobotInterface", "/TrajectoryGenerator"], nodes
    assert topics == ["/IDesiredPositionConn", "/IMeasuredPositionConn", "/IReferenceTorqueConn"], topics
    launch = Launch(workspace, pkg, "pid.launch.xml", workspace.root / "pid.launch.log")
    try:
        launch.start_loaded(nodes)
        listed = workspace.run("ros2 node list --no-daemon").stdout.split()
        assert set(nodes) <= set(listed), listed
        counts = _count(workspace, topics, 3.0)
        assert all(c > 0 for c in counts.values()), counts
    finally:
        left = launch.stop()
    assert not left, f"outlived SIGINT by 90 s (killed): {left}"


# publishes /clock and counts the messages of the topics given (std_msgs/Float64) in three phases of
# SECONDS each: no /clock at all, /clock advancing by STEP each 10 ms, /clock standing still
_SIM_CLOCK = r'''
import json, sys, time
import rclpy
from rclpy.qos import qos_profile_sensor_data
from rosgraph_msgs.msg import Clock
from std_msgs.msg import Float64
seconds, step, topics = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3:]
rclpy.init()
node = rclpy.create_node("robomda_sim_clock")
clock = node.create_publisher(Clock, "/clock", 10)
counts = {t: 0 for t in topics}
def counter(t):
    def cb(_):
        counts[t] += 1
    return cb
subs = [node.create_subscription(Float64, t, counter(t), qos_profile_sensor_data) for t in topics]
deadline = time.monotonic() + 60
while any(s.get_publisher_count() == 0 for s in subs) and time.monotonic() < deadline:
    rclpy.spin_once(node, timeout_sec=0.1)
sim = 1000.0
def phase(advance, publish=True):
    global sim
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if publish:
            sim += advance
            msg = Clock()
            msg.clock.sec, msg.clock.nanosec = int(sim), int(round((sim % 1) * 1e9)) % 1000000000
            clock.publish(msg)
        rclpy.spin_once(node, timeout_sec=0.01)
    taken = dict(counts)
    for t in topics:
        counts[t] = 0
    return taken
result = {"no_clock": phase(0.0, publish=False), "running": phase(step)}
phase(0.0)  # what was under way when the clock stopped
result["standing"] = phase(0.0)
print(json.dumps(result))
'''


@needs_launch
def test_pid_timers_follow_the_simulated_clock(workspace: Workspace) -> None:
    pkg = _package(workspace, "pid")
    wrapper = workspace.root / "pid_sim_time.launch.xml"
    wrapper.write_text(f"""<launch>
  <set_parameter name="use_sim_time" value="true"/>
  <include file="$(find-pkg-share {pkg})/launch/{pkg}.launch.xml"/>
</launch>
""")
    topics = _connection_topics(workspace, pkg)
    (workspace.root / "sim_clock.py").write_text(_SIM_CLOCK)
    launch = Launch(workspace, "", str(wrapper), workspace.root / "pid_sim_time.launch.log")
    try:
        launch.start_loaded(_composable_nodes(workspace, pkg))
        run = workspace.run(f"exec python3 {workspace.root / 'sim_clock.py'} 4 0.01 {' '.join(topics)}", timeout=240)
    finally:
        left = launch.stop()
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-3000:]
    counts = json.loads(run.stdout.strip().splitlines()[-1])
    # wall timers would publish ~400 messages a topic in each phase
    assert all(c == 0 for c in counts["no_clock"].values()), counts
    assert all(c > 0 for c in counts["running"].values()), counts
    assert all(c == 0 for c in counts["standing"].values()), counts
    assert not left, f"outlived SIGINT by 90 s (killed): {left}"


# for each topic given: publishers and subscribers once both are there (60 s at most), and every
# topic of the graph; prints {"counts": {"topic": [pubs, subs]}, "topics": [...]}
_GRAPH = r'''
import json, sys, time
import rclpy
topics = sys.argv[1:]
rclpy.init()
node = rclpy.create_node("robomda_graph")
deadline = time.monotonic() + 60
counts = {}
while time.monotonic() < deadline:
    rclpy.spin_once(node, timeout_sec=0.2)
    counts = {t: [node.count_publishers(t), node.count_subscribers(t)] for t in topics}
    if all(p > 0 and s > 0 for p, s in counts.values()):
        break
print(json.dumps({"counts": counts, "topics": sorted(n for n, _ in node.get_topic_names_and_types())}))
'''


def _param_get(ws: Workspace, node: str, name: str) -> str:
    """What ``ros2 param get`` says of parameter ``name`` of ``node`` ("Integer value is: 80")."""
    run = ws.run(f"ros2 param get --no-daemon {node} {name}", timeout=120)
    return (run.stdout + run.stderr).strip()


@contextlib.contextmanager
def _tuned(ws: Workspace, pkg: str, instance: str, values: str):
    """The installed user parameter file of ``instance`` with ``values`` (lines under ros__parameters),
    as a user's tuned file is installed once the package is built again; restored afterwards."""
    user = ws.root / "install" / pkg / "share" / pkg / "config" / f"{instance}.user.yaml"
    fresh = user.read_text()
    assert fresh.endswith("\n/**:\n  ros__parameters: {}\n"), fresh
    user.write_text(fresh.replace("ros__parameters: {}", "ros__parameters:\n    " + values))
    try:
        yield
    finally:
        user.write_text(fresh)


@needs_launch
def test_learning_under_a_pushed_namespace_connects_both_kinds_of_node(workspace: Workspace) -> None:
    # learning has nodes in the root namespace (learner, csGen) and in atf/driver, atf (fri,
    # jointCtrl, ...): included under <push-ros-namespace>, the ends of each connection still meet,
    # and each node gets its parameters: the model's values that differ from the component's
    # defaults (jointCtrl gain 12.5, not 10.0; csIter controlMode impedance, not position) and a
    # user file's (learner window 80, not 50), in composable nodes and in a node of its own
    pkg = _package(workspace, "learning")
    wrapper = workspace.root / "learning_pushed.launch.xml"
    share = f"$(find-pkg-share {pkg})/config"
    wrapper.write_text(f"""<launch>
  <group>
    <push-ros-namespace namespace="robot"/>
    <include file="$(find-pkg-share {pkg})/launch/{pkg}.launch.xml"/>
    <node pkg="{pkg}" exec="joint_controller_node" name="jointCtrlAlone" namespace="atf/driver" output="screen">
      <param from="{share}/atf_driver_jointCtrl.yaml"/>
      <param from="{share}/atf_driver_jointCtrl.user.yaml"/>
      <remap from="torque" to="jointCtrlAloneTorque"/>
    </node>
  </group>
</launch>
""")
    nodes = [f"/robot{n}" for n in _composable_nodes(workspace, pkg)]
    # fri (in atf/driver) publishes measuredPose to learner (root); jointCtrl and fri (atf/driver)
    # and jsIter (atf) share atf_driver_measuredJoints
    topics = ["/robot/measuredPose", "/robot/atf_driver_measuredJoints", "/robot/atf_driver_torqueCmd"]
    (workspace.root / "graph.py").write_text(_GRAPH)
    launch = Launch(workspace, "", str(wrapper), workspace.root / "learning_pushed.launch.log")
    params = {}
    with _tuned(workspace, pkg, "learner", "window: 80"):
        try:
            launch.start()
            assert launch.wait_for(lambda t: t.count("Loaded node '") >= 6), launch.text()[-5000:]
            run = workspace.run(f"exec python3 {workspace.root / 'graph.py'} {' '.join(topics)}", timeout=240)
            assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-3000:]
            graph = json.loads(run.stdout.strip().splitlines()[-1])
            counts = _count(workspace, topics, 3.0)
            for node, name in [("/robot/atf/driver/jointCtrl", "gain"), ("/robot/atf/csIter", "controlMode"),
                               ("/robot/learner", "window"), ("/robot/atf/driver/jointCtrlAlone", "gain"),
                               ("/robot/atf/driver/fri", "update_period")]:
                params[node, name] = _param_get(workspace, node, name)
        finally:
            left = launch.stop()
    text = launch.text()
    assert all(f"Loaded node '{n}'" in text for n in ["/robot/learner", "/robot/atf/driver/fri"]), (nodes, text[-3000:])
    assert all(p > 0 and s > 0 for p, s in graph["counts"].values()), graph
    strays = [t for t in graph["topics"] if t.split("/")[1] in {"measuredPose", "atf_driver_measuredJoints",
                                                                 "atf_driver_torqueCmd", "doorTrajectory"}]
    assert not strays, f"topics outside the pushed namespace: {strays}"
    assert all(c > 0 for c in counts.values()), counts
    assert params == {("/robot/atf/driver/jointCtrl", "gain"): "Double value is: 12.5",
                      ("/robot/atf/csIter", "controlMode"): "String value is: impedance",
                      ("/robot/learner", "window"): "Integer value is: 80",
                      ("/robot/atf/driver/jointCtrlAlone", "gain"): "Double value is: 12.5",
                      ("/robot/atf/driver/fri", "update_period"): "Double value is: 0.01"}, params
    assert not left, f"outlived SIGINT by 90 s (killed): {left}"


@needs_launch
def test_managed_under_a_pushed_namespace_gets_its_parameters_and_activates(workspace: Workspace) -> None:
    # lifecycle nodes loaded into containers under <push-ros-namespace>: the lifecycle managers find
    # them (node_names follow the namespace), each has the value of its user file (controller
    # damping 33, not 20), and they become active
    pkg = _package(workspace, "managed")
    wrapper = workspace.root / "managed_pushed.launch.xml"
    wrapper.write_text(f"""<launch>
  <group>
    <push-ros-namespace namespace="robot"/>
    <include file="$(find-pkg-share {pkg})/launch/{pkg}.launch.xml"/>
  </group>
</launch>
""")
    launch = Launch(workspace, "", str(wrapper), workspace.root / "managed_pushed.launch.log")
    finished = lambda text: len(re.findall(r"\[lifecycle_manager-\d+\]: process has finished cleanly", text)) == 2
    with _tuned(workspace, pkg, "controller", "damping: 33"):
        try:
            launch.start_loaded([f"/robot{n}" for n in _composable_nodes(workspace, pkg)])
            assert launch.wait_for(finished), launch.text()[-5000:]
            damping = _param_get(workspace, "/robot/controller", "damping")
            threshold = _param_get(workspace, "/robot/vision", "threshold")
            guid = _param_get(workspace, "/robot/camera", "guid")
            state = _lifecycle_get(workspace, "/robot/controller")
        finally:
            left = launch.stop()
    assert damping == "Integer value is: 33", damping
    assert threshold == "Integer value is: 100" and guid == "String value is: 000A47010C0A3D12", (threshold, guid)
    assert state.startswith("active"), state
    assert not _error_lines(launch.text()), launch.text()[-5000:]
    assert not left, f"outlived SIGINT by 90 s (killed): {left}"


@pytest.mark.skipif(not (PREFIX / "install_py" / "bin" / "ros2").exists(), reason="no stage 2 to check")
def test_check_says_ok_on_the_tree_and_fails_on_one_that_cannot_launch(tmp_path: Path) -> None:
    env = dict(os.environ, ROS_DOMAIN_ID=DOMAIN)
    good = subprocess.run([str(TOOLCHAIN / "build.sh"), "--check", "--no-apt"], env=dict(env, ROS2_PREFIX=str(PREFIX)),
                          capture_output=True, text=True, timeout=600)
    assert good.returncode == 0 and "check: OK" in good.stdout, good.stdout + good.stderr
    assert "run: ros2 launch of a tiny launch file: OK" in good.stdout, good.stdout
    # a copy of the tree (links to every file) without the compiled Python type support of
    # rcl_interfaces: every package is still installed, but launch_ros cannot run
    broken = tmp_path / "ros2"
    broken.mkdir()
    for part in ("src", "src_py", "venv", "install"):
        (broken / part).symlink_to(PREFIX / part)
    subprocess.run(["cp", "-rs", str(PREFIX / "install_py"), str(broken / "install_py")], check=True)
    gone = [p for p in (broken / "install_py").rglob("*rcl_interfaces_s__rosidl_typesupport_c*.so")]
    assert gone, "no compiled type support of rcl_interfaces found in install_py"
    for p in gone:
        p.unlink()
    bad = subprocess.run([str(TOOLCHAIN / "build.sh"), "--check", "--no-apt"], env=dict(env, ROS2_PREFIX=str(broken)),
                         capture_output=True, text=True, timeout=600)
    assert bad.returncode == 1, bad.stdout + bad.stderr
    assert "stage 2: all" in bad.stdout, bad.stdout  # the packages are all there ...
    assert "MISSING: run: import of the Python type support" in bad.stdout, bad.stdout  # ... but it cannot run
    assert "check: incomplete" in bad.stdout, bad.stdout
