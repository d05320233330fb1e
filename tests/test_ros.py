"""The ROS 1 and ROS 2 targets (docs/ros.md), checked with real ROS tools.

Each real-tool check is its own test and skips with a visible reason when
its tool is missing (Debian: ros-core-dev catkin catkin-lint
python3-roslaunch python3-rostopic python3-rosnode libstd-srvs-dev;
PyPI: catkin_pkg). Goldens: fixtures/cases/<case>/expected/<target>/ with
the layout of tests/test_golden.py; regenerate with ROBOMDA_REGEN_ROS=1.
"""

from __future__ import annotations

import contextlib
import fcntl
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import time
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from edits import distributed_variant
from robomda.api import generate, import_model, targets
from robomda.resources import target_of_middleware

ROOT = Path(__file__).resolve().parent.parent
# every case, and the ROS-only fixtures (fixtures/ros: models the Orocos target refuses)
CASES = sorted(p.parent for p in [*(ROOT / "fixtures" / "cases").glob("*/model.xmi"),
                                  *(ROOT / "fixtures" / "ros").glob("*/model.xmi")])
TARGETS = [t for t in targets() if any(m.startswith("ROS") for m, s in target_of_middleware().items() if s == t)]
FS = "{urn:robomda:fileset:1}"
SYS_PY = "/usr/bin/python3"
REGEN = os.environ.get("ROBOMDA_REGEN_ROS") == "1"
ROS_ENV_PATH = "/usr/bin:/bin:/usr/sbin:/sbin"


def _files(done) -> dict[str, str]:
    root = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {n.get("path"): n.text or "" for n in root.iter(f"{FS}file")}


_RUNS: dict[tuple[str, str], object] = {}


def _run(case: Path, target: str):
    key = (case.name, target)
    if key not in _RUNS:
        _RUNS[key] = generate(case / "model.xmi", case / "out", target, write=False)
    return _RUNS[key]


def _ros_env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYENV", "VIRTUAL_ENV", "PYTHON"))}
    env["PATH"] = ROS_ENV_PATH
    env.update(extra)
    return env


def _need(tool: str) -> str:
    path = shutil.which(tool, path=ROS_ENV_PATH)
    if path is None:
        pytest.skip(f"{tool} not installed (Debian ROS packages, see tests/run.sh)")
    return path


# ------------------------------------------------------------------ goldens
@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
@pytest.mark.parametrize("target", TARGETS)
def test_ros_goldens(case: Path, target: str) -> None:
    done = _run(case, target)
    files = _files(done)
    expected = case / "expected" / target
    root = etree.fromstring(done.stages["text"].encode("utf-8"))
    listing = "".join(f"{n.get('mode', 'generated')}\t{n.get('path')}\n" for n in root.iter(f"{FS}file"))
    items = [("psm.xml", done.stages["psm"]), ("files.tsv", listing)]
    items += [(f"files/{p}", t) for p, t in files.items()]
    if REGEN:
        shutil.rmtree(expected, ignore_errors=True)
        for rel, text in items:
            (expected / rel).parent.mkdir(parents=True, exist_ok=True)
            (expected / rel).write_text(text, encoding="utf-8", newline="\n")
    failures = [rel for rel, text in items
                if not (expected / rel).is_file() or (expected / rel).read_text(encoding="utf-8") != text]
    listed = {p.relative_to(expected / "files").as_posix() for p in (expected / "files").rglob("*") if p.is_file()}
    assert not failures, f"differ from goldens in {expected}: {failures}"
    assert listed == set(files), "golden files not generated any more: " + ", ".join(sorted(listed - set(files)))


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
@pytest.mark.parametrize("target", TARGETS)
def test_every_file_says_it_is_generated(case: Path, target: str) -> None:
    for path, text in _files(_run(case, target)).items():
        head = "\n".join(text.splitlines()[:4])
        assert "by robomda (m2t/" in head, path


# ------------------------------------------------------- mapping content
def test_pid_ros1_mapping() -> None:
    files = _files(_run(ROOT / "fixtures/cases/pid", "ros1"))
    src = files["src/PIDController.cpp"]
    assert 'nh_.advertise<std_msgs::Float64>("referenceTorque", 1, false)' in src
    assert 'nh_.subscribe("desiredPosition", 1, &PIDController::on_desiredPosition, this)' in src
    assert "::PIDJointController::setDesiredPosition((*msg).data);" in src
    assert 'private_nh_.advertiseService("reset", &PIDController::on_reset, this)' in src
    assert 'private_nh_.param<double>("kp", value, 20.0);' in src
    launch = etree.fromstring(files["launch/pid_control_pc.launch"].encode())
    assert launch.find("machine").attrib == {"name": "control_pc", "address": "localhost"}
    assert [n.get("name") for n in launch.iter("node")] == ["TrajectoryGenerator", "PIDController", "RobotInterface"]
    assert "kp: 20.0" in files["config/PIDController.yaml"]


def test_pid_ros2_mapping() -> None:
    files = _files(_run(ROOT / "fixtures/cases/pid", "ros2"))
    src = files["src/PIDController.cpp"]
    assert "RCLCPP_COMPONENTS_REGISTER_NODE(pid::PIDController)" in src
    assert 'rclcpp::QoS(rclcpp::KeepLast(1)).reliable().durability_volatile()' in src
    assert 'this->declare_parameter<double>("kp", 20.0)' in src
    # one line, or an item a line where it would pass 100 columns (lint_cmake)
    register = re.findall(r"^rclcpp_components_register_nodes\(([^)]*)\)", files["CMakeLists.txt"], re.M)
    assert [" ".join(r.split()) for r in register] == ['${PROJECT_NAME}_components "pid::TrajectoryGenerator" '
                                                       '"pid::PIDController" "pid::RobotInterface"']
    assert "\n/**:\n  ros__parameters:\n    update_period: 0.01\n    kp: 20.0" in files["config/PIDController.yaml"]
    assert "config/params.yaml" not in files and "config/params.user.yaml" not in files
    assert files["config/PIDController.user.yaml"].endswith("\n/**:\n  ros__parameters: {}\n")
    launch = etree.fromstring(files["launch/pid_control_pc.launch.xml"].encode())
    node = launch.find(".//composable_node[@name='PIDController']")
    assert [p.get("from") for p in node.iter("param")] == [f"$(find-pkg-share pid)/config/PIDController{s}.yaml"
                                                           for s in ("", ".user")]
    # issue 36 item 7: the timer runs on the node's clock (use_sim_time), callbacks take a const message,
    # headers install under the package's own include folder
    assert "timer_ = rclcpp::create_timer(this, this->get_clock(), rclcpp::Duration::from_seconds(period_)," in src
    assert "create_wall_timer" not in src
    assert "void PIDController::on_desiredPosition(const std_msgs::msg::Float64::ConstSharedPtr msg)" in src
    assert "::SharedPtr msg" not in files["include/pid/PIDController.hpp"]
    cmake = files["CMakeLists.txt"]
    assert "install(DIRECTORY include/ DESTINATION include/${PROJECT_NAME})" in cmake
    assert "$<INSTALL_INTERFACE:include/${PROJECT_NAME}>" in cmake and "DESTINATION include)" not in cmake


