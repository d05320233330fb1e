"""The OpenRTM-aist target (pipelines/openrtm.xml, docs/openrtm.md).

Every fixture's RTC.xml files and RtsProfile are valid against the XSDs of
schemas/openrtm/ (written from the published formats), and say what the
model says: ports, configuration, connections, the deployment sequence.
Tests marked ``openrtm_toolchain`` build a generated package on a real
OpenRTM-aist 2.0 (toolchains/openrtm/build.sh), start it with its start
script and a naming service of their own, and check the components reach
Active in the modelled order and the reader of every modelled connection
gets data. Structured configuration values (fixture structured) are the
other targets' values, and the generated reader parses them (g++ alone).
"""

from __future__ import annotations

import os
import re
import select
import shutil
import signal
import socket
import subprocess
import time
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted(p.parent for p in (ROOT / "fixtures" / "cases").glob("*/model.xmi"))
FS = "{urn:robomda:fileset:1}"
RTC = "{http://www.openrtp.org/namespaces/rtc}"
RTS = "{http://www.openrtp.org/namespaces/rts}"
SCHEMAS = ROOT / "schemas" / "openrtm"


def _files(case: Path) -> dict[str, str]:
    done = generate(case / "model.xmi", case / "out", "openrtm", write=False)
    files = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {node.get("path"): node.text or "" for node in files.iter(f"{FS}file")}


@pytest.fixture(scope="module")
def schemas() -> tuple[etree.XMLSchema, etree.XMLSchema]:
    return (etree.XMLSchema(etree.parse(str(SCHEMAS / "rtc-profile.xsd"))),
            etree.XMLSchema(etree.parse(str(SCHEMAS / "rts-profile.xsd"))))


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_profiles_are_valid(case: Path, schemas: tuple[etree.XMLSchema, etree.XMLSchema]) -> None:
    rtc_schema, rts_schema = schemas
    files = _files(case)
    profiles = [p for p in files if p.endswith("/RTC.xml")]
    systems = [p for p in files if p.endswith(".rtsys.xml")]
    assert profiles and len(systems) == 1
    for path in profiles + systems:
        doc = etree.fromstring(files[path].encode("utf-8"))
        schema = rtc_schema if path in profiles else rts_schema
        assert schema.validate(doc), f"{path}: {schema.error_log}"


def test_the_schemas_reject_what_openrtm_would(schemas: tuple[etree.XMLSchema, etree.XMLSchema]) -> None:
    rtc_schema, rts_schema = schemas
    files = _files(ROOT / "fixtures" / "cases" / "headlamp")
    profile = files["rtc/VisionProcessing/RTC.xml"]
    for bad in (profile.replace('rtc:portType="DataInPort"', 'rtc:portType="InPort"', 1),
                re.sub(r"<rtc:OnFinalize [^>]*/>", "", profile),
                profile.replace("rtc:executionRate=", "rtc:rate=")):
        assert bad != profile and not rtc_schema.validate(etree.fromstring(bad.encode("utf-8")))
    system = files["deploy/headlamp.rtsys.xml"]
    # a connector to a port no component has, a Preceding component that is not in the system
    for bad in (system.replace('rts:portName="vision.visionValue"', 'rts:portName="vision.nothing"', 1),
                system.replace('rts:PrecedingComponents rts:componentId="RTC:robomda:headlamp:IndustrialArm:1.0.0" '
                               'rts:instanceName="arm"', 'rts:PrecedingComponents rts:componentId="x" rts:instanceName="nobody"', 1)):
        assert bad != system and not rts_schema.validate(etree.fromstring(bad.encode("utf-8")))


