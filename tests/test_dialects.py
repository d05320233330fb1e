"""Components drawn as classes with ports, in the modelling tools' own profiles (issue 51).

The robotics modelling tools draw a component as a class with ports, stereotyped by their own
profile. robomda reads such a class as a component when its tool's profile says so (the table
xslt/import/dialects.xml, recognised by the profile's namespace URI), when it has ports and types a
part, or when its parts are typed by components; the rule is bind's (xslt/m2m/bind/classes.xsl,
docs/profile.md "Components drawn as classes"). The dialect fixtures (fixtures/cases/robotml, written
by its make.py from the profile's public definition) have goldens on every target with every other
case (tests/test_golden.py); this file checks what each dialect means, on the fixture and on small
models written here in each dialect's shape.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import check, generate, import_model
from robomda.diagnostics import Diagnostic, RobomdaError

ROOT = Path(__file__).resolve().parent.parent
ROBOTML = ROOT / "fixtures" / "cases" / "robotml"
NS = {"p": "urn:robomda:pim:1"}
PRIM = "pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#"


def _load_make(folder: Path):
    spec = importlib.util.spec_from_file_location(f"make_{folder.name}", folder / "make.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module



def _pim(model: Path, warnings: list[Diagnostic] | None = None) -> etree._Element:
    return etree.fromstring(import_model(model, warnings=warnings if warnings is not None else []).encode("utf-8"))


def test_robotml_classes_are_components_with_the_directions_robotml_means() -> None:
    pim = _pim(ROBOTML / "model.xmi")
    # the import marks the classes RobotML makes components, and the directions of their ports
    marked = {c.get("name"): c.get("dialect") for c in pim.xpath("//p:application//p:*[@dialect][p:port or p:part]",
                                                                    namespaces=NS)}
    assert marked == {"Odometry": "RobotML::SensorSystem", "Planner": "RobotML::Software",
                      "Base": "RobotML::ActuatorSystem", "Rover": "RobotML::RoboticSystem"}
    ports = {(p.getparent().get("name"), p.get("name")): (p.get("direction"), p.get("buffer"))
             for p in pim.xpath("//p:port", namespaces=NS)}
    # a DataFlowPort with no direction tag is in (the enumeration's first literal): never out
    assert ports == {("Odometry", "pose"): ("out", None), ("Planner", "pose"): ("in", "4"),
                     ("Planner", "cmd"): ("out", None), ("Base", "cmd"): ("in", None)}
    # bind takes them as components (drawn as classes), with the Rover's attributes as its parts
    components = {c.get("name"): c.get("drawn-as") for c in pim.xpath("//p:application//p:component", namespaces=NS)}
    assert components == {"Odometry": "class", "Planner": "class", "Base": "class", "Rover": "class"}
    assert [p.get("name") for p in pim.xpath("//p:component[@name='Rover']/p:part", namespaces=NS)] == \
        ["odometry", "planner", "base"]
    data = {(d.getparent().get("name"), d.get("name")): d.get("direction")
            for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS)}
    assert data == {("Odometry", "pose"): "out", ("Planner", "pose"): "in", ("Planner", "cmd"): "out",
                    ("Base", "cmd"): "in"}
    # data flows writer -> reader as RobotML means; bufferSize makes a queue of that size
    flows = {c.get("name"): ([w.get("instance") + "." + w.get("data-port") for w in c.xpath("p:writer", namespaces=NS)],
                             [r.get("instance") + "." + r.get("data-port") for r in c.xpath("p:reader", namespaces=NS)],
                             c.find("p:policy", NS).get("type"), c.find("p:policy", NS).get("size"))
             for c in pim.xpath("//p:binding/p:connection", namespaces=NS)}
    assert flows == {"poseConn": (["odometry.pose"], ["planner.pose"], "BUFFER", "4"),
                     "cmdConn": (["planner.cmd"], ["base.cmd"], "DATA", "1")}


# ------------------------------------------------------------- every dialect fixture
FIXTURES = {  # fixture -> names its files must hold on every target
    "robotml": ("odometry", "planner", "base"),
    "p4r": ("camera", "detector", "logger", "threshold"),
    "umlrt": ("sensor_reading", "data_request", "controller"),
    "sysml": ("fluid_pressure", "pump_command", "maxPressure"),
    "designer": ("sensor", "filter", "reading_in", "scale"),
}


@pytest.mark.parametrize("fixture", sorted(FIXTURES))
def test_dialect_fixture_is_what_its_make_py_writes(fixture: str) -> None:
    folder = ROOT / "fixtures" / "cases" / fixture
    for path, text in _load_make(folder).texts().items():
        assert path.read_text(encoding="utf-8") == text, f"{path}: run {folder / 'make.py'}"


@pytest.mark.parametrize("target", ["orocos", "ros1", "ros2", "openrtm"])
@pytest.mark.parametrize("fixture", sorted(FIXTURES))
def test_dialect_fixture_generates_on_every_target(fixture: str, target: str) -> None:
    """Each dialect fixture has goldens on every target (tests/test_golden.py generates them and compares
    every file, so it generates there), holding each name the dialect must carry through."""
    files = ROOT / "fixtures" / "cases" / fixture / "expected" / target / "files"
    text = "\n".join(p.read_text(encoding="utf-8") for p in sorted(files.rglob("*")) if p.is_file())
    for name in FIXTURES[fixture]:
        assert name in text, (target, name)
    if fixture == "p4r" and target == "ros2":
        assert "rclcpp_lifecycle" in text  # its users run managed (lifecycle) nodes


# ------------------------------------------------------------- small models of each shape
def _xmi(body: str, stereotypes: str = "", extra_ns: str = "") -> str:
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<xmi:XMI xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" '
            'xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML"' + extra_ns + '>\n'
            '  <uml:Model xmi:id="m" name="shapes">\n' + body + '  </uml:Model>\n' + stereotypes + '</xmi:XMI>\n')


def _class(ident: str, name: str, ports: list[tuple[str, str]], parts: list[tuple[str, str]] = (),
           connectors: str = "", composite: bool = False) -> str:
    """A class with ports (name, type) and parts (name, type; UML's composite parts when ``composite``,
    else with no aggregation, as RobotML writes them)."""
    owned = "".join(f'      <ownedAttribute xmi:type="uml:Port" xmi:id="{ident}_{p}" name="{p}" type="{t}" '
                    f'aggregation="composite"/>\n' for p, t in ports)
    aggregation = ' aggregation="composite"' if composite else ""
    owned += "".join(f'      <ownedAttribute xmi:type="uml:Property" xmi:id="{ident}_{p}" name="{p}" type="{t}"'
                     f'{aggregation}/>\n' for p, t in parts)
    return f'    <packagedElement xmi:type="uml:Class" xmi:id="{ident}" name="{name}">\n{owned}{connectors}    </packagedElement>\n'


def _connector(ident: str, a: tuple[str, str], b: tuple[str, str]) -> str:
    return (f'      <ownedConnector xmi:type="uml:Connector" xmi:id="{ident}" name="{ident}">\n'
            f'        <end xmi:type="uml:ConnectorEnd" xmi:id="{ident}a" partWithPort="{a[0]}" role="{a[1]}"/>\n'
            f'        <end xmi:type="uml:ConnectorEnd" xmi:id="{ident}b" partWithPort="{b[0]}" role="{b[1]}"/>\n'
            f'      </ownedConnector>\n')


DATA = ('    <packagedElement xmi:type="uml:DataType" xmi:id="d" name="Reading">\n'
        f'      <ownedAttribute xmi:type="uml:Property" xmi:id="d_v" name="value"><type xmi:type="uml:PrimitiveType" '
        f'href="{PRIM}Real"/></ownedAttribute>\n    </packagedElement>\n')


def test_plain_uml_classes_with_ports_that_type_parts_are_components(tmp_path: Path) -> None:
    """No profile at all: a class with ports used as a part is a component, and so is the class whose
    parts they are; the data ports' directions come from UML (a port typed by its datum writes it, a
    conjugated one reads it)."""
    model = tmp_path / "plain.uml"
    model.write_text(_xmi(
        DATA + _class("s", "Sensor", [("out", "d")])
        + _class("f", "Filter", [("in", "d")]).replace('name="in" type="d"', 'name="in" type="d" isConjugated="true"')
        + _class("sys", "Robot", [], [("sensor", "s"), ("filter", "f")],
                 _connector("c1", ("sys_sensor", "s_out"), ("sys_filter", "f_in")))), encoding="utf-8")
    pim = _pim(model)
    assert sorted(c.get("name") for c in pim.xpath("//p:application//p:component[@drawn-as='class']",
                                                   namespaces=NS)) == ["Filter", "Robot", "Sensor"]
    [connection] = pim.xpath("//p:binding/p:connection", namespaces=NS)
    assert connection.find("p:writer", NS).get("instance") == "sensor"
    assert connection.find("p:reader", NS).get("instance") == "filter"
    assert check(model).exit_code == 0


def test_a_realizing_class_stays_the_atomic_code_of_its_component(tmp_path: Path) -> None:
    """A class that realizes a component is the component's code (seed 000), never a component of its
    own, even with ports and parts."""
    body = (DATA + _class("code", "FilterCode", [("p", "d")])
            + '    <packagedElement xmi:type="uml:Component" xmi:id="comp" name="Filter">\n'
              '      <ownedAttribute xmi:type="uml:Port" xmi:id="comp_p" name="p" type="d" aggregation="composite"/>\n'
              '      <realization xmi:type="uml:ComponentRealization" xmi:id="r" realizingClassifier="code" '
              'abstraction="comp"/>\n    </packagedElement>\n')
    model = tmp_path / "realized.uml"
    model.write_text(_xmi(body), encoding="utf-8")
    pim = _pim(model)
    assert [c.get("name") for c in pim.xpath("//p:application//p:class", namespaces=NS)] == ["FilterCode"]
    assert [c.get("name") for c in pim.xpath("//p:application//p:component", namespaces=NS)] == ["Filter"]


def test_a_class_with_untyped_ports_in_no_profile_gets_oro005_naming_it(tmp_path: Path) -> None:
    model = tmp_path / "lonely.uml"
    model.write_text(_xmi('    <packagedElement xmi:type="uml:Class" xmi:id="c1" name="Camera">\n'
                          '      <ownedAttribute xmi:type="uml:Port" xmi:id="p1" name="image" aggregation="composite"/>\n'
                          '    </packagedElement>\n'), encoding="utf-8")
    result = check(model)
    [oro] = [d for d in result.diagnostics if d.code == "ORO005"]
    assert result.exit_code == 1 and oro.severity == "error"
    assert "'Camera' (its ports have no type and no direction" in oro.message
    assert "the type of no part and in no known profile" in oro.message and "docs/profile.md" in oro.message


ROBOTML_NS = ' xmlns:RobotML="http://Papyrus/RobotML/1"'


def _arm_and_brain(tmp_path: Path, name: str, ports: tuple[tuple[str, str], tuple[str, str]], port_apps: str,
                   head: str = DATA, tail: str = "", apps: str = "") -> Path:
    """A RobotML robot: «Software» Arm and Brain, each with one port (name, type), parts arm and brain of
    Robot joined by a connector; ``port_apps`` the ports' stereotypes (ids a_<port>, b_<port>)."""
    (pa, ta), (pb, tb) = ports
    body = (head + _class("a", "Arm", [(pa, ta)]) + _class("b", "Brain", [(pb, tb)])
            + _class("sys", "Robot", [], [("arm", "a"), ("brain", "b")],
                     _connector("c1", ("sys_arm", f"a_{pa}"), ("sys_brain", f"b_{pb}"))) + tail)
    model = tmp_path / name
    model.write_text(_xmi(body, '  <RobotML:Software xmi:id="s1" base_Class="a"/>\n'
                                '  <RobotML:Software xmi:id="s2" base_Class="b"/>\n' + port_apps + apps, ROBOTML_NS),
                     encoding="utf-8")
    return model


