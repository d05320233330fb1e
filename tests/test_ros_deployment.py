"""Seed 002's runtime architecture on the ROS targets (docs/deployment.md, docs/ros.md).

The distributed fixture mixes Orocos and ROS 1: each target generates only
the instances deployed on its middleware, and the one connection between
them is a topic both sides name alike. Variants of the fixture (every
process on ROS 1, on ROS 2, one end on ROS 2) check containers, component
sets, threads and the transports no target can provide. No ROS tool is
needed here: tests/test_ros.py runs the ROS 1 variant under roscore.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from edits import distributed_variant
from robomda.api import generate
from robomda.diagnostics import RobomdaError

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "fixtures" / "cases" / "distributed"
MANAGED = ROOT / "fixtures" / "ros" / "managed"
FS = "{urn:robomda:fileset:1}"
R = "{urn:robomda:psm-ros:1}"
CAMERA_DEPLOYMENT = ('<deployment xmi:type="uml:Deployment" xmi:id="_7r_06xjuD8PlcTvtlRdcOv" '
                     'client="_dstRttCameraEEw2X3y4Z5a" supplier="_ZFkQzwZWOKVfkNutf1AcmA" '
                     'deployedArtifact="_ZFkQzwZWOKVfkNutf1AcmA"/>')
VISION_DEPLOYMENT = ('<deployment xmi:type="uml:Deployment" xmi:id="_nb0fXVyf8f6tTvodAYVVsB" '
                     'client="_dstRttVisionEEb6C7d8E9f" supplier="_1co18VX-WHKsg9uJFeno6f" '
                     'deployedArtifact="_1co18VX-WHKsg9uJFeno6f"/>')
ORO_PROCESSES = 3  # rttControl, rttCamera, rttVision: ' version="2.10"' on their Middleware stereotype
TO_ROS2 = ((' version="2.10"', ' kind="ROS2"', ORO_PROCESSES), (' kind="ROS"', ' kind="ROS2"', 1))  # every process


def _files(done) -> dict[str, str]:
    return {n.get("path"): n.text or "" for n in etree.fromstring(done.stages["text"].encode()).iter(f"{FS}file")}


def test_the_mixed_model_generates_each_component_once_with_one_agreed_topic() -> None:
    ros = generate(CASE / "model.xmi", None, "ros1", write=False)
    oro = generate(CASE / "model.xmi", None, "orocos", write=False)
    psm = etree.fromstring(ros.stages["psm"].encode())
    assert [i.get("name") for i in psm.iter(f"{R}instance")] == ["forceSensor"]
    assert [n.get("class") for n in psm.iter(f"{R}node")] == ["WristForceSensor"]
    left = sorted(d.message.split("'")[1] for d in ros.warnings if d.code == "ROS110")
    assert left == ["arm", "camera", "controller", "vision"]
    ros_files, oro_files = _files(ros), _files(oro)
    assert not any("ImpedanceController" in p or "IndustrialArm" in p for p in ros_files)
    assert not any("WristForceSensor" in p for p in oro_files)
    launch = ros_files["launch/distributed_control_pc.launch"]
    assert '<remap from="wrench" to="/wrenchConn"/>' in launch
    # the Orocos side streams the same topic into the controller (rtt_roscomm, transport 3)
    ops = oro_files["deploy/control_pc_rtt_control.ops"]
    assert 'transport = 3' in ops and 'name_id = "/wrenchConn"' in ops


def test_every_process_on_ros2_is_a_container_and_the_set_a_launch_file(tmp_path: Path) -> None:
    model = distributed_variant(tmp_path, *TO_ROS2)
    done = generate(model, None, "ros2", write=False)
    files = _files(done)
    schema = xmlschema.XMLSchema(str(ROOT / "schemas/ros2-launch/1/launch.xsd"))
    launches = {p: etree.fromstring(t.encode()) for p, t in files.items() if p.endswith(".launch.xml")}
    for path, text in files.items():
        if path.endswith(".launch.xml"):
            schema.validate(text)
    control = launches["launch/distributed_control_pc.launch.xml"]
    containers = {c.get("name"): c for c in control.iter("node_container")}
    assert set(containers) == {"rtt_control", "ros_sensor"}
    # the thread: a multi-threaded container; its members load in the modelled start order
    assert containers["rtt_control"].get("exec") == "component_container_mt"
    assert containers["ros_sensor"].get("exec") == "component_container"
    assert [n.get("name") for n in containers["rtt_control"].iter("composable_node")] == ["arm", "controller"]
    assert [n.get("plugin") for n in containers["ros_sensor"].iter("composable_node")] == ["distributed::WristForceSensor"]
    # the component set: its own launch file, holding the two processes wholly in it, included by its host's
    vision = launches["launch/distributed_vision_pc.launch.xml"]
    assert [i.get("file") for i in vision.iter("include")] == [
        "$(find-pkg-share distributed)/launch/distributed_vision_set.launch.xml"]
    in_set = launches["launch/distributed_vision_set.launch.xml"]
    assert {c.get("name"): [n.get("name") for n in c.iter("composable_node")] for c in in_set.iter("node_container")} \
        == {"rtt_camera": ["camera"], "rtt_vision": ["vision"]}
    # every instance exactly once over all host files (the top file includes them all)
    placed = [n.get("name") for p, x in launches.items() if p != "launch/distributed.launch.xml"
              for n in x.iter("composable_node")]
    assert sorted(placed) == ["arm", "camera", "controller", "forceSensor", "vision"]
    assert not any(d.code.startswith("ROS11") for d in done.warnings)


def test_a_set_member_in_a_shared_process_is_loaded_into_its_container(tmp_path: Path) -> None:
    """camera leaves the set and joins vision's process: the host file starts that container with
    camera in it, and the set's file loads vision into the running container."""
    camera_manifestation = ('<manifestation xmi:type="uml:Manifestation" xmi:id="_9ep2JQCW_S88pcgnoowbe2" '
                            'client="_dstVisionSetArtG0h1I2j3" supplier="_ZFkQzwZWOKVfkNutf1AcmA" '
                            'utilizedElement="_ZFkQzwZWOKVfkNutf1AcmA"/>')
    model = distributed_variant(tmp_path, *TO_ROS2, (camera_manifestation, "", 1), (CAMERA_DEPLOYMENT, "", 1),
                                (VISION_DEPLOYMENT, VISION_DEPLOYMENT + CAMERA_DEPLOYMENT.replace(
                                    'client="_dstRttCameraEEw2X3y4Z5a"', 'client="_dstRttVisionEEb6C7d8E9f"'), 1))
    files = _files(generate(model, None, "ros2", write=False))
    host = etree.fromstring(files["launch/distributed_vision_pc.launch.xml"].encode())
    in_set = etree.fromstring(files["launch/distributed_vision_set.launch.xml"].encode())
    assert {c.get("name"): [n.get("name") for n in c.iter("composable_node")] for c in host.iter("node_container")} \
        == {"rtt_vision": ["camera"]}
    loads = list(in_set.iter("load_composable_node"))
    assert [(x.get("target"), [n.get("name") for n in x.iter("composable_node")]) for x in loads] \
        == [("/rtt_vision", ["vision"])]
    xmlschema.XMLSchema(str(ROOT / "schemas/ros2-launch/1/launch.xsd")).validate(files["launch/distributed_vision_set.launch.xml"])


