"""Seed 004's substitutability rule (xslt/check/substitute.xsl): `check --replace` and «Alternative»."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from robomda.api import check, import_model
from robomda.cli import main

ROOT = Path(__file__).resolve().parents[1]
PIDSWAP = ROOT / "fixtures" / "cases" / "pidswap" / "model.xmi"


def _codes(model: Path, *replace: str) -> list[str]:
    return [d.code for d in check(model, replace=replace).diagnostics if d.code.startswith("SUB") and d.severity != "info"]


def _sub(done) -> list:
    """The substitutability findings (pidswap's StartAfter also gives ROS's PLT011 warning)."""
    return [d for d in done.diagnostics if d.code.startswith("SUB") and d.severity != "info"]


def test_a_valid_replacement_reports_nothing() -> None:
    done = check(PIDSWAP, replace=["PIDController=PIDControllerFast"])
    assert done.exit_code == 0
    assert _sub(done) == []
    # the alternative is said to be no instance (SUB030, a note); ROS cannot keep the StartAfter order (PLT011)
    assert [(d.code, d.severity) for d in done.diagnostics] == [("SUB030", "info"), ("PLT011", "warning")]


def test_a_qualified_name_picks_the_component() -> None:
    done = check(PIDSWAP, replace=["pidswap::components::PIDController=pid::components::PIDControllerFast"])
    # the model is named pidswap: the first is right, the second names nothing
    assert [d.code for d in _sub(done)] == ["SUB009"]
    assert "'pid::components::PIDControllerFast' names no component" in _sub(done)[0].message
    assert _sub(check(PIDSWAP, replace=["pidswap::components::PIDController=PIDControllerFast"])) == []


def test_every_violation_names_both_components_and_the_port(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["check", str(PIDSWAP), "--replace", "RobotInterface=PIDControllerFast", "--format", "json"])
    report = json.loads(capsys.readouterr().out)
    assert code == 1
    report["diagnostics"] = [d for d in report["diagnostics"] if d["code"].startswith("SUB") and d["code"] != "SUB030"]
    found = {(d["code"], d["message"].split(": ", 1)[1]) for d in report["diagnostics"]}
    head = ("component 'PIDControllerFast' (hardware-dependent computational) cannot replace 'RobotInterface' "
            "(hardware-dependent interface)")
    assert all(d["message"].startswith(head) for d in report["diagnostics"])
    # the robot interface's outputs (one of them the torque limit, a constant), its property, its period
    assert ("SUB001", "it has no output port 'measuredPosition' (Real) that 'RobotInterface' provides") in found
    assert ("SUB001", "it has no output port 'torqueLimit' (Real, a configuration constant) that 'RobotInterface' "
            "provides") in found
    assert any(c == "SUB005" and "'inertia'" in m for c, m in found)
    # of the controller's inputs, the trajectory generator feeds desiredPosition; the two others only the robot
    # interface wrote, which is the one replaced
    unfed = sorted(m.split("'")[1] for c, m in found if c == "SUB003")
    assert unfed == ["measuredPosition", "torqueLimit"]
    lines = {d["code"]: d for d in report["diagnostics"]}
    assert lines["SUB001"]["line"] > 0 and lines["SUB001"]["file"].endswith("model.xmi")


def test_an_input_of_another_type_and_a_missing_provided_interface() -> None:
    # the controller in the trajectory generator's place: it reads what nothing but the generator wrote
    codes = _codes(PIDSWAP, "TrajectoryGenerator=PIDControllerFast")
    assert "SUB001" in codes  # desiredPosition
    assert "SUB003" in codes  # desiredPosition is no input of the generator, and only the generator writes it
    assert "SUB004" not in codes


def test_an_alternative_is_no_instance_of_its_own() -> None:
    bound = import_model(PIDSWAP)
    assert 'component="_pswF00k"' not in bound.split("<pim:binding", 1)[1].split("<pim:connection", 1)[0].replace(
        "<pim:bound-component", "")
    assert 'name="PIDControllerFast"' not in bound.split("<pim:binding", 1)[1]


def test_a_constant_port_is_marked_in_the_binding() -> None:
    bound = import_model(PIDSWAP)
    ports = [line for line in bound.splitlines() if 'name="torqueLimit"' in line and "<pim:data-port" in line]
    assert len(ports) == 2 and all('constant="true"' in p for p in ports)
    assert all('constant="true"' not in line for line in bound.splitlines() if 'name="referenceTorque"' in line)


def test_a_constant_read_before_its_writer_configures_is_a_warning(tmp_path: Path) -> None:
    text = PIDSWAP.read_text(encoding="utf-8")
    dependency = ('    <packagedElement xmi:type="uml:Dependency" xmi:id="_pswD01" name="startAfter" client="_pid075k" '
                  'supplier="_pid083k"/>\n')
    assert dependency in text
    model = tmp_path / "model.xmi"
    model.write_text(text.replace(dependency, ""), encoding="utf-8")
    found = [d for d in check(model, "orocos").diagnostics if d.code == "SUB020"]
    assert len(found) == 1 and found[0].severity == "warning"
    assert "'PIDController' reads configuration constant 'torqueLimit'" in found[0].message
    assert "from 'RobotInterface'" in found[0].message
    assert not [d for d in check(PIDSWAP, "orocos").diagnostics if d.code == "SUB020"]


def test_orocos_reads_and_writes_a_constant_in_configure_only() -> None:
    from robomda.api import generate

    files = {p.name: t for p, t in _generated(generate(PIDSWAP, None, "orocos", write=False)).items()}
    controller, robot = files["PIDController.cpp"], files["RobotInterface.cpp"]
    configure = controller.split("::configureHook()", 1)[1].split("\n}", 1)[0]
    assert "port_torqueLimit.read(torqueLimit_constant) == RTT::NoData" in configure
    assert "setTorqueLimit(torqueLimit_constant)" in configure
    update = controller.split("::updateHook()", 1)[1].split("\n}", 1)[0]
    assert "torqueLimit" not in update
    assert "port_torqueLimit.write(" in robot.split("::configureHook()", 1)[1].split("\n}", 1)[0]
    assert "torqueLimit" not in robot.split("::updateHook()", 1)[1].split("\n}", 1)[0]


def test_ros_latches_a_constant() -> None:
    from robomda.api import generate

    ros1 = {p.name: t for p, t in _generated(generate(PIDSWAP, None, "ros1", write=False)).items()}
    assert 'nh_.advertise<std_msgs::Float64>("torqueLimit", 1, true);' in ros1["RobotInterface.cpp"]
    assert 'nh_.advertise<std_msgs::Float64>("measuredPosition", 1, false);' in ros1["RobotInterface.cpp"]
    ros2 = {p.name: t for p, t in _generated(generate(PIDSWAP, None, "ros2", write=False)).items()}
    assert '"torqueLimit", rclcpp::QoS(rclcpp::KeepLast(1)).reliable().transient_local()' in ros2["PIDController.cpp"]
    assert '"torqueLimit", rclcpp::QoS(rclcpp::KeepLast(1)).reliable().transient_local()' in ros2["RobotInterface.cpp"]
    step = ros2["RobotInterface.cpp"].split("::step()", 1)[1].split("\n}", 1)[0]
    assert "pub_torqueLimit_" not in step and "pub_measuredPosition_" in step


def _generated(done) -> dict[Path, str]:
    from lxml import etree

    tree = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {Path(f.get("path")): f.text or "" for f in tree.iter("{urn:robomda:fileset:1}file")}
