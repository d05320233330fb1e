"""Structured robot data (issue 14): data types, enumerations, arrays and inheritance.

The quad-arm fixture (fixtures/cases/quadarm, seed 001) is edited one
defect or one variation at a time; its goldens (tests/test_golden.py), its
broken variants (fixtures/broken, tests/test_broken.py) and its deployment on
RTT 2.10 (tests/test_orocos_deploy.py) are elsewhere. Here: what the Orocos
PSM and text make of each kind of type, and each diagnostic.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from lxml import etree

from edits import edit
from robomda.api import generate
from robomda.diagnostics import RobomdaError

ROOT = Path(__file__).resolve().parents[1]
QUADARM = ROOT / "fixtures" / "cases" / "quadarm"
O = "{urn:robomda:psm-orocos:1}"
FS = "{urn:robomda:fileset:1}"
REAL = 'href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Real"'


@pytest.fixture
def model(tmp_path: Path) -> Path:
    """A copy of the quad-arm model, with its atomic code, to edit."""
    shutil.copytree(QUADARM, tmp_path / "quadarm", ignore=shutil.ignore_patterns("expected"))
    return tmp_path / "quadarm" / "model.xmi"


def _psm(model: Path) -> etree._Element:
    return etree.fromstring(generate(model, None, "orocos", write=False).stages["psm"].encode("utf-8"))


def _files(model: Path) -> dict[str, str]:
    text = generate(model, None, "orocos", write=False).stages["text"]
    return {n.get("path"): n.text or "" for n in etree.fromstring(text.encode("utf-8")).iter(f"{FS}file")}


def _error(model: Path) -> RobomdaError:
    with pytest.raises(RobomdaError) as info:
        generate(model, None, "orocos", write=False)
    return info.value


def _attribute(model: Path, name: str, type_xml: str, extra: str = "") -> None:
    """Give the controller class one more protected attribute (a property)."""
    edit(model, '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa061a" name="gains"',
         f'<ownedAttribute xmi:type="uml:Property" xmi:id="_t{name}" name="{name}" visibility="protected">'
         f'{type_xml}{extra}</ownedAttribute>\n      '
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa061a" name="gains"')


def _multiplicity(lower: str, upper: str) -> str:
    return (f'<lowerValue xmi:type="uml:LiteralInteger" xmi:id="_tl" value="{lower}"/>'
            f'<upperValue xmi:type="uml:LiteralUnlimitedNatural" xmi:id="_tu" value="{upper}"/>')


def test_the_typekit_registers_every_type_the_components_use() -> None:
    files = _files(QUADARM / "model.xmi")
    typekit = files["src/typekit.cpp"]
    for line in ('types->addType(new ControlModeTypeInfo());',
                 'types->addType(new RTT::types::StructTypeInfo<::quadarm::types::JointState>("/quadarm/JointState"));',
                 'archive & make_nvp("position", value.position);',  # inherited from JointAngles
                 'to_string[::quadarm::types::ControlMode::IMPEDANCE] = "IMPEDANCE";'):
        assert line in typekit
    # JointAngles is only a general of JointState: no port or property uses it
    assert "JointAngles" not in typekit and "include/JointAngles.hpp" not in files
    assert "std::vector<double> position = std::vector<double>(7, 0.0);" in files["include/JointState.hpp"]
    assert "orocos_typekit(quadarm-typekit src/typekit.cpp)" in files["CMakeLists.txt"]
    for deploy in ("deploy/quadarm.xml", "deploy/quadarm.ops", "deploy/quadarm.lua"):
        libraries = list(dict.fromkeys(re.findall(r"quadarm/quadarm[-a-z]*", files[deploy])))
        assert libraries[:2] == ["quadarm/quadarm-typekit", "quadarm/quadarm"], deploy


def test_sixteen_and_eight_bit_integers_are_carried_as_rtt_ints(model: Path) -> None:
    """RTT 2.10 knows no short or unsigned char: int16 / octet as int / unsigned int, XML long / ulong."""
    _attribute(model, "count", '<type xmi:type="uml:PrimitiveType" '
               'href="pathmap://XML_TYPES/XMLPrimitiveTypes.library.uml#short"/>',
               '<defaultValue xmi:type="uml:LiteralInteger" xmi:id="_tv" value="-3"/>')
    _attribute(model, "code", '<type xmi:type="uml:PrimitiveType" '
               'href="pathmap://XML_TYPES/XMLPrimitiveTypes.library.uml#unsignedByte"/>')
    props = {p.get("name"): p for p in _psm(model).iter(f"{O}property")}
    assert (props["count"].get("cpp-type"), props["count"].get("xml-type")) == ("int", "long")
    assert (props["code"].get("cpp-type"), props["code"].get("xml-type")) == ("unsigned int", "ulong")
    assert 'type="short"' not in _files(model)["deploy/quadarm.xml"]


def test_an_integer_default_outside_its_model_type_is_an_error(model: Path) -> None:
    _attribute(model, "count", '<type xmi:type="uml:PrimitiveType" '
               'href="pathmap://XML_TYPES/XMLPrimitiveTypes.library.uml#short"/>',
               '<defaultValue xmi:type="uml:LiteralInteger" xmi:id="_tv" value="40000"/>')
    error = _error(model)
    assert "ORO002" in str(error) and "-32768 to 32767" in str(error)


@pytest.mark.parametrize(("lower", "upper", "cpp", "sample"), [
    ("3", "3", "std::vector<double>", "std::vector<double>(3, 0.0)"),
    ("0", "3", "std::vector<double>", "std::vector<double>()"),
    ("0", "*", "std::vector<double>", "std::vector<double>()"),
])
def test_every_multiplicity_is_a_vector(model: Path, lower: str, upper: str, cpp: str, sample: str) -> None:
    _attribute(model, "limits", f'<type xmi:type="uml:PrimitiveType" {REAL}/>', _multiplicity(lower, upper))
    limits = next(p for p in _psm(model).iter(f"{O}property") if p.get("name") == "limits")
    assert (limits.get("cpp-type"), limits.get("xml-type"), limits.get("cpp-default")) == (cpp, "array", sample)


def test_an_array_of_booleans_is_never_left_out_silently(model: Path) -> None:
    """A convention-selected attribute RTT cannot carry is no property, with a located warning (ORO013)."""
    _attribute(model, "enabled", '<type xmi:type="uml:PrimitiveType" '
               'href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Boolean"/>', _multiplicity("7", "7"))
    done = generate(model, None, "orocos", write=False)
    said = [str(w) for w in done.warnings if "ORO013" in str(w)]
    assert len(said) == 1 and "'enabled'" in said[0] and "Boolean[7]" in said[0], said
    assert "enabled" not in [p.get("name") for p in _psm(model).iter(f"{O}property")]


def test_an_operation_parameter_of_booleans_is_an_error(model: Path) -> None:
    """An operation the component offers must carry every parameter: refused by name (ORO001)."""
    edit(model, '<ownedOperation xmi:type="uml:Operation" xmi:id="_qa084o" name="maxTracking"',
         '<ownedOperation xmi:type="uml:Operation" xmi:id="_tmask" name="setMask" visibility="protected">'
         '<ownedParameter xmi:type="uml:Parameter" xmi:id="_tmaskp" name="enabled">'
         '<type xmi:type="uml:PrimitiveType" href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Boolean"/>'
         + _multiplicity("7", "7") + '</ownedParameter></ownedOperation>\n      '
         '<ownedOperation xmi:type="uml:Operation" xmi:id="_qa084o" name="maxTracking"')
    error = _error(model)
    assert "ORO001" in str(error) and "'enabled'" in str(error) and "Boolean[7]" in str(error)


def test_a_data_type_that_contains_itself_is_an_error(model: Path) -> None:
    edit(model, '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa035a" name="damping"',
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_tself" name="inner" visibility="public">'
         '<type xmi:type="uml:DataType" xmi:idref="_qa005t"/></ownedAttribute>\n      '
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa035a" name="damping"')
    error = _error(model)
    assert "ORO012" in str(error) and "Gains > Gains" in str(error)


def test_an_array_property_of_a_data_type_that_contains_itself_is_an_error(model: Path) -> None:
    """An array of such a type: ORO012 as well, not an endless value tree."""
    edit(model, '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa035a" name="damping"',
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_tself" name="inner" visibility="public">'
         '<type xmi:type="uml:DataType" xmi:idref="_qa005t"/>' + _multiplicity("2", "2") + '</ownedAttribute>\n      '
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa035a" name="damping"')
    edit(model, '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa061a" name="gains" visibility="protected">',
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa061a" name="gains" visibility="protected">'
         '<lowerValue xmi:type="uml:LiteralInteger" xmi:id="_tl2" value="2"/>'
         '<upperValue xmi:type="uml:LiteralUnlimitedNatural" xmi:id="_tu2" value="2"/>')
    error = _error(model)
    assert "ORO012" in str(error) and "Gains > Gains" in str(error)


def test_a_data_type_property_takes_no_default_of_its_own(model: Path) -> None:
    edit(model, '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa061a" name="gains" visibility="protected">',
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa061a" name="gains" visibility="protected">'
         '<defaultValue xmi:type="uml:OpaqueExpression" xmi:id="_tgv"><body>{1, 2, 3}</body></defaultValue>')
    error = _error(model)
    assert "ORO002" in str(error) and "the data type's attributes give its value" in str(error)


def test_a_realizing_class_inherits_its_generals_attributes(model: Path) -> None:
    """Generalization of realizing classes: a base class's attribute is a property of the component."""
    edit(model, '<packagedElement xmi:type="uml:Class" xmi:id="_qa006c" name="LwrArm">',
         '<packagedElement xmi:type="uml:Class" xmi:id="_tbase" name="ArmBase">'
         f'<ownedAttribute xmi:type="uml:Property" xmi:id="_tba" name="payload" visibility="protected">'
         f'<type xmi:type="uml:PrimitiveType" {REAL}/>'
         '<defaultValue xmi:type="uml:LiteralReal" xmi:id="_tbv" value="1.5"/></ownedAttribute></packagedElement>\n    '
         '<packagedElement xmi:type="uml:Class" xmi:id="_qa006c" name="LwrArm">'
         '<generalization xmi:type="uml:Generalization" xmi:id="_tgen" general="_tbase"/>')
    arm = next(t for t in _psm(model).iter(f"{O}task-context") if t.get("name") == "ArmInterface")
    assert [p.get("name") for p in arm.iter(f"{O}property")] == ["payload", "mode", "inertia"]
    assert "arm1.payload = 1.5" in _files(model)["deploy/quadarm.ops"]