def test_ros1_names_what_it_cannot_express(tmp_path: Path) -> None:
    model = distributed_variant(tmp_path, (' version="2.10"', ' kind="ROS"', ORO_PROCESSES))
    done = generate(model, None, "ros1", write=False)
    codes = {d.code: d for d in done.warnings}
    assert "ROS111" in codes and "'controller', 'arm'" in codes["ROS111"].message
    assert codes["ROS111"].element_name == "rttControl" and codes["ROS111"].line
    assert "ROS112" in codes and codes["ROS112"].element_name == "controlLoop"
    files = _files(done)
    assert "launch/distributed_vision_set.launch" in files
    assert "4 cores, 8192 MiB memory, real-time kernel" in files["launch/distributed_control_pc.launch"]


def test_a_connection_no_transport_carries_is_an_error_naming_both_ends(tmp_path: Path) -> None:
    # forceSensor on ROS 2 feeds the Orocos controller: Orocos RTT 2.10 reaches ROS 1 only
    model = distributed_variant(tmp_path, (' kind="ROS"', ' kind="ROS2"', 1))
    with pytest.raises(RobomdaError) as failed:
        generate(model, tmp_path / "out", "ros2")
    errors = [d for d in failed.value.diagnostics if d.code == "ROS011"]
    assert len(errors) == 1 and errors[0].line
    assert "'forceSensor' (ROS2) and 'controller' (OROCOS)" in errors[0].message
    assert not (tmp_path / "out").exists()