def test_ros2_remaps_named_from_the_root_follow_a_pushed_namespace() -> None:
    # learning: learner is in the root namespace, fri in atf/driver; a relative name of a root node
    # resolves under a pushed namespace, a namespaced node's name from the root must start with it
    launch = _files(_run(ROOT / "fixtures/cases/learning", "ros2"))["launch/learning_armpc.launch.xml"]
    remaps = {(n.get("name"), r.get("from")): r.get("to")
              for n in etree.fromstring(launch.encode()).iter("composable_node") for r in n.iter("remap")}
    assert remaps[("learner", "cartPos")] == "measuredPose"
    assert remaps[("fri", "cartPos")] == "$(var ros_namespace '')/measuredPose"
    assert remaps[("learner", "setCompliant")] == "$(var ros_namespace '')/atf/driver/jointCtrl/setCompliant"
    assert not [to for to in remaps.values() if to.startswith("/")]


def test_a_port_of_a_data_type_converts_to_the_packages_type() -> None:
    """ROS 1: jointstate::JointSample is the generated message, so the model's type is
    ::jointstate::types::JointSample (issue 10 item 8, issue 37 item 4; catkin builds the fixture below)."""
    for target in TARGETS:
        files = _files(_run(ROOT / "fixtures/ros/jointstate", target))
        # broken after its parenthesis where the line would pass 100 columns
        assert "::SampledPIDController::setMeasuredPosition(from_msg_value<::jointstate::types::JointSample>(*msg));" \
            in re.sub(r"\(\n\s*", "(", files["src/PIDController.cpp"])
        assert "to_msg(::SimulatedJoint::getMeasuredPosition(), msg);" in files["src/RobotInterface.cpp"]
        assert files["msg/JointSample.msg"].splitlines()[-2:] == ["float64 position", "float64 velocity"]
        conversions = files["include/jointstate/msg_conversions.hpp"]
        assert "inline void from_msg(const jointstate::" in conversions \
            and "::jointstate::types::JointSample & v)" in conversions
        header = files["include/JointSample.hpp"]
        assert "namespace jointstate\n{\nnamespace types\n{\n" in header and "struct JointSample\n" in header
        assert "#ifdef ROBOMDA_GLOBAL_TYPE_NAMES\nusing ::jointstate::types::JointSample;\n#endif" in header


def test_a_stamped_data_type_carries_a_std_msgs_header() -> None:
    """Issue 37 item 6: JointSample specialises Stamped (stamp: Real, frameId: String = "joint1"): its
    message begins with std_msgs/Header, which the conversions fill from stamp and frameId and back,
    the publisher stamps a datum without a stamp with the time of publishing, and the package depends
    on std_msgs for it (catkin builds the fixture: test_ros1_package_builds_with_catkin)."""
    for target in TARGETS:
        files = _files(_run(ROOT / "fixtures/ros/jointstate", target))
        body = [line for line in files["msg/JointSample.msg"].splitlines() if not line.startswith("#")]
        assert body == ["std_msgs/Header header", "float64 position", "float64 velocity"], body
        header = files["include/JointSample.hpp"]
        assert "  double stamp = 0.0;\n  std::string frameId = \"joint1\";\n  double position" in header
        conversions = files["include/jointstate/msg_conversions.hpp"]
        assert "  m.header.frame_id = v.frameId;" in conversions and "  v.frameId = m.header.frame_id;" in conversions
        publisher = files["src/RobotInterface.cpp"]
        if target == "ros1":
            assert "  m.header.stamp = ros::Time(v.stamp);" in conversions
            assert "  v.stamp = m.header.stamp.toSec();" in conversions
            assert "if (msg.header.stamp.isZero()) {\n      msg.header.stamp = ros::Time::now();" in publisher
            assert "generate_messages(DEPENDENCIES std_msgs)" in files["CMakeLists.txt"]
        else:
            assert "  m.header.stamp.sec = static_cast<std::int32_t>(std::floor(v.stamp));" in conversions
            assert "  v.stamp = static_cast<double>(m.header.stamp.sec) + 1e-9 * m.header.stamp.nanosec;" in conversions
            assert "msg.header.stamp.nanosec == 0) {\n      msg.header.stamp = this->now();" in publisher
            assert '"msg/JointSample.msg" DEPENDENCIES std_msgs)' in files["CMakeLists.txt"]
        assert "<depend>std_msgs</depend>" in files["package.xml"]
        # the controller only receives: no stamping there
        assert "header.stamp" not in files["src/PIDController.cpp"]


def test_a_stamped_type_without_its_two_attributes_is_ros120(tmp_path: Path) -> None:
    """A Stamped whose frameId is an Integer: a warning on Stamped, no header, both fields ordinary."""
    src = (ROOT / "fixtures/ros/jointstate/model.xmi").read_text(encoding="utf-8")
    start = src.index('name="frameId"')
    end = src.index("</ownedAttribute>", start)
    attribute = src[start:end]
    changed = attribute.replace("#String", "#Integer").split("<defaultValue")[0] + "  "
    model = tmp_path / "model.xmi"
    model.write_text(src[:start] + changed + src[end:], encoding="utf-8")
    for target in TARGETS:
        done = generate(model, tmp_path / "out", target, write=False)
        ros120 = [w for w in done.warnings if w.code == "ROS120"]
        assert len(ros120) == 1 and "'Stamped'" in ros120[0].message, done.warnings
        files = _files(done)
        body = [line for line in files["msg/JointSample.msg"].splitlines() if not line.startswith("#")]
        assert body == ["float64 stamp", "int32 frame_id", "float64 position", "float64 velocity"], body


def test_warnings() -> None:
    ros2 = _run(ROOT / "fixtures/cases/pid", "ros2")
    assert [w.code for w in ros2.warnings] == ["ROS100"]  # deployed on ROS (1), generated for ROS 2
    assert _run(ROOT / "fixtures/cases/pid", "ros1").warnings == []
    head = _run(ROOT / "fixtures/cases/headlamp", "ros1")
    codes = [w.code for w in head.warnings]
    assert codes.count("ROS100") == 1 and "ROS101" in codes
    assert any("setWidth" in w.message for w in head.warnings)


