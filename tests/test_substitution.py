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
    return [d.code for d in check(model, replace=replace).diagnostics]


def test_a_valid_replacement_reports_nothing() -> None:
    done = check(PIDSWAP, replace=["PIDController=PIDControllerFast"])
    assert done.exit_code == 0
    assert done.diagnostics == []


def test_a_qualified_name_picks_the_component() -> None:
    done = check(PIDSWAP, replace=["pidswap::components::PIDController=pid::components::PIDControllerFast"])
    # the model is named pidswap: the first is right, the second names nothing
    assert [d.code for d in done.diagnostics] == ["SUB009"]
    assert "'pid::components::PIDControllerFast' names no component" in done.diagnostics[0].message
    assert check(PIDSWAP, replace=["pidswap::components::PIDController=PIDControllerFast"]).diagnostics == []


def test_every_violation_names_both_components_and_the_port(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["check", str(PIDSWAP), "--replace", "RobotInterface=PIDControllerFast", "--format", "json"])
    report = json.loads(capsys.readouterr().out)
    assert code == 1
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
