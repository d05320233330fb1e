"""The dialect fixtures built and run on the real middleware, data flowing as each dialect means (issue 51).

Not in CI (markers ``orocos_toolchain`` and ``ros2_toolchain``, deselected there by conftest.py): the
toolchains are built from public sources by toolchains/orocos and toolchains/ros2. For each dialect
fixture (fixtures/cases/robotml: RobotML; fixtures/cases/p4r: Papyrus for Robotics), its components have
no realizing class, so robomda writes the user's classes once; the test fills them in as a user would
(a source writes a counter, the component in the middle passes what it reads on) and then:

- Orocos: builds the package, deploys its .ops in ``rttlua`` with a probe that checks every component
  Running, every modelled reader port an input and connected, and samples at the probes it connects to
  the writers at the end of each chain, which write only what went through the component before them:
  so every connection carried data from the port the dialect makes a writer to the one it makes a
  reader (the other way round, RTT refuses the connection); then a clean stop.
- ROS 2: builds the package with colcon (with fixtures/ros/p4rlib, whose ports Papyrus for Robotics'
  ROS 2 library types); launches it; for Papyrus for Robotics the nodes are managed
  (lifecycle) nodes, and each reports ``active``; messages flow on every connection topic, and the
  topic in the middle carries what went through; SIGINT stops it with no ERROR line.
"""

from __future__ import annotations

import os
import re
import subprocess
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from robomda.api import generate

ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT / "fixtures" / "cases"
OROCOS_ENV = ROOT / "toolchains" / "orocos" / "env.sh"
OROCOS = Path(os.environ.get("OROCOS_INSTALL", Path.home() / "orocos" / "install"))

