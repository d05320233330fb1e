"""A component model with no deployment yet (issue 30 item 1), and artifacts nested in a platform node.

The first model a robot developer draws has components, ports and connectors and no execution
environment. ``import`` and ``check`` show and check it with no error; every command says once
(BND028, on the first instance) that its instances run in one default process on the target's
middleware, and how to model the platform; ``generate`` deploys them so. A model that draws
execution environments but leaves an instance out of them keeps BND006, now naming the
environments and both fixes. An Artifact nested in an execution environment deploys what it
manifests there. Models: tests/nodeploy_models.py, in the Eclipse UML2 / Papyrus and Enterprise
Architect dialects; the real-tool checks of a no-deployment package (catkin, roslaunch, the Orocos
goldens) run on the fixture case fixtures/cases/undeployed with every other case.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from nodeploy_models import write
from robomda.api import check, generate, import_model
from robomda.diagnostics import Diagnostic, RobomdaError

NS = {"p": "urn:robomda:pim:1"}
DIALECTS = {"eclipse": ("rover.uml", "_nd"), "ea": ("rover.ea.xmi", "EAID_")}


def _model(tmp_path: Path, dialect: str, **options: object) -> tuple[Path, str]:
    name, prefix = DIALECTS[dialect]
    return write(tmp_path / name, dialect, **options), prefix


def _bnd(found: list[Diagnostic]) -> list[tuple[str, str | None, int | None]]:
    return [(d.code, d.xmi_id, d.line) for d in found if d.code.startswith("BND")]


@pytest.mark.parametrize("dialect", sorted(DIALECTS))
def test_import_check_and_generate_agree_on_a_model_without_platform(dialect: str, tmp_path: Path) -> None:
    model, p = _model(tmp_path, dialect)
    found: list[Diagnostic] = []
    pim = etree.fromstring(import_model(model, warnings=found).encode("utf-8"))
    # one warning, on the first instance (its line in the file), naming every instance and the fix
    [warning] = [d for d in found if d.code == "BND028"]
    assert warning.severity == "warning" and warning.xmi_id == f"{p}PartW" and warning.line
    assert f'xmi:id="{p}PartW"' in model.read_text(encoding="utf-8").splitlines()[warning.line - 1]
    for words in ("'wheels', 'planner'", "no execution environment", "host localhost (127.0.0.1)",
                  "ExecutionEnvironment", "Deployment", "docs/profile.md"):
        assert words in warning.message
    # what was understood: a default host and process, no middleware drawn
    host = pim.xpath("//p:binding/p:host", namespaces=NS)
    assert [(h.get("name"), h.get("address"), h.get("default")) for h in host] == [("localhost", "127.0.0.1", "true")]
    [process] = pim.xpath("//p:binding/p:process", namespaces=NS)
    assert process.get("default") == "true" and process.get("middleware") is None and process.get("name") == "rover"
    instances = pim.xpath("//p:binding/p:instance", namespaces=NS)
    assert [(i.get("name"), i.get("execution-environment"), i.get("middleware")) for i in instances] == \
        [("wheels", process.get("xmi-id"), None), ("planner", process.get("xmi-id"), None)]
    # check: no error, the default target (Orocos), the same one warning
    checked = check(model)
    assert checked.exit_code == 0 and checked.targets == ["orocos"], [d.format() for d in checked.diagnostics]
    assert _bnd(checked.diagnostics) == _bnd(found)
    # generate (without a target: Orocos, as check): the same warning, both instances deployed
    done = generate(model, tmp_path / "out", write=False)
    assert done.target == "orocos"
    assert _bnd(done.warnings) == _bnd(found)
    files = {f.get("path"): f.text or "" for f in etree.fromstring(done.stages["text"].encode()).iter(
        "{urn:robomda:fileset:1}file")}
    ops = files["deploy/rover.ops"]
    assert 'loadComponent("wheels", "rover::WheelDriver")' in ops and 'loadComponent("planner", "rover::Planner")' in ops
    assert "connect" in ops and "odometry" in ops


def test_instances_run_on_the_only_node_when_it_holds_no_environment(tmp_path: Path) -> None:
    model, _ = _model(tmp_path, "eclipse", node=True)
    found: list[Diagnostic] = []
    pim = etree.fromstring(import_model(model, warnings=found).encode("utf-8"))
    [process] = pim.xpath("//p:binding/p:process", namespaces=NS)
    assert (process.get("xmi-id"), process.get("host"), process.get("default")) == ("_ndPC", "_ndPC", "true")
    assert not pim.xpath("//p:binding/p:host[@default]", namespaces=NS)
    assert {i.get("host") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)} == {"_ndPC"}
    [warning] = [d for d in found if d.code == "BND028"]
    assert "on host 'robotPC'" in warning.message
    assert check(model, "orocos").exit_code == 0


@pytest.mark.parametrize("dialect", sorted(DIALECTS))
def test_an_instance_left_out_of_drawn_environments_is_still_an_error(dialect: str, tmp_path: Path) -> None:
    """Some instances deployed, others not: the platform is drawn and an instance was left out of it,
    which a default process beside the drawn ones would hide. BND006 stays, naming both fixes."""
    model, p = _model(tmp_path, dialect, node=True, environment="OROCOS", deploy="ROS")
    with pytest.raises(RobomdaError) as info:
        import_model(model)
    [error] = [d for d in info.value.diagnostics if d.severity == "error"]
    assert (error.code, error.xmi_id) == ("BND006", f"{p}PartP")
    for words in ("'planner'", "2 of them ('OROCOS', 'ROS')", "draw a Deployment", "nest the component"):
        assert words in error.message
    assert check(model).exit_code == 1


@pytest.mark.parametrize("dialect", sorted(DIALECTS))
def test_an_artifact_nested_in_an_environment_deploys_what_it_manifests_there(dialect: str, tmp_path: Path) -> None:
    model, p = _model(tmp_path, dialect, node=True, environment="OROCOS", deploy="ROS", nested_artifact=True)
    found: list[Diagnostic] = []
    pim = etree.fromstring(import_model(model, warnings=found).encode("utf-8"))
    assert pim.xpath("//p:platform/p:artifact", namespaces=NS)[0].get("node") == f"{p}EE"
    placed = {i.get("name"): (i.get("execution-environment"), i.get("middleware"), i.get("host"))
              for i in pim.xpath("//p:binding/p:instance", namespaces=NS)}
    assert placed == {"wheels": (f"{p}EE2", "ROS", f"{p}PC"), "planner": (f"{p}EE", "OROCOS", f"{p}PC")}
    # the artifact (a component set: it manifests a part) is deployed where it is nested: no CMP011
    [on] = pim.xpath("//p:binding/p:component-set/p:on", namespaces=NS)
    assert (on.get("deployment"), on.get("host")) == (f"{p}Art", f"{p}PC")
    assert not [d for d in found if d.code in ("BND006", "BND028")]
    checked = check(model, "orocos")
    assert checked.exit_code == 0, [d.format() for d in checked.diagnostics]