def test_a_robotml_inout_port_is_a_writer_and_a_reader_with_a_warning(tmp_path: Path) -> None:
    model = _arm_and_brain(tmp_path, "inout.uml", (("state", "d"), ("state", "d")),
                           '  <RobotML:DataFlowPort xmi:id="s3" base_Port="a_state" direction="inout"/>\n'
                           '  <RobotML:DataFlowPort xmi:id="s4" base_Port="b_state" direction="out"/>\n')
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    [warning] = [d for d in found if d.code == "BND029"]
    assert warning.severity == "warning" and warning.xmi_id == "a_state"
    assert "'state_out'" in warning.message and "'state_in'" in warning.message
    data = sorted((d.getparent().get("name"), d.get("name"), d.get("direction"))
                  for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS))
    assert data == [("Arm", "state_in", "in"), ("Arm", "state_out", "out"), ("Brain", "state", "out")]
    # the brain writes, the arm's reading half reads: the direction the model says, not inverted
    [connection] = pim.xpath("//p:binding/p:connection", namespaces=NS)
    assert [(w.get("instance"), w.get("data-port")) for w in connection.findall("p:writer", NS)] == [("brain", "state")]
    assert [(r.get("instance"), r.get("data-port")) for r in connection.findall("p:reader", NS)] == [("arm", "state_in")]


def test_an_unknown_robotml_direction_is_a_located_error(tmp_path: Path) -> None:
    body = DATA + _class("a", "Arm", [("state", "d")])
    apps = ('  <RobotML:Software xmi:id="s1" base_Class="a"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s3" base_Port="a_state" direction="sideways"/>\n')
    model = tmp_path / "sideways.uml"
    model.write_text(_xmi(body, apps, ROBOTML_NS), encoding="utf-8")
    with pytest.raises(RobomdaError) as caught:
        import_model(model, warnings=[])
    [error] = [d for d in caught.value.diagnostics if d.code == "BND030"]
    assert error.xmi_id == "a_state" and error.line and "'sideways'" in error.message
    assert "RobotML::DataFlowPort" in error.message


def test_a_robotml_service_port_provides_or_requires_its_interface_by_kind(tmp_path: Path) -> None:
    iface = ('    <packagedElement xmi:type="uml:Interface" xmi:id="i" name="Reset">\n'
             '      <ownedOperation xmi:type="uml:Operation" xmi:id="i_op" name="reset"/>\n    </packagedElement>\n')
    body = (iface + '    <packagedElement xmi:type="uml:Class" xmi:id="a" name="Arm">\n'
            '      <ownedAttribute xmi:type="uml:Port" xmi:id="a_srv" name="srv" type="i" aggregation="composite"/>\n'
            '      <ownedOperation xmi:type="uml:Operation" xmi:id="a_op" name="reset"/>\n    </packagedElement>\n'
            + _class("b", "Brain", [("cli", "i")])
            + _class("sys", "Robot", [], [("arm", "a"), ("brain", "b")],
                     _connector("c1", ("sys_brain", "b_cli"), ("sys_arm", "a_srv"))))
    apps = ('  <RobotML:Software xmi:id="s1" base_Class="a"/>\n  <RobotML:Software xmi:id="s2" base_Class="b"/>\n'
            '  <RobotML:ServicePort xmi:id="s3" base_Port="a_srv"/>\n'
            '  <RobotML:ServicePort xmi:id="s4" base_Port="b_cli" kind="required"/>\n')
    model = tmp_path / "service.uml"
    model.write_text(_xmi(body, apps, ROBOTML_NS), encoding="utf-8")
    pim = _pim(model)
    # kind absent means provided (the enumeration's first literal)
    assert pim.xpath("//p:port[@id='a_srv']/p:provided/@interface", namespaces=NS) == ["i"]
    assert pim.xpath("//p:port[@id='b_cli']/p:required/@interface", namespaces=NS) == ["i"]
    roles = {(s.getparent().get("name"), s.get("role"))
             for s in pim.xpath("//p:binding/p:bound-component/p:service-port", namespaces=NS)}
    assert roles == {("Arm", "provided"), ("Brain", "required")}
    [call] = pim.xpath("//p:binding/p:call", namespaces=NS)
    assert (call.find("p:caller", NS).get("instance"), call.find("p:provider", NS).get("instance")) == ("brain", "arm")


def test_robotml_software_is_the_activity_when_periodic(tmp_path: Path) -> None:
    """«Software» stands for «Activity»: its period when isPeriodic is true (the tag's default is false),
    and its priority; a period without isPeriodic is kept in the model and named by IMP120."""
    pim = _pim(ROBOTML / "model.xmi")
    [activity] = pim.xpath("//p:binding/p:instance[@name='planner']/p:activity", namespaces=NS)
    assert (activity.get("period"), activity.get("period-source"), activity.get("period-holder")) == \
        ("0.1", "stereotype", "_rml_s_plan")
    assert (activity.get("priority"), activity.get("priority-holder")) == ("2", "_rml_s_plan")
    body = DATA + _class("a", "Arm", [("state", "d")])
    apps = ('  <RobotML:Software xmi:id="s1" base_Class="a" period="5.0"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s3" base_Port="a_state" direction="out"/>\n')
    model = tmp_path / "aperiodic.uml"
    model.write_text(_xmi(body, apps, ROBOTML_NS), encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    [warning] = [d for d in found if d.code == "IMP120"]
    assert warning.xmi_id == "s1" and warning.line and "period 5.0" in warning.message
    assert "isPeriodic" in warning.message and "Class 'Arm'" in warning.message
    # the value stays in the PIM (nothing lost), and means no period
    assert pim.xpath("//p:stereotype[@id='s1']/p:tag[@name='period']/@value", namespaces=NS) == ["5.0"]
    assert pim.xpath("//p:binding/p:instance/p:activity/@period", namespaces=NS) == ["0"]


# ------------------------------------------------------------- random models of each dialect's shape
hypothesis = pytest.importorskip("hypothesis", reason="hypothesis not installed (pip install -e '.[test]')")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

import os  # noqa: E402

EXAMPLES = int(os.environ.get("ROBOMDA_HYPOTHESIS_EXAMPLES", "100")) // 4 or 1
RANDOM = os.environ.get("ROBOMDA_HYPOTHESIS_RANDOM", "") not in ("", "0")
SYSTEMS = ["Software", "RoboticSystem", "SensorSystem", "ActuatorSystem", "CameraSystem", "System", "Hardware"]


@st.composite
def robotml_systems(draw) -> tuple[str, dict[str, str]]:
    """A RobotML system: components of the «System» family with DataFlowPorts of every direction (the tag
    absent or written), parts with or without aggregation, connectors between parts' ports of one type.
    Returns the file and the direction each port was drawn with ('' = no tag)."""
    n = draw(st.integers(min_value=1, max_value=4))
    types = ["d", "e"]
    body = DATA + DATA.replace('"d"', '"e"').replace('"d_v"', '"e_v"').replace("Reading", "Level")
    apps, drawn, ports_of = [], {}, {}
    for c in range(n):
        ports = []
        for k in range(draw(st.integers(min_value=1, max_value=3))):
            pid, typ = f"c{c}_p{k}", draw(st.sampled_from(types))
            direction = draw(st.sampled_from(["", "in", "out", "inout"]))
            ports.append((pid, typ))
            drawn[pid] = direction
            tags = f' direction="{direction}"' if direction else ""
            if draw(st.booleans()):
                tags += f' bufferSize="{draw(st.integers(min_value=0, max_value=5))}"'
            apps.append(f'  <RobotML:DataFlowPort xmi:id="a_{pid}" base_Port="{pid}"{tags}/>\n')
        ports_of[f"c{c}"] = ports
        body += (f'    <packagedElement xmi:type="uml:Class" xmi:id="c{c}" name="Comp{c}">\n'
                 + "".join(f'      <ownedAttribute xmi:type="uml:Port" xmi:id="{p}" name="p{p.split("_p")[1]}" '
                           f'type="{t}" aggregation="composite"/>\n' for p, t in ports)
                 + '    </packagedElement>\n')
        stereo = draw(st.sampled_from(SYSTEMS))
        extra = ""
        if stereo == "Software" and draw(st.booleans()):
            extra = f' isPeriodic="{draw(st.sampled_from(["true", "false"]))}" period="0.5"'
        apps.append(f'  <RobotML:{stereo} xmi:id="a_c{c}" base_Class="c{c}"{extra}/>\n')
    parts = [(f"sys_q{c}", f"c{c}", draw(st.booleans())) for c in range(n)]
    connectors = ""
    for k in range(draw(st.integers(min_value=0, max_value=3))):
        a, b = draw(st.sampled_from(range(n))), draw(st.sampled_from(range(n)))
        pa, pb = draw(st.sampled_from(ports_of[f"c{a}"])), draw(st.sampled_from(ports_of[f"c{b}"]))
        if pa[1] == pb[1] and pa[0] != pb[0]:
            connectors += _connector(f"k{k}", (f"sys_q{a}", pa[0]), (f"sys_q{b}", pb[0]))
    body += ('    <packagedElement xmi:type="uml:Class" xmi:id="sys" name="Robot">\n'
             + "".join(f'      <ownedAttribute xmi:type="uml:Property" xmi:id="{p}" name="{p[4:]}" type="{t}"'
                       + (' aggregation="composite"' if comp else "") + '/>\n' for p, t, comp in parts)
             + connectors + '    </packagedElement>\n')
    apps.append('  <RobotML:RoboticSystem xmi:id="a_sys" base_Class="sys"/>\n')
    return _xmi(body, "".join(apps), ROBOTML_NS), drawn


@settings(max_examples=EXAMPLES, derandomize=not RANDOM, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(robotml_systems())
def test_random_robotml_systems_keep_every_direction(system: tuple[str, dict[str, str]]) -> None:
    """Whatever RobotML system is drawn: robomda never ends INTERNAL; when it binds, every part is an
    instance and every port has the data ports its direction means (no tag: in), never inverted, and
    every connection's writers write and its readers read."""
    text, drawn = system
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "random.uml"
        model.write_text(text, encoding="utf-8")
        result = check(model)
        assert result.exit_code in (0, 1), [d.format() for d in result.diagnostics]
        assert not [d for d in result.diagnostics if d.code == "INTERNAL"]
        try:
            pim = _pim(model)
        except RobomdaError as caught:
            # a connector that joins two writers or two readers is the model's error, located
            assert {d.code for d in caught.diagnostics if d.severity == "error"} <= {"BND007", "BND008"}, \
                [d.format() for d in caught.diagnostics]
            return
    want = {"": ["in"], "in": ["in"], "out": ["out"], "inout": ["in", "out"]}
    got: dict[str, list[str]] = {}
    for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS):
        got.setdefault(d.get("port"), []).append(d.get("direction"))
    assert {p: sorted(v) for p, v in got.items()} == {p: want[v] for p, v in drawn.items()}
    assert len(pim.xpath("//p:binding/p:instance", namespaces=NS)) == len(
        pim.xpath("//p:component[@name='Robot']/p:part", namespaces=NS))
    for connection in pim.xpath("//p:binding/p:connection", namespaces=NS):
        for w in connection.findall("p:writer", NS):
            assert drawn[w.get("port")] in ("out", "inout")
        for r in connection.findall("p:reader", NS):
            assert drawn[r.get("port")] in ("", "in", "inout")


# ------------------------------------------------------------- Papyrus for Robotics
P4R = ROOT / "fixtures" / "cases" / "p4r"



def test_p4r_components_services_and_patterns_mean_what_papyrus_for_robotics_means() -> None:
    found: list[Diagnostic] = []
    pim = _pim(P4R / "model.xmi", found)
    # no warning about what the dialect reads: the activities' untyped ports, the services' bindings
    assert not [d for d in found if d.code in ("IMP101", "IMP118", "BND004", "BND007")], [d.format() for d in found]
    # component definitions are components; activities, services and parameter blocks never
    components = sorted(c.get("name") for c in pim.xpath("//p:application//p:component", namespaces=NS))
    assert components == ["Camera", "Detector", "Logger", "System"]
    # the services carry the pattern's argument as their datum
    patterns = {i.get("name"): (i.get("pattern"), i.get("provided-direction"),
                                [a.get("type-name") for a in i.findall("p:attribute", NS)])
                for i in pim.xpath("//p:interface", namespaces=NS)}
    assert patterns == {"P_Image": ("Push", "out", ["Image"]), "S_Boxes": ("Send", "in", ["Boxes"]),
                        "Q_Classify": ("Query", None, [])}
    # a Query is one operation, from its request (the binding's first argument) to its answer (the last)
    [classify] = pim.xpath("//p:interface[@name='Q_Classify']/p:operation", namespaces=NS)
    assert classify.get("name") == "Classify"
    assert [(p.get("name"), p.get("direction"), p.get("type-name")) for p in classify.findall("p:parameter", NS)] == \
        [("request", "in", "Boxes"), ("answer", "return", "Verdict")]
    # the detector asks, the logger answers: a service port each, one call between the instances
    services = {(s.getparent().get("name"), s.get("name")): s.get("role")
                for s in pim.xpath("//p:binding/p:bound-component/p:service-port", namespaces=NS)}
    assert services == {("Detector", "classify"): "required", ("Logger", "classify"): "provided"}
    [call] = pim.xpath("//p:binding/p:call", namespaces=NS)
    assert (call.find("p:caller", NS).get("instance"), call.find("p:provider", NS).get("instance")) == \
        ("detector", "logger")
    # Push provided publishes, required subscribes; Send required sends, provided receives
    data = {(d.getparent().get("name"), d.get("name")): d.get("direction")
            for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS)}
    assert data == {("Camera", "image"): "out", ("Detector", "image"): "in", ("Detector", "boxes"): "out",
                    ("Logger", "boxes"): "in"}
    flows = {c.get("name"): (c.find("p:writer", NS).get("instance"), c.find("p:reader", NS).get("instance"))
             for c in pim.xpath("//p:binding/p:connection", namespaces=NS)}
    assert flows == {"Connects1": ("camera", "detector"), "Connects2": ("detector", "logger")}
    # the parameter blocks' attributes are the components' properties; the activity instance is none
    camera = pim.xpath("//p:component[@name='Camera']", namespaces=NS)[0]
    assert [a.get("name") for a in camera.findall("p:attribute", NS)] == ["rate"]
    assert [a.get("name") for a in pim.xpath("//p:component[@name='Detector']/p:attribute", namespaces=NS)] == \
        ["threshold"]
    # its users run managed (lifecycle) nodes: the default process is managed
    [process] = pim.xpath("//p:binding/p:process", namespaces=NS)
    assert process.get("managed") == "true"