# fixture -> (the user's code, by user source file: (text to replace, its replacement)),
#            the probe: (instances, reader ports that must be connected, writer ports whose values must
#            change, the Lua type of each probed writer, its field that counts)
USER_OROCOS = {
    "robotml": {
        "src/Odometry.cpp": ("  // write: port_pose.write(value)\n",
                             "  ::robotml::types::Pose pose;\n  pose.x = ++count_;\n  port_pose.write(pose);\n"),
        "src/Planner.cpp": ("  // read: port_pose.read(sample)\n",
                            "  ::robotml::types::Pose pose;\n  while (port_pose.read(pose) == RTT::NewData) {\n"
                            "    ::robotml::types::Twist cmd;\n    cmd.linear = pose.x;\n    port_cmd.write(cmd);\n  }\n"),
    },
    "p4r": {
        "src/Camera.cpp": ("  // write: port_image.write(value)\n",
                           "  ::p4r::types::Image image;\n  image.width = ++count_;\n  port_image.write(image);\n"),
        # the detector asks the logger's Query (an operation) about what it read, and sends on the answer
        "src/Detector.cpp": ("  // read: port_image.read(sample)\n",
                             "  ::p4r::types::Image image;\n  while (port_image.read(image) == RTT::NewData) {\n"
                             "    ::p4r::types::Boxes boxes;\n    boxes.count = image.width;\n"
                             "    boxes.count = Classify(boxes).label;\n    port_boxes.write(boxes);\n  }\n"),
        "src/Logger.cpp": ("Classify(const ::p4r::types::Boxes& /*request*/)\n{\n  return ::p4r::types::Verdict();",
                           "Classify(const ::p4r::types::Boxes& request)\n{\n  ::p4r::types::Verdict verdict;\n"
                           "  verdict.label = request.count + 1000;\n  return verdict;"),
    },
    # UML-RT: the sensor sends readings, the controller answers each with a request (a signal), which
    # the sensor receives: messages both ways on one pair of ports
    "umlrt": {
        "src/Sensor.cpp": ("  // write: port_data_reading.write(value)\n", "  port_data_reading.write(++count_);\n"),
        "src/Controller.cpp": ("  // read: port_sensor_reading.read(sample)\n",
                               "  double reading = 0.0;\n  while (port_sensor_reading.read(reading) == RTT::NewData) {\n"
                               "    port_sensor_request.write(true);\n  }\n"),
    },
    # Papyrus Designer: the sensor writes a count, the filter (inside the composite) adds the gain the
    # tuner sets through its required interface (an operation call), the monitor reads what comes out
    "designer": {
        "src/Sensor.cpp": ("  // write: port_reading.write(value)\n",
                           "  ::designer::types::Sample sample;\n  sample.value = ++count_;\n  port_reading.write(sample);\n"),
        "src/Filter.cpp": [("  // read: port_input.read(sample)\n  // write: port_output.write(value)\n",
                            "  ::designer::types::Sample sample;\n  while (port_input.read(sample) == RTT::NewData) {\n"
                            "    sample.value += gain_;\n    port_output.write(sample);\n  }\n"),
                           ("double Filter::scale(double /*value*/)\n{\n  return 0.0;",
                            "double Filter::scale(double value)\n{\n  gain_ = value;\n  return gain_;")],
        "include/designer/Filter.hpp": ("  void reset() override;\n", "  void reset() override;\n\nprivate:\n  double gain_ = 0.0;\n"),
        "src/Tuner.cpp": ("void Tuner::updateHook()\n{\n}", "void Tuner::updateHook()\n{\n  scale(1000.0);\n}"),
    },
    # SysML: the pump writes its pressure through the proxy port, the controller answers with a command
    "sysml": {
        "src/Pump.cpp": ("  // write: port_fluid_pressure.write(value)\n", "  port_fluid_pressure.write(++count_);\n"),
        "src/Sensor.cpp": ("  // write: port_level.write(value)\n", "  port_level.write(++count_);\n"),
        "src/Controller.cpp": ("  // read: port_pump_pressure.read(sample), port_level.read(sample)\n",
                               "  double pressure = 0.0;\n  while (port_pump_pressure.read(pressure) == RTT::NewData) {\n"
                               "    port_pump_command.write(pressure / 2);\n  }\n"),
    },
}
COUNTERS = {"robotml": "double", "p4r": "int", "umlrt": "double", "sysml": "double", "designer": "double"}
# instances, reader ports that must be connected, the writers probed: (instance, port, RTT type[, a
# field and the least value it must reach]); the probed writers write only what went through the
# component before them (p4r's detector: the logger's answer, at least 1000)
PROBES = {
    "robotml": (["odometry", "planner", "base"], [("planner", "pose"), ("base", "cmd")],
                [("planner", "cmd", "/robotml/Twist")]),
    "p4r": (["camera", "detector", "logger"], [("detector", "image"), ("logger", "boxes")],
            [("detector", "boxes", "/p4r/Boxes", "count", "1000")]),
    "umlrt": (["sensor", "controller"], [("controller", "sensor_reading"), ("sensor", "data_request")],
              [("controller", "sensor_request", "bool")]),
    "designer": (["sensor", "processing_filter", "monitor", "tuner"],
                 [("processing_filter", "input"), ("monitor", "reading_in")],
                 [("processing_filter", "output", "/designer/Sample", "value", "1000")]),
    "sysml": (["pump", "sensor", "controller"],
              [("controller", "pump_pressure"), ("pump", "fluid_command"), ("controller", "level")],
              [("controller", "pump_command", "double"), ("sensor", "level", "double")]),
}