def test_managed_processes_are_lifecycle_nodes_a_manager_drives_in_the_deployment_sequence() -> None:
    """Seed 002 on ROS 2 with managed processes (fixtures/ros/managed): their instances load as the
    lifecycle classes of their nodes, and each host's lifecycle manager configures, then activates,
    them in start order; the other instances stay plain nodes."""
    done = generate(MANAGED / "model.xmi", None, "ros2", write=False)
    assert "ROS113" not in [w.code for w in done.warnings]
    psm = etree.fromstring(done.stages["psm"].encode())
    managed = {i.get("name") for i in psm.iter(f"{R}instance") if i.get("managed") == "true"}
    assert managed == {"controller", "arm", "vision"}
    assert sorted(n.get("lifecycle-type-name") for n in psm.iter(f"{R}node") if n.get("lifecycle-type-name")) == [
        "managed::lifecycle::ImpedanceController", "managed::lifecycle::IndustrialArm", "managed::lifecycle::VisionProcessing"]
    files = _files(done)
    order = {i.get("name"): int(i.get("start-order")) for i in psm.iter(f"{R}instance")}
    for host, launch in (("control_pc", "launch/managed_control_pc.launch.xml"), ("vision_pc", "launch/managed_vision_pc.launch.xml")):
        root = etree.fromstring(files[launch].encode())
        manager = [n for n in root.iter("node") if n.get("exec") == "lifecycle_manager"]
        assert len(manager) == 1 and manager[0].get("name") == f"{host}_lifecycle_manager"
        param = manager[0].find("param")
        assert param.get("name") == "node_names" and param.get("value-sep") == ","
        # each name from the launch's root: after the pushed namespace, if any
        prefix = "$(var ros_namespace '')/"
        assert all(n.startswith(prefix) for n in param.get("value").split(",")), param.get("value")
        names = [n.removeprefix(prefix) for n in param.get("value").split(",")]
        here = {i.get("name") for i in psm.iter(f"{R}instance") if i.get("host") == host} & managed
        assert set(names) == here and names == sorted(names, key=order.get)
    plugins = {c.get("name"): c.get("plugin") for f in files if f.endswith(".launch.xml")
               for c in etree.fromstring(files[f].encode()).iter("composable_node")}
    assert plugins["controller"] == "managed::lifecycle::ImpedanceController"
    assert plugins["camera"] == "managed::Guppy80" and plugins["forceSensor"] == "managed::WristForceSensor"
    cmake = files["CMakeLists.txt"]
    assert "src/lifecycle/ImpedanceController.cpp" in cmake and '"managed::lifecycle::VisionProcessing"' in cmake
    assert "add_executable(lifecycle_manager src/lifecycle_manager.cpp)" in cmake
    assert "find_package(rclcpp_lifecycle REQUIRED)" in cmake and "<depend>lifecycle_msgs</depend>" in files["package.xml"]
    assert not any(p.startswith("src/lifecycle/") and "Guppy80" in p for p in files)


def test_a_lifecycle_node_runs_its_hooks_in_the_transitions() -> None:
    """configure() in on_configure before the ports exist, start() in on_activate after the publishers
    are activated, stop() in on_deactivate; a hook that returns false fails the transition."""
    source = _files(generate(MANAGED / "model.xmi", None, "ros2", write=False))["src/lifecycle/ImpedanceController.cpp"]
    bodies = dict(re.findall(r"::on_(configure|activate|deactivate|cleanup|shutdown)\(\s*const rclcpp_lifecycle::State &[^)]*\)\n\{\n(.*?)\n\}",
                             source, flags=re.S))
    assert set(bodies) == {"configure", "activate", "deactivate", "cleanup", "shutdown"}
    configure = bodies["configure"]
    assert configure.index("::ImpedanceControl::configure()") < configure.index("create_publisher")
    assert "return CallbackReturn::FAILURE;" in configure and "configure() failed" in configure
    activate = bodies["activate"]
    assert activate.index("pub_armCommand_->on_activate();") < activate.index("::ImpedanceControl::start()") \
        < activate.index("rclcpp::create_timer(this, this->get_clock(),")
    deactivate = bodies["deactivate"]
    assert deactivate.index("running_ = false;") < deactivate.index("::ImpedanceControl::stop();") \
        < deactivate.index("pub_armCommand_->on_deactivate();")
    assert "pub_armCommand_.reset();" in bodies["cleanup"] and "::ImpedanceControl::stop();" in bodies["shutdown"]
    # the destructor transitions only a live context: after Ctrl-C the transition would log ERROR lines
    destructor = source[source.index("ImpedanceController::~ImpedanceController()"):source.index("::on_configure(")]
    assert destructor.index("get_context()->is_valid() &&") < destructor.index("shutdown();") \
        < destructor.index("::ImpedanceControl::stop();")
    assert "class ImpedanceController : public rclcpp_lifecycle::LifecycleNode, public ::ImpedanceControl" \
        in _files(generate(MANAGED / "model.xmi", None, "ros2", write=False))["include/managed/lifecycle/ImpedanceController.hpp"]


def test_ros1_names_the_managed_processes_it_cannot_manage() -> None:
    done = generate(MANAGED / "model.xmi", None, "ros1", write=False)
    managed = sorted(d.element_name for d in done.warnings if d.code == "ROS113")
    assert managed == ["controlProcess", "visionProcess"]
    assert "ROS 1 has no node lifecycle" in next(d.message for d in done.warnings if d.code == "ROS113")
