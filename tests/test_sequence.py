"""The deployment sequence ("A starts before B", seed 002): StartAfter dependencies end to end.

- import keeps the StartAfter dependencies (stereotype, or the name
  startAfter in an unprofiled model) and reports a dangling end (IMP020);
- bind gives every instance its pim:start-after constraints and its
  @start-order (Kahn's algorithm, ties in document order), leaves it off the
  instances on a cycle and after one, and rejects an end that is not an
  instance (BND012);
- the Orocos deployment files load, configure and start in that order.

The models are copies of the fixtures with their dependencies replaced.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate, import_model
from robomda.diagnostics import RobomdaError

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "fixtures" / "cases"
PIM = "urn:robomda:pim:1"
NS = {"p": PIM}
XMI = "http://www.omg.org/spec/XMI/20131001"
UML = "http://www.eclipse.org/uml2/5.0.0/UML"
ROBOMDA = "http://robomda.org/profile/robomda/1"
FS = "{urn:robomda:fileset:1}"

# the parts of the headlamp composite, in document order
PARTS = {"camera": "_ZFkQzwZWOKVfkNutf1AcmA", "forceSensor": "_0R9NxJby6L7s3E0jUY2jf5",
         "vision": "_1co18VX-WHKsg9uJFeno6f", "controller": "_U8PsGZiyebb543bfRpF91k",
         "arm": "_0YRRtQfL5e_lmHjEY3UpNA"}
COMPOSITE = "_HLYj89JO6qXduW8lPEtPdO"
COMPONENTS_PACKAGE = "_FS46xFGaEBgd8BhetoTQcD"


def _x(name: str) -> str:
    return f"{{{XMI}}}{name}"


def headlamp(tmp_path: Path, constraints: list[tuple[str, str]], *, stereotype: bool = True,
             name: str = "dep", xmi_type: str = "uml:Dependency") -> Path:
    """The Papyrus headlamp fixture with its dependencies replaced by one per
    (later, earlier) pair; ends are part names, or raw ids when not a part."""
    tree = etree.parse(str(CASES / "headlamp" / "model.xmi"))
    root = tree.getroot()
    for dep in [e for e in root.iter("packagedElement") if e.get(_x("type")) == "uml:Dependency"]:
        dep.getparent().remove(dep)
    for app in root.findall(f"{{{ROBOMDA}}}StartAfter"):
        root.remove(app)
    package = next(e for e in root.iter("packagedElement") if e.get(_x("id")) == COMPONENTS_PACKAGE)
    for n, (later, earlier) in enumerate(constraints, 1):
        dep = etree.SubElement(package, "packagedElement")
        dep.set(_x("type"), xmi_type)
        dep.set(_x("id"), f"_seqDep{n}")
        dep.set("name", name if name != "dep" else f"dep{n}")
        dep.set("client", PARTS.get(later, later))
        dep.set("supplier", PARTS.get(earlier, earlier))
        if stereotype:
            app = etree.SubElement(root, f"{{{ROBOMDA}}}StartAfter")
            app.set(_x("id"), f"_seqApp{n}")
            app.set("base_Dependency", f"_seqDep{n}")
    model = tmp_path / "model.xmi"
    tree.write(str(model), xml_declaration=True, encoding="UTF-8")
    return model


def bound(model: Path) -> etree._Element:
    return etree.fromstring(import_model(model).encode("utf-8"))


def start_orders(doc: etree._Element) -> dict[str, int | None]:
    """instance name -> @start-order (None when absent), in document order."""
    return {i.get("name"): (int(i.get("start-order")) if i.get("start-order") else None)
            for i in doc.iterfind("p:binding/p:instance", NS)}


def in_start_order(orders: dict[str, int | None]) -> list[str]:
    return [n for n, _ in sorted(((n, o) for n, o in orders.items() if o is not None), key=lambda t: t[1])]


def failure(model: Path, target: str | None = None) -> RobomdaError:
    with pytest.raises(RobomdaError) as info:
        if target:
            generate(model, model.parent / "out", target, write=False)
        else:
            import_model(model)
    return info.value


# ------------------------------------------------------------------ import
def test_import_keeps_start_after_dependencies_only(tmp_path: Path) -> None:
    model = headlamp(tmp_path, [("controller", "arm")])
    doc = etree.fromstring(import_model(model, bind=False).encode("utf-8"))
    deps = doc.findall(".//p:dependency", NS)
    assert len(deps) == 1
    assert deps[0].get("id") == "_seqDep1" and deps[0].get("qualified-name") == "headlamp::components::dep1"
    assert [s.get("name") for s in deps[0].findall("p:stereotype", NS)] == ["StartAfter"]
    assert deps[0].find("p:client", NS).get("element") == PARTS["controller"]
    assert deps[0].find("p:supplier", NS).get("element") == PARTS["arm"]


def test_import_drops_other_plain_dependencies(tmp_path: Path) -> None:
    model = headlamp(tmp_path, [("controller", "arm")], stereotype=False, name="needs")
    doc = etree.fromstring(import_model(model, bind=False).encode("utf-8"))
    assert doc.findall(".//p:dependency", NS) == []
    assert not any(i.findall("p:start-after", NS) for i in doc.iterfind("p:binding/p:instance", NS))


def test_unprofiled_dependency_named_start_after(tmp_path: Path) -> None:
    model = headlamp(tmp_path, [("camera", "arm")], stereotype=False, name="STARTAFTER")
    doc = bound(model)
    assert in_start_order(start_orders(doc)) == ["forceSensor", "vision", "controller", "arm", "camera"]


def test_a_usage_named_start_after_is_not_a_constraint(tmp_path: Path) -> None:
    model = headlamp(tmp_path, [("camera", "arm")], stereotype=False, name="startAfter", xmi_type="uml:Usage")
    assert start_orders(bound(model)) == {"camera": 1, "forceSensor": 2, "vision": 3, "controller": 4, "arm": 5}


def test_dangling_supplier_is_imp020(tmp_path: Path) -> None:
    model = headlamp(tmp_path, [("controller", "_gone")])
    diagnostics = failure(model).diagnostics
    assert [d.code for d in diagnostics] == ["IMP020"]
    assert diagnostics[0].xmi_id == "_seqDep1" and "_gone" in diagnostics[0].message
    assert diagnostics[0].line and diagnostics[0].file == str(model)


def test_dangling_client_is_imp020_in_the_ea_dialect(tmp_path: Path) -> None:
    text = (CASES / "headlamp" / "model.ea.xmi").read_text(encoding="cp1252")
    found = re.search(r'<packagedElement xmi:type="uml:Dependency" xmi:id="([^"]+)"[^>]*client="([^"]+)"', text)
    assert found, "the EA fixture has a StartAfter dependency"
    dep, client = found.groups()
    model = tmp_path / "model.ea.xmi"
    model.write_text(text[:found.start()] + found.group(0).replace(client, "EAID_MISSING") + text[found.end():],
                     encoding="cp1252")
    diagnostics = failure(model).diagnostics
    assert [d.code for d in diagnostics] == ["IMP020"]
    assert diagnostics[0].xmi_id == dep and "EAID_MISSING" in diagnostics[0].message


# -------------------------------------------------------------------- bind
def test_no_constraint_keeps_document_order(tmp_path: Path) -> None:
    doc = bound(headlamp(tmp_path, []))
    assert start_orders(doc) == {"camera": 1, "forceSensor": 2, "vision": 3, "controller": 4, "arm": 5}
    assert doc.findall(".//p:start-after", NS) == []


def test_fixture_controller_after_arm_and_vision() -> None:
    for name in ("model.xmi", "model.ea.xmi"):
        doc = bound(CASES / "headlamp" / name)
        assert start_orders(doc) == {"camera": 1, "forceSensor": 2, "vision": 3, "controller": 5, "arm": 4}, name
        controller = doc.find("p:binding/p:instance[@name='controller']", NS)
        assert [s.get("instance") for s in controller.findall("p:start-after", NS)] == ["arm", "vision"]
        deps = {d.get("name"): d.get("id") for d in doc.iterfind(".//p:dependency", NS)}
        assert [s.get("xmi-id") for s in controller.findall("p:start-after", NS)] == \
            [deps["controllerAfterArm"], deps["controllerAfterVision"]]


def test_chain(tmp_path: Path) -> None:
    # camera after arm, arm after controller: the chain controller, arm, camera
    doc = bound(headlamp(tmp_path, [("camera", "arm"), ("arm", "controller")]))
    assert start_orders(doc) == {"camera": 5, "forceSensor": 1, "vision": 2, "controller": 3, "arm": 4}
    camera = doc.find("p:binding/p:instance[@name='camera']", NS)
    assert [(s.get("instance"), s.get("xmi-id")) for s in camera.findall("p:start-after", NS)] == [("arm", "_seqDep1")]


def test_ties_keep_document_order(tmp_path: Path) -> None:
    # only vision is constrained: controller (free) keeps its place before arm
    doc = bound(headlamp(tmp_path, [("vision", "arm")]))
    assert in_start_order(start_orders(doc)) == ["camera", "forceSensor", "controller", "arm", "vision"]
    # two instances released by the same one start in document order
    doc = bound(headlamp(tmp_path, [("camera", "arm"), ("forceSensor", "arm"), ("vision", "controller")]))
    assert in_start_order(start_orders(doc)) == ["controller", "vision", "arm", "camera", "forceSensor"]


def test_duplicate_constraints_count_once_each(tmp_path: Path) -> None:
    doc = bound(headlamp(tmp_path, [("camera", "arm"), ("camera", "arm")]))
    assert in_start_order(start_orders(doc)) == ["forceSensor", "vision", "controller", "arm", "camera"]
    camera = doc.find("p:binding/p:instance[@name='camera']", NS)
    assert [s.get("xmi-id") for s in camera.findall("p:start-after", NS)] == ["_seqDep1", "_seqDep2"]


def test_cycle_leaves_start_order_off(tmp_path: Path) -> None:
    # arm <-> controller is a cycle; camera waits for arm, so it is after the cycle
    doc = bound(headlamp(tmp_path, [("arm", "controller"), ("controller", "arm"), ("camera", "arm")]))
    assert start_orders(doc) == {"camera": None, "forceSensor": 1, "vision": 2, "controller": None, "arm": None}


def test_self_constraint_is_a_cycle(tmp_path: Path) -> None:
    doc = bound(headlamp(tmp_path, [("vision", "vision")]))
    assert start_orders(doc) == {"camera": 1, "forceSensor": 2, "vision": None, "controller": 3, "arm": 4}


def test_components_mode(tmp_path: Path) -> None:
    """Without a composite the components are the instances (pid fixture)."""
    text = (CASES / "pid" / "model.xmi").read_text(encoding="utf-8")
    anchor = '    <packagedElement xmi:type="uml:Component" xmi:id="_pid071k" name="TrajectoryGenerator">'
    dep = ('    <packagedElement xmi:type="uml:Dependency" xmi:id="_seq1" name="startAfter"'
           ' client="_pid071k" supplier="_pid083k"/>\n')
    model = tmp_path / "model.xmi"
    model.write_text(text.replace(anchor, dep + anchor, 1), encoding="utf-8")
    doc = bound(model)
    assert doc.find("p:binding", NS).get("instances-from") == "components"
    assert start_orders(doc) == {"TrajectoryGenerator": 3, "PIDController": 1, "RobotInterface": 2}


@pytest.mark.parametrize(("later", "earlier", "what"), [
    ("controller", COMPOSITE, "supplier"),           # the composite is no instance
    ("_QZjQLKDPm9lYATkGnxV7dw", "arm", "client"),     # a port
])
def test_end_that_is_no_instance_is_bnd012(tmp_path: Path, later: str, earlier: str, what: str) -> None:
    model = headlamp(tmp_path, [("camera", "arm"), (later, earlier)])
    diagnostics = failure(model).diagnostics
    assert [d.code for d in diagnostics] == ["BND012"]
    assert diagnostics[0].xmi_id == "_seqDep2" and what in diagnostics[0].message
    assert diagnostics[0].line and diagnostics[0].element_kind == "uml:Dependency"


# ------------------------------------------------------------------ orocos
def deploy_files(model: Path) -> dict[str, str]:
    done = generate(model, model.parent / "out", "orocos", write=False)
    files = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {f.get("path"): f.text or "" for f in files.iter(f"{FS}file") if f.get("path").startswith("deploy/")}


def test_orocos_files_start_in_start_order(tmp_path: Path) -> None:
    files = deploy_files(headlamp(tmp_path, [("camera", "arm"), ("arm", "controller")]))
    order = ["forceSensor", "vision", "controller", "arm", "camera"]
    ops = files["deploy/headlamp.ops"]
    assert re.findall(r'^loadComponent\("(\w+)"', ops, re.M) == order
    assert re.findall(r"^if \( !(\w+)\.configure\(\) \)", ops, re.M) == order
    assert re.findall(r"^  if \( !(\w+)\.start\(\) \)", ops, re.M) == order
    assert "// in start order (deployment sequence: arm after controller; camera after arm)" in ops
    lua = files["deploy/headlamp.lua"]
    names = re.search(r"^local names = \{(.*)\}$", lua, re.M).group(1)
    assert re.findall(r'"(\w+)"', names) == order
    assert re.findall(r'depl:loadComponent\("(\w+)"', lua) == order
    assert "for _, n in ipairs(names) do check(comps[n]:start()" in lua
    xml = files["deploy/headlamp.xml"]
    assert re.findall(r'<struct name="(\w+)" type="headlamp::', xml) == order


def test_orocos_files_of_the_fixture() -> None:
    files = deploy_files(CASES / "headlamp" / "model.xmi")
    assert re.findall(r"^  if \( !(\w+)\.start\(\) \)", files["deploy/headlamp.ops"], re.M) == \
        ["camera", "forceSensor", "vision", "arm", "controller"]


def test_orocos_files_without_constraints_say_nothing(tmp_path: Path) -> None:
    files = deploy_files(headlamp(tmp_path, []))
    assert re.findall(r"^  if \( !(\w+)\.start\(\) \)", files["deploy/headlamp.ops"], re.M) == list(PARTS)
    assert not any("deployment sequence" in text for text in files.values())