# ------------------------------------------------------------------- ROS
def _ros_files(model: Path, target: str) -> dict[str, str]:
    text = generate(model, None, target, write=False).stages["text"]
    return {n.get("path"): n.text or "" for n in etree.fromstring(text.encode("utf-8")).iter(f"{FS}file")}


def _body(text: str) -> list[str]:
    """The lines of a generated file below its banner."""
    return [line for line in text.splitlines() if not line.startswith(("#", "//"))]


@pytest.mark.parametrize("target", ["ros1", "ros2"])
def test_ros_messages_carry_nested_types_arrays_and_enumerations(target: str) -> None:
    files = _ros_files(QUADARM / "model.xmi", target)
    assert _body(files["msg/JointState.msg"]) == [
        "float64[7] position", "float64[7] velocity", "float64[7] effort", "ControlMode mode"]
    assert _body(files["msg/JointTorques.msg"]) == ["float64[7] torque", "Gains gains"]
    assert _body(files["msg/ControlMode.msg"]) == [
        "int32 POSITION=0", "int32 IMPEDANCE=1", "int32 TORQUE=2", "int32 value"]
    assert _body(files["msg/Gains.msg"]) == ["float64 stiffness", "float64 damping", "float64 max_torque"]
    conversions = files["include/quadarm/msg_conversions.hpp"]
    assert "m.max_torque = v.maxTorque;" in conversions and "from_msg(m.mode, v.mode);" in conversions
    assert "v = static_cast<::quadarm::types::ControlMode>(m.value);" in conversions


