"""Composites of any depth (seed 003, issue 13): nothing of a nested model is lost.

The fixtures fixtures/cases/calligraphy and fixtures/cases/learning are two
applications of seed 003 that reuse the Arm Trajectory Follower reference
architecture from one library file (fixtures/libraries/atf, reached through
each case's atf/ link), three levels deep. These tests count, independently
of the stylesheets, what the imported model holds (the leaf parts below the
top composite, every composite part, every use of every assembly connector)
and find each of them in every later stage and in the generated deployment
files of every target; and they check that a change to the library file
regenerates both applications in a batch run, and nothing else.
"""

from __future__ import annotations

import itertools
import re
import shutil
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate, import_model, targets
from robomda.batch import run_batch
from robomda.diagnostics import RobomdaError

from edits import edit

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "fixtures" / "cases"
APPS = ["calligraphy", "learning"]
PIM = "{urn:robomda:pim:1}"


def _walk(model: etree._Element) -> tuple[list[str], list[str], list[tuple[str, str]]]:
    """(leaf part paths, composite part paths, (connector id, path of its composite) per assembly use),
    read from the imported PIM by walking the parts of the top composites."""
    by_id = {e.get("id"): e for e in model.iter() if e.get("id")}
    components = [c for c in model.iter(f"{PIM}component")]

    def part_type(part: etree._Element):
        found = by_id.get(part.get("type"))
        return found if found is not None and found.tag == f"{PIM}component" else None

    def is_composite(component) -> bool:
        return any(part_type(p) is not None for p in component.findall(f"{PIM}part"))

    used_as_part = {p.get("type") for p in model.iter(f"{PIM}part")}
    tops = [c for c in components if is_composite(c) and c.get("id") not in used_as_part]
    leaves, composites, uses = [], [], []

    def assemblies(component, path: str) -> None:
        own_ports = {p.get("id") for p in component.findall(f"{PIM}port")}
        for connector in component.findall(f"{PIM}connector"):
            ends = connector.findall(f"{PIM}end")
            delegation = connector.get("kind") == "delegation" or any(
                e.get("part") is None and e.get("role") in own_ports for e in ends)
            if not delegation and sum(e.get("part") is not None for e in ends) >= 2:
                uses.append((connector.get("id"), path))

    def expand(component, prefix: list[str]) -> None:
        for part in component.findall(f"{PIM}part"):
            kind = part_type(part)
            if kind is None:
                continue
            path = prefix + [part.get("name") or kind.get("name")]
            if is_composite(kind):
                composites.append(".".join(path))
                assemblies(kind, ".".join(path))
                expand(kind, path)
            else:
                leaves.append(".".join(path))

    for top in tops:
        assemblies(top, "")
        expand(top, [])
    return leaves, composites, uses


@pytest.fixture(scope="module")
def runs() -> dict[tuple[str, str], object]:
    return {(app, target): generate(CASES / app / "model.xmi", CASES / app / "out", target, write=False)
            for app in APPS for target in targets()}


@pytest.mark.parametrize("app", APPS)
def test_every_part_and_connector_reaches_the_binding(app: str, runs) -> None:
    done = runs[(app, "orocos")]
    leaves, composites, uses = _walk(etree.fromstring(done.stages["import"].encode("utf-8")))
    assert len(leaves) == 6 and len(composites) == 2 and len(uses) >= 7  # the fixture is what it says
    assert max(p.count(".") for p in leaves) == 2  # three levels: atf > driver > fri
    binding = etree.fromstring(done.stages["bind"].encode("utf-8")).find(f"{PIM}binding")
    instances = binding.findall(f"{PIM}instance")
    assert sorted(i.get("path") or i.get("name") for i in instances) == sorted(leaves)
    assert sorted(i.get("name") for i in instances) == sorted(p.replace(".", "_") for p in leaves)
    assert [c.get("path") for c in binding.findall(f"{PIM}composite-instance")] == composites
    # every assembly connector, at every level, is in a connection point
    joined = {k for c in binding.findall(f"{PIM}connection") + binding.findall(f"{PIM}call")
              for k in c.get("connectors").split()}
    assert {connector for connector, _ in uses} <= joined
    # and every connection joins instances that exist
    names = {i.get("name") for i in instances}
    for connection in binding.findall(f"{PIM}connection"):
        ends = connection.findall(f"{PIM}writer") + connection.findall(f"{PIM}reader")
        assert {e.get("instance") for e in ends} <= names