PROBE = """require("rttlib")
local tc = rtt.getTC()
local depl = tc:getPeer("Deployer")
local ok = true
local function check(cond, what) print((cond and "PROBE ok " or "PROBE FAILED ") .. what); ok = ok and cond end
check(depl:runScript("%(ops)s"), "runScript %(ops)s")
for _, n in ipairs({%(instances)s}) do
  check(depl:getPeer(n):getState() == "Running", n .. " Running")
end
for _, e in ipairs({%(readers)s}) do
  local port = depl:getPeer(e[1]):getPort(e[2])
  check(port:info().connected and port:info().porttype == "in", e[1] .. "." .. e[2] .. " an input, connected")
end
for _, w in ipairs({%(writers)s}) do
  local ip = rtt.InputPort(w[3])
  tc:addPort(ip, "probe_" .. w[2])
  check(depl:connect(w[1] .. "." .. w[2], "lua.probe_" .. w[2], rtt.Variable("ConnPolicy")), "probe of " .. w[1] .. "." .. w[2])
  local seen, reached = 0, 0
  for k = 1, 80 do
    local fs, v = ip:read()
    if fs == "NewData" then
      seen = seen + 1
      if w[4] and tonumber(tostring(v[w[4]])) >= tonumber(w[5]) then reached = reached + 1 end
    end
    rtt.sleep(0, 25000000)
  end
  check(seen >= 3, w[1] .. "." .. w[2] .. " carries what went through (" .. seen .. " samples)")
  if w[4] then check(reached >= 3, w[1] .. "." .. w[2] .. "." .. w[4] .. " reaches " .. w[5] .. " (" .. reached .. " samples)") end
  ip:disconnect()
end
print(ok and "PROBE-RESULT: OK" or "PROBE-RESULT: FAILED")
for _, n in ipairs({%(instances)s}) do depl:getPeer(n):stop() end
for _, n in ipairs({%(instances)s}) do depl:getPeer(n):cleanup() end
os.exit(ok and 0 or 1)
"""


def _lua_list(items) -> str:
    return ", ".join("{" + ", ".join(f'"{x}"' for x in item) + "}" if isinstance(item, tuple) else f'"{item}"'
                     for item in items)


def _fill_in(out: Path, edits: dict[str, tuple[str, str] | list[tuple[str, str]]], counter_type: str) -> None:
    """The user's code: each edit (or list of edits) applied once to the user file robomda wrote; a source
    gets a counter."""
    for rel, change in edits.items():
        path = out / rel
        text = path.read_text(encoding="utf-8")
        for old, new in change if isinstance(change, list) else [change]:
            assert text.count(old) == 1, f"{rel}: the skeleton robomda writes changed; update this test"
            text = text.replace(old, new)
        path.write_text(text, encoding="utf-8")
        if "count_" in text and "count_ = 0" not in text:
            header = next((out / "include").rglob(Path(rel).stem + ".hpp"))
            htext = header.read_text(encoding="utf-8")
            htext = htext.replace("  void cleanupHook() override;\n",
                                  f"  void cleanupHook() override;\n\nprivate:\n  {counter_type} count_ = 0;\n", 1)
            header.write_text(htext, encoding="utf-8")


@pytest.mark.orocos_toolchain
@pytest.mark.skipif(not (OROCOS / "bin" / "deployer").exists(),
                    reason=f"no Orocos toolchain in {OROCOS}: build it with toolchains/orocos/build.sh")
@pytest.mark.parametrize("fixture", sorted(USER_OROCOS))
def test_orocos_components_run_and_data_flows_as_the_dialect_means(fixture: str, tmp_path: Path) -> None:
    out = tmp_path / fixture
    generate(CASES / fixture / "model.xmi", out, "orocos")
    _fill_in(out, USER_OROCOS[fixture], COUNTERS[fixture])

    def bash(script: str, timeout: int = 1800) -> subprocess.CompletedProcess[str]:
        return subprocess.run(["bash", "-c", f"source {OROCOS_ENV} >/dev/null && {script}"], cwd=tmp_path,
                              env=dict(os.environ, OROCOS_INSTALL=str(OROCOS)), capture_output=True, text=True,
                              timeout=timeout)

    built = bash(f"oro_build_pkg {out}")
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    # warnings that point into the generated package (RTT's own headers warn under GCC 12)
    warnings = [line for line in (built.stdout + built.stderr).splitlines() if "warning:" in line and str(out) in line]
    assert not warnings, warnings[:10]
    instances, readers, writers = PROBES[fixture]
    probe = tmp_path / "probe.lua"
    probe.write_text(PROBE % {"ops": out / "deploy" / f"{fixture}.ops", "instances": _lua_list(instances),
                              "readers": _lua_list(readers), "writers": _lua_list(writers)}, encoding="utf-8")
    # from the deployment's folder: the user's tuned values (deploy/<instance>.user.cpf) are read from there
    run = bash(f"oro_add_prefix {out}/install && cd {out}/deploy && timeout -s INT 120 rttlua {probe} </dev/null",
               timeout=300)
    said = run.stdout + run.stderr
    assert run.returncode == 0 and "PROBE-RESULT: OK" in run.stdout, said[-4000:]
    assert not re.search(r"\[ *(ERROR|CRITICAL|FATAL) *\]", said), said[-4000:]