def test_the_data_type_headers_are_the_same_on_every_target() -> None:
    """include/<Type>.hpp is written once for all targets (m2t/common/data-types.xsl)."""
    orocos = _files(QUADARM / "model.xmi")
    for target in ("ros1", "ros2"):
        ros = _ros_files(QUADARM / "model.xmi", target)
        for header in ("ControlMode.hpp", "Gains.hpp", "JointState.hpp", "JointTorques.hpp"):
            assert ros["include/" + header] == orocos["include/" + header], (target, header)


def test_ros_parameters_of_data_types_enumerations_and_arrays() -> None:
    files = _ros_files(QUADARM / "model.xmi", "ros2")
    params = "".join(text for path, text in sorted(files.items()) if path.startswith("config/") and path.endswith(".yaml"))
    assert "    gains:\n      stiffness: 300.0\n      damping: 20.0\n      maxTorque: 80.0\n" in params
    assert '    mode: "IMPEDANCE"\n' in params and "    desired: [0.0, 0.5, 0.0, -1.0, 0.0, 0.5, 0.0]\n" in params
    controller = files["src/JointPositionController.cpp"]
    assert 'declare_parameter<double>("gains.stiffness", 300.0)' in controller
    assert "if (value.size() == 7) {" in controller
    ros1 = _ros_files(QUADARM / "model.xmi", "ros1")
    assert 'private_nh_.param<double>("gains/stiffness", value, 300.0);' in ros1["src/JointPositionController.cpp"]
    assert 'if (value == "TORQUE") {' in ros1["src/ArmInterface.cpp"]