@pytest.mark.parametrize("app", APPS)
@pytest.mark.parametrize("target", targets())
def test_every_operation_call_reaches_every_target(app: str, target: str, runs) -> None:
    """Seed 003's promoted operation: the application's component calls ICompliance.setCompliant,
    which the joint controller two composites down provides; each target generates both ends and
    joins them."""
    done = runs[(app, target)]
    binding = etree.fromstring(done.stages["bind"].encode("utf-8")).find(f"{PIM}binding")
    calls = binding.findall(f"{PIM}call")
    assert [(c.find(f"{PIM}provider").get("instance")) for c in calls] == ["atf_driver_jointCtrl"]
    files = {f.get("path"): f.text or "" for f in etree.fromstring(done.stages["text"].encode("utf-8"))}
    caller = calls[0].find(f"{PIM}caller").get("instance")
    code = "".join(text for path, text in files.items() if path.startswith("src/"))
    if target == "orocos":
        assert 'this->provides("ICompliance")->addOperation("setCompliant"' in code
        assert 'this->requires("ICompliance")->addOperationCaller(caller_setCompliant);' in code
        xml = etree.fromstring(files[f"deploy/{app}.xml"].encode("utf-8"))
        peers = xml.find(f"struct[@name='{caller}']/struct[@name='Peers']")
        assert [v.text for v in peers.iter("value")] == ["atf_driver_jointCtrl"]
        assert f'connectServices("{caller}", "atf_driver_jointCtrl")' in files[f"deploy/{app}.ops"]
        assert f'depl:connectServices("{caller}", "atf_driver_jointCtrl")' in files[f"deploy/{app}.lua"]
    elif target == "openrtm":
        assert "CORBA::Boolean JointController::ComplianceServant::setCompliant(CORBA::Boolean enable)" in code
        assert "m_compliancePort.registerProvider(\"ICompliance\", \"ICompliance\", m_complianceServant);" in code
        assert "return m_compliance->setCompliant(enable);" in code
        assert "interface ICompliance" in files["idl/ICompliance.idl"]
        conf = files[f"deploy/{app}.rtc.conf"]
        assert f"{caller}.compliance?port=atf_driver_jointCtrl.compliance" in conf
    else:
        assert 'advertiseService("setCompliant"' in code or 'create_service<std_srvs::srv::SetBool>(\n    "~/setCompliant"' in code
        assert 'serviceClient<std_srvs::SetBool>("setCompliant")' in code or 'create_client<std_srvs::srv::SetBool>("setCompliant")' in code
        launch = "".join(text for path, text in files.items() if path.startswith("launch/"))
        # named from the root: ROS 1 absolutely, ROS 2 under the namespace the launch is pushed into
        root = "/$(arg ns)/" if target == "ros1" else "$(var ros_namespace '')/"
        assert launch.count(f'<remap from="setCompliant" to="{root}atf/driver/jointCtrl/setCompliant"/>') == 1


def _connections(binding: etree._Element) -> list[tuple[str, str, str, str]]:
    """(writer instance, writer port, reader instance, reader port) of every connection of the binding."""
    pairs = []
    for connection in binding.findall(f"{PIM}connection"):
        writer = connection.find(f"{PIM}writer")
        for reader in connection.findall(f"{PIM}reader"):
            pairs.append((writer.get("instance"), writer.get("data-port"), reader.get("instance"),
                          reader.get("data-port")))
    return pairs


@pytest.mark.parametrize("app", APPS)
def test_every_instance_and_connection_reaches_the_orocos_deployment(app: str, runs) -> None:
    done = runs[(app, "orocos")]
    binding = etree.fromstring(done.stages["bind"].encode("utf-8")).find(f"{PIM}binding")
    files = {f.get("path"): f.text or "" for f in etree.fromstring(done.stages["text"].encode("utf-8"))}
    xml = etree.fromstring(files[f"deploy/{app}.xml"].encode("utf-8"))
    loaded = {s.get("name") for s in xml.findall("struct") if s.get("type") not in ("ConnPolicy", "PropertyBag")}
    assert {i.get("name") for i in binding.findall(f"{PIM}instance")} <= loaded
    ops, lua = files[f"deploy/{app}.ops"], files[f"deploy/{app}.lua"]
    for writer, wport, reader, rport in _connections(binding):
        assert f'connect("{writer}.{wport}", "{reader}.{rport}"' in ops
        assert f'"{writer}", "{wport}", "{reader}", "{rport}"' in lua or f'{writer}.{wport}' in lua