# ----------------------------------------- platform switch: PIM functional part
def test_switching_execution_environment_changes_only_the_platform(tmp_path: Path) -> None:
    src = (ROOT / "fixtures/cases/meka/model.xmi").read_text(encoding="utf-8")
    assert src.count('xmi:type="uml:ExecutionEnvironment"') == 1
    switched = re.sub(r'(xmi:type="uml:ExecutionEnvironment" xmi:id="[^"]+" name=)"OROCOS"', r'\1"ROS"', src)
    assert switched != src
    (tmp_path / "model.xmi").write_text(switched, encoding="utf-8")
    a = etree.fromstring(import_model(ROOT / "fixtures/cases/meka/model.xmi").encode())
    b = etree.fromstring(import_model(tmp_path / "model.xmi").encode())
    pim = "{urn:robomda:pim:1}"
    assert etree.tostring(a.find(f"{pim}application")) == etree.tostring(b.find(f"{pim}application"))
    assert etree.tostring(a.find(f"{pim}platform")) != etree.tostring(b.find(f"{pim}platform"))
    assert {i.get("middleware") for i in b.iter(f"{pim}instance")} == {"ROS"}
    assert [c.tag for c in a] == [c.tag for c in b]
    # and the ROS 1 target no longer warns that the platform says otherwise
    done = generate(tmp_path / "model.xmi", tmp_path / "out", "ros1", write=False)
    assert "ROS100" not in [w.code for w in done.warnings]


# ------------------------------------------------------------ package.xml
@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
@pytest.mark.parametrize("target", TARGETS)
def test_package_xml_with_catkin_pkg(case: Path, target: str, tmp_path: Path) -> None:
    package = pytest.importorskip("catkin_pkg.package", reason="catkin_pkg (PyPI) not installed")
    (tmp_path / "package.xml").write_text(_files(_run(case, target))["package.xml"], encoding="utf-8")
    pkg = package.parse_package(str(tmp_path / "package.xml"))
    pkg.validate()
    assert pkg.package_format == 3
    build_type = pkg.get_build_type()
    assert build_type == ("catkin" if target == "ros1" else "ament_cmake")


# ---------------------------------------------------------- ROS 2 launch XML
@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_ros2_launch_xml_against_launch_ros_rules(case: Path) -> None:
    schema = xmlschema.XMLSchema(str(ROOT / "schemas/ros2-launch/1/launch.xsd"))
    launches = {p: t for p, t in _files(_run(case, "ros2")).items() if p.endswith(".launch.xml")}
    assert launches
    for path, text in launches.items():
        schema.validate(text)