@pytest.mark.parametrize(("target", "field", "warned"), [("ros1", "float64[] limits", True),
                                                          ("ros2", "float64[<=7] limits", False)])
def test_a_bounded_array_field(model: Path, target: str, field: str, warned: bool) -> None:
    """ROS 2 messages bound arrays; ROS 1 ones cannot: unbounded, with a located warning (ROS108)."""
    edit(model, '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa032a" name="torque"',
         f'<ownedAttribute xmi:type="uml:Property" xmi:id="_tlim" name="limits" visibility="public">'
         f'<type xmi:type="uml:PrimitiveType" {REAL}/>{_multiplicity("0", "7")}</ownedAttribute>\n      '
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa032a" name="torque"')
    done = generate(model, None, target, write=False)
    files = {n.get("path"): n.text or "" for n in etree.fromstring(done.stages["text"].encode()).iter(f"{FS}file")}
    assert field in _body(files["msg/JointTorques.msg"])
    said = [str(w) for w in done.warnings if "ROS108" in str(w)]
    assert bool(said) == warned and all("'limits'" in w and "at most 7" in w for w in said), said


def test_a_port_carrying_an_array_of_numbers_is_a_multi_array(model: Path) -> None:
    edit(model, 'xmi:id="_qa088a" name="torques" visibility="public">\n        <type xmi:type="uml:DataType" xmi:idref="_qa004t"/>',
         f'xmi:id="_qa088a" name="torques" visibility="public"><type xmi:type="uml:PrimitiveType" {REAL}/>'
         + _multiplicity("7", "7"))
    # the accessors carry the port's type (else CMP020)
    for key, direction in (("_qa060p", 'name="value"'), ("_qa079p", 'name="return" direction="return"')):
        edit(model, f'xmi:id="{key}" {direction}>\n          <type xmi:type="uml:DataType" xmi:idref="_qa004t"/>',
             f'xmi:id="{key}" {direction}><type xmi:type="uml:PrimitiveType" {REAL}/>'
             + _multiplicity("7", "7").replace('"_tl"', f'"{key}l"').replace('"_tu"', f'"{key}u"'))
    psm = etree.fromstring(generate(model, None, "ros1", write=False).stages["psm"].encode())
    messages = {p.get("name"): p.find("{urn:robomda:psm-ros:1}message") for p in psm.iter("{urn:robomda:psm-ros:1}port")}
    assert messages["torques"].get("msg") == "std_msgs/Float64MultiArray"
    assert messages["torques"].get("cpp-type") == "std::vector<double>"
    # published with its layout: one dimension named after the port, of the sample's size (issue 37)
    publisher = _ros_files(model, "ros1")["src/JointPositionController.cpp"]
    for line in ('msg.layout.dim.resize(1);', 'msg.layout.dim[0].label = "torques";',
                 'msg.layout.dim[0].size = static_cast<unsigned int>(value.size());', 'msg.layout.data_offset = 0;'):
        assert line in publisher, line


def test_a_ros_data_type_that_contains_itself_is_an_error(model: Path) -> None:
    edit(model, '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa035a" name="damping"',
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_tself" name="inner" visibility="public">'
         '<type xmi:type="uml:DataType" xmi:idref="_qa005t"/></ownedAttribute>\n      '
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa035a" name="damping"')
    with pytest.raises(RobomdaError) as info:
        generate(model, None, "ros1", write=False)
    assert "ROS010" in str(info.value) and "Gains > Gains" in str(info.value)


def test_a_driven_device_without_degrees_of_freedom_is_named(model: Path) -> None:
    """A Dependency from a part to a Device says the part drives it; a Device with no dof: BND022, nothing checked."""
    edit(model, '<defaultValue xmi:type="uml:LiteralInteger" xmi:id="_qa212v" value="7"/>', "")
    said = [str(w) for w in generate(model, None, "orocos", write=False).warnings]
    assert [w for w in said if "BND022" in w and "'lwr1'" in w and "arm1" in w], said
    assert not [w for w in said if "BND021" in w], said


def test_a_data_type_ros_cannot_declare_is_named_not_dropped(model: Path) -> None:
    """A data type the atomic code uses (here a private attribute) with a member ROS cannot type: no
    header, and a located warning saying the atomic code must declare it (ROS109), not an error."""
    edit(model, '<packagedElement xmi:type="uml:DataType" xmi:id="_qa005t" name="Gains">',
         '<packagedElement xmi:type="uml:DataType" xmi:id="_tcal" name="Calibration">'
         '<ownedAttribute xmi:type="uml:Property" xmi:id="_tcala" name="arm" visibility="public">'
         '<type xmi:type="uml:Class" xmi:idref="_qa006c"/></ownedAttribute></packagedElement>\n    '
         '<packagedElement xmi:type="uml:DataType" xmi:id="_qa005t" name="Gains">')
    _attribute(model, "calibration", '<type xmi:type="uml:DataType" xmi:idref="_tcal"/>')
    edit(model, 'xmi:id="_tcalibration" name="calibration" visibility="protected"',
         'xmi:id="_tcalibration" name="calibration" visibility="private"')
    done = generate(model, None, "ros1", write=False)
    said = [str(w) for w in done.warnings if "ROS109" in str(w)]
    assert len(said) == 1 and "'Calibration'" in said[0] and "::Calibration" in said[0], said
    files = {n.get("path") for n in etree.fromstring(done.stages["text"].encode()).iter(f"{FS}file")}
    assert "include/Calibration.hpp" not in files and "include/Gains.hpp" in files


# ------------------------------------------------- class against ports (issue 37)
@pytest.mark.parametrize(("type_xml", "label"), [
    ('<type xmi:type="uml:PrimitiveType" ' + REAL + '/>', "'Real'"),
    ('<type xmi:type="uml:PrimitiveType" ' + REAL + '/>' + _multiplicity("0", "*"), "'Real[0..*]'"),
    ('<type xmi:type="uml:DataType" xmi:idref="_qa004t"/>', "'JointTorques'"),
])
def test_an_accessor_typed_otherwise_than_its_port_is_a_located_error(model: Path, type_xml: str, label: str) -> None:
    """CMP020: the arm's getJointState() result against its output port's JointState."""
    from robomda.api import check
    edit(model, 'xmi:id="_qa058p" name="return" direction="return">\n          <type xmi:type="uml:DataType" xmi:idref="_qa003t"/>',
         'xmi:id="_qa058p" name="return" direction="return">' + type_xml)
    found = [d for d in check(model, "orocos").diagnostics if d.code == "CMP020"]
    assert len(found) == 1 and found[0].severity == "error", found
    said = str(found[0])
    assert "getJointState()" in said and f"type {label}" in said and "carries 'JointState'" in said, said
    assert "_qa058p" in said and found[0].line is not None


def test_an_accessor_of_the_ports_type_passes(model: Path) -> None:
    from robomda.api import check
    assert not [d for d in check(model, "orocos").diagnostics if d.code in ("CMP020", "CMP021")]