@pytest.mark.parametrize("pattern, signature, name", [("Query", "_5u2FwCanEeiurq-kTHMlgA", "Q_Boxes"),
                                                      ("Action", "_3PvFcDBhEeqxv6YJjwaRyw", "A_Boxes")])
def test_a_p4r_service_robomda_cannot_read_is_left_out_with_a_warning_naming_its_pattern(
        pattern: str, signature: str, name: str, tmp_path: Path) -> None:
    text = (P4R / "model.xmi").read_text(encoding="utf-8")
    # the Send becomes a Query that binds its request only (no answer to read), or an Action
    text = text.replace("_6uKNsCanEeiurq-kTHMlgA", signature).replace('name="S_Boxes"', f'name="{name}"')
    model = tmp_path / "query.uml"
    model.write_text(text, encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    warnings = [d for d in found if d.code == "BND004"]
    assert {d.xmi_id for d in warnings} == {"_p4r_det_boxes", "_p4r_log_boxes"}
    assert all(f"a {pattern} of Papyrus for Robotics::ServiceDefinition" in d.message for d in warnings)
    assert [d.code for d in found if d.code == "BND031"] == ["BND031"]
    assert [c.get("name") for c in pim.xpath("//p:binding/p:connection", namespaces=NS)] == ["Connects1"]
    # the Query the fixture draws in full is still a call
    assert [c.get("name") for c in pim.xpath("//p:binding/p:call", namespaces=NS)] == ["Connects3"]


@st.composite
def p4r_systems(draw) -> tuple[str, dict[str, tuple[str, str]]]:
    """A Papyrus for Robotics system: component definitions whose ports each provide or use one of a
    Push, a Send and a Query service (written by the p4r fixture's make.py), connected where a port that
    provides a service meets one that uses it. Returns the file and, by port id, (pattern, role)."""
    make = _load_make(P4R)
    services = {"Push": ("_h_push", make.PUSH, ("_p4r_image",)), "Send": ("_h_send", make.SEND, ("_p4r_boxes",)),
                "Query": ("_h_query", make.QUERY, ("_p4r_boxes", "_p4r_image"))}
    body = ('  <packagedElement xmi:type="uml:Package" xmi:id="_h_svc" name="services">\n'
            '    <packagedElement xmi:type="uml:DataType" xmi:id="_p4r_image" name="Image">\n'
            + make._field("_p4r_image_w", "width", "Integer") + '    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:DataType" xmi:id="_p4r_boxes" name="Boxes">\n'
            + make._field("_p4r_boxes_n", "count", "Integer") + '    </packagedElement>\n'
            + "".join(make._service_definition(i, f"{p[0]}_{p}", pattern, *actuals)
                      for p, (i, pattern, actuals) in services.items())
            + '  </packagedElement>\n')
    apps = [f'<robotics.services:ServiceDefinition xmi:id="{i}_s" base_Interface="{i}"/>' for i, _, _ in services.values()]
    drawn: dict[str, tuple[str, str]] = {}
    n = draw(st.integers(min_value=2, max_value=3))
    for c in range(n):
        ports = []
        for k in range(draw(st.integers(min_value=1, max_value=3))):
            pattern, role = draw(st.sampled_from(sorted(services))), draw(st.sampled_from(["provided", "required"]))
            ports.append((f"p{k}", role, services[pattern][0]))
            drawn[f"_h_c{c}_p{k}"] = (pattern, role)
        body += make._component(f"_h_c{c}", f"Comp{c}", ports, [], apps)
    system = '  <packagedElement xmi:type="uml:Class" xmi:id="_h_sys" name="System">\n'
    for c in range(n):
        system += f'    <ownedAttribute xmi:type="uml:Property" xmi:id="_h_sys_c{c}" name="c{c}" type="_h_c{c}"/>\n'
        apps.append(f'<robotics.components:ComponentInstance xmi:id="_h_sys_c{c}_s" base_Property="_h_sys_c{c}"/>')
    pairs = [(a, b) for a in drawn for b in drawn if a.split("_p")[0] < b.split("_p")[0]
             and drawn[a][0] == drawn[b][0] and drawn[a][1] != drawn[b][1]]
    for k, (a, b) in enumerate(draw(st.lists(st.sampled_from(pairs), unique=True, max_size=3)) if pairs else []):
        system += (f'    <ownedConnector xmi:type="uml:Connector" xmi:id="_h_k{k}" name="Connects{k}">\n'
                   f'      <end xmi:type="uml:ConnectorEnd" xmi:id="_h_k{k}a" partWithPort="_h_sys_{a.split("_")[2]}" role="{a}"/>\n'
                   f'      <end xmi:type="uml:ConnectorEnd" xmi:id="_h_k{k}b" partWithPort="_h_sys_{b.split("_")[2]}" role="{b}"/>\n'
                   f'    </ownedConnector>\n')
        apps.append(f'<robotics.generics:Connects xmi:id="_h_k{k}_s" base_Connector="_h_k{k}"/>')
    system += '  </packagedElement>\n'
    apps.append('<robotics.components:System xmi:id="_h_sys_s" base_Class="_h_sys"/>')
    xmlns = "".join(f' xmlns:{p}="{u}"' for p, u in make.NS.items())
    text = ('<?xml version="1.0" encoding="UTF-8"?>\n<xmi:XMI xmi:version="20131001" '
            'xmlns:xmi="http://www.omg.org/spec/XMI/20131001" xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML"'
            + xmlns + '>\n<uml:Model xmi:id="_h_model" name="random">\n' + body + system + '</uml:Model>\n'
            + "".join(f"{a}\n" for a in apps) + '</xmi:XMI>\n')
    return text, drawn


@settings(max_examples=EXAMPLES, derandomize=not RANDOM, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(p4r_systems())
def test_random_p4r_systems_mean_what_each_pattern_means(system: tuple[str, dict[str, tuple[str, str]]]) -> None:
    """Whatever Papyrus for Robotics system is drawn: every port is bound as its pattern and role mean (Push:
    provided writes; Send: provided reads; Query: a service port of that role), never inverted, and every
    connector is a connection from the writer to the reader, or a call from the user to the provider."""
    text, drawn = system
    import tempfile
    found: list[Diagnostic] = []
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "random.uml"
        model.write_text(text, encoding="utf-8")
        try:
            pim = _pim(model, found)
        except RobomdaError as caught:
            # with no connector drawn, a reader several writers feed or a Query several ports provide: the
            # model's ambiguity, located
            assert {d.code for d in caught.diagnostics if d.severity == "error"} <= {"BND008", "BND019"}, \
                [d.format() for d in caught.diagnostics]
            return
    assert not [d for d in found if d.code in ("BND004", "BND007", "INTERNAL")], [d.format() for d in found]
    data = {"Push": {"provided": "out", "required": "in"}, "Send": {"provided": "in", "required": "out"}}
    got = {d.get("port"): ("data", d.get("direction"))
           for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS)}
    got |= {s.get("port"): ("service", s.get("role"))
            for s in pim.xpath("//p:binding/p:bound-component/p:service-port", namespaces=NS)}
    assert got == {p: ("service", role) if pattern == "Query" else ("data", data[pattern][role])
                   for p, (pattern, role) in drawn.items()}
    for connection in pim.xpath("//p:binding/p:connection", namespaces=NS):
        assert got[connection.find("p:writer", NS).get("port")] == ("data", "out")
        assert got[connection.find("p:reader", NS).get("port")] == ("data", "in")
    for call in pim.xpath("//p:binding/p:call", namespaces=NS):
        assert drawn[call.find("p:caller", NS).get("port")] == ("Query", "required")
        assert drawn[call.find("p:provider", NS).get("port")] == ("Query", "provided")


@pytest.mark.parametrize("target, srv", [("ros2", "p4r/srv/classify.hpp"), ("ros1", "p4r/Classify.h")])
def test_a_p4r_query_is_a_ros_service_of_the_package_own(target: str, srv: str, tmp_path: Path) -> None:
    """A Query from Boxes to Verdict: srv/Classify.srv carries the request's and the answer's messages;
    the logger's node serves it (~/Classify), the detector's calls it, remapped to the logger's."""
    out = tmp_path / target
    generate(P4R / "model.xmi", out, target)
    lines = [line for line in (out / "srv" / "Classify.srv").read_text(encoding="utf-8").splitlines()
             if not line.startswith("#")]
    assert lines == ["Boxes request", "---", "Verdict answer"]
    cmake = (out / "CMakeLists.txt").read_text(encoding="utf-8")
    assert ('"srv/Classify.srv"' if target == "ros2" else "add_service_files(FILES Classify.srv)") in cmake
    include = f'#include "{srv}"' if target == "ros2" else f"#include <{srv}>"  # ROS 2: cpplint's style
    assert include in (out / "include" / "p4r" / "Logger.hpp").read_text(encoding="utf-8")
    logger = (out / "src" / "Logger.cpp").read_text(encoding="utf-8")
    assert "Classify(from_msg_value<::p4r::types::Boxes>(request" in logger and "answer);" in logger
    detector = (out / "src" / "Detector.cpp").read_text(encoding="utf-8")
    assert "::p4r::types::Verdict Detector::Classify(const ::p4r::types::Boxes & request)" in detector
    # the user's class answers it: the generated base declares the operation for the user to implement
    base = (out / "include" / "p4r" / "LoggerBase.hpp").read_text(encoding="utf-8")
    assert "virtual ::p4r::types::Verdict Classify(const ::p4r::types::Boxes & request) = 0;" in base
    launch = "\n".join(p.read_text(encoding="utf-8") for p in (out / "launch").iterdir())
    assert 'from="Classify"' in launch and "logger/Classify" in launch


def test_an_operation_no_ros_service_can_carry_is_refused_naming_why(tmp_path: Path) -> None:
    """The Query's answer of a type no ROS message carries (a class): ROS009 says why, where."""
    text = (P4R / "model.xmi").read_text(encoding="utf-8")
    text = text.replace('actual="_p4r_verdict"', 'actual="_p4r_odd"').replace(
        '</uml:Model>', '<packagedElement xmi:type="uml:Class" xmi:id="_p4r_odd" name="Odd"/>\n</uml:Model>')
    model = tmp_path / "odd.uml"
    model.write_text(text, encoding="utf-8")
    with pytest.raises(RobomdaError) as caught:
        generate(model, tmp_path / "out", "ros2")
    [error] = [d for d in caught.value.diagnostics if d.code == "ROS009"]
    assert "Classify" in error.message and "no ROS message carries" in error.message and error.line
    assert not (tmp_path / "out").exists()


# ------------------------------------------------------------- false refusals of real files (issue 51 item 5)
def test_components_of_one_name_in_different_packages_are_qualified(tmp_path: Path) -> None:
    """Legal UML: two components named Camera in packages front and rear. Their instances, classes and
    nodes are named by the qualified names (front_Camera, FrontCamera), not refused as BND009 / ORO004."""
    body = DATA
    for pkg in ("front", "rear"):
        body += (f'    <packagedElement xmi:type="uml:Package" xmi:id="{pkg}" name="{pkg}">\n'
                 f'      <packagedElement xmi:type="uml:Component" xmi:id="{pkg}_cam" name="Camera">\n'
                 f'        <ownedAttribute xmi:type="uml:Port" xmi:id="{pkg}_p" name="image" type="d" aggregation="composite"/>\n'
                 f'      </packagedElement>\n    </packagedElement>\n')
    model = tmp_path / "twins.uml"
    model.write_text(_xmi(body), encoding="utf-8")
    pim = _pim(model)
    assert [i.get("name") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)] == ["front_Camera", "rear_Camera"]
    for target, word in (("orocos", "class FrontCamera"), ("ros1", "class FrontCamera"), ("ros2", "class FrontCamera"),
                         ("openrtm", "class FrontCamera")):
        done = generate(model, tmp_path / target, target, write=False)
        text = "\n".join(f.text or "" for f in etree.fromstring(done.stages["text"].encode()).iter(
            "{urn:robomda:fileset:1}file"))
        assert word in text and word.replace("Front", "Rear") in text, target