@pytest.mark.parametrize("app", APPS)
@pytest.mark.parametrize("target", ["ros1", "ros2"])
def test_every_instance_and_connection_reaches_the_ros_launch(app: str, target: str, runs) -> None:
    done = runs[(app, target)]
    binding = etree.fromstring(done.stages["bind"].encode("utf-8")).find(f"{PIM}binding")
    files = {f.get("path"): f.text or "" for f in etree.fromstring(done.stages["text"].encode("utf-8"))}
    launch = "\n".join(text for path, text in files.items() if path.startswith("launch/"))
    namespace = "ns" if target == "ros1" else "namespace"
    for instance in binding.findall(f"{PIM}instance"):
        if instance.get("parent"):  # a node in the namespace of its composite parts
            name = instance.get("path").rsplit(".", 1)[1]
            assert f'name="{name}" {namespace}="{instance.get("parent").replace(".", "/")}"' in launch
        else:
            assert re.search(f'name="{re.escape(instance.get("name"))}"[ >]', launch), instance.get("name")
    # both ends of every connection are remapped onto one topic (named from the root in a namespace)
    for connection in binding.findall(f"{PIM}connection"):
        name = connection.get("name")
        rooted = sum(launch.count(f'to="{root}/{name}"') for root in ("", "$(var ros_namespace \'\')", "/$(arg ns)"))
        assert launch.count(f'to="{name}"') + rooted >= 2


def test_a_changed_library_regenerates_both_applications_and_nothing_else(tmp_path: Path) -> None:
    apps = _apps_copy(tmp_path)
    shutil.copytree(CASES / "pid", apps / "pid", ignore=shutil.ignore_patterns("expected"))
    out = tmp_path / "out"
    first = run_batch(apps, out, "ros1", jobs=1)
    assert {r.model: r.status for r in first.results} == {
        "calligraphy/model.xmi": "ok", "learning/model.xmi": "ok", "pid/model.xmi": "ok",
        "lib/atf/ArmTrajectoryFollower.uml": "library"}
    assert first.exit_code == 0
    edit(apps / "lib" / "atf" / "ArmTrajectoryFollower.uml",
         'xmi:id="_atfCsV1v" value="position"', 'xmi:id="_atfCsV1v" value="impedance"')
    again = run_batch(apps, out, "ros1", jobs=1)
    assert {r.model: r.status for r in again.results} == {
        "calligraphy/model.xmi": "ok", "learning/model.xmi": "ok", "pid/model.xmi": "skipped",
        "lib/atf/ArmTrajectoryFollower.uml": "library"}
    for app in APPS:
        assert "impedance" in (out / app / "model.xmi" / "config" / "atf_csIter.yaml").read_text()


# (application, instance, property, value): a part's slot three levels up (calligraphy's gain), a
# composite's own default for a property it promotes (learning's gain), a slot on a part typed by a
# composite reaching the property it promotes (learning's controlMode), a slot on a plain part
VALUES = [("calligraphy", "atf_driver_jointCtrl", "gain", "20.0"),
          ("calligraphy", "planner", "characterFile", "hiragana.xml"),
          ("calligraphy", "atf_csIter", "controlMode", "position"),
          ("learning", "atf_driver_jointCtrl", "gain", "12.5"),
          ("learning", "atf_csIter", "controlMode", "impedance")]


@pytest.mark.parametrize(("app", "instance", "prop", "value"), VALUES)
def test_values_set_above_reach_every_target(app: str, instance: str, prop: str, value: str, runs) -> None:
    orocos = {f.get("path"): f.text or "" for f in etree.fromstring(runs[(app, "orocos")].stages["text"].encode())}
    xml = etree.fromstring(orocos[f"deploy/{app}.xml"].encode("utf-8"))
    component = xml.find(f"struct[@name='{instance}']")
    assert component.find(f"struct[@name='Properties']/simple[@name='{prop}']/value").text == value
    literal = f'"{value}"' if not value[0].isdigit() else value
    assert f"{instance}.{prop} = {literal}" in orocos[f"deploy/{app}.ops"]
    ros1 = {f.get("path"): f.text or "" for f in etree.fromstring(runs[(app, "ros1")].stages["text"].encode())}
    assert f"{prop}: {literal}" in ros1[f"config/{instance}.yaml"]
    ros2 = {f.get("path"): f.text or "" for f in etree.fromstring(runs[(app, "ros2")].stages["text"].encode())}
    # ROS 2: a file of the instance's own, keyed /** (its node's name moves under a pushed namespace)
    lines = [line for line in ros2[f"config/{instance}.yaml"].splitlines() if not line.startswith("#")]
    assert lines[:2] == ["/**:", "  ros__parameters:"] and f"    {prop}: {literal}" in lines