# ------------------------------------------------------ ROS 1: real tools
@pytest.fixture(scope="session")
def catkin_ws(tmp_path_factory) -> Path:
    """Every case's ROS 1 package in one catkin workspace, built once per run: under pytest-xdist
    the first worker builds it in the folder the run's workers share, the others wait for it."""
    _need("catkin_make")
    root = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        root = root.parent
    ws = root / "catkin_ws_all"
    with open(root / "catkin_ws_all.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not (ws / ".built").is_file():
            shutil.rmtree(ws, ignore_errors=True)
            _build_catkin_ws(ws, tmp_path_factory)
            (ws / ".built").write_text("built\n")
    return ws


def _build_catkin_ws(ws: Path, tmp_path_factory) -> None:
    for case in CASES:
        generate(case / "model.xmi", ws / "src" / case.name, "ros1")
    # the distributed fixture with every process on ROS 1: two machines, a set, a thread
    # (the three Orocos processes of the fixture carry ' version="2.10"' on their Middleware)
    generate(distributed_variant(tmp_path_factory.mktemp("all_ros"), (' version="2.10"', ' kind="ROS"', 3)),
             ws / "src" / "distributed_ros", "ros1", package_name="distributed_ros")
    # -C: catkin_make takes its workspace from $PWD, not from the cwd. CMake's unity build batches each
    # node's sources into one translation unit, so ros/ros.h is parsed once a node, not once a file: this
    # build takes 85 s instead of about 200 s (CI stays under 20 minutes). The price: a source that
    # compiles only thanks to an include another source of its node makes would pass here; each source
    # opens with its own header, and the toolchain tests (ROS 2, Orocos) build file by file.
    proc = subprocess.run(["catkin_make", "-C", str(ws), "-DPYTHON_EXECUTABLE=" + SYS_PY, "-DCMAKE_UNITY_BUILD=ON"], cwd=ws,
                          env=_ros_env(PWD=str(ws)),
                          capture_output=True, text=True, timeout=1200)
    assert proc.returncode == 0 and (ws / "devel").is_dir(), proc.stdout[-4000:] + proc.stderr[-4000:]


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_ros1_package_builds_with_catkin(case: Path, catkin_ws: Path) -> None:
    nodes = etree.fromstring(_run(case, "ros1").stages["psm"].encode()).iter("{urn:robomda:psm-ros:1}node")
    for node in nodes:
        exe = catkin_ws / "devel" / "lib" / case.name / node.get("executable")
        assert exe.is_file() and os.access(exe, os.X_OK), exe


def _rostest(ws: Path, target: str, home: Path) -> subprocess.CompletedProcess[str]:
    """rostest of ``target`` (PACKAGE FILE.test, or a .test path) in the built workspace: a master of its own."""
    return subprocess.run(["bash", "-c", f"source {ws}/devel/setup.bash && rostest {target}"], cwd=ws,
                          env=_ros_env(ROS_HOME=str(home)), capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_ros1_system_passes_its_own_rostest(case: Path, catkin_ws: Path, tmp_path: Path) -> None:
    """The package's generated test (test/<model>.test: the system as modelled, issue 52) passes under rostest."""
    _need("rostest")
    package = catkin_ws / "src" / case.name
    name = etree.parse(str(package / "package.xml")).findtext("name")
    test = next((package / "test").glob("*.test"))
    done = _rostest(catkin_ws, f"{name} {test.name}", tmp_path)
    said = done.stdout + done.stderr
    assert done.returncode == 0 and "FAILURES: 0" in said and "ERRORS: 0" in said, said[-4000:]


def test_ros1_rostest_names_the_connection_a_launch_file_breaks(catkin_ws: Path, tmp_path: Path) -> None:
    """With one remap taken out of the host launch file (a copy), the generated test fails naming that connection."""
    _need("rostest")
    package = catkin_ws / "src" / "pid"
    host = next(p for p in (package / "launch").glob("pid_*.launch"))
    text = host.read_text(encoding="utf-8")
    remap = re.search(r'<remap from="(\w+)" to="(\w+)"/>', text)
    broken = tmp_path / host.name
    broken.write_text(text.replace(remap.group(0), "", 1), encoding="utf-8")
    test = (package / "test" / "pid.test").read_text(encoding="utf-8")
    # rostest runs a .test file of a package: this one at the package's root, out of test/ (which the
    # test above reads), gone afterwards
    broken_test = package / f"broken-{os.getpid()}-{tmp_path.name}.test"
    broken_test.write_text(re.sub(r'<include file="[^"]*"/>', f'<include file="{broken}"/>', test), encoding="utf-8")
    try:
        done = _rostest(catkin_ws, str(broken_test), tmp_path)
    finally:
        broken_test.unlink()
    said = done.stdout + done.stderr
    assert done.returncode != 0, said[-3000:]
    assert re.search(rf"connection \w+\.{remap.group(1)} -> \w+\.\w+: \w+ does not publish on a topic {remap.group(2)}"
                     rf"|connection \w+\.\w+ -> \w+\.{remap.group(1)}: \w+ does not publish on a topic {remap.group(2)}", said), \
        said[-4000:]


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_ros1_catkin_lint_no_error(case: Path, tmp_path: Path) -> None:
    lint = _need("catkin_lint")
    generate(case / "model.xmi", tmp_path / case.name, "ros1")
    proc = subprocess.run([lint, "-W2", str(tmp_path / case.name)], env=_ros_env(), capture_output=True, text=True)
    errors = [line for line in proc.stdout.splitlines() + proc.stderr.splitlines() if ": error:" in line]
    assert not errors, "\n".join(errors)
    # and no warning (-W1): the atomic-code library is an imported target, not an include
    # folder outside the package (issue 10 item 7)
    warnings = [line for line in proc.stdout.splitlines() + proc.stderr.splitlines() if ": warning:" in line]
    assert not warnings, "\n".join(warnings)


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_ros1_launch_files_load_with_roslaunch(case: Path, catkin_ws: Path) -> None:
    _need("roslaunch")
    pkg = catkin_ws / "src" / case.name
    launches = sorted((pkg / "launch").glob("*.launch"))
    assert len(launches) >= 2
    env = _ros_env(ROS_PACKAGE_PATH=str(catkin_ws / "src") + ":/usr/share",
                   CMAKE_PREFIX_PATH=str(catkin_ws / "devel") + ":/usr")
    # a node inside a composite part runs in the namespace of its path; a job's instance that only a
    # switch starts (idle) is in its job's launch file instead, and each job coordinator is a node
    psm = etree.fromstring(_run(case, "ros1").stages["psm"].encode())
    expected = sorted(["/" + "".join(i.get("namespace", "") + "/" if i.get("namespace") else "")
                       + i.get("node-name", i.get("name")) for i in psm.iter("{urn:robomda:psm-ros:1}instance")
                       if i.get("idle") != "true"]
                      + ["/" + c.get("node") for c in psm.iter("{urn:robomda:psm-ros:1}coordinator")])
    for launch in launches:
        nodes = _roslaunch_config(launch, env, "print('\\n'.join(sorted(n.namespace + n.name for n in c.nodes)))")
        if launch.name == f"{_deploy_name(case)}.launch":
            assert nodes.split() == expected
        check = subprocess.run(["roslaunch", "--nodes", str(launch)], env=env, capture_output=True, text=True)
        assert check.returncode == 0, check.stderr


def _roslaunch_config(launch: Path, env: dict, show: str) -> str:
    """What SHOW (Python, with the loaded configuration as ``c``) prints of LAUNCH as roslaunch's
    own loader reads it, machines assigned."""
    script = ("import sys, roslaunch.config, roslaunch.xmlloader\n"
              "c = roslaunch.config.ROSLaunchConfig()\n"
              "roslaunch.xmlloader.XmlLoader().load(sys.argv[1], c, verbose=False)\n"
              "c.assign_machines()\n" + show + "\n")
    proc = subprocess.run([SYS_PY, "-c", script, str(launch)], env=env, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def test_ros1_namespace_argument_moves_every_name_of_learning(tmp_path: Path) -> None:
    """roslaunch's own loader, no build: learning included with ns=robot inside another group puts
    every node and parameter under /robot, and the two ends of each connection resolve to one name."""
    _need("roslaunch")
    pkg = tmp_path / "src" / "learning"
    generate(ROOT / "fixtures" / "cases" / "learning" / "model.xmi", pkg, "ros1")
    wrapper = tmp_path / "wrapper.launch"
    wrapper.write_text(f'''<launch><group ns="ignored"><include file="{pkg}/launch/learning.launch">
  <arg name="ns" value="robot"/></include></group></launch>''')
    env = _ros_env(ROS_PACKAGE_PATH=str(tmp_path / "src") + ":/usr/share")
    shown = _roslaunch_config(wrapper, env, "import json; print(json.dumps({'nodes': {n.namespace + n.name: [[a, b if "
                              "b.startswith('/') else n.namespace + b] for a, b in n.remap_args] for n in c.nodes}, "
                              "'params': sorted(c.params)}))")
    found = json.loads(shown)
    nodes = found["nodes"]
    assert sorted(nodes) == ["/robot/atf/csIter", "/robot/atf/driver/fri", "/robot/atf/driver/jointCtrl",
                             "/robot/atf/jsIter", "/robot/csGen", "/robot/learner"]
    assert all(to.startswith("/robot/") for remaps in nodes.values() for _, to in remaps), nodes
    remap = {(node, port): to for node, remaps in nodes.items() for port, to in remaps}
    # fri (atf/driver) -> learner (the root) and csIter (atf); a service client to jointCtrl's service
    assert remap["/robot/atf/driver/fri", "cartPos"] == remap["/robot/learner", "cartPos"] == "/robot/measuredPose"
    assert remap["/robot/atf/csIter", "cartPos"] == "/robot/measuredPose"
    assert remap["/robot/learner", "setCompliant"] == "/robot/atf/driver/jointCtrl/setCompliant"
    assert {"/robot/atf/driver/jointCtrl/gain", "/robot/learner/window"} <= set(found["params"])
    assert not [p for p in found["params"] if p.startswith(("/atf", "/learner", "/ignored"))]


def _deploy_name(case: Path) -> str:
    return etree.fromstring(_run(case, "ros1").stages["psm"].encode()).get("deploy-name")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextlib.contextmanager
def _package_held(catkin_ws: Path, package: str):
    """The shared workspace's ``package`` for this test alone: a test that edits its user files and one
    that launches it may run at once on two pytest-xdist workers (a CI run once read the other's values)."""
    with open(catkin_ws / f"{package}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield


@contextlib.contextmanager
def _roscore_running(catkin_ws: Path, launch: Path, output: Path | None = None):
    """A roscore on a free port with ``launch`` running under it; yields the environment of its tools.
    ``output``: a file for what roslaunch and its nodes print (else it is discarded)."""
    for tool in ("roscore", "roslaunch", "rostopic", "rosnode"):
        _need(tool)
    port = _free_port()
    env = _ros_env(ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_HOSTNAME="127.0.0.1",
                   ROS_PACKAGE_PATH=str(catkin_ws / "src") + ":/usr/share",
                   CMAKE_PREFIX_PATH=str(catkin_ws / "devel") + ":/usr",
                   ROS_HOME=str(catkin_ws / "ros_home"), ROS_LOG_DIR=str(catkin_ws / "ros_log"),
                   # the generated messages' Python classes, for rostopic
                   PYTHONPATH=str(catkin_ws / "devel" / "lib" / "python3" / "dist-packages"))
    procs = []
    try:
        procs.append(subprocess.Popen(["roscore", "-p", str(port)], env=env, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL, start_new_session=True))
        deadline = time.monotonic() + 30
        while subprocess.run(["rosnode", "list"], env=env, capture_output=True).returncode != 0:
            assert time.monotonic() < deadline, "roscore did not come up"
            time.sleep(0.5)
        printed = open(output, "w") if output else subprocess.DEVNULL  # noqa: SIM115 (closed with the process)
        procs.append(subprocess.Popen(["roslaunch", str(launch)], env=env,
                                      stdout=printed, stderr=subprocess.STDOUT if output else subprocess.DEVNULL,
                                      start_new_session=True))
        yield env
    finally:
        for proc in reversed(procs):
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGINT)
                try:
                    proc.wait(timeout=15)
                except subprocess.TimeoutExpired:
                    os.killpg(proc.pid, signal.SIGKILL)
                    proc.wait()


def _wait_for(env: dict, want_nodes: set[str], want_topics: set[str]) -> None:
    deadline = time.monotonic() + 30
    while True:
        nodes = set(subprocess.run(["rosnode", "list"], env=env, capture_output=True, text=True).stdout.split())
        topics = set(subprocess.run(["rostopic", "list"], env=env, capture_output=True, text=True).stdout.split())
        if want_nodes <= nodes and want_topics <= topics:
            return
        assert time.monotonic() < deadline, f"nodes {sorted(nodes)}, topics {sorted(topics)}"
        time.sleep(0.5)


def test_ros1_quadarm_structured_messages_flow_under_roscore(catkin_ws: Path) -> None:
    """Seed 001's quad-arm loop: generated messages with fixed arrays, a nested data type and an
    enumeration flow between the arms and their controllers, and the parameters of a data type, an
    enumeration and an array reach the nodes (the arms move to the controllers' desired angles)."""
    with _roscore_running(catkin_ws, catkin_ws / "src/quadarm/launch/quadarm.launch") as env:
        _wait_for(env, {f"/{kind}{k}" for kind in ("arm", "ctrl") for k in range(1, 5)},
                  {f"/{kind}{k}" for kind in ("state", "torques") for k in range(1, 5)})
        types = {t: subprocess.run(["rostopic", "type", t], env=env, capture_output=True, text=True,
                                   timeout=20).stdout.strip() for t in ("/state1", "/torques4")}
        assert types == {"/state1": "quadarm/JointState", "/torques4": "quadarm/JointTorques"}
        torques = subprocess.run(["rostopic", "echo", "-n", "1", "/torques4"], env=env, capture_output=True,
                                 text=True, timeout=30).stdout
        assert re.search(r"torque: \[[^\]]*\]\ngains: \n  stiffness: 300\.0\n  damping: 20\.0\n  max_torque: 80\.0",
                         torques), torques
        deadline = time.monotonic() + 30
        while True:
            state = subprocess.run(["rostopic", "echo", "-n", "1", "/state1"], env=env, capture_output=True,
                                   text=True, timeout=30).stdout
            assert re.search(r"mode: \n  value: 1\n", state), state  # IMPEDANCE, the arm's mode parameter
            position = [float(v) for v in re.search(r"position: \[([^\]]*)\]", state).group(1).split(",")]
            assert len(position) == 7
            # desired = {0.0, 0.5, 0.0, -1.0, 0.0, 0.5, 0.0}: the controller's array parameter
            if abs(position[1] - 0.5) < 0.05 and abs(position[3] + 1.0) < 0.05:
                break
            assert time.monotonic() < deadline, state
            time.sleep(0.5)


def test_ros1_pid_runs_under_roscore(catkin_ws: Path) -> None:
    with _roscore_running(catkin_ws, catkin_ws / "src/pid/launch/pid.launch") as env:
        want_nodes = {"/TrajectoryGenerator", "/PIDController", "/RobotInterface"}
        want_topics = {"/IDesiredPositionConn", "/IMeasuredPositionConn", "/IReferenceTorqueConn"}
        _wait_for(env, want_nodes, want_topics)
        for topic in sorted(want_topics):
            info = subprocess.run(["rostopic", "type", topic], env=env, capture_output=True, text=True, timeout=20)
            assert info.stdout.strip() == "std_msgs/Float64"
            echo = subprocess.run(["rostopic", "echo", "-n", "3", topic], env=env, capture_output=True,
                                  text=True, timeout=30)
            assert echo.stdout.count("data:") == 3, echo.stdout + echo.stderr
        # the loop closes: the joint moves
        pos = subprocess.run(["rostopic", "echo", "-n", "20", "/IMeasuredPositionConn"], env=env,
                             capture_output=True, text=True, timeout=30).stdout
        values = [float(v) for v in re.findall(r"data: (\S+)", pos)]
        assert any(v != 0.0 for v in values), values
        service = subprocess.run(["rosservice", "call", "/PIDController/reset"], env=env, capture_output=True,
                                 text=True, timeout=20) if shutil.which("rosservice", path=ROS_ENV_PATH) else None
        if service is not None:
            assert service.returncode == 0, service.stderr


def _rostopic_info(env: dict, topic: str) -> tuple[set[str], set[str]]:
    """(publishers, subscribers) of ``topic``, as ``rostopic info`` names their nodes."""
    text = subprocess.run(["rostopic", "info", topic], env=env, capture_output=True, text=True, timeout=20).stdout
    pubs, _, subs = text.partition("Subscribers:")
    return set(re.findall(r"^ \* (\S+)", pubs, re.M)), set(re.findall(r"^ \* (\S+)", subs, re.M))


def _rosparam(env: dict, name: str) -> str:
    return subprocess.run(["rosparam", "get", name], env=env, capture_output=True, text=True, timeout=20).stdout.strip()


def test_ros1_learning_runs_in_the_namespace_its_argument_names(catkin_ws: Path, tmp_path: Path) -> None:
    """Issue 36 item 7 on ROS 1: learning's nodes in namespaces of their own (atf/driver) name their topics
    from the root, which an enclosing <group ns> cannot move; its launch files take the namespace as
    argument ns: every node, topic and parameter is then under /robot and both ends of each connection
    meet there, even inside a group."""
    wrapper = tmp_path / "learning_ns.launch"
    wrapper.write_text(f"""<launch>
  <group ns="ignored">
    <include file="{catkin_ws}/src/learning/launch/learning.launch"><arg name="ns" value="robot"/></include>
  </group>
</launch>
""")
    with _roscore_running(catkin_ws, wrapper) as env:
        _wait_for(env, {"/robot/learner", "/robot/csGen", "/robot/atf/driver/fri", "/robot/atf/driver/jointCtrl",
                        "/robot/atf/jsIter", "/robot/atf/csIter"},
                  {"/robot/measuredPose", "/robot/atf_driver_measuredJoints", "/robot/atf_driver_torqueCmd"})
        # fri (atf/driver) -> learner (root); fri, jointCtrl (atf/driver) and jsIter (atf) share measuredJoints
        assert _rostopic_info(env, "/robot/measuredPose") == (
            {"/robot/atf/driver/fri"}, {"/robot/learner", "/robot/atf/csIter"})
        pubs, subs = _rostopic_info(env, "/robot/atf_driver_measuredJoints")
        assert pubs == {"/robot/atf/driver/fri"} and {"/robot/atf/driver/jointCtrl", "/robot/atf/jsIter"} <= subs
        echo = subprocess.run(["rostopic", "echo", "-n", "2", "/robot/measuredPose"], env=env, capture_output=True,
                              text=True, timeout=30)
        assert echo.returncode == 0 and echo.stdout.count("---") == 2, echo.stdout + echo.stderr
        topics = subprocess.run(["rostopic", "list"], env=env, capture_output=True, text=True).stdout.split()
        assert [t for t in topics if not t.startswith(("/robot/", "/rosout"))] == []
        # the parameters follow the node: the model's values, private to the moved node
        assert _rosparam(env, "/robot/atf/driver/jointCtrl/gain") == "12.5"
        assert _rosparam(env, "/robot/learner/window") == "50"


def test_ros1_pid_follows_an_enclosing_group(catkin_ws: Path, tmp_path: Path) -> None:
    """A package whose remaps are all relative (no node in a namespace of its own) follows a <group ns>."""
    wrapper = tmp_path / "pid_group.launch"
    wrapper.write_text(f"""<launch>
  <group ns="robot"><include file="{catkin_ws}/src/pid/launch/pid.launch"/></group>
</launch>
""")
    assert "<arg" not in (catkin_ws / "src/pid/launch/pid.launch").read_text()
    with _roscore_running(catkin_ws, wrapper) as env:
        _wait_for(env, {"/robot/TrajectoryGenerator", "/robot/PIDController", "/robot/RobotInterface"},
                  {"/robot/IDesiredPositionConn", "/robot/IMeasuredPositionConn", "/robot/IReferenceTorqueConn"})
        assert _rostopic_info(env, "/robot/IReferenceTorqueConn") == ({"/robot/PIDController"}, {"/robot/RobotInterface"})
        echo = subprocess.run(["rostopic", "echo", "-n", "3", "/robot/IReferenceTorqueConn"], env=env,
                              capture_output=True, text=True, timeout=30)
        assert echo.stdout.count("data:") == 3, echo.stdout + echo.stderr
        assert _rosparam(env, "/robot/PIDController/kp") == "20.0"


def test_ros1_configuration_constant_reaches_a_late_subscriber(catkin_ws: Path) -> None:
    """Seed 004's configuration constant («Constant», pidswap's torque limit): the robot interface publishes
    it once, on a latched topic, so a subscriber that comes long after still receives it, and only it."""
    with _roscore_running(catkin_ws, catkin_ws / "src/pidswap/launch/pidswap.launch") as env:
        _wait_for(env, {"/PIDController", "/RobotInterface"}, {"/IJointLimitConn", "/IReferenceTorqueConn"})
        # the loop runs (torques flow) well after the one publish of the limit
        torques = subprocess.run(["rostopic", "echo", "-n", "20", "/IReferenceTorqueConn"], env=env,
                                 capture_output=True, text=True, timeout=30).stdout
        assert torques.count("data:") == 20, torques
        late = subprocess.run(["timeout", "5", "rostopic", "echo", "/IJointLimitConn"], env=env,
                              capture_output=True, text=True)
        # the latched sample, once: nothing is published per cycle
        assert re.findall(r"data: (\S+)", late.stdout) == ["5.0"], late.stdout + late.stderr


def _pid(env: dict, node: str) -> int:
    info = subprocess.run(["rosnode", "info", node], env=env, capture_output=True, text=True, timeout=30).stdout
    found = re.search(r"Pid: (\d+)", info)
    assert found, info
    return int(found.group(1))


def _job(env: dict, want: str, log: Path) -> None:
    """Waits until the coordinator publishes job ``want`` on /arm/job (latched)."""
    deadline = time.monotonic() + 60
    while True:
        said = subprocess.run(["rostopic", "echo", "-n", "1", "/arm/job"], env=env, capture_output=True,
                              text=True, timeout=30).stdout
        if f"data: \"{want}\"" in said:
            return
        assert time.monotonic() < deadline, said + log.read_text(errors="replace")[-4000:]
        time.sleep(0.5)


def _flows(env: dict, topic: str, count: int = 3) -> list[float]:
    echo = subprocess.run(["rostopic", "echo", "-n", str(count), topic], env=env, capture_output=True,
                          text=True, timeout=30)
    values = [float(v) for v in re.findall(r"data: (\S+)", echo.stdout)]
    assert len(values) == count, echo.stdout + echo.stderr
    return values


def _nodes(env: dict) -> set[str]:
    return set(subprocess.run(["rosnode", "list"], env=env, capture_output=True, text=True).stdout.split())


def _until_nodes(env: dict, present: set[str], absent: set[str], log: Path) -> None:
    deadline = time.monotonic() + 30
    while not (present <= _nodes(env) and not absent & _nodes(env)):
        assert time.monotonic() < deadline, f"{sorted(_nodes(env))}\n" + log.read_text(errors="replace")[-4000:]
        time.sleep(0.5)


def test_ros1_teleop_switches_jobs_and_never_restarts_the_shared_robot(catkin_ws: Path, tmp_path: Path) -> None:
    """Seed 004 §4.3 on ROS 1 (docs/jobs.md): the launch file starts job teleoperation; event play on
    /arm/event shuts the trackball down, reloads invkin's gain and starts the player; teleoperate goes
    back. The shared robot interface is never restarted (its PID), data flows before and after each
    switch, and the robot's cycle counter never starts again."""
    log = tmp_path / "teleop.log"
    with _roscore_running(catkin_ws, catkin_ws / "src/teleop/launch/teleop.launch", log) as env:
        _wait_for(env, {"/trackball", "/invkin", "/robot", "/arm_coordinator"}, {"/command", "/joint", "/arm/job"})
        _job(env, "teleoperation", log)
        assert "/player" not in _nodes(env)  # idle: only a switch starts it
        robot = _pid(env, "/robot")
        _flows(env, "/trackballPose"), _flows(env, "/command")
        before = _flows(env, "/cycles", 1)[0]
        assert subprocess.run(["rosparam", "get", "/invkin/gain"], env=env, capture_output=True,
                              text=True).stdout.strip() == "1.0"
        for event, job, gone, came, gain in (("play", "playback", "/trackball", "/player", "2.0"),
                                             ("teleoperate", "teleoperation", "/player", "/trackball", "1.0")):
            pub = subprocess.run(["rostopic", "pub", "-1", "/arm/event", "std_msgs/String", f"data: '{event}'"],
                                 env=env, capture_output=True, text=True, timeout=60)
            assert pub.returncode == 0, pub.stderr
            _job(env, job, log)
            _until_nodes(env, {came, "/robot", "/invkin"}, {gone}, log)
            assert _pid(env, "/robot") == robot  # the shared node: never restarted
            assert subprocess.run(["rosparam", "get", "/invkin/gain"], env=env, capture_output=True,
                                  text=True).stdout.strip() == gain
            _flows(env, "/trackballPose"), _flows(env, "/command")  # the new source feeds invkin
            now = _flows(env, "/cycles", 1)[0]
            assert now > before, (before, now)  # counting on: the robot interface ran through the switch
            before = now
    text = log.read_text(errors="replace")
    assert "job playback active (event play)" in text and "job teleoperation active (event teleoperate)" in text, text[-4000:]
    assert "/invkin: 1 values reloaded" in text and "/trackball: shut down" in text, text[-4000:]


def test_ros1_package_moved_away_names_the_option_then_configures(tmp_path: Path) -> None:
    """A package copied into a workspace failed with an unexplained NOTFOUND (issue 10 item 7)."""
    cmake = _need("cmake")
    _need("catkin_make")
    generate(ROOT / "fixtures" / "cases" / "pid" / "model.xmi", tmp_path / "out" / "pid", "ros1")
    moved = tmp_path / "ws" / "src" / "deeper" / "pid"
    shutil.copytree(tmp_path / "out" / "pid", moved)
    args = [cmake, "-S", str(moved), "-DPYTHON_EXECUTABLE=/usr/bin/python3"]
    lost = subprocess.run(args + ["-B", str(tmp_path / "b1")], env=_ros_env(), capture_output=True, text=True)
    assert lost.returncode != 0
    assert "atomic-code library pid_atomic: no directory" in lost.stderr
    assert "give its place with -DPID_PID_ATOMIC_DIR=DIR" in " ".join(lost.stderr.split())
    atomic = ROOT / "fixtures" / "cases" / "pid" / "atomic"
    found = subprocess.run(args + ["-B", str(tmp_path / "b2"), f"-DPID_PID_ATOMIC_DIR={atomic}"],
                           env=_ros_env(), capture_output=True, text=True)
    assert found.returncode == 0, found.stderr[-2000:]


def test_ros1_tuned_parameters_in_the_user_file_win(tmp_path: Path) -> None:
    """Tuning on the robot meant editing a generated file, which then blocked regeneration (issue 10 item 6)."""
    _need("roslaunch")
    ws = tmp_path / "ws"
    pkg = ws / "src" / "pid"
    generate(ROOT / "fixtures" / "cases" / "pid" / "model.xmi", pkg, "ros1")
    user = pkg / "config" / "PIDController.user.yaml"
    assert "This file is yours" in user.read_text()
    user.write_text(user.read_text().replace("{}", "kp: 42.5"))
    env = _ros_env(ROS_PACKAGE_PATH=str(ws / "src") + ":/usr/share")
    dump = subprocess.run(["roslaunch", "--dump-params", str(pkg / "launch" / "pid.launch")], env=env,
                          capture_output=True, text=True)
    assert dump.returncode == 0, dump.stderr
    assert "/PIDController/kp: 42.5" in dump.stdout and "/PIDController/ki: 0.5" in dump.stdout
    # regeneration keeps the tuned value and rewrites the generated files
    done = generate(ROOT / "fixtures" / "cases" / "pid" / "model.xmi", pkg, "ros1")
    assert "kp: 42.5" in user.read_text() and "config/PIDController.user.yaml" in done.report.kept_user


def _assert_topics_live(env: dict, connections: dict, node) -> None:
    """Each topic of CONNECTIONS (topic -> pim:connection): its writer (NODE(instance name) is
    its node) publishes, its readers subscribe, and data flows."""
    pim = "{urn:robomda:pim:1}"
    for topic, connection in sorted(connections.items()):
        info = subprocess.run(["rostopic", "info", topic], env=env, capture_output=True, text=True,
                              timeout=20).stdout
        publishers = info.split("Subscribers:")[0]
        subscribers = info.split("Subscribers:")[1] if "Subscribers:" in info else ""
        assert f"* {node(connection.find(f'{pim}writer').get('instance'))} " in publishers, info
        for reader in connection.findall(f"{pim}reader"):
            assert f"* {node(reader.get('instance'))} " in subscribers, (topic, info)
        echo = subprocess.run(["rostopic", "echo", "-n", "2", topic], env=env, capture_output=True,
                              text=True, timeout=30)
        assert echo.stdout.count("data:") == 2, (topic, echo.stdout + echo.stderr)


def test_ros1_distributed_runs_on_two_machines_with_every_connection_live(catkin_ws: Path) -> None:
    """Seed 002's deployment on ROS 1: the two hosts are two <machine>s on the loopback address,
    the component set has a launch file of its own that its host's includes, and every connection
    of the model, within a host and across the two, is a live topic."""
    pkg = catkin_ws / "src" / "distributed_ros"
    launch = pkg / "launch" / "distributed.launch"
    assert (pkg / "launch" / "distributed_vision_set.launch").is_file()
    env = _ros_env(ROS_PACKAGE_PATH=str(catkin_ws / "src") + ":/usr/share",
                   CMAKE_PREFIX_PATH=str(catkin_ws / "devel") + ":/usr")
    machines, nodes = _roslaunch_config(launch, env, "print(sorted((m.name, m.address) for m in c.machines.values()"
                                        " if m.name))\nprint(sorted((n.name, n.machine_name) for n in c.nodes))").splitlines()
    assert machines == str([("control_pc", "127.0.0.1"), ("vision_pc", "127.0.0.1")])
    assert nodes == str(sorted([("arm", "control_pc"), ("camera", "vision_pc"), ("controller", "control_pc"),
                                ("forceSensor", "control_pc"), ("vision", "vision_pc")]))
    case = ROOT / "fixtures" / "cases" / "distributed"
    binding = etree.fromstring(_run(case, "orocos").stages["bind"].encode()).find("{urn:robomda:pim:1}binding")
    connections = {"/" + c.get("name"): c for c in binding.findall("{urn:robomda:pim:1}connection")}
    assert len(connections) == 6
    with _roscore_running(catkin_ws, launch) as ros:
        _wait_for(ros, {"/arm", "/camera", "/controller", "/forceSensor", "/vision"}, set(connections))
        _assert_topics_live(ros, connections, lambda name: "/" + name)


@pytest.mark.parametrize("app", ["calligraphy", "learning"])
def test_ros1_composites_run_under_roscore_with_every_connection_live(app: str, catkin_ws: Path) -> None:
    """Seed 003's applications: each node in the namespace of its composite parts, and every
    connection of the model, at any depth, a topic with its writer publishing and its readers
    subscribed."""
    binding = etree.fromstring(_run(ROOT / "fixtures" / "cases" / app, "ros1").stages["bind"].encode()).find(
        "{urn:robomda:pim:1}binding")
    pim = "{urn:robomda:pim:1}"

    def node(instance_name: str) -> str:
        found = binding.find(f"{pim}instance[@name='{instance_name}']")
        return "/" + (found.get("path") or found.get("name")).replace(".", "/")

    want_nodes = {node(i.get("name")) for i in binding.findall(f"{pim}instance")}
    assert "/atf/driver/fri" in want_nodes
    connections = {"/" + c.get("name"): c for c in binding.findall(f"{pim}connection")}
    with _roscore_running(catkin_ws, catkin_ws / "src" / app / "launch" / f"{app}.launch") as env:
        _wait_for(env, want_nodes, set(connections))
        _assert_topics_live(env, connections, node)
        # every operation call: the provider's service is up where the caller's client is
        # remapped to, and answers
        calls = binding.findall(f"{pim}call")
        assert calls, "the fixture calls an operation (seed 003's ICompliance)"
        launch_text = "".join(p.read_text() for p in (catkin_ws / "src" / app / "launch").glob("*.launch"))
        services = set(subprocess.run(["rosservice", "list"], env=env, capture_output=True, text=True,
                                      timeout=20).stdout.split())
        for call in calls:
            service = node(call.find(f"{pim}provider").get("instance")) + "/setCompliant"
            assert service in services, (service, sorted(services))
            # from the root, or from the package's namespace argument (docs/ros.md, "Namespaces"), empty here
            assert (f'<remap from="setCompliant" to="{service}"/>' in launch_text
                    or f'<remap from="setCompliant" to="/$(arg ns){service}"/>' in launch_text), service
            answer = subprocess.run(["rosservice", "call", service, "true"], env=env, capture_output=True,
                                    text=True, timeout=20)
            assert "success: True" in answer.stdout, answer.stdout + answer.stderr


def test_ros1_a_list_of_mappings_parameter_is_read_by_the_node(catkin_ws: Path) -> None:
    """Issue 37: the node reads `stages` item by item: a user value with six items, or one whose member
    is a string, is logged (the member keeps its value); seven good items with a member left out are not."""
    user = catkin_ws / "src/structured/config"
    item = "{stiffness: 100, damping: 5.0, maxTorque: 10.0}"
    values = {1: f"stages: [{', '.join([item] * 6)}]\n",
              2: f"stages: [{', '.join([item] * 6 + ['{stiffness: stiff}'])}]\n",
              3: f"stages: [{', '.join([item] * 6 + ['{damping: 1.0}'])}]\n"}
    printed = catkin_ws / "structured-items.out"
    with _package_held(catkin_ws, "structured"):
        pristine = {k: (user / f"ctrl{k}.user.yaml").read_text() for k in values}
        try:
            for k, text in values.items():
                (user / f"ctrl{k}.user.yaml").write_text(text)
            with _roscore_running(catkin_ws, catkin_ws / "src/structured/launch/structured.launch", printed) as env:
                _wait_for(env, {f"/ctrl{k}" for k in range(1, 5)}, {"/state1", "/torques1"})
                time.sleep(2)
        finally:
            for k, text in pristine.items():
                (user / f"ctrl{k}.user.yaml").write_text(text)
    said = printed.read_text(errors="replace")
    rejected = [line for line in said.splitlines() if "parameter stages: not a list of 7 mappings" in line]
    assert len(rejected) == 2, said[-3000:]  # ctrl1 (six items) and ctrl2 (a string stiffness), not ctrl3
    assert "(stiffness, damping, maxTorque)" in rejected[0]


def test_ros1_structured_parameters_reach_the_nodes(catkin_ws: Path) -> None:
    """Issue 37: fixture `structured`'s property of each structured kind is a parameter with the value
    the Orocos deployment formats give it (tests/test_orocos_deploy.py), and the node reads every one
    without a complaint (a fixed array of another size or an unknown enumeration literal is logged as
    an error to /rosout). `stages` (an array of a data type) is a list of mappings on ROS 1."""
    yaml = pytest.importorskip("yaml", reason="PyYAML not installed")
    printed = catkin_ws / "structured-roslaunch.out"
    with _package_held(catkin_ws, "structured"), \
            _roscore_running(catkin_ws, catkin_ws / "src/structured/launch/structured.launch", printed) as env:
        _wait_for(env, {f"/ctrl{k}" for k in range(1, 5)}, {"/state1", "/torques1"})
        got = yaml.safe_load(subprocess.run(["rosparam", "get", "/ctrl1"], env=env, capture_output=True, text=True,
                                            timeout=30).stdout)
        gains = {"stiffness": 300.0, "damping": 20.0, "maxTorque": 80.0}
        assert {k: got.get(k) for k in ("gains", "desired", "fallback", "offsets", "limits", "limit")} == {
            "gains": gains, "desired": [0.0, 0.5, 0.0, -1.0, 0.0, 0.5, 0.0], "fallback": "TORQUE",
            "offsets": [1, -2, 3, 0, 0, 0, 7], "limits": [1.5, 2.5],
            "limit": {"torque": [0.0] * 7, "gains": gains}}
        assert got.get("stages") == [gains] * 7  # a list of mappings (issue 37): ROS 2 has none, ROS107
        assert "history" not in got  # empty: the node's default
        time.sleep(2)
        assert set(subprocess.run(["rosnode", "list"], env=env, capture_output=True, text=True).stdout.split()) >= {
            f"/ctrl{k}" for k in range(1, 5)}
    said = printed.read_text(errors="replace")
    assert "process[ctrl1-" in said, said[-3000:]  # the nodes' output is there
    assert not [line for line in said.splitlines() if "ERROR" in line and "parameter " in line], said[-3000:]