def test_components_with_lollipops_and_sockets_and_no_system_are_generated(tmp_path: Path) -> None:
    """Issue 51 item 4: a component diagram with components that provide and require interfaces directly
    (no port, no composite): each gets a port per interface and one instance, wired by interface, with one
    located warning that says so and how to draw the system."""
    body = ('    <packagedElement xmi:type="uml:Interface" xmi:id="i" name="Scan">\n'
            f'      <ownedAttribute xmi:type="uml:Property" xmi:id="i_v" name="range"><type xmi:type="uml:PrimitiveType" '
            f'href="{PRIM}Real"/></ownedAttribute>\n    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Component" xmi:id="laser" name="Laser">\n'
            '      <interfaceRealization xmi:type="uml:InterfaceRealization" xmi:id="laser_r" client="laser" supplier="i" '
            'contract="i"/>\n    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Component" xmi:id="nav" name="Navigator"/>\n'
            '    <packagedElement xmi:type="uml:Usage" xmi:id="nav_u" client="nav" supplier="i"/>\n')
    model = tmp_path / "lollipops.uml"
    model.write_text(_xmi(body), encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    [warning] = [d for d in found if d.code == "BND032"]
    assert warning.xmi_id == "laser" and warning.line and "'Laser', 'Navigator'" in warning.message
    assert "draw a class or component whose parts" in warning.message
    ports = {(p.getparent().get("name"), p.get("name"), p.get("implicit")) for p in pim.xpath("//p:port", namespaces=NS)}
    assert ports == {("Laser", "Scan", "true"), ("Navigator", "Scan", "true")}
    [connection] = pim.xpath("//p:binding/p:connection", namespaces=NS)
    assert (connection.find("p:writer", NS).get("instance"), connection.find("p:reader", NS).get("instance")) == \
        ("Laser", "Navigator")
    assert check(model).exit_code == 0


# ------------------------------------------------------------- UML-RT
UMLRT = ROOT / "fixtures" / "cases" / "umlrt"



def _message_flows(pim: etree._Element) -> dict[str, tuple[str, str, str, str]]:
    return {c.find("p:writer", NS).get("data-port"): (c.find("p:writer", NS).get("instance"),
                                                       c.find("p:reader", NS).get("instance"),
                                                       c.find("p:reader", NS).get("data-port"),
                                                       c.find("p:policy", NS).get("type"))
            for c in pim.xpath("//p:binding/p:connection", namespaces=NS)}


def test_umlrt_messages_received_are_inputs_sent_are_outputs_swapped_when_conjugated() -> None:
    found: list[Diagnostic] = []
    pim = _pim(UMLRT / "model.xmi", found)
    # capsules are components; the top capsule the model names is the system, Spare is left beside it
    assert [i.get("name") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)] == ["sensor", "controller"]
    data = {(d.getparent().get("name"), d.get("name")): (d.get("direction"), d.get("primitive"))
            for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS)}
    # the controller's port is not conjugated: it receives the in-set (reading) and sends request;
    # the sensor's is conjugated: the other way round
    assert data == {("Controller", "sensor_reading"): ("in", "float64"), ("Controller", "sensor_request"): ("out", "boolean"),
                    ("Sensor", "data_reading"): ("out", "float64"), ("Sensor", "data_request"): ("in", "boolean")}
    # one connection per message, queued (a message must not be dropped)
    assert _message_flows(pim) == {"data_reading": ("sensor", "controller", "sensor_reading", "BUFFER"),
                                   "sensor_request": ("controller", "sensor", "data_request", "BUFFER")}
    # a message with no payload is a boolean signal, said once; the runtime's ports are noted, not ports
    [signal] = [d for d in found if d.code == "IMP121"]
    assert signal.xmi_id == "_rt_request" and "boolean signal" in signal.message
    assert sorted(d.xmi_id for d in found if d.code == "BND033") == ["_rt_sensor_log", "_rt_sensor_timer"]
    assert not [d for d in found if d.code in ("IMP115", "BND020", "BND005")], [d.format() for d in found]


RSA_NS = ' xmlns:UMLRealTime="http:///schemas/UMLRealTime/_3TUzoHq6Ed2hSeAAWZznoA/119"'