# ------------------------------------------------------------------------------------------- ROS 2
# the dialect fixtures, and fixtures/ros/p4rlib: Papyrus for Robotics ports typed by its ROS 2 library,
# carried as std_msgs/String and std_msgs/Int32 themselves
ROS2_FIXTURES = ["robotml", "p4r", "umlrt", "sysml", "designer", "p4rlib"]
# nodes whose output flows only on what they receive (no period): their topics flowing proves that the
# connection into them carries data in the direction the dialect means
MANAGED = {"p4r": ["/camera", "/detector", "/logger"], "p4rlib": ["/talker", "/relay", "/counter"]}
# the user's code on ROS 2, as for Orocos: p4r's detector asks the logger's Query (a service of the
# package's own, srv/Classify.srv) on each image and sends on the label of the latest answer; the
# logger answers each request with its count + 1000
USER_ROS2 = {
    "p4r": {
        "src/DetectorImpl.cpp": [("void DetectorImpl::update()\n{\n}",
                                  "void DetectorImpl::update()\n{\n  ::p4r::types::Boxes boxes;\n  boxes.count = 41;\n"
                                  "  boxes_.count = Classify(boxes).label;\n}"),
                                 ("  return ::p4r::types::Boxes();", "  return boxes_;")],
        "include/p4r/DetectorImpl.hpp": [("};\n", "\nprivate:\n  ::p4r::types::Boxes boxes_;\n};\n")],
        "src/LoggerImpl.cpp": [("Classify(const ::p4r::types::Boxes& /*request*/)\n{\n  return ::p4r::types::Verdict();",
                                "Classify(const ::p4r::types::Boxes& request)\n{\n  ::p4r::types::Verdict verdict;\n"
                                "  verdict.label = request.count + 1000;\n  return verdict;")],
    },
    # designer: the sensor writes 1, the filter adds the gain the tuner sets through its required
    # interface (a service of the package's own, srv/Scale.srv), the monitor reads what comes out
    "designer": {
        "src/SensorImpl.cpp": [("  return ::designer::types::Sample();",
                                "  ::designer::types::Sample sample;\n  sample.value = 1.0;\n  return sample;")],
        "src/FilterImpl.cpp": [("FilterImpl::setInput(const ::designer::types::Sample& /*value*/)\n{\n",
                                "FilterImpl::setInput(const ::designer::types::Sample& value)\n{\n  input_ = value;\n"),
                               ("  return ::designer::types::Sample();",
                                "  ::designer::types::Sample sample = input_;\n  sample.value += gain_;\n  return sample;"),
                               ("double FilterImpl::scale(double /*value*/)\n{\n  return 0.0;",
                                "double FilterImpl::scale(double value)\n{\n  gain_ = value;\n  return gain_;")],
        "include/designer/FilterImpl.hpp": [("};\n", "\nprivate:\n  ::designer::types::Sample input_;\n  double gain_ = 0.0;\n};\n")],
        "src/TunerImpl.cpp": [("void TunerImpl::update()\n{\n}", "void TunerImpl::update()\n{\n  scale(1000.0);\n}")],
    },
}
# (service, its type, a request, what the answer holds); (topic, what it carries once answers come back)
QUERIES = {"p4r": (("/logger/Classify", "p4r/srv/Classify", "{request: {count: 1}}", "label=1001"),
                   ("/Connects2", "count: 1041")),
           "designer": (("/processing/filter/scale", "designer/srv/Scale", "{value: {data: 2.0}}", "data=2.0"),
                        ("/filtered", "value: 1001.0"))}