def _apps_copy(tmp_path: Path) -> Path:
    """The two applications and their library, copied into TMP/apps (each app's atf/ a link to lib/atf)."""
    apps = tmp_path / "apps"
    shutil.copytree(ROOT / "fixtures" / "libraries" / "atf", apps / "lib" / "atf")
    for app in APPS:
        shutil.copytree(CASES / app, apps / app, ignore=shutil.ignore_patterns("expected", "atf"))
        (apps / app / "atf").symlink_to(Path("..") / "lib" / "atf")
    return apps


@pytest.mark.parametrize(("target", "code"), [("orocos", "ORO008"), ("ros1", "ROS104"), ("ros2", "ROS104")])
def test_a_value_on_an_attribute_the_target_does_not_expose_is_named(tmp_path: Path, target: str, code: str) -> None:
    apps = _apps_copy(tmp_path)
    model = apps / "calligraphy" / "model.xmi"
    # the planner's characterFile, which the application sets, made private: no property any more
    edit(model, 'xmi:id="_calPlV1" name="characterFile" visibility="protected"',
         'xmi:id="_calPlV1" name="characterFile" visibility="private"')
    done = generate(model, tmp_path / "out", target, write=False)
    found = [d for d in done.warnings if d.code == code]
    assert len(found) == 1 and "'hiragana.xml'" in found[0].message and "'planner'" in found[0].message
    assert found[0].line is not None  # located on the slot


def test_an_unbound_required_interface_and_an_undeclared_operation_are_named(tmp_path: Path) -> None:
    """Without its connector the planner's required ICompliance is bound to nothing (the model has
    other connectors, so bind does not guess), and a planner class that does not declare setCompliant
    cannot call it: each target names both with a located warning, and generates the caller anyway."""
    case = tmp_path / "calligraphy"
    shutil.copytree(CASES / "calligraphy", case)  # the library link is copied as files
    model = case / "model.xmi"
    text = model.read_text(encoding="utf-8")
    for opening, closing in (('<ownedConnector xmi:type="uml:Connector" xmi:id="_calSysC9"', "</ownedConnector>"),
                             ('<ownedOperation xmi:type="uml:Operation" xmi:id="_calPlS1"', "</ownedOperation>")):
        start = text.index(opening)
        edit(model, text[start:text.index(closing, start) + len(closing)], "")
    pim = etree.fromstring(import_model(model).encode("utf-8"))
    assert pim.find(f"{PIM}binding/{PIM}call") is None
    for target, unbound, undeclared in (("orocos", "ORO010", "ORO011"), ("ros1", "ROS105", "ROS106"),
                                        ("ros2", "ROS105", "ROS106")):
        done = generate(model, tmp_path / "out", target, write=False)
        for code in (unbound, undeclared):
            named = [d for d in done.warnings if d.code == code]
            assert len(named) == 1 and named[0].line is not None and "ICompliance" in named[0].message, code
        assert "caller_setCompliant" in done.stages["text"] or "client_setCompliant_" in done.stages["text"]


@pytest.mark.parametrize("app", APPS)
def test_a_policy_drawn_inside_the_library_reaches_every_orocos_file(app: str, runs) -> None:
    """HyperFlex's flattening lost DATA / CIRCULAR_BUFFER policies and never wrote lock_policy: the
    torque loop inside the arm driver (a CIRCULAR_BUFFER of 4, LOCKED, init) keeps every field."""
    files = {f.get("path"): f.text or "" for f in etree.fromstring(runs[(app, "orocos")].stages["text"].encode())}
    policy = etree.fromstring(files[f"deploy/{app}.xml"].encode()).find("struct[@name='atf_driver_torqueCmd']")
    assert {s.get("name"): s.findtext("value") for s in policy.findall("simple")} == {
        "type": "2", "size": "4", "lock_policy": "1", "init": "1", "pull": "0"}
    ops = files[f"deploy/{app}.ops"]
    for field in ("type = CIRCULAR_BUFFER", "size = 4", "lock_policy = LOCKED", "init = true", "pull = false"):
        assert f"cp_atf_driver_torqueCmd.{field}" in ops
    lua = files[f"deploy/{app}.lua"].split("-- connection point atf_driver_torqueCmd", 1)[1].split("end", 1)[0]
    for field in ("cp.type = rtt.globals.CIRCULAR_BUFFER", "cp.size = 4", "cp.lock_policy = rtt.globals.LOCKED",
                  "cp.init = true", "cp.pull = false"):
        assert field in lua