def test_headlamp_says_what_the_model_says() -> None:
    files = _files(ROOT / "fixtures" / "cases" / "headlamp")
    system = etree.fromstring(files["deploy/headlamp.rtsys.xml"].encode("utf-8"))
    # the deployment sequence: arm before controller (StartAfter arm, vision), in both messages
    for message in ("StartUp", "Activation"):
        targets = system.findall(f"{RTS}{message}/{RTS}targets")
        names = [t.find(f"{RTS}TargetComponent").get(f"{RTS}instanceName") for t in targets]
        assert names == ["camera", "forceSensor", "vision", "arm", "controller"]
        preceding = targets[-1].findall(f"{RTS}Preceding/{RTS}PrecedingComponents")
        assert [p.get(f"{RTS}instanceName") for p in preceding] == ["arm", "vision"]
    connectors = {(c.find(f"{RTS}sourceDataPort").get(f"{RTS}portName"), c.find(f"{RTS}targetDataPort").get(f"{RTS}portName"))
                  for c in system.findall(f"{RTS}DataPortConnectors")}
    assert ("camera.visionValue", "vision.visionValue") in connectors and len(connectors) == 6
    rates = {c.get(f"{RTS}instanceName"): c.find(f"{RTS}ExecutionContexts").get(f"{RTS}rate")
             for c in system.findall(f"{RTS}Components")}
    assert rates["camera"] == "333.333333"
    conf = files["deploy/headlamp.rtc.conf"]
    assert "manager.components.preactivation: camera, forceSensor, vision, arm, controller\n" in conf
    assert "camera.visionValue?port=vision.visionValue&dataflow_type=push" in conf
    assert "headlamp.vision.config_file: ../conf/vision.conf\n" in conf
    assert "conf.default.threshold: 100\n" in files["conf/vision.conf"]
    profile = etree.fromstring(files["rtc/VisionProcessing/RTC.xml"].encode("utf-8"))
    ports = [(p.get(f"{RTC}portType"), p.get(f"{RTC}name"), p.get(f"{RTC}type")) for p in profile.findall(f"{RTC}DataPorts")]
    assert ports == [("DataInPort", "visionValue", "RTC::TimedLong"), ("DataOutPort", "channelPosition", "RTC::TimedLong"),
                     ("DataInPort", "toolPose", "RTC::TimedLong")]
    source = files["src/VisionProcessing.cpp"]
    assert "class VisionProcessing : public RTC::DataFlowComponentBase, public ::GumChannelDetector" in \
        files["include/headlamp/VisionProcessing.h"]
    assert 'bindParameter("threshold", ::GumChannelDetector::threshold, "100");' in source
    assert "return ::GumChannelDetector::configure() ? RTC::RTC_OK : RTC::RTC_ERROR;" in source


def test_data_types_are_carried_by_a_generated_idl() -> None:
    files = _files(ROOT / "fixtures" / "cases" / "quadarm")
    idl = files["idl/quadarm_types.idl"]
    # OpenRTM's data-port convention: a time stamp first, then the datum; a fixed array an IDL array,
    # a type referred to by its scoped name (a member "gains" of type Gains would clash in IDL)
    assert '#include "BasicDataType.idl"' in idl
    assert "  struct TimedJointState\n  {\n    RTC::Time tm;\n    ::quadarm::JointState data;\n  };" in idl
    assert "    double position[7];\n" in idl and "    ::quadarm::Gains gains;\n" in idl
    assert "  enum ControlMode { POSITION, IMPEDANCE, TORQUE };" in idl
    profile = etree.fromstring(files["rtc/ArmInterface/RTC.xml"].encode("utf-8"))
    ports = [(p.get(f"{RTC}portType"), p.get(f"{RTC}name"), p.get(f"{RTC}type"), p.get(f"{RTC}idlFile"))
             for p in profile.findall(f"{RTC}DataPorts")]
    assert ports == [("DataOutPort", "jointState", "quadarm::TimedJointState", "quadarm_types.idl"),
                     ("DataInPort", "torques", "quadarm::TimedJointTorques", "quadarm_types.idl")]
    source = files["src/ArmInterface.cpp"]
    assert "  toIdl(::LwrArm::getJointState(), m_jointState.data);\n" in source
    assert "    ::quadarm::types::JointTorques value;\n    fromIdl(m_torques.data, value);\n    ::LwrArm::setTorques(value);\n" in source
    convert = files["include/quadarm/quadarm_types.h"]
    assert "inline void toIdl(const ::quadarm::types::JointState& in, ::quadarm::JointState& out)\n{\n  toIdlArray(in.position, out.position);" in convert
    # the model's C++ types for the atomic code, as on the other targets
    assert "struct JointState" in files["include/JointState.hpp"]
    conf = files["deploy/quadarm.rtc.conf"]
    assert "arm1.jointState?port=ctrl1.jointState&" in conf


def _with_empty_enum(text: str, holders: tuple[str, ...], old_type: str) -> str:
    """$text with an enumeration Empty (no literal) typing the first $old_type after each of $holders."""
    text = text.replace('<packagedElement xmi:type="uml:DataType" xmi:id="_qa002t"',
                        '<packagedElement xmi:type="uml:Enumeration" xmi:id="_rtmE" name="Empty"/>\n'
                        '    <packagedElement xmi:type="uml:DataType" xmi:id="_qa002t"', 1)
    for holder in holders:
        head, tail = text.split(holder, 1)
        text = head + holder + tail.replace(old_type, '<type xmi:type="uml:Enumeration" xmi:idref="_rtmE"/>', 1)
    return text