def test_rsa_rte_conjugates_by_its_rtport_tag_and_reads_sets_by_the_protocol(tmp_path: Path) -> None:
    """RSA-RTE / RTist: no RTMessageSet, no UML isConjugated; the protocol's realized interface holds the
    messages received, the used one those sent, and «RTPort» isConjugate swaps them."""
    body = ('    <packagedElement xmi:type="uml:Collaboration" xmi:id="pp" name="PingPong">\n'
            '      <interfaceRealization xmi:id="pp_r" client="pp" supplier="in" contract="in"/>\n'
            '    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Interface" xmi:id="in" name="PingPong">\n'
            '      <ownedOperation xmi:id="pong" name="pong"><ownedParameter xmi:id="pong_n" name="n">'
            f'<type xmi:type="uml:PrimitiveType" href="{PRIM}Integer"/></ownedParameter></ownedOperation>\n'
            '    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Interface" xmi:id="out" name="PingPong~">\n'
            '      <ownedOperation xmi:id="ping" name="ping"><ownedParameter xmi:id="ping_n" name="n">'
            f'<type xmi:type="uml:PrimitiveType" href="{PRIM}Integer"/></ownedParameter></ownedOperation>\n'
            '    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Usage" xmi:id="pp_u" client="pp" supplier="out"/>\n'
            + _class("pinger", "Pinger", [("p", "pp")]) + _class("ponger", "Ponger", [("p", "pp")])
            + _class("top", "Top", [], [("pinger", "pinger"), ("ponger", "ponger")],
                     _connector("c", ("top_pinger", "pinger_p"), ("top_ponger", "ponger_p")), composite=True))
    apps = ('  <UMLRealTime:Protocol xmi:id="s1" base_Collaboration="pp"/>\n'
            '  <UMLRealTime:Capsule xmi:id="s2" base_Class="pinger"/>\n  <UMLRealTime:Capsule xmi:id="s3" base_Class="ponger"/>\n'
            '  <UMLRealTime:Capsule xmi:id="s4" base_Class="top"/>\n'
            '  <UMLRealTime:RTPort xmi:id="s5" isConjugate="true" base_Port="ponger_p"/>\n')
    model = tmp_path / "pingpong.emx"
    model.write_text(_xmi(body, apps, RSA_NS), encoding="utf-8")
    pim = _pim(model)
    # the pinger (not conjugated) receives pong and sends ping; the conjugated ponger the other way round
    assert _message_flows(pim) == {"p_ping": ("pinger", "ponger", "p_ping", "BUFFER"),
                                   "p_pong": ("ponger", "pinger", "p_pong", "BUFFER")}
    assert pim.xpath("//p:port[@id='ponger_p']/@conjugated", namespaces=NS) == ["true"]


# ------------------------------------------------------------- SysML
SYSML = ROOT / "fixtures" / "cases" / "sysml"



def test_sysml_flow_properties_and_flow_ports_keep_their_directions() -> None:
    found: list[Diagnostic] = []
    pim = _pim(SYSML / "model.xmi", found)
    # blocks are components, the interface block never; the plant is the system
    assert sorted(c.get("name") for c in pim.xpath("//p:application//p:component", namespaces=NS)) == \
        ["Controller", "Plant", "Pump", "Sensor"]
    data = {(d.getparent().get("name"), d.get("name")): d.get("direction")
            for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS)}
    # a proxy port carries each flow property of its interface block, swapped when conjugated
    assert data == {("Pump", "fluid_pressure"): "out", ("Pump", "fluid_command"): "in",
                    ("Sensor", "level"): "out",
                    ("Controller", "pump_pressure"): "in", ("Controller", "pump_command"): "out",
                    ("Controller", "level"): "in"}
    flows = {c.find("p:writer", NS).get("instance") + "." + c.find("p:writer", NS).get("data-port"):
             c.find("p:reader", NS).get("instance") + "." + c.find("p:reader", NS).get("data-port")
             for c in pim.xpath("//p:binding/p:connection", namespaces=NS)}
    assert flows == {"pump.fluid_pressure": "controller.pump_pressure", "controller.pump_command": "pump.fluid_command",
                     "sensor.level": "controller.level"}
    # the value property is a property of the pump
    assert pim.xpath("//p:component[@name='Pump']/p:attribute/@name", namespaces=NS) == ["maxPressure"]
    assert not [d for d in found if d.severity == "error"]


SYSML11_NS = (' xmlns:Blocks="http://www.eclipse.org/papyrus/0.7.0/SysML/Blocks"'
              ' xmlns:PortAndFlows="http://www.eclipse.org/papyrus/0.7.0/SysML/PortAndFlows"')


def test_a_sysml_flow_port_without_direction_is_inout_and_its_own_conjugation_swaps_it(tmp_path: Path) -> None:
    """SysML 1.1 (Papyrus 0.7.0): FlowPort direction absent = inout (a writer and a reader, BND029); the
    stereotype's isConjugated tag swaps an in port to out."""
    body = (DATA + _class("a", "Tank", [("q", "d")]) + _class("b", "Valve", [("q", "d")])
            + _class("sys", "Plant", [], [("tank", "a"), ("valve", "b")],
                     _connector("k", ("sys_tank", "a_q"), ("sys_valve", "b_q")), composite=True))
    apps = ('  <Blocks:Block xmi:id="s1" base_Class="a"/>\n  <Blocks:Block xmi:id="s2" base_Class="b"/>\n'
            '  <Blocks:Block xmi:id="s3" base_Class="sys"/>\n'
            '  <PortAndFlows:FlowPort xmi:id="s4" base_Port="a_q"/>\n'
            '  <PortAndFlows:FlowPort xmi:id="s5" base_Port="b_q" direction="in" isConjugated="true"/>\n')
    model = tmp_path / "tanks.uml"
    model.write_text(_xmi(body, apps, SYSML11_NS), encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    data = sorted((d.getparent().get("name"), d.get("name"), d.get("direction"))
                  for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS))
    assert data == [("Tank", "q_in", "in"), ("Tank", "q_out", "out"), ("Valve", "q", "out")]
    assert [d.xmi_id for d in found if d.code == "BND029"] == ["a_q"]
    [connection] = pim.xpath("//p:binding/p:connection", namespaces=NS)
    assert (connection.find("p:writer", NS).get("instance"), connection.find("p:reader", NS).get("data-port")) == \
        ("valve", "q_in")


def test_a_class_drawn_as_a_component_implements_the_operations_its_ports_provide(tmp_path: Path) -> None:
    """RobotML: a «ServicePort» provides its interface, and the class declares none of its operations (its
    code implements them): they are the component's own, for its user class; no BND020."""
    iface = ('    <packagedElement xmi:type="uml:Interface" xmi:id="i" name="Reset">\n'
             '      <ownedOperation xmi:type="uml:Operation" xmi:id="i_op" name="reset"/>\n    </packagedElement>\n')
    model = _arm_and_brain(tmp_path, "service.uml", (("srv", "i"), ("cli", "i")),
                           '  <RobotML:ServicePort xmi:id="s3" base_Port="a_srv"/>\n'
                           '  <RobotML:ServicePort xmi:id="s4" base_Port="b_cli" kind="required"/>\n', head=iface)
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    assert pim.xpath("//p:component[@name='Arm']/p:operation/@name", namespaces=NS) == ["reset"]
    assert pim.xpath("//p:component[@name='Brain']/p:operation", namespaces=NS) == []
    assert len(pim.xpath("//p:binding/p:call", namespaces=NS)) == 1
    for target in ("orocos", "ros2"):
        done = generate(model, tmp_path / target, target, write=False)
        assert "reset" in done.stages["text"], target


def test_ports_typed_by_a_library_robomda_does_not_have_are_said_once(tmp_path: Path) -> None:
    lib = "pathmap://Robotml_LIBRARIES/RobotMLPlatformLibraries.uml#"
    body = (DATA + '    <packagedElement xmi:type="uml:Class" xmi:id="a" name="Camera">\n'
            f'      <ownedAttribute xmi:type="uml:Port" xmi:id="a_img" name="image" aggregation="composite">'
            f'<type xmi:type="uml:DataType" href="{lib}_img"/></ownedAttribute>\n'
            '      <ownedAttribute xmi:type="uml:Port" xmi:id="a_v" name="value" type="d" aggregation="composite"/>\n'
            '    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Class" xmi:id="b" name="Viewer">\n'
            f'      <ownedAttribute xmi:type="uml:Port" xmi:id="b_img" name="image" aggregation="composite">'
            f'<type xmi:type="uml:DataType" href="{lib}_img"/></ownedAttribute>\n'
            '    </packagedElement>\n'
            + _class("sys", "Robot", [], [("camera", "a"), ("viewer", "b")],
                     _connector("c1", ("sys_camera", "a_img"), ("sys_viewer", "b_img"))))
    apps = ('  <RobotML:CameraSystem xmi:id="s1" base_Class="a"/>\n  <RobotML:Software xmi:id="s2" base_Class="b"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s3" base_Port="a_img" direction="out"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s4" base_Port="a_v" direction="out"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s5" base_Port="b_img"/>\n')
    model = tmp_path / "library.uml"
    model.write_text(_xmi(body, apps, ROBOTML_NS), encoding="utf-8")
    found: list[Diagnostic] = []
    _pim(model, found)
    [once] = [d for d in found if d.code == "BND034"]
    assert once.xmi_id == "a_img" and once.line and "2 ports are typed" in once.message
    assert [d.xmi_id for d in found if d.code == "BND031"] == ["c1"]
    assert check(model).exit_code == 0


def test_a_robotml_deployment_plan_allocates_instances_to_their_middleware(tmp_path: Path) -> None:
    """«Allocate» from a deployment plan's instance to an instance of a «RoboticMiddleware» class with kind
    OROCOS deploys the part there; to a simulator, a located warning (IMP123), not silence."""
    plan = ('    <packagedElement xmi:type="uml:Class" xmi:id="oro" name="Orocos"/>\n'
              '    <packagedElement xmi:type="uml:Class" xmi:id="sim" name="Morse"/>\n'
              '    <packagedElement xmi:type="uml:Package" xmi:id="plan" name="plan">\n'
              '      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="i_oro" name="orocos" classifier="oro"/>\n'
              '      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="i_sim" name="morse" classifier="sim"/>\n'
              '      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="i_main" name="mainInstance" classifier="sys">\n'
              '        <slot xmi:id="sl1" definingFeature="sys_arm"><value xmi:type="uml:InstanceValue" xmi:id="v1" instance="i_arm"/></slot>\n'
              '        <slot xmi:id="sl2" definingFeature="sys_brain"><value xmi:type="uml:InstanceValue" xmi:id="v2" instance="i_brain"/></slot>\n'
              '      </packagedElement>\n'
              '      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="i_arm" name="mainInstance.arm" classifier="a"/>\n'
              '      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="i_brain" name="mainInstance.brain" classifier="b"/>\n'
              '      <packagedElement xmi:type="uml:Abstraction" xmi:id="al1" name="allocate to orocos" client="i_brain" supplier="i_oro"/>\n'
              '      <packagedElement xmi:type="uml:Abstraction" xmi:id="al2" name="allocate to morse" client="i_arm" supplier="i_sim"/>\n'
              '    </packagedElement>\n')
    apps = ('  <RobotML:RoboticMiddleware xmi:id="s5" base_Class="oro" kind="OROCOS"/>\n'
            '  <RobotML:BlenderMorse xmi:id="s6" base_Class="sim"/>\n'
            '  <RobotML:DeploymentPlan xmi:id="s7" base_Package="plan" mainInstance="i_main"/>\n'
            '  <RobotML:Allocate xmi:id="s8" base_Abstraction="al1"/>\n  <RobotML:Allocate xmi:id="s9" base_Abstraction="al2"/>\n')
    model = _arm_and_brain(tmp_path, "plan.uml", (("state", "d"), ("state", "d")),
                           '  <RobotML:DataFlowPort xmi:id="s3" base_Port="a_state" direction="out"/>\n'
                           '  <RobotML:DataFlowPort xmi:id="s4" base_Port="b_state"/>\n', tail=plan, apps=apps)
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    [ee] = pim.xpath("//p:platform/p:node[@kind='execution-environment']", namespaces=NS)
    assert (ee.get("name"), ee.get("middleware")) == ("orocos", "OROCOS")
    assert [d.get("deployed") for d in ee.findall("p:deployment", NS)] == ["sys_brain"]
    [sim] = [d for d in found if d.code == "IMP123"]
    assert sim.xmi_id == "al2" and sim.line and "simulator 'morse' (BlenderMorse)" in sim.message
    assert not [d for d in found if d.code in ("IMP111", "IMP115")], [d.format() for d in found]
    # the brain runs on Orocos; the simulated arm with it, as the only process
    assert {i.get("name"): i.get("middleware") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)} == \
        {"arm": "OROCOS", "brain": "OROCOS"}