def _fixture_model(fixture: str) -> Path:
    return next(p for p in (CASES / fixture / "model.xmi", ROOT / "fixtures" / "ros" / fixture / "model.xmi")
                if p.is_file())


@pytest.fixture(scope="module")
def ros2_ws(tmp_path_factory):
    ros2 = pytest.importorskip("test_ros2_toolchain", reason="tests/test_ros2_toolchain.py is not importable")
    if not (ros2.PREFIX / "install" / "setup.bash").is_file() or not (ros2.PREFIX / "install_py" / "bin" / "ros2").exists():
        pytest.skip(f"no ROS 2 with launch built in {ros2.PREFIX}: build it with toolchains/ros2/build.sh")
    ws = tmp_path_factory.mktemp("dialects_ros2")
    (ws / "home").mkdir()
    packages = {}
    for fixture in ROS2_FIXTURES:
        out = ws / "src" / fixture
        generate(_fixture_model(fixture), out, "ros2")
        for rel, edits in USER_ROS2.get(fixture, {}).items():
            text = (out / rel).read_text(encoding="utf-8")
            for old, new in edits:
                assert text.count(old) == 1, f"{rel}: the skeleton robomda writes changed; update this test"
                text = text.replace(old, new)
            (out / rel).write_text(text, encoding="utf-8")
        packages[fixture] = fixture
    return ros2, ros2.Workspace(ws, packages, ros2.colcon_build(ws, "--continue-on-error "))


@pytest.mark.ros2_toolchain
@pytest.mark.parametrize("fixture", ROS2_FIXTURES)
def test_ros2_package_builds_and_data_flows_on_every_connection(fixture: str, ros2_ws) -> None:
    ros2, ws = ros2_ws
    pkg = ws.packages[fixture]
    log = ws.root / "log" / "latest_build" / pkg / "stdout_stderr.log"
    said = log.read_text(errors="replace") if log.is_file() else ws.build.stdout + ws.build.stderr
    assert (ws.root / "install" / pkg).is_dir(), said[-4000:]
    assert not [line for line in said.splitlines() if "warning:" in line and f"/src/{fixture}/" in line], said[-4000:]
    launch = ros2.Launch(ws, pkg, f"{pkg}.launch.xml", ws.root / f"{fixture}.launch.log")
    try:
        nodes = ros2._composable_nodes(ws, pkg)
        launch.start_loaded(nodes)
        for node in MANAGED.get(fixture, []):
            deadline = time.monotonic() + 240
            while not ros2._lifecycle_get(ws, node).startswith("active") and time.monotonic() < deadline:
                time.sleep(2)
            assert ros2._lifecycle_get(ws, node).startswith("active [3]"), (node, launch.text()[-3000:])
        # the connection topics (a client's remap names its provider's service, under the namespace)
        topics = sorted({"/" + r.get("to") for f in ros2._launch_files(ws, pkg) for r in ET.parse(f).iter("remap")
                         if "$(" not in r.get("to")})
        assert topics, "no connection topic in the launch files"
        counts = ros2._count(ws, topics, 3.0)
        assert all(c > 0 for c in counts.values()), (counts, launch.text()[-3000:])
        if fixture in QUERIES:
            (service, srv, request, answer), (topic, carried) = QUERIES[fixture]
            called = ws.run(f"timeout 60 ros2 service call {service} {srv} '{request}'", timeout=90)
            assert answer in called.stdout, called.stdout[-2000:] + called.stderr[-2000:]
            echoed = ws.run(f"timeout 15 ros2 topic echo {topic} || true", timeout=60)
            assert carried in echoed.stdout, echoed.stdout[-2000:] + launch.text()[-2000:]
    finally:
        left = launch.stop()
    assert not left, f"processes outlived SIGINT: {left}"
    assert not re.search(r"\[ERROR\]", launch.text()), launch.text()[-3000:]