def test_a_port_no_openrtm_type_carries_is_named(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    from robomda.cli import main
    # quadarm with the datum of IJointState (and its accessors) an enumeration without literals
    text = _with_empty_enum((ROOT / "fixtures" / "cases" / "quadarm" / "model.xmi").read_text(),
                            ('xmi:id="_qa087a" name="jointState" visibility="public">', 'xmi:id="_qa058p" name="return" direction="return">',
                             'xmi:id="_qa081p" name="value">'), '<type xmi:type="uml:DataType" xmi:idref="_qa003t"/>')
    model = tmp_path / "model.xmi"
    model.write_text(text)
    shutil.copytree(ROOT / "fixtures" / "cases" / "quadarm" / "atomic", tmp_path / "atomic")
    assert main(["generate", str(model), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 0
    err = capsys.readouterr().err
    assert "[RTM001] port 'jointState' of component 'ArmInterface' carries Empty" in err
    assert "[RTM001] connection 'state1' carries Empty" in err
    conf = (tmp_path / "out" / "deploy" / "quadarm.rtc.conf").read_text()
    assert "ctrl1.torques?port=arm1.torques&" in conf and "jointState" not in conf


def test_a_data_type_default_that_does_not_fit_is_located(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    from robomda.cli import main
    text = (ROOT / "fixtures" / "cases" / "quadarm" / "model.xmi").read_text()
    bad = text.replace('<defaultValue xmi:type="uml:LiteralReal" xmi:id="_qa034v" value="300.0"/>',
                       '<defaultValue xmi:type="uml:OpaqueExpression" xmi:id="_qa034v"><body>{1.0, 2.0}</body></defaultValue>')
    assert bad != text
    (tmp_path / "model.xmi").write_text(bad)
    shutil.copytree(ROOT / "fixtures" / "cases" / "quadarm" / "atomic", tmp_path / "atomic")
    assert main(["generate", str(tmp_path / "model.xmi"), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 1
    assert "model.xmi:53:7: error: [RTM022] default '{1.0, 2.0}' is a list, for a single value (uml:Property 'stiffness', _qa033a)" \
        in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_a_data_type_openrtm_cannot_declare_is_located(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    from robomda.cli import main
    # quadarm with JointState's attribute mode of an enumeration without literals
    text = _with_empty_enum((ROOT / "fixtures" / "cases" / "quadarm" / "model.xmi").read_text(),
                            ('xmi:id="_qa200a" name="mode" visibility="public">',), '<type xmi:type="uml:Enumeration" xmi:idref="_qa001t"/>')
    (tmp_path / "model.xmi").write_text(text)
    shutil.copytree(ROOT / "fixtures" / "cases" / "quadarm" / "atomic", tmp_path / "atomic")
    assert main(["generate", str(tmp_path / "model.xmi"), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 1
    err = capsys.readouterr().err
    assert "error: [RTM021] attribute 'mode' of data type 'JointState' has type 'Empty'" in err and "INTERNAL" not in err
    assert not (tmp_path / "out").exists()


def test_cpu_affinity_is_written_as_openrtm_checks_it(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    """OpenRTM-aist 2.0.2 pins an execution context to the first n CPUs for a list of n and checks
    the pinning against the list counted from 1: tuned's masks 1 and 3 are "1" and "1,2", kept
    exactly; distributed's mask 2 (CPU 1 only) cannot be, and RTM023 says so."""
    from robomda.cli import main
    tuned = _files(ROOT / "fixtures" / "cases" / "tuned")
    assert "exec_cxt.periodic.cpu_affinity: 1\n" in tuned["conf/camera.conf"]
    assert "exec_cxt.periodic.cpu_affinity: 1,2\n" in tuned["conf/vision.conf"]
    case = ROOT / "fixtures" / "cases" / "distributed"
    assert main(["generate", str(case / "model.xmi"), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 0
    assert "warning: [RTM023] instance 'arm' asks for CPUs 1 (mask 2)" in capsys.readouterr().err


def _conf_values(text: str) -> dict[str, str]:
    return dict(re.findall(r"^conf\.default\.(\w+): (.*)$", text, re.M))


def test_structured_parameters_have_the_values_of_every_target() -> None:
    """Fixture structured (issue 37): every structured attribute is a configuration parameter, and
    each instance's .conf holds the values ROS 1's parameter files give (the same values in each
    target's deployment files); RTC.xml and the RtsProfile hold them too."""
    yaml = pytest.importorskip("yaml", reason="PyYAML not installed")
    case = ROOT / "fixtures" / "cases" / "structured"
    files = _files(case)
    done = generate(case / "model.xmi", case / "out", "ros1", write=False)
    ros = {node.get("path"): node.text or "" for node in etree.fromstring(done.stages["text"].encode("utf-8")).iter(f"{FS}file")}
    values = _conf_values(files["conf/ctrl1.conf"])
    assert values["desired"] == "[0.0, 0.5, 0.0, -1.0, 0.0, 0.5, 0.0]" and values["fallback"] == "TORQUE"
    assert values["gains"] == "{stiffness: 300.0, damping: 20.0, maxTorque: 80.0}" and values["history"] == "[]"
    assert values["stages"] == "[" + ", ".join(["{stiffness: 300.0, damping: 20.0, maxTorque: 80.0}"] * 7) + "]"
    for instance in ("arm1", "ctrl1", "arm4", "ctrl4"):
        mine = {name: yaml.safe_load(text) for name, text in _conf_values(files[f"conf/{instance}.conf"]).items()}
        theirs = yaml.safe_load(ros[f"config/{instance}.yaml"])
        theirs.pop("update_period")
        assert theirs and {name: mine.get(name) for name in theirs} == theirs, instance
    assert set(_conf_values(files["conf/ctrl1.conf"])) == {"gains", "desired", "fallback", "offsets", "limits", "history", "stages", "limit"}
    profile = etree.fromstring(files["rtc/JointPositionController/RTC.xml"].encode("utf-8"))
    configuration = {c.get(f"{RTC}name"): (c.get(f"{RTC}type"), c.get(f"{RTC}defaultValue")) for c in profile.iter(f"{RTC}Configuration")}
    assert configuration["offsets"] == ("std::vector<int>", "[1, -2, 3, 0, 0, 0, 7]")
    assert configuration["limit"] == ("::structured::types::JointTorques", values["limit"])
    system = etree.fromstring(files["deploy/structured.rtsys.xml"].encode("utf-8"))
    data = {d.get(f"{RTS}name"): d.get(f"{RTS}data") for d in system.iter(f"{RTS}ConfigurationData")}
    assert data["stages"] == values["stages"]
    source = files["src/JointPositionController.cpp"]
    assert ('bindParameter("offsets", ::JointController::offsets, "[1, -2, 3, 0, 0, 0, 7]", '
            "&::structured::conf::parseList<int, 7, 7>);") in source
    assert 'bindParameter("limits", ::JointController::limits, "[1.5, 2.5]", &::structured::conf::parseList<double, 0, ::structured::conf::unbounded>);' in source


def test_a_structured_value_that_does_not_fit_is_located(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    from robomda.cli import main
    text = (ROOT / "fixtures" / "cases" / "structured" / "model.xmi").read_text()
    # offsets: Integer[7] with eight values (the model beside quadarm's atomic code, as in fixtures/cases)
    bad = text.replace("<body>{1, -2, 3, 0, 0, 0, 7}</body>", "<body>{1, 2, 3, 4, 5, 6, 7, 8}</body>", 1)
    assert bad != text
    model = _structured_beside_quadarm(tmp_path, bad)
    assert main(["generate", str(model), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 1
    err = capsys.readouterr().err
    assert "error: [RTM002] default '{1, 2, 3, 4, 5, 6, 7, 8}' has 8 values, the array at most 7" in err and "INTERNAL" not in err
    assert not (tmp_path / "out").exists()


def _structured_beside_quadarm(tmp_path: Path, text: str) -> Path:
    """The structured model $text in tmp_path/structured, beside quadarm's atomic code as in fixtures/cases."""
    (tmp_path / "structured").mkdir()
    (tmp_path / "structured" / "model.xmi").write_text(text)
    shutil.copytree(ROOT / "fixtures" / "cases" / "quadarm" / "atomic", tmp_path / "quadarm" / "atomic")
    return tmp_path / "structured" / "model.xmi"


# a part's values (seed 003) on ctrl2's structured attributes: an array, an enumeration
CTRL2_VALUES = ('<ownedAttribute xmi:type="uml:Property" xmi:id="_qa103m" name="ctrl2" visibility="public" type="_qa011k" aggregation="composite"/>',
                '<ownedAttribute xmi:type="uml:Property" xmi:id="_qa103m" name="ctrl2" visibility="public" type="_qa011k" aggregation="composite">'
                '<defaultValue xmi:type="uml:InstanceValue" xmi:id="_rtmV" instance="_rtmIS"/></ownedAttribute>')
CTRL2_SLOTS = ('<packagedElement xmi:type="uml:InstanceSpecification" xmi:id="_rtmIS" name="ctrl2_settings">'
               '<slot xmi:type="uml:Slot" xmi:id="_rtmS1" definingFeature="_st2a">'
               '<value xmi:type="uml:OpaqueExpression" xmi:id="_rtmS1v"><body>{7, 6, 5, 4, 3, 2, 1}</body></value></slot>'
               '<slot xmi:type="uml:Slot" xmi:id="_rtmS2" definingFeature="_st1a">'
               '<value xmi:type="uml:OpaqueExpression" xmi:id="_rtmS2v"><body>POSITION</body></value></slot>%s</packagedElement>\n'
               '  </packagedElement>\n</uml:Model>')


def test_a_part_sets_structured_values(tmp_path: Path) -> None:
    text = (ROOT / "fixtures" / "cases" / "structured" / "model.xmi").read_text()
    text = text.replace(*CTRL2_VALUES).replace("  </packagedElement>\n</uml:Model>", CTRL2_SLOTS % "")
    model = _structured_beside_quadarm(tmp_path, text)
    done = generate(model, tmp_path / "out", "openrtm", write=False)
    files = {node.get("path"): node.text or "" for node in etree.fromstring(done.stages["text"].encode("utf-8")).iter(f"{FS}file")}
    ctrl2, ctrl1 = _conf_values(files["conf/ctrl2.conf"]), _conf_values(files["conf/ctrl1.conf"])
    assert (ctrl2["offsets"], ctrl2["fallback"]) == ("[7, 6, 5, 4, 3, 2, 1]", "POSITION")
    assert (ctrl1["offsets"], ctrl1["fallback"]) == ("[1, -2, 3, 0, 0, 0, 7]", "TORQUE")
    assert {k: v for k, v in ctrl2.items() if k not in ("offsets", "fallback")} == \
        {k: v for k, v in ctrl1.items() if k not in ("offsets", "fallback")}


def test_a_part_value_for_a_data_type_is_located(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    from robomda.cli import main
    gains = ('<slot xmi:type="uml:Slot" xmi:id="_rtmS3" definingFeature="_qa061a">'
             '<value xmi:type="uml:OpaqueExpression" xmi:id="_rtmS3v"><body>{1.0, 2.0, 3.0}</body></value></slot>')
    text = (ROOT / "fixtures" / "cases" / "structured" / "model.xmi").read_text()
    text = text.replace(*CTRL2_VALUES).replace("  </packagedElement>\n</uml:Model>", CTRL2_SLOTS % gains)
    model = _structured_beside_quadarm(tmp_path, text)
    assert main(["generate", str(model), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 1
    err = capsys.readouterr().err
    assert "error: [RTM002] value '{1.0, 2.0, 3.0}' of data type 'Gains': the data type's attributes give its value" in err
    assert "INTERNAL" not in err and not (tmp_path / "out").exists()


def test_an_attribute_openrtm_has_no_type_for_is_no_parameter(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    """What is still no parameter (RTM013): an array of an enumeration without a literal."""
    from robomda.cli import main
    text = _with_empty_enum((ROOT / "fixtures" / "cases" / "structured" / "model.xmi").read_text(),
                            ('xmi:id="_st4a" name="history" visibility="protected">',),
                            '<type xmi:type="uml:PrimitiveType" href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Real"/>')
    model = _structured_beside_quadarm(tmp_path, text)
    assert main(["generate", str(model), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 0
    err = capsys.readouterr().err
    assert "warning: [RTM013] attribute 'history' of type 'Empty[*]' is no OpenRTM configuration parameter" in err
    values = _conf_values((tmp_path / "out" / "conf" / "ctrl1.conf").read_text())
    assert "history" not in values and values["limits"] == "[1.5, 2.5]"


def test_the_configuration_reader_parses_what_the_package_writes(tmp_path: Path) -> None:
    """<pkg>_conf.h compiled alone (-Wall -Wextra -Werror, C++14): every value ctrl1.conf holds
    parses into the model's C++ types with the model's values; a value that does not fit (a word
    for a number, an unknown attribute or literal, an array of the wrong size, trailing text) is
    refused, which bindParameter answers with the default."""
    compiler = shutil.which("g++") or shutil.which("c++")
    if compiler is None:
        pytest.skip("no C++ compiler")
    out = tmp_path / "structured"
    generate(ROOT / "fixtures" / "cases" / "structured" / "model.xmi", out, "openrtm", write=True)
    values = _conf_values((out / "conf" / "ctrl1.conf").read_text())
    main = "\n".join([
        "#include <structured/structured_conf.h>",
        "#include <cstdio>",
        "using namespace structured;",
        "using conf::unbounded;",
        "int main()",
        "{",
        "  types::Gains gains; std::vector<double> desired, limits, history; types::ControlMode fallback = types::POSITION;",
        "  std::vector<int> offsets; std::vector<types::Gains> stages; types::JointTorques limit;",
        f"  bool ok = conf::parse(gains, {_c(values['gains'])}) && conf::parseList<double, 7, 7>(desired, {_c(values['desired'])})",
        f"    && conf::parse(fallback, {_c(values['fallback'])}) && conf::parseList<int, 7, 7>(offsets, {_c(values['offsets'])})",
        f"    && conf::parseList<double, 0, unbounded>(limits, {_c(values['limits'])}) && conf::parseList<double, 0, unbounded>(history, {_c(values['history'])})",
        f"    && conf::parseList<types::Gains, 7, 7>(stages, {_c(values['stages'])}) && conf::parse(limit, {_c(values['limit'])});",
        '  std::printf("parsed %d %g %g %d %d %d %g %d %zu %g %zu %g %zu\\n", ok, gains.stiffness, desired[3], fallback == types::TORQUE,',
        "              offsets[1], offsets[6], limits[1], int(history.size()), stages.size(), stages[6].maxTorque, limit.torque.size(),",
        "              limit.gains.damping, desired.size());",
        "  // OpenRTM's own habit: a vector without brackets",
        '  const bool bare = conf::parseList<int, 0, unbounded>(offsets, " 4, 5,6 ");',
        '  std::printf("bare %d %zu\\n", bare, offsets.size());',
        "  const char* bad[] = {\"{stiffness: stiff}\", \"{stiffness: 1.0, spring: 2.0}\", \"{stiffness: 1.0\", \"{stiffness: 1.0} x\"};",
        "  int refused = 0;",
        "  for (const char* text : bad) refused += !conf::parse(gains, text);",
        "  refused += !conf::parseList<double, 7, 7>(desired, \"[1.0, 2.0]\");",
        "  refused += !conf::parseList<int, 0, unbounded>(offsets, \"[1, 2.5]\");",
        "  refused += !conf::parseList<int, 0, unbounded>(offsets, \"[1, 99999999999]\");",
        "  refused += !conf::parse(fallback, \"FAST\");",
        '  std::printf("refused %d kept %g %zu %d\\n", refused, gains.stiffness, desired.size(), fallback == types::TORQUE);',
        "  return 0;",
        "}",
        ""])
    (tmp_path / "main.cpp").write_text(main)
    built = subprocess.run(["nice", "-n", "19", compiler, "-std=c++14", "-Wall", "-Wextra", "-Werror", "-I", str(out / "include"),
                            str(tmp_path / "main.cpp"), "-o", str(tmp_path / "main")], capture_output=True, text=True, timeout=600)
    assert built.returncode == 0, built.stderr[-4000:]
    ran = subprocess.run([str(tmp_path / "main")], capture_output=True, text=True, timeout=60, check=True).stdout
    assert ran.splitlines() == ["parsed 1 300 -1 1 -2 7 2.5 0 7 80 7 20 7", "bare 1 3", "refused 8 kept 300 7 1"]


def _c(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def test_every_rts_profile_reads_with_rtsprofile() -> None:
    """rtshell's rtsprofile library (what rtstart / rtresurrect read a system with) loads every
    fixture's RtsProfile: its components, connectors and the StartUp / Activation conditions."""
    rts_profile = pytest.importorskip("rtsprofile.rts_profile")
    for case in CASES:
        files = _files(case)
        text = next(files[p] for p in files if p.endswith(".rtsys.xml"))
        system = etree.fromstring(text.encode("utf-8"))
        profile = rts_profile.RtsProfile(xml_spec=text)
        assert [c.instance_name for c in profile.components] == \
            [c.get(f"{RTS}instanceName") for c in system.findall(f"{RTS}Components")], case.name
        assert len(profile.data_port_connectors) == len(system.findall(f"{RTS}DataPortConnectors")), case.name
        for message, read in (("StartUp", profile.startup), ("Activation", profile.activation)):
            targets = system.findall(f"{RTS}{message}/{RTS}targets")
            assert [(t.sequence, t.target_component.instance_name) for t in read.targets] == \
                [(int(t.get(f"{RTS}sequence")), t.find(f"{RTS}TargetComponent").get(f"{RTS}instanceName")) for t in targets]
            preceding = {t.target_component.instance_name: [p.instance_name for p in t.preceding_components]
                         for t in read.targets if hasattr(t, "preceding_components")}
            assert preceding == {t.find(f"{RTS}TargetComponent").get(f"{RTS}instanceName"):
                                 [p.get(f"{RTS}instanceName") for p in t.findall(f"{RTS}Preceding/{RTS}PrecedingComponents")]
                                 for t in targets if t.find(f"{RTS}Preceding") is not None}, case.name


# ---------------------------------------------------------------- real OpenRTM
OPENRTM = Path(os.environ.get("OPENRTM_INSTALL", Path.home() / "openrtm" / "install"))
ENV_SH = ROOT / "toolchains" / "openrtm" / "env.sh"


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _bash(script: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    # unoptimised (build type None): the test needs components that run, and builds them at nice 19
    env = dict(os.environ, RTM_CMAKE_ARGS=os.environ.get("RTM_CMAKE_ARGS", "-DCMAKE_BUILD_TYPE=None"))
    return subprocess.run(["bash", "-c", f"source {ENV_SH} && {script}"], cwd=cwd, capture_output=True, text=True,
                          timeout=3600, check=False, env=env)


def _wait_for(predicate, seconds: float) -> bool:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.2)
    return predicate()


def _stop(process: subprocess.Popen[str]) -> None:
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGTERM)
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()


def _naming_service(tmp_path: Path, out: Path) -> tuple[subprocess.Popen[str], int, dict[str, str]]:
    """An omniNames on a free loopback port (its log in TMP_PATH), its port, and the environment in
    which the start scripts of package OUT (built) and rtcd2 run against it."""
    ns_port = _free_port()
    names = subprocess.Popen(["omniNames", "-start", str(ns_port), "-logdir", str(tmp_path)], stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, start_new_session=True, text=True)
    env = dict(os.environ, RTM_NAMESERVER=f"localhost:{ns_port}", RTM_MODULES=str(out / "build"),
               LD_LIBRARY_PATH=f"{OPENRTM / 'lib'}:{os.environ.get('LD_LIBRARY_PATH', '')}",
               PATH=f"{OPENRTM / 'bin'}:{os.environ['PATH']}")
    return names, ns_port, env


def _single_middleware(case: Path) -> bool:
    """Whether the fixture deploys every instance, and at least one, on one middleware."""
    bound = etree.parse(str(case / "expected" / "bind.xml"))
    kinds = {m for m in bound.xpath("//@middleware")}
    return len(kinds) == 1


RUN_CASES = [c for c in CASES if _single_middleware(c)]


def _system(out: Path) -> etree._Element:
    return etree.parse(str(next((out / "deploy").glob("*.rtsys.xml")))).getroot()


def _probe_port(out: Path, case: str) -> tuple[str, str, bool]:
    """The port the probe reads (instance.port), its data type, and whether the probe prints the datum.

    headlamp: vision.channelPosition, which grows only while camera.visionValue reaches vision over
    the modelled connection visionValueConn; elsewhere the source of the RtsProfile's first
    DataPortConnector: a modelled connection's writer, whose every sample OpenRTM writes to each
    of its connectors."""
    if case == "headlamp":
        return "vision.channelPosition", "RTC::TimedLong", True
    connector = _system(out).find(f"{RTS}DataPortConnectors")
    assert connector is not None, f"{case}: the RtsProfile has no data-port connection"
    port = connector.find(f"{RTS}sourceDataPort").get(f"{RTS}portName")
    instance, name = port.split(".", 1)
    component = next(c for c in _system(out).findall(f"{RTS}Components") if c.get(f"{RTS}instanceName") == instance)
    type_name = component.get(f"{RTS}id").split(":")[3]
    profile = etree.parse(str(out / "rtc" / type_name / "RTC.xml")).getroot()
    data_type = next(p.get(f"{RTC}type") for p in profile.findall(f"{RTC}DataPorts") if p.get(f"{RTC}name") == name)
    return port, data_type, False


def _probe_args(out: Path, data_type: str) -> str:
    if data_type.startswith("RTC::"):
        return f"-DPROBE_TYPE={data_type}"
    idl = next((out / "idl").glob("*_types.idl")).stem
    return f"-DPROBE_TYPE={data_type} -DPROBE_HEADER={idl}.hh -DPROBE_PACKAGE_BUILD={out / 'build'}"


def _activation_order(out: Path) -> list[str]:
    """The instances the managers' logs say are activated, manager by manager in the start scripts' order."""
    names: list[str] = []
    for script in sorted((out / "deploy").glob("start_*.sh")):
        for log in re.findall(r"^wait_active (\S+)", script.read_text(), re.M):
            path = out / "deploy" / log
            names += re.findall(r"(\w+) activated\.", path.read_text(errors="replace") if path.exists() else "")
    return names


def _logs(out: Path) -> str:
    return "".join(f"== {p.name}\n{p.read_text(errors='replace')[-3000:]}" for p in sorted((out / "deploy").glob("*.log")))


def _log_text(out: Path) -> str:
    return "".join(p.read_text(errors="replace") for p in sorted((out / "deploy").glob("*.log")))


def _unfed_readers(out: Path) -> list[str]:
    """The reader ends (instance.port) of the RtsProfile's DataPortConnectors whose component has
    not logged, at INFO, that the port's first sample arrived (the generated onExecute logs
    "input port <instance>.<port>: first sample received" once, after it read the sample). The
    logger's name is not the instance's (OpenRTM-aist 2.0.2 names it at creation, type name and
    number), so the message names the instance."""
    text = _log_text(out)
    ports = [c.find(f"{RTS}targetDataPort").get(f"{RTS}portName") for c in _system(out).findall(f"{RTS}DataPortConnectors")]
    return [p for p in ports if not re.search(rf" INFO: .*input port {re.escape(p)}: first sample received$", text, re.M)]


# fixture structured: values no reader can parse, in two instances' .conf (a data type, arrays, an
# enumeration, a primitive): each must be reported by its component, and no other value
SPOILED = {"ctrl4": ("gains", "desired", "fallback", "offsets", "limits", "history", "stages", "limit"), "arm4": ("mode", "inertia")}


def _spoil_configuration(out: Path) -> list[tuple[str, str]]:
    spoiled: list[tuple[str, str]] = []
    for instance, names in SPOILED.items():
        path = out / "conf" / f"{instance}.conf"
        text = path.read_text()
        for name in names:
            text, count = re.subn(rf"^conf\.default\.{name}: .*$", f"conf.default.{name}: {{oops", text, flags=re.M)
            assert count == 1, (instance, name, text)
            spoiled.append((instance, name))
        path.write_text(text)
    return sorted(spoiled)


def _reported_configuration(out: Path) -> list[tuple[str, str]]:
    found = re.findall(r" WARNING: .*configuration parameter (\w+) of (\w+): value '(.*)' does not parse", _log_text(out))
    return sorted((instance, name) for name, instance, _ in found)


def _read_probe(probe: subprocess.Popen[str], seconds: float) -> list[tuple[int, int, int]]:
    """The probe's samples (sec, nsec, datum), up to 20, within $seconds: a probe that prints
    nothing ends the wait at the deadline instead of blocking the read."""
    samples: list[tuple[int, int, int]] = []
    end = time.monotonic() + seconds
    assert probe.stdout is not None
    while time.monotonic() < end and len(samples) < 20:
        if not select.select([probe.stdout], [], [], max(0.0, end - time.monotonic()))[0]:
            break
        line = probe.stdout.readline()
        if not line:
            break
        match = re.match(r"probe: (\d+) (\d+)(?: (-?\d+))?", line)
        if match:
            samples.append((int(match.group(1)), int(match.group(2)), int(match.group(3) or 0)))
    return samples


@pytest.mark.openrtm_toolchain
@pytest.mark.parametrize("case", RUN_CASES, ids=[c.name for c in RUN_CASES])
def test_fixture_runs_on_openrtm(case: Path, tmp_path: Path) -> None:
    """The package builds; its start scripts bring every instance to Active in the RtsProfile's
    Activation order with every modelled connection made; the reader of every DataPortConnector
    logs that its port's first sample arrived (data reaches each modelled reader); a probe reads
    samples with rising time stamps from a port of a modelled connection (headlamp: values that
    need the connection). Structured: every value the model gives parses, and each spoiled one
    (SPOILED) is reported by its component."""
    if not (OPENRTM / "bin" / "rtcd2").exists():
        pytest.skip(f"no OpenRTM-aist in {OPENRTM} (toolchains/openrtm/build.sh builds it)")
    out = tmp_path / case.name
    generate(case / "model.xmi", out, "openrtm", write=True)
    spoiled = _spoil_configuration(out) if case.name == "structured" else []
    built = _bash(f"rtm_build_pkg {out}", tmp_path)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    order = [t.find(f"{RTS}TargetComponent").get(f"{RTS}instanceName")
             for t in sorted(_system(out).findall(f"{RTS}Activation/{RTS}targets"), key=lambda t: int(t.get(f"{RTS}sequence")))]
    port, data_type, prints_data = _probe_port(out, case.name)
    built = _bash(f"rtm_build_probe {tmp_path / 'probe'} {_probe_args(out, data_type)}", tmp_path)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    names, ns_port, env = _naming_service(tmp_path, out)
    started: list[subprocess.Popen[str]] = []
    probe = None
    try:
        time.sleep(1)
        for script in sorted((out / "deploy").glob("start_*.sh")):
            started.append(subprocess.Popen(["sh", str(script)], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                            start_new_session=True, text=True))
        assert _wait_for(lambda: len(_activation_order(out)) >= len(order), 90), _logs(out)
        # (a job coordinator, activated after its manager's instances, is no component of the RtsProfile)
        assert [n for n in _activation_order(out) if n in order] == order
        text = _logs(out)
        # (a manager that is no master says "Master manager not found": a warning, no error)
        assert "Connection error" not in text and " ERROR: " not in text, text
        assert _reported_configuration(out) == spoiled, _logs(out)
        assert _wait_for(lambda: not _unfed_readers(out), 30), (_unfed_readers(out), _logs(out))
        conf = tmp_path / "probe.rtc.conf"
        conf.write_text(f"corba.nameservers: localhost:{ns_port}\nnaming.formats: %n.rtc\nlogger.enable: NO\n"
                        f"manager.modules.load_path: {tmp_path / 'probe'}\nmanager.preload.modules: Probe.so\n"
                        "manager.components.precreate: Probe?instance_name=probe\n"
                        f"manager.components.preconnect: rtcname://*/{port}?port=probe.in\n"
                        "manager.components.preactivation: probe\nexec_cxt.periodic.rate: 100\n")
        probe = subprocess.Popen(["rtcd2", "-f", str(conf)], env=env, cwd=tmp_path, stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, start_new_session=True, text=True)
        samples = _read_probe(probe, 40)
        assert len(samples) >= 20, (samples, _logs(out))
        stamps = [(sec, nsec) for sec, nsec, _ in samples]
        assert stamps == sorted(stamps) and stamps[-1] > stamps[0], samples
        if prints_data:
            values = [value for _, _, value in samples]
            assert values[-1] > values[0] > 0, values
    finally:
        for process in [probe, *reversed(started), names]:
            if process is not None:
                _stop(process)
        shutil.rmtree(out / "build", ignore_errors=True)


@pytest.mark.openrtm_toolchain
def test_user_classes_build_on_openrtm(tmp_path: Path) -> None:
    """Components without a realizing class (fixtures/ros/usercode): the generated bases and the
    user's classes, as first written, build into modules that export <Class>Init."""
    if not (OPENRTM / "bin" / "rtcd2").exists():
        pytest.skip(f"no OpenRTM-aist in {OPENRTM} (toolchains/openrtm/build.sh builds it)")
    out = tmp_path / "usercode"
    generate(ROOT / "fixtures" / "ros" / "usercode" / "model.xmi", out, "openrtm", write=True)
    built = _bash(f"rtm_build_pkg {out} && nm -D {out}/build/Arm.so {out}/build/Planner.so", tmp_path)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    assert " T ArmInit" in built.stdout and " T PlannerInit" in built.stdout