@st.composite
def sysml_systems(draw) -> tuple[str, dict[str, tuple[str, bool]], dict[str, str]]:
    """A SysML 1.6 system: blocks with proxy ports typed by interface blocks whose flow properties have every
    direction (the tag absent or written), some ports conjugated, and connectors between ports of one type.
    Returns the file, each port's (interface block, conjugated) and each flow property's drawn direction."""
    n_ib = draw(st.integers(min_value=1, max_value=2))
    flows: dict[str, str] = {}
    body = DATA
    apps = []
    for k in range(n_ib):
        props = []
        for m in range(draw(st.integers(min_value=1, max_value=3))):
            fid, direction = f"ib{k}_f{m}", draw(st.sampled_from(["", "in", "out", "inout"]))
            flows[fid] = direction
            props.append(f'      <ownedAttribute xmi:type="uml:Property" xmi:id="{fid}" name="f{m}" type="d"/>\n')
            apps.append(f'  <PortsAndFlows:FlowProperty xmi:id="a_{fid}" base_Property="{fid}"'
                        + (f' direction="{direction}"' if direction else "") + '/>\n')
        body += f'    <packagedElement xmi:type="uml:Class" xmi:id="ib{k}" name="IB{k}">\n' + "".join(props) + '    </packagedElement>\n'
        apps.append(f'  <PortsAndFlows:InterfaceBlock xmi:id="a_ib{k}" base_Class="ib{k}"/>\n')
    ports: dict[str, tuple[str, bool]] = {}
    n = draw(st.integers(min_value=1, max_value=3))
    for c in range(n):
        owned = ""
        for k in range(draw(st.integers(min_value=1, max_value=2))):
            pid, ib, conj = f"b{c}_p{k}", f"ib{draw(st.integers(min_value=0, max_value=n_ib - 1))}", draw(st.booleans())
            ports[pid] = (ib, conj)
            owned += (f'      <ownedAttribute xmi:type="uml:Port" xmi:id="{pid}" name="p{k}" type="{ib}" aggregation="composite"'
                      + (' isConjugated="true"' if conj else "") + '/>\n')
            apps.append(f'  <PortsAndFlows:ProxyPort xmi:id="a_{pid}" base_Port="{pid}"/>\n')
        body += f'    <packagedElement xmi:type="uml:Class" xmi:id="b{c}" name="Block{c}">\n{owned}    </packagedElement>\n'
        apps.append(f'  <Blocks:Block xmi:id="a_b{c}" base_Class="b{c}"/>\n')
    connectors = ""
    for k in range(draw(st.integers(min_value=0, max_value=3))):
        a, b = draw(st.sampled_from(sorted(ports))), draw(st.sampled_from(sorted(ports)))
        if a != b and ports[a][0] == ports[b][0]:
            connectors += _connector(f"k{k}", (f"sys_q{a[1:].split('_')[0]}", a), (f"sys_q{b[1:].split('_')[0]}", b))
    body += _class("sys", "System", [], [(f"q{c}", f"b{c}") for c in range(n)], connectors, composite=True)
    apps.append('  <Blocks:Block xmi:id="a_sys" base_Class="sys"/>\n')
    ns = (' xmlns:Blocks="http://www.eclipse.org/papyrus/sysml/1.6/SysML/Blocks"'
          ' xmlns:PortsAndFlows="http://www.eclipse.org/papyrus/sysml/1.6/SysML/PortsAndFlows"')
    return _xmi(body, "".join(apps), ns), ports, flows


@settings(max_examples=EXAMPLES, derandomize=not RANDOM, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(sysml_systems())
def test_random_sysml_systems_keep_every_flow_direction(system) -> None:
    """Whatever SysML system is drawn: robomda never ends INTERNAL; when it binds, each proxy port carries each
    flow property of its type in the property's direction (no tag: inout, both), swapped when the port is
    conjugated, and every connection's writer writes and its reader reads."""
    text, ports, flows = system
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "random.uml"
        model.write_text(text, encoding="utf-8")
        result = check(model)
        assert result.exit_code in (0, 1) and not [d for d in result.diagnostics if d.code == "INTERNAL"]
        try:
            pim = _pim(model)
        except RobomdaError as caught:
            assert {d.code for d in caught.diagnostics if d.severity == "error"} <= {"BND007", "BND008"}, \
                [d.format() for d in caught.diagnostics]
            return
    flip = {"in": "out", "out": "in"}
    for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS):
        ib, conj = ports[d.get("port")]
        drawn = flows[d.get("datum")] or "inout"
        want = {"in", "out"} if drawn == "inout" else {flip[drawn] if conj else drawn}
        assert d.get("direction") in want, (d.get("port"), d.get("datum"), drawn, conj)
    for connection in pim.xpath("//p:binding/p:connection", namespaces=NS):
        for end, role in (("p:writer", "out"), ("p:reader", "in")):
            for e in connection.findall(end, NS):
                [dp] = pim.xpath(f"//p:bound-component/p:data-port[@port='{e.get('port')}'][@name='{e.get('data-port')}']",
                                 namespaces=NS)
                assert dp.get("direction") == role


@st.composite
def umlrt_systems(draw) -> tuple[str, dict[str, bool], dict[str, str]]:
    """A Papyrus-RT system: one protocol with an in set and an out set (rtMsgKind absent or written) of random
    messages, capsules with ports typed by it, some conjugated, and connectors between them. Returns the file,
    each port's conjugation and each message's set ('in' or 'out')."""
    sets = {"in": draw(st.sampled_from(["", "in"])), "out": "out"}
    messages: dict[str, str] = {}
    interfaces = ""
    for kind in ("in", "out"):
        ops = ""
        for m in range(draw(st.integers(min_value=1, max_value=2))):
            mid = f"{kind}_m{m}"
            messages[mid] = kind
            payload = (f'<ownedParameter xmi:id="{mid}_p" name="v"><type xmi:type="uml:PrimitiveType" href="{PRIM}Real"/>'
                       f'</ownedParameter>' if draw(st.booleans()) else "")
            ops += f'      <ownedOperation xmi:type="uml:Operation" xmi:id="{mid}" name="{kind}{m}">{payload}</ownedOperation>\n'
        interfaces += (f'    <packagedElement xmi:type="uml:Interface" xmi:id="set_{kind}" name="P{"~" if kind == "out" else ""}">\n'
                       f'{ops}    </packagedElement>\n')
    body = ('    <packagedElement xmi:type="uml:Collaboration" xmi:id="proto" name="P">\n'
            '      <interfaceRealization xmi:type="uml:InterfaceRealization" xmi:id="proto_r" client="proto" supplier="set_in" contract="set_in"/>\n'
            '    </packagedElement>\n' + interfaces
            + '    <packagedElement xmi:type="uml:Usage" xmi:id="proto_u" client="proto" supplier="set_out"/>\n')
    apps = ['  <UMLRealTime:Protocol xmi:id="a_proto" base_Collaboration="proto"/>\n']
    apps += [f'  <UMLRealTime:RTMessageSet xmi:id="a_set_{k}" base_Interface="set_{k}"' + (f' rtMsgKind="{v}"' if v else "") + '/>\n'
             for k, v in sets.items()]
    ports: dict[str, bool] = {}
    n = draw(st.integers(min_value=2, max_value=3))
    for c in range(n):
        conj = draw(st.booleans())
        ports[f"c{c}_p"] = conj
        body += (f'    <packagedElement xmi:type="uml:Class" xmi:id="c{c}" name="Capsule{c}" isActive="true">\n'
                 f'      <ownedAttribute xmi:type="uml:Port" xmi:id="c{c}_p" name="p" type="proto" aggregation="composite"'
                 + (' isConjugated="true"' if conj else "") + '/>\n    </packagedElement>\n')
        apps.append(f'  <UMLRealTime:Capsule xmi:id="a_c{c}" base_Class="c{c}"/>\n')
    connectors = "".join(_connector(f"k{c}", (f"top_q{c}", f"c{c}_p"), (f"top_q{c + 1}", f"c{c + 1}_p"))
                         for c in range(n - 1) if ports[f"c{c}_p"] != ports[f"c{c + 1}_p"] or draw(st.booleans()))
    body += _class("top", "Top", [], [(f"q{c}", f"c{c}") for c in range(n)], connectors, composite=True)
    apps.append('  <UMLRealTime:Capsule xmi:id="a_top" base_Class="top"/>\n')
    return _xmi(body, "".join(apps), ' xmlns:UMLRealTime="http://www.eclipse.org/papyrus/umlrt"'), ports, messages


@settings(max_examples=EXAMPLES, derandomize=not RANDOM, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(umlrt_systems())
def test_random_umlrt_systems_receive_the_in_set_and_send_the_out_set(system) -> None:
    """Whatever UML-RT system is drawn: robomda never ends INTERNAL; when it binds, a port receives the
    messages of the set its protocol realizes (rtMsgKind in, absent or written) and sends those of the set it
    uses, swapped when conjugated; every message connection is a queue from a sender to a receiver."""
    text, ports, messages = system
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "random.uml"
        model.write_text(text, encoding="utf-8")
        result = check(model)
        assert result.exit_code in (0, 1) and not [d for d in result.diagnostics if d.code == "INTERNAL"]
        try:
            pim = _pim(model)
        except RobomdaError as caught:
            assert {d.code for d in caught.diagnostics if d.severity == "error"} <= {"BND007", "BND008"}, \
                [d.format() for d in caught.diagnostics]
            return
    for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS):
        received = messages[d.get("datum")] == "in"
        if ports[d.get("port")]:
            received = not received
        assert d.get("direction") == ("in" if received else "out"), (d.get("port"), d.get("datum"))
    for connection in pim.xpath("//p:binding/p:connection", namespaces=NS):
        assert connection.find("p:policy", NS).get("type") == "BUFFER"


