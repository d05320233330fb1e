"""The classes of defects real UML exports showed (issue 11), one test each, through the driver.

Each model under tests/data/import/classes/ is hand-written in a tool's
dialect and carries one class of quirk: untyped properties (1), attributes
typed by behaviours (2), ports typed by a protocol, a class, a data type, a
signal or something else (3), elements in unusual owners (4), stereotype
applications that leave defaults out (6), files with nothing robomda uses
(7). Every run must end with exit code 0, 1 or 2 (never INTERNAL), with
located warnings for what is not imported, and with the PIM content the
class asks for. Also: every error of a stage is reported, not the first.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from robomda.api import check, import_model
from robomda.cli import main
from robomda.diagnostics import Diagnostic, RobomdaError

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "import" / "classes"
NS = {"p": "urn:robomda:pim:1"}


def _pim(name: str, *, bind: bool = True) -> tuple[etree._Element, list[Diagnostic]]:
    found: list[Diagnostic] = []
    text = import_model(DATA / name, bind=bind, warnings=found)
    return etree.fromstring(text.encode("utf-8")), found


def _one(doc: etree._Element, xpath: str) -> etree._Element:
    hits = doc.xpath(xpath, namespaces=NS)
    assert len(hits) == 1, f"{xpath}: {len(hits)} matches"
    return hits[0]


def _codes(found: list[Diagnostic]) -> list[tuple[str, str | None]]:
    return [(d.code, d.xmi_id) for d in found]


# ------------------------------------------------------------ class 1
def test_untyped_properties_and_ports_are_warned_and_kept() -> None:
    doc, found = _pim("untyped.uml")
    assert ("IMP101", "sensorGain") in _codes(found)
    assert ("IMP101", "sensorSpare") in _codes(found)
    assert ("IMP101", "partTodo") in _codes(found)
    # located on the XMI line of the element
    spare = next(d for d in found if d.xmi_id == "sensorSpare")
    assert spare.line == 12 and spare.severity == "warning"
    # an untyped composite property is an attribute, not a part; the typed part stays a part
    todo = _one(doc, "//p:component[@name='System']/p:attribute[@id='partTodo']")
    assert todo.get("aggregation") == "composite" and todo.get("type") is None
    _one(doc, "//p:component[@name='System']/p:part[@id='partSensor'][@type='sensor']")
    _one(doc, "//p:binding/p:instance[@name='sensor']")


def test_untyped_composite_attribute_in_the_ea_dialect() -> None:
    doc, found = _pim("untyped.ea.xmi", bind=False)
    assert ("IMP101", "EAID_A1") in _codes(found)
    _one(doc, "//p:class[@name='Controller']/p:attribute[@name='loop'][@aggregation='composite'][not(@type)]")
    _one(doc, "//p:attribute[@name='rate'][@primitive='float64']")


# ------------------------------------------------------------ class 2
def test_attributes_typed_by_behaviours_are_functions_not_dangling() -> None:
    done = check(DATA / "behaviour-typed.uml", "orocos")
    assert done.exit_code == 0, [d.format() for d in done.diagnostics]
    assert not [d for d in done.diagnostics if d.code.startswith("BND")]
    assert {(d.code, d.xmi_id) for d in done.diagnostics if d.code == "IMP103"} == \
        {("IMP103", "fnAcquire"), ("IMP103", "fnFilter")}
    doc, _ = _pim("behaviour-typed.uml")
    a = _one(doc, "//p:component[@name='Lidar']/p:attribute[@name='acquire']")
    assert (a.get("type"), a.get("type-name"), a.get("type-metaclass")) == (None, "Acquire", "OpaqueBehavior")
    assert _one(doc, "//p:attribute[@name='filter']").get("type-metaclass") == "Activity"


# ------------------------------------------------------------ class 3
def test_ports_typed_by_protocol_class_data_type_and_signal() -> None:
    doc, found = _pim("port-types.uml")
    assert not [d for d in found if d.code.startswith("BND")]
    # a protocol: realized interface provided, used interface required; conjugated: swapped
    drive = _one(doc, "//p:component[@name='Drive']/p:port[@name='motion']")
    assert drive.get("type-metaclass") == "Collaboration" and drive.get("type") is None
    assert [(e.tag.split("}")[1], e.get("interface"), e.get("via")) for e in drive.xpath("p:provided|p:required", namespaces=NS)] \
        == [("provided", "ifState", "protoIR"), ("required", "ifCmd", "protoU")]
    planner = _one(doc, "//p:component[@name='Planner']/p:port[@name='motion']")
    assert [(e.tag.split("}")[1], e.get("interface")) for e in planner.xpath("p:provided|p:required", namespaces=NS)] \
        == [("provided", "ifCmd"), ("required", "ifState")]
    # a Signal is a data type of the PIM
    _one(doc, "//p:datatype[@id='sgStop'][@name='Stop']/p:attribute[@name='reason']")

    def dp(component: str, port: str) -> list[tuple[str, str, str]]:
        return [(d.get("direction"), d.get("interface"), d.get("datum"))
                for d in doc.xpath(f"//p:bound-component[@name='{component}']/p:data-port[@port-name='{port}']",
                                   namespaces=NS)]

    assert dp("Drive", "motion") == [("out", "ifState", "ifStateV"), ("in", "ifCmd", "ifCmdV")]
    assert dp("Planner", "motion") == [("out", "ifCmd", "ifCmdV"), ("in", "ifState", "ifStateV")]
    # typed by a class: its realized interface (conjugated: in) and its used one (out)
    assert dp("Planner", "side") == [("in", "ifState", "ifStateV"), ("out", "ifCmd", "ifCmdV")]
    # typed by a data type or signal: the port carries it (conjugated: in)
    assert dp("Drive", "pose") == [("out", "dtPose", "drivePose")]
    assert dp("Planner", "pose") == [("in", "dtPose", "plannerPose")]
    assert dp("Drive", "stop") == [("in", "sgStop", "driveStop")]
    # anything else: a located warning, no data port
    assert ("IMP102", "plannerHuman") in _codes(found)
    assert dp("Planner", "human") == []
    # the connections of both interfaces join the protocol ports without a false APP00x
    done = check(DATA / "port-types.uml")
    assert not [d for d in done.diagnostics if d.code in ("APP001", "APP002", "APP003", "APP004", "BND002")]


def test_every_port_problem_is_reported(tmp_path: Path) -> None:
    # two interfaces with two attributes each: every port using them is in error
    model = tmp_path / "two-ports.uml"
    model.write_text((DATA / "port-types.uml").read_text(encoding="utf-8")
                     .replace('<ownedAttribute xmi:id="ifCmdV"', '<ownedAttribute xmi:id="ifCmdW" name="w"/>'
                              '<ownedAttribute xmi:id="ifCmdV"')
                     .replace('<ownedAttribute xmi:id="ifStateV"', '<ownedAttribute xmi:id="ifStateW" name="w"/>'
                              '<ownedAttribute xmi:id="ifStateV"'),
                     encoding="utf-8")
    with pytest.raises(RobomdaError) as info:
        import_model(model)
    errors = [(d.code, d.xmi_id) for d in info.value.diagnostics if d.severity == "error"]
    # both interfaces, not only the first port's
    assert ("BND005", "ifState") in errors and ("BND005", "ifCmd") in errors
    assert ("BND005", "ifState") == errors[0]


def test_every_dangling_reference_is_reported(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model = tmp_path / "dangling.uml"
    model.write_text((DATA / "untyped.uml").read_text(encoding="utf-8")
                     .replace('xmi:id="sensorGain" name="gain"', 'xmi:id="sensorGain" name="gain" type="nowhere1"')
                     .replace('xmi:id="partTodo" name="todo"', 'xmi:id="partTodo" name="todo" type="nowhere2"'),
                     encoding="utf-8")
    assert main(["check", str(model)]) == 1
    captured = capsys.readouterr()
    errors = [line for line in captured.err.splitlines() if ": error: " in line]
    assert len(errors) == 2, captured.err
    assert "[IMP010]" in errors[0] and "sensorGain" in errors[0] and "nowhere1" in errors[0]
    assert "[IMP010]" in errors[1] and "partTodo" in errors[1] and "nowhere2" in errors[1]
    assert ":13:" in errors[0] and ":17:" in errors[1]
    assert "2 errors" in captured.out


# ------------------------------------------------------------ class 4
def test_components_in_nodes_and_connectors_under_the_model() -> None:
    doc, found = _pim("vp-owners.xmi")
    # Visual Paradigm: components as deployment xmi:type="uml:Component" of a Node
    wheel = _one(doc, "//p:application//p:component[@id='vpWheel']")
    assert wheel.get("qualified-name") == "vp::rover::Wheel"
    _one(doc, "//p:application//p:component[@id='vpLog']/p:port[@id='vpLogIn']")
    # the connector under the Model belongs to the composite whose parts it joins
    _one(doc, "//p:component[@name='Rover']/p:connector[@id='vpConn'][@kind='assembly']")
    connection = _one(doc, "//p:binding/p:connection")
    assert connection.get("connectors") == "vpConn"
    assert [w.get("instance") for w in connection.xpath("p:writer", namespaces=NS)] == ["wheel"]
    assert [r.get("instance") for r in connection.xpath("p:reader", namespaces=NS)] == ["logger"]
    # a node holds no deployment made of a component
    assert not doc.xpath("//p:deployment", namespaces=NS)
    # the connector with one end is named, not dropped in silence
    assert ("IMP110", "vpLoose") in _codes(found)


def test_components_nested_in_an_ea_node() -> None:
    doc, _ = _pim("untyped.ea.xmi", bind=False)
    c = _one(doc, "//p:application//p:component[@id='EAID_NESTED']")
    assert c.get("qualified-name") == "plant::robot::Driver"
    _one(c, "p:attribute[@id='EAID_A3']")
    _one(doc, "//p:platform/p:node[@id='EAID_NODE']")


def test_a_component_nested_in_a_node_runs_on_it() -> None:
    """A component owned by a Node (no Deployment) was imported but deployed nowhere (BND006 with
    two execution environments): it runs on the node that owns it."""
    doc, found = _pim("nested-deployed.uml")
    assert _one(doc, "//p:application//p:component[@id='ndC1']").get("node") == "ndN1"
    placed = {i.get("name"): (i.get("host"), i.get("execution-environment"))
              for i in doc.xpath("//p:binding/p:instance", namespaces=NS)}
    assert placed == {"Tracker": ("ndN1", "ndE1"), "Viewer": ("ndN2", "ndE2")}
    assert not [d for d in found if d.severity == "error"]


# ------------------------------------------------------------ class 6
def test_a_middleware_stereotype_means_its_default_kind() -> None:
    done = check(DATA / "middleware-default.uml", "orocos")
    assert done.exit_code == 0, [d.format() for d in done.diagnostics]
    assert not [d for d in done.diagnostics if d.code == "BND003"]
    doc, _ = _pim("middleware-default.uml")
    assert [i.get("middleware") for i in doc.xpath("//p:binding/p:instance", namespaces=NS)] == ["OROCOS", "OROCOS"]


def test_an_unknown_environment_name_without_stereotype_is_still_bnd003(tmp_path: Path) -> None:
    model = tmp_path / "no-stereotype.uml"
    text = (DATA / "middleware-default.uml").read_text(encoding="utf-8")
    model.write_text(text.replace('<robomda:Middleware xmi:id="mw1" base_ExecutionEnvironment="rttVision"/>', ""),
                     encoding="utf-8")
    with pytest.raises(RobomdaError) as info:
        import_model(model)
    assert [(d.code, d.xmi_id) for d in info.value.diagnostics] == [("BND003", "rttVision")]


# ------------------------------------------------------------ class 7
@pytest.mark.parametrize(("name", "holds"), [("profile-only.uml", "is a profile, not a model: it holds no component"),
                                            ("use-cases-only.uml", "holds no component")])
def test_a_file_with_nothing_robomda_uses_says_so(name: str, holds: str, tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    # check runs what generate runs (issue 10 item 4): it fails as generate does
    assert main(["check", str(DATA / name)]) == 1
    err = capsys.readouterr().err
    assert "warning: [IMP030] nothing to generate from" in err and holds in err
    assert "[ORO005] nothing to generate" in err
    assert ("2 Stereotype" if name == "profile-only.uml" else "2 UseCase, 1 Actor") in err
    # generating says why nothing was generated, and writes nothing
    assert main(["generate", str(DATA / name), "-o", str(tmp_path / "out")]) == 1
    err = capsys.readouterr().err
    assert "[IMP030]" in err and "[ORO005] nothing to generate" in err
    assert not (tmp_path / "out").exists()


# ------------------------------------------- nothing dropped: notes shown
def test_the_import_command_prints_its_warnings(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["import", str(DATA / "vp-owners.xmi"), "-o", str(tmp_path / "vp.xml")]) == 0
    err = capsys.readouterr().err
    assert "warning: [IMP110] Connector 'loose'" in err and "vp-owners.xmi:30:" in err


def test_every_instance_without_environment_and_every_unknown_middleware(tmp_path: Path) -> None:
    # two environments named after no middleware, each with a component, and
    # a third component deployed nowhere (the model has several environments)
    text = (DATA / "middleware-default.uml").read_text(encoding="utf-8")
    text = text.replace('<robomda:Middleware xmi:id="mw1" base_ExecutionEnvironment="rttVision"/>', "")
    text = text.replace('<robomda:Middleware xmi:id="mw2" base_ExecutionEnvironment="rttDetect" kind="OROCOS"/>', "")
    text = text.replace('<packagedElement xmi:type="uml:Node"',
                        '<packagedElement xmi:type="uml:Component" xmi:id="lost" name="Lost">'
                        '<ownedAttribute xmi:type="uml:Port" xmi:id="lostIn" name="image" type="ifImg" '
                        'isConjugated="true"/></packagedElement><packagedElement xmi:type="uml:Node"')
    model = tmp_path / "several.uml"
    model.write_text(text, encoding="utf-8")
    with pytest.raises(RobomdaError) as info:
        import_model(model)
    assert [(d.code, d.xmi_id) for d in info.value.diagnostics if d.severity == "error"] == \
        [("BND006", "lost"), ("BND003", "rttVision"), ("BND003", "rttDetect")]


def test_every_pair_of_same_named_instances(tmp_path: Path) -> None:
    text = (DATA / "vp-owners.xmi").read_text(encoding="utf-8")
    # two pairs of parts with one name each
    text = text.replace('name="logger"', 'name="wheel"').replace(
        '<ownedAttribute xmi:type="uml:Property" xmi:id="vpPartW"',
        '<ownedAttribute xmi:type="uml:Property" xmi:id="vpPartX" name="spare" type="vpWheel" aggregation="composite"/>'
        '<ownedAttribute xmi:type="uml:Property" xmi:id="vpPartY" name="spare" type="vpLog" aggregation="composite"/>'
        '<ownedAttribute xmi:type="uml:Property" xmi:id="vpPartW"')
    model = tmp_path / "names.xmi"
    model.write_text(text, encoding="utf-8")
    with pytest.raises(RobomdaError) as info:
        import_model(model)
    assert [(d.code, d.xmi_id) for d in info.value.diagnostics if d.severity == "error"] == \
        [("BND009", "vpPartY"), ("BND009", "vpPartL")]