def test_papyrus_designer_flow_ports_give_the_direction_and_absent_means_inout(tmp_path: Path) -> None:
    """Papyrus Designer: classes with ports used as parts are components (the rule for any tool); GCM's
    «FlowPort» direction gives a port typed by its datum its direction, absent meaning inout."""
    body = (DATA + _class("p", "Producer", [("q", "d")]) + _class("c", "Consumer", [("q", "d")])
            + _class("mo", "Monitor", [("q", "d")])
            + _class("sys", "System", [], [("prod", "p"), ("con", "c"), ("mon", "mo")],
                     _connector("k1", ("sys_prod", "p_q"), ("sys_con", "c_q"))
                     + _connector("k2", ("sys_prod", "p_q"), ("sys_mon", "mo_q")), composite=True))
    apps = ('  <GCM:FlowPort xmi:id="g1" base_Port="p_q" direction="out"/>\n'
            '  <GCM:FlowPort xmi:id="g2" base_Port="c_q" direction="in"/>\n'
            '  <GCM:FlowPort xmi:id="g3" base_Port="mo_q"/>\n')
    model = tmp_path / "designer.uml"
    model.write_text(_xmi(body, apps, ' xmlns:GCM="http://www.eclipse.org/papyrus/GCM/1"'), encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    data = sorted((d.getparent().get("name"), d.get("name"), d.get("direction"))
                  for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS))
    assert data == [("Consumer", "q", "in"), ("Monitor", "q_in", "in"), ("Monitor", "q_out", "out"),
                    ("Producer", "q", "out")]
    assert [d.xmi_id for d in found if d.code == "BND029"] == ["mo_q"]


def test_the_top_capsule_the_model_names_is_the_system(tmp_path: Path) -> None:
    """Papyrus-RT: the model's UMLRT_Default_top annotation names the top capsule; another capsule whose
    parts would be instances too (a test harness drawn beside it) is not the system."""
    body = (DATA + _class("s", "Sensor", [("v", "d")])
            + _class("top", "Top", [], [("sensor", "s")], composite=True)
            + _class("bench", "Bench", [], [("probe", "s")], composite=True))
    annotation = ('    <eAnnotations xmi:type="ecore:EAnnotation" xmi:id="ann" source="UMLRT_Default_top">\n'
                  '      <details xmi:type="ecore:EStringToStringMapEntry" xmi:id="ann_d" key="top_name" value="Top"/>\n'
                  '    </eAnnotations>\n')
    apps = "".join(f'  <UMLRealTime:Capsule xmi:id="a_{c}" base_Class="{c}"/>\n' for c in ("s", "top", "bench"))
    text = _xmi(annotation + body, apps, ' xmlns:UMLRealTime="http://www.eclipse.org/papyrus/umlrt"'
                ' xmlns:ecore="http://www.eclipse.org/emf/2002/Ecore"')
    model = tmp_path / "tops.uml"
    model.write_text(text, encoding="utf-8")
    pim = _pim(model)
    assert pim.xpath("//p:application/@top", namespaces=NS) == ["Top"]
    assert [i.get("name") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)] == ["sensor"]
    # without the annotation, both composites are systems
    model.write_text(text.replace(annotation, ""), encoding="utf-8")
    assert sorted(i.get("name") for i in _pim(model).xpath("//p:binding/p:instance", namespaces=NS)) == ["probe", "sensor"]


# ------------------------------------------------------------- Papyrus for Robotics' ROS 2 library (item 3)
P4RLIB = ROOT / "fixtures" / "ros" / "p4rlib"


def test_p4r_ports_typed_by_its_ros2_library_carry_the_library_messages(tmp_path: Path) -> None:
    found: list[Diagnostic] = []
    pim = _pim(P4RLIB / "model.xmi", found)
    # no library reference is lost: each service the ports name is stood in, once, in a package
    # named after its ROS package, binding the pattern its prefix names to the library's message
    services = {i.get("id"): (i.getparent().get("name"), i.get("name"), i.get("pattern"),
                              [(a.get("type-name"), a.get("type-library")) for a in i.findall("p:attribute", NS)])
                for i in pim.xpath("//p:interface", namespaces=NS)}
    assert services == {
        "robomda.lib.std_msgs.P_String": ("std_msgs", "P_String", "Push", [("std_msgs/String", "ros-message")]),
        "robomda.lib.std_msgs.S_Int32": ("std_msgs", "S_Int32", "Send", [("std_msgs/Int32", "ros-message")]),
        "robomda.lib.std_srvs.Q_Trigger": ("std_srvs", "Q_Trigger", "Query", []),
        # the model's own service, whose data type has a field of a library message
        "_p4rlib_p_lab": ("services", "P_Labelled", "Push", [("Labelled", "local")])}
    fields = {a.get("name"): (a.get("type-name"), a.get("type-library"), a.get("primitive"))
              for a in pim.xpath("//p:datatype[@name='Labelled']/p:attribute", namespaces=NS)}
    assert fields == {"label": ("std_msgs/String", "ros-message", None), "score": (fields["score"][0], "ros-primitive",
                                                                                    "float64")}
    assert not [d for d in found if d.code in ("IMP112", "BND034")], [d.format() for d in found]
    # the Query is left out, said where it is drawn; the rest flows as the patterns mean
    [query] = [d for d in found if d.code == "BND004"]
    assert query.xmi_id == "_p4rlib_rly_reset" and query.line and "a Query" in query.message
    data = {(d.getparent().get("name"), d.get("name")): (d.get("direction"), d.get("type-name"))
            for d in pim.xpath("//p:binding/p:bound-component/p:data-port", namespaces=NS)}
    assert data == {("Talker", "chatter"): ("out", "std_msgs/String"), ("Relay", "chatter"): ("in", "std_msgs/String"),
                    ("Relay", "count"): ("out", "std_msgs/Int32"), ("Counter", "count"): ("in", "std_msgs/Int32"),
                    ("Relay", "labelled"): ("out", "Labelled"), ("Counter", "labelled"): ("in", "Labelled")}
    # the library's primitive ids are primitives: the parameter typed by its float64 is a float64
    [rate] = pim.xpath("//p:component[@name='Talker']/p:attribute[@name='rate']", namespaces=NS)
    assert (rate.get("primitive"), rate.get("type-library")) == ("float64", "ros-primitive")


@pytest.mark.parametrize("target, cpp", [("ros2", "std_msgs::msg::String"), ("ros1", "std_msgs::String")])
def test_the_ros_targets_carry_a_library_message_as_it_is(target: str, cpp: str, tmp_path: Path) -> None:
    generate(P4RLIB / "model.xmi", tmp_path / target, target, write=True)
    talker = (tmp_path / target / "src" / "Talker.cpp").read_text(encoding="utf-8")
    assert f"create_publisher<{cpp}>" in talker or f"advertise<{cpp}>" in talker
    # the user's base class declares its accessors with the message, so it includes its header
    base = (tmp_path / target / "include" / "p4rlib" / "TalkerBase.hpp").read_text(encoding="utf-8")
    header = "std_msgs/msg/string.hpp" if target == "ros2" else "std_msgs/String.h"
    assert f"#include <{header}>" in base and f"virtual {cpp} getString() const = 0;" in base
    assert "<depend>std_msgs</depend>" in (tmp_path / target / "package.xml").read_text(encoding="utf-8")
    # a field of a library message: its header in the data type's, its type in the generated message,
    # copied as it is, and the messages generated with that package as their dependency
    header = "std_msgs/msg/string.hpp" if target == "ros2" else "std_msgs/String.h"
    assert f"#include <{header}>" in (tmp_path / target / "include" / "Labelled.hpp").read_text(encoding="utf-8")
    assert "std_msgs/String label\n" in (tmp_path / target / "msg" / "Labelled.msg").read_text(encoding="utf-8")
    cmake = (tmp_path / target / "CMakeLists.txt").read_text(encoding="utf-8")
    assert ("DEPENDENCIES std_msgs)" in cmake) and "m.label = v.label;" in (
        tmp_path / target / "include" / "p4rlib" / "msg_conversions.hpp").read_text(encoding="utf-8")


def test_orocos_and_openrtm_name_a_library_message_they_cannot_carry(tmp_path: Path) -> None:
    with pytest.raises(RobomdaError) as failed:
        generate(P4RLIB / "model.xmi", tmp_path / "orocos", "orocos", write=True)
    errors = [d for d in failed.value.diagnostics if d.severity == "error"]
    assert errors and all(d.code == "ORO001" and d.line and "message of the ROS library" in d.message for d in errors)
    assert not (tmp_path / "orocos").exists()
    with pytest.raises(RobomdaError) as failed:
        generate(P4RLIB / "model.xmi", tmp_path / "openrtm", "openrtm", write=True)
    said = failed.value.diagnostics
    # a port carrying one is left out (RTM001), a data type's field of one has no IDL type (RTM021)
    assert {d.xmi_id for d in said if d.code == "RTM001" and "message of the ROS library" in d.message} >= \
        {"_p4rlib_tlk_chatter", "_p4rlib_rly_count"}
    assert [d.xmi_id for d in said if d.code == "RTM021" and "message of the ROS library" in d.message] == \
        ["_p4rlib_lab_label"]
    assert not (tmp_path / "openrtm").exists()


# ------------------------------------------------------------- SysML «Allocate» as deployment (item 2)
def _allocated(tmp_path: Path, allocations: str, hardware: str) -> Path:
    text = (SYSML / "model.xmi").read_text(encoding="utf-8")
    text = text.replace(' xmlns:robomda=', ' xmlns:Allocations="http://www.eclipse.org/papyrus/sysml/1.6/SysML/Allocations"'
                                           ' xmlns:robomda=')
    applied = "".join(f'  <Allocations:Allocate xmi:id="{a}_s" base_Abstraction="{a}"/>\n'
                      for a in ("_al1", "_al2"))
    text = text.replace("  </uml:Model>\n", hardware + allocations + "  </uml:Model>\n" + applied)
    model = tmp_path / "allocated.uml"
    model.write_text(text, encoding="utf-8")
    return model


def test_a_sysml_allocation_to_a_node_deploys_the_part_there(tmp_path: Path) -> None:
    model = _allocated(tmp_path,
                       '    <packagedElement xmi:type="uml:Abstraction" xmi:id="_al1" client="_sy_plant_ctrl" supplier="_n1"/>\n'
                       '    <packagedElement xmi:type="uml:Abstraction" xmi:id="_al2" client="_sy_plant_pump _sy_plant_sensor"'
                       ' supplier="_n2"/>\n',
                       '    <packagedElement xmi:type="uml:Node" xmi:id="_n1" name="Onboard"/>\n'
                       '    <packagedElement xmi:type="uml:Node" xmi:id="_n2" name="Ground"/>\n')
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    # read, so neither "not imported" nor a stereotype left out
    assert not [d for d in found if d.code in ("IMP111", "IMP115", "IMP124")], [d.format() for d in found]
    hosts = {i.get("name"): i.get("host") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)}
    assert hosts == {"controller": "_n1", "pump": "_n2", "sensor": "_n2"}


def test_a_sysml_allocation_to_what_is_no_node_is_said(tmp_path: Path) -> None:
    model = _allocated(tmp_path,
                       '    <packagedElement xmi:type="uml:Abstraction" xmi:id="_al1" client="_sy_plant_ctrl" supplier="_hw"/>\n'
                       '    <packagedElement xmi:type="uml:Abstraction" xmi:id="_al2" client="_sy_sensor" supplier="_hw"/>\n',
                       '    <packagedElement xmi:type="uml:Class" xmi:id="_hw" name="OnboardComputer"/>\n')
    found: list[Diagnostic] = []
    _pim(model, found)
    # said once per element allocated to, naming what is allocated (a SysML model tracing its blocks
    # to requirements allocates dozens)
    [said] = [d for d in found if d.code == "IMP124"]
    assert said.xmi_id == "_al1" and said.line
    assert "2 allocations («Allocate») of 'controller', 'Sensor' to Class 'OnboardComputer', which is no Node" \
        in said.message
    assert not [d for d in found if d.code in ("IMP111", "IMP115")], [d.format() for d in found]


# ------------------------------------------------------------- a capsule's own behaviour (UML-RT)
def test_a_capsule_whose_behaviour_talks_to_its_part_is_named_not_taken_for_a_delegation(tmp_path: Path) -> None:
    text = (UMLRT / "model.xmi").read_text(encoding="utf-8")
    # Top's own state machine talks to its sensor through an internal behaviour port
    text = text.replace(
        '      <ownedConnector xmi:type="uml:Connector" xmi:id="_rt_conn" name="RTConnector1">',
        '      <ownedAttribute xmi:type="uml:Port" xmi:id="_rt_topc_own" name="own" type="_rt_proto" visibility="protected"'
        ' aggregation="composite" isBehavior="true" isService="false"/>\n'
        '      <ownedConnector xmi:type="uml:Connector" xmi:id="_rt_own" name="RTConnector2">\n'
        '        <end xmi:type="uml:ConnectorEnd" xmi:id="_rt_own_a" role="_rt_topc_own"/>\n'
        '        <end xmi:type="uml:ConnectorEnd" xmi:id="_rt_own_b" partWithPort="_rt_topc_sensor" role="_rt_sensor_data"/>\n'
        '      </ownedConnector>\n'
        '      <ownedConnector xmi:type="uml:Connector" xmi:id="_rt_conn" name="RTConnector1">')
    model = tmp_path / "behaviour.uml"
    model.write_text(text, encoding="utf-8")
    with pytest.raises(RobomdaError) as failed:
        _pim(model)
    [said] = [d for d in failed.value.diagnostics if d.severity == "error"]
    assert said.code == "BND035" and said.xmi_id == "_rt_own" and said.line
    assert "behaviour port 'own' of 'Top'" in said.message and "part 'sensor'" in said.message


# ------------------------------------------------------------- Papyrus Designer deployment plans (item 2)
def _designer_plans(plans: list[tuple[str, str]]) -> str:
    """A Producer / Consumer system, two Nodes and a deployment plan per (plan, node): its main
    instance of the system allocated («Allocate» of Papyrus Designer's Alloc profile) to an instance
    of the node."""
    body = (DATA + _class("p", "Producer", [("q", "d")]) + _class("c", "Consumer", [("q", "d")])
            + _class("sys", "System", [], [("prod", "p"), ("con", "c")],
                     _connector("k1", ("sys_prod", "p_q"), ("sys_con", "c_q")), composite=True)
            + '    <packagedElement xmi:type="uml:Node" xmi:id="linux" name="Linux"/>\n'
            '    <packagedElement xmi:type="uml:Node" xmi:id="board" name="Board"/>\n')
    apps = ('  <GCM:FlowPort xmi:id="g1" base_Port="p_q" direction="out"/>\n'
            '  <GCM:FlowPort xmi:id="g2" base_Port="c_q" direction="in"/>\n')
    for plan, node in plans:
        body += (f'    <packagedElement xmi:type="uml:Package" xmi:id="{plan}" name="{plan}">\n'
                 f'      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="{plan}_main" name="mainInstance"'
                 f' classifier="sys"/>\n'
                 f'      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="{plan}_node" name="{node}"'
                 f' classifier="{node}"/>\n'
                 f'      <packagedElement xmi:type="uml:Abstraction" xmi:id="{plan}_a" name="allocate to {node}"'
                 f' client="{plan}_main" supplier="{plan}_node"/>\n'
                 '    </packagedElement>\n')
        apps += (f'  <Deployment:DeploymentPlan xmi:id="{plan}_s" base_Package="{plan}" mainInstance="{plan}_main"/>\n'
                 f'  <Alloc:Allocate xmi:id="{plan}_as" base_Abstraction="{plan}_a"/>\n')
    return _xmi(body, apps, ' xmlns:GCM="http://www.eclipse.org/papyrus/GCM/1"'
                ' xmlns:Alloc="http://www.eclipse.org/papyrus/Alloc/1"'
                ' xmlns:Deployment="http://www.eclipse.org/papyrus/Deployment/1"')


def test_a_papyrus_designer_deployment_plan_puts_the_system_on_its_node(tmp_path: Path) -> None:
    model = tmp_path / "plan.uml"
    model.write_text(_designer_plans([("onboard", "board")]), encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    assert not [d for d in found if d.code in ("IMP111", "IMP115", "IMP124", "IMP125")], [d.format() for d in found]
    hosts = {i.get("name"): i.get("host") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)}
    assert hosts == {"prod": "board", "con": "board"}


def test_rival_papyrus_designer_plans_are_said_and_none_is_read(tmp_path: Path) -> None:
    model = tmp_path / "plans.uml"
    model.write_text(_designer_plans([("onboard", "board"), ("desktop", "linux")]), encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    [said] = [d for d in found if d.code == "IMP125"]
    assert said.line and "2 deployment plans ('onboard', 'desktop')" in said.message
    assert not [d for d in found if d.code in ("IMP111", "IMP115")], [d.format() for d in found]
    # neither plan's node: the instances run where the model's other deployments put them
    assert not {i.get("host") for i in pim.xpath("//p:binding/p:instance", namespaces=NS)} & {"board", "linux"}


def test_the_robotml_platform_library_primitives_are_primitives_and_its_types_are_named(tmp_path: Path) -> None:
    """RobotML's platform library is not shipped with models; its primitives are read by their ids
    (Float64, Bool ...: ports typed by them generate), its data types named in BND034."""
    lib = "pathmap://Robotml_LIBRARIES/RobotMLPlatformLibraries.uml#"
    port = ('      <ownedAttribute xmi:type="uml:Port" xmi:id="{}" name="{}" aggregation="composite">'
            '<type xmi:type="uml:{}" href="{}"/></ownedAttribute>\n')
    body = ('    <packagedElement xmi:type="uml:Class" xmi:id="a" name="Sick">\n'
            + port.format("a_on", "on", "PrimitiveType", lib + "_NZnTsAIUEeCVrLEBH5ejnQ")
            + port.format("a_scan", "scan", "DataType", lib + "_zdwdIAKsEeCQReIOIWJ0nA")
            + '    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Class" xmi:id="b" name="Planner">\n'
            + port.format("b_on", "on", "PrimitiveType", lib + "_NZnTsAIUEeCVrLEBH5ejnQ")
            + '    </packagedElement>\n'
            + _class("sys", "Robot", [], [("sick", "a"), ("planner", "b")],
                     _connector("c1", ("sys_sick", "a_on"), ("sys_planner", "b_on"))))
    apps = ('  <RobotML:SensorSystem xmi:id="s1" base_Class="a"/>\n  <RobotML:Software xmi:id="s2" base_Class="b"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s3" base_Port="a_on" direction="out"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s4" base_Port="a_scan" direction="out"/>\n'
            '  <RobotML:DataFlowPort xmi:id="s5" base_Port="b_on"/>\n')
    model = tmp_path / "library.uml"
    model.write_text(_xmi(body, apps, ROBOTML_NS), encoding="utf-8")
    found: list[Diagnostic] = []
    pim = _pim(model, found)
    [on] = pim.xpath("//p:component[@name='Sick']/p:port[@name='on']", namespaces=NS)
    assert (on.get("type-name"), on.get("type-library"), on.get("primitive")) == ("Bool", "robotml", "boolean")
    flows = [(c.find("p:writer", NS).get("instance"), c.find("p:reader", NS).get("instance"))
             for c in pim.xpath("//p:binding/p:connection", namespaces=NS)]
    assert flows == [("sick", "planner")]
    [once] = [d for d in found if d.code == "BND034"]
    assert once.xmi_id == "a_scan" and "'scan' of Sick: LaserScan" in once.message


def test_classes_a_profile_makes_components_with_lollipops_get_named_ports(tmp_path: Path) -> None:
    """A class its profile makes a component (RobotML) with no port that provides or requires an
    interface gets a port per interface, named after it (it once got a port with no name)."""
    body = ('    <packagedElement xmi:type="uml:Interface" xmi:id="i" name="IReading">\n'
            f'      <ownedAttribute xmi:type="uml:Property" xmi:id="i_v" name="value"><type xmi:type="uml:PrimitiveType" '
            f'href="{PRIM}Real"/></ownedAttribute>\n    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Class" xmi:id="a" name="Sensor">\n'
            '      <interfaceRealization xmi:type="uml:InterfaceRealization" xmi:id="a_r" client="a" supplier="i"'
            ' contract="i"/>\n    </packagedElement>\n'
            '    <packagedElement xmi:type="uml:Class" xmi:id="b" name="Logger"/>\n'
            '    <packagedElement xmi:type="uml:Usage" xmi:id="b_u" client="b" supplier="i"/>\n')
    apps = '  <RobotML:SensorSystem xmi:id="s1" base_Class="a"/>\n  <RobotML:Software xmi:id="s2" base_Class="b"/>\n'
    model = tmp_path / "lollipops.uml"
    model.write_text(_xmi(body, apps, ROBOTML_NS), encoding="utf-8")
    pim = _pim(model)
    ports = {(p.getparent().get("name"), p.get("name"), p.get("qualified-name"))
             for p in pim.xpath("//p:component/p:port[@implicit='true']", namespaces=NS)}
    assert ports == {("Sensor", "IReading", "shapes::Sensor::IReading"), ("Logger", "IReading", "shapes::Logger::IReading")}
    flows = [(c.find("p:writer", NS).get("data-port"), c.find("p:reader", NS).get("data-port"))
             for c in pim.xpath("//p:binding/p:connection", namespaces=NS)]
    assert flows == [("IReading", "IReading")]


def test_a_papyrus_for_robotics_model_deployed_on_nothing_is_a_ros2_model(tmp_path: Path) -> None:
    """Its tool runs its components as managed (lifecycle) nodes, which only ROS 2 has: without
    --target, check and generate take ROS 2 (a model of plain UML deployed on nothing stays Orocos's)."""
    from robomda.api import default_targets

    assert default_targets(P4R / "model.xmi") == ["ros2"]
    assert check(P4R / "model.xmi").targets == ["ros2"]
    assert generate(P4R / "model.xmi", tmp_path / "out").target == "ros2"
    assert default_targets(SYSML / "model.xmi") == ["orocos"]
