"""A robot's degrees of freedom from the robomda profile and from URDF files (issue 14, item 6; seed 001).

A Device stereotyped «Robot» names its degrees of freedom (tag dof) or a
URDF file (tag urdf, relative to the model file) whose movable joints the
import counts, on the chain from rootLink to tipLink when they are given
(xslt/import/urdf.xsl, pim:kinematic-chain); bind takes the tag, else the
URDF count, else the unprofiled attribute dof, warns when they disagree
(BND023), and checks the driving instances' arrays against it (BND021,
xslt/m2m/bind/devices.xsl). The models are the quad-arm fixture
(fixtures/cases/quadarm) with stereotype applications added here; the URDF
files are written here, small made-up robots.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import check, import_model
from robomda.diagnostics import Diagnostic, RobomdaError

ROOT = Path(__file__).resolve().parents[1]
QUADARM = ROOT / "fixtures" / "cases" / "quadarm"
PIM = "{urn:robomda:pim:1}"
LWR1, LWR2 = "_qa210v", "_qa220v"  # the quad-arm's first two arm devices (dof attribute 7 each)


# ------------------------------------------------------------------ models
@pytest.fixture
def model(tmp_path: Path) -> Path:
    """A copy of the quad-arm model (no atomic code: nothing is built here), to profile."""
    folder = tmp_path / "quadarm"
    folder.mkdir()
    shutil.copy(QUADARM / "model.xmi", folder / "model.xmi")
    return folder / "model.xmi"


def wrapped(text: str, inside: str, after: str) -> str:
    """A model file whose root is a uml:Model, wrapped in xmi:XMI (which can hold stereotype applications),
    with ``inside`` added at the end of the model and ``after`` after it."""
    start = re.search(r"<uml:Model ([^>]*)>", text)
    assert start, "the root is a uml:Model"
    namespaces = " ".join(re.findall(r'xmlns:\w+="[^"]*"', start.group(1)))
    rest = re.sub(r'\s*xmlns:\w+="[^"]*"|\s*xmi:version="[^"]*"', "", start.group(1)).strip()
    text = text.replace(start.group(0), f'<xmi:XMI xmi:version="20131001" {namespaces} '
                        f'xmlns:robomda="http://robomda.org/profile/robomda/1">\n<uml:Model {rest}>', 1)
    assert text.count("</uml:Model>") == 1
    return text.replace("</uml:Model>", f"{inside}</uml:Model>\n{after}</xmi:XMI>")


def robots(model: Path, applications: dict[str, dict[str, str]]) -> None:
    """Apply «Robot» to each device id with the given tags (the application of device ``_qa210v`` gets the
    xmi:id ``_robot_qa210v``)."""
    stereotypes = "".join(
        f'  <robomda:Robot xmi:id="_robot{device}" base_Device="{device}"'
        + "".join(f' {tag}="{value}"' for tag, value in tags.items()) + "/>\n"
        for device, tags in applications.items())
    model.write_text(wrapped(model.read_text(encoding="utf-8"), "", stereotypes), encoding="utf-8")


def without_dof_attribute(model: Path, device: str = LWR1) -> None:
    """Remove the unprofiled attribute dof of a device (its ownedAttribute element)."""
    text = model.read_text(encoding="utf-8")
    number = {LWR1: "1", LWR2: "2"}[device]
    attribute = re.compile(rf'\s*<ownedAttribute xmi:type="uml:Property" xmi:id="_qa2{number}1a" name="dof".*?</ownedAttribute>',
                           re.S)
    assert len(attribute.findall(text)) == 1
    model.write_text(attribute.sub("", text), encoding="utf-8")


# ------------------------------------------------------------------- URDF
def urdf(path: Path, joints: list[tuple[str, str, str, str]], *, name: str = "robot", extra: str = "") -> Path:
    """A URDF file: one link per name the joints use, then the joints (name, type, parent, child)."""
    links: list[str] = []
    for _, _, parent, child in joints:
        links += [x for x in (parent, child) if x not in links]
    lines = ['<?xml version="1.0"?>', f'<robot name="{name}">']
    lines += [f'  <link name="{link}"/>' for link in links]
    for joint, kind, parent, child in joints:
        lines += [f'  <joint name="{joint}" type="{kind}">', f'    <parent link="{parent}"/>',
                  f'    <child link="{child}"/>', '    <axis xyz="0 0 1"/>', '  </joint>']
    lines += [extra, "</robot>", ""]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines), encoding="utf-8")
    return path


def serial(prefix: str, count: int, base: str, kind: str = "revolute") -> list[tuple[str, str, str, str]]:
    """``count`` joints in a row below link ``base``: <prefix>1 .. <prefix>N moving links <prefix>link1 ..."""
    links = [base] + [f"{prefix}link{i}" for i in range(1, count + 1)]
    return [(f"{prefix}{i}", kind, links[i - 1], links[i]) for i in range(1, count + 1)]


def arm(path: Path, count: int) -> Path:
    """A serial arm: ``count`` revolute joints from base to link<count>, and a fixed flange."""
    return urdf(path, serial("a", count, "base") + [("flange", "fixed", f"alink{count}", "tool")], name=f"arm{count}")


def torso(path: Path) -> Path:
    """A two-armed robot: a prismatic lift, a 7-joint left arm, a 6-joint right arm with a two-finger
    gripper (one finger mimics the other), a continuous head joint, a fixed camera.

        world -lift- torso -l1..l7- llink7 (left)
                     torso -r1..r6- rlink6 -fixed- hand -finger_a / finger_b (mimic)
                     torso -pan- head -fixed- camera
    """
    joints = ([("lift", "prismatic", "world", "torso")] + serial("l", 7, "torso") + serial("r", 6, "torso")
              + [("wrist_flange", "fixed", "rlink6", "hand"), ("finger_a", "prismatic", "hand", "finger_a_link"),
                 ("finger_b", "prismatic", "hand", "finger_b_link"), ("pan", "continuous", "torso", "head"),
                 ("camera_mount", "fixed", "head", "camera")])
    path = urdf(path, joints, name="twoarms")
    text = path.read_text(encoding="utf-8")
    mimic = '    <child link="finger_b_link"/>\n'
    path.write_text(text.replace(mimic, mimic + '    <mimic joint="finger_a" multiplier="1"/>\n'), encoding="utf-8")
    return path


# ------------------------------------------------------------------ helpers
def pim(model: Path, warnings: list[Diagnostic] | None = None) -> etree._Element:
    return etree.fromstring(import_model(model, bind=False, warnings=warnings).encode("utf-8"))


def chain(model: Path, device: str = LWR1) -> etree._Element | None:
    node = pim(model).find(f".//{PIM}node[@id='{device}']")
    assert node is not None
    return node.find(f"{PIM}kinematic-chain")


def joints(found: etree._Element | None) -> list[str]:
    assert found is not None
    return [j.get("name") for j in found.iter(f"{PIM}joint")]


def failure(model: Path) -> RobomdaError:
    with pytest.raises(RobomdaError) as info:
        import_model(model, bind=False)
    return info.value


def only(error: RobomdaError, code: str) -> Diagnostic:
    """The one diagnostic of ``error``, which must have ``code`` and be located on the «Robot» application."""
    assert [d.code for d in error.diagnostics] == [code], str(error)
    found = error.diagnostics[0]
    assert found.xmi_id == f"_robot{LWR1}" and found.element_kind == "robomda:Robot", found.format()
    assert found.line and found.file and found.file.endswith("model.xmi"), found.format()
    assert error.exit_code == 1 and "Traceback" not in str(error) and "INTERNAL" not in str(error)
    return found


# ===================================================== counting the joints
def test_the_movable_joints_of_the_whole_file_without_root_and_tip(model: Path) -> None:
    arm(model.parent / "arm6.urdf", 6)
    robots(model, {LWR1: {"urdf": "arm6.urdf"}})
    found = chain(model)
    assert found is not None and found.get("dof") == "6" and found.get("robot") == "arm6"
    assert found.get("urdf") == "arm6.urdf" and found.get("root-link") is None and found.get("tip-link") is None
    # the fixed flange does not count; the joints in file order
    assert joints(found) == ["a1", "a2", "a3", "a4", "a5", "a6"]
    # a device without the stereotype has no chain
    assert chain(model, LWR2) is None


def test_revolute_continuous_prismatic_count_one_fixed_and_mimic_none(model: Path) -> None:
    torso(model.parent / "twoarms.urdf")
    robots(model, {LWR1: {"urdf": "twoarms.urdf"}})
    found = chain(model)
    # lift + 7 + 6 + finger_a + pan = 16; finger_b mimics finger_a
    assert found is not None and found.get("dof") == "16"
    mimic = found.find(f"{PIM}joint[@name='finger_b']")
    assert mimic is not None and mimic.get("mimics") == "finger_a" and mimic.get("type") == "prismatic"
    assert {j.get("type") for j in found.iter(f"{PIM}joint")} == {"prismatic", "revolute", "continuous"}


@pytest.mark.parametrize("tags, dof, expected", [
    ({"rootLink": "torso", "tipLink": "llink7"}, "7", [f"l{i}" for i in range(1, 8)]),
    ({"rootLink": "world", "tipLink": "llink7"}, "8", ["lift"] + [f"l{i}" for i in range(1, 8)]),
    ({"rootLink": "rlink2", "tipLink": "finger_b_link"}, "4", ["r3", "r4", "r5", "r6", "finger_b"]),
    ({"tipLink": "rlink6"}, "7", ["lift"] + [f"r{i}" for i in range(1, 7)]),
    ({"rootLink": "rlink4"}, "3", ["r5", "r6", "finger_a", "finger_b"]),
    ({"rootLink": "head", "tipLink": "camera"}, "0", []),
    ({"rootLink": "torso", "tipLink": "torso"}, "0", []),
], ids=["root-tip", "from-the-tree-root", "through-a-fixed-joint", "tip-only", "root-only", "fixed-only", "one-link"])
def test_the_chain_from_root_link_to_tip_link(model: Path, tags: dict[str, str], dof: str, expected: list[str]) -> None:
    torso(model.parent / "robots" / "twoarms.urdf")
    robots(model, {LWR1: {"urdf": "robots/twoarms.urdf", **tags}})
    found = chain(model)
    assert found is not None and found.get("dof") == dof
    assert joints(found) == expected  # from the root down (root only: file order)
    assert found.get("root-link") == tags.get("rootLink") and found.get("tip-link") == tags.get("tipLink")


def test_a_path_with_spaces_and_backslashes(model: Path) -> None:
    arm(model.parent / "robot files" / "arm 5.urdf", 5)
    robots(model, {LWR1: {"urdf": "robot files\\arm 5.urdf"}})
    found = chain(model)
    assert found is not None and found.get("dof") == "5" and found.get("urdf") == "robot files\\arm 5.urdf"


def test_a_file_in_the_model_path(model: Path, tmp_path: Path) -> None:
    arm(tmp_path / "descriptions" / "arm4.urdf", 4)
    robots(model, {LWR1: {"urdf": "../descriptions/arm4.urdf"}})
    assert only(failure(model), "IMP040")
    text = import_model(model, bind=False, model_path=[tmp_path / "descriptions"])
    assert 'dof="4"' in text


def test_tags_as_child_elements_and_unset_tags_as_empty_strings(model: Path) -> None:
    """Some tools write a tag as a child element; EA writes unset String tags as ""."""
    arm(model.parent / "arm3.urdf", 3)
    robots(model, {LWR1: {"rootLink": "", "tipLink": ""}})
    text = model.read_text(encoding="utf-8")
    assert text.count('rootLink="" tipLink=""/>') == 1
    model.write_text(text.replace('rootLink="" tipLink=""/>',
                                  'rootLink="" tipLink=""><urdf>arm3.urdf</urdf></robomda:Robot>'), encoding="utf-8")
    found = chain(model)
    assert found is not None and found.get("dof") == "3" and found.get("root-link") is None


def test_a_device_of_another_model_file_reads_its_urdf_beside_that_file(tmp_path: Path) -> None:
    """Models split over several files (fixtures/cases/split): the path is relative to the file of the Device."""
    shutil.copytree(ROOT / "fixtures" / "cases" / "split", tmp_path / "split", ignore=shutil.ignore_patterns("expected"))
    library = tmp_path / "split" / "components" / "RobotInterface.compdef.uml"
    library.write_text(wrapped(library.read_text(encoding="utf-8"),
                               '  <packagedElement xmi:type="uml:Device" xmi:id="_spArm" name="arm"/>\n',
                               '  <robomda:Robot xmi:id="_spArmR" base_Device="_spArm" urdf="arm.urdf"/>\n'),
                       encoding="utf-8")
    arm(library.parent / "arm.urdf", 4)
    arm(tmp_path / "split" / "arm.urdf", 5)  # beside the model file: not the one meant
    found = pim(tmp_path / "split" / "model.xmi").find(f".//{PIM}node[@id='_spArm']/{PIM}kinematic-chain")
    assert found is not None and found.get("dof") == "4"
    (library.parent / "arm.urdf").unlink()
    [missing] = failure(tmp_path / "split" / "model.xmi").diagnostics
    assert missing.code == "IMP042" and missing.xmi_id == "_spArmR"
    assert missing.file and missing.file.endswith("RobotInterface.compdef.uml") and missing.line


# =================================================================== errors
def test_a_missing_urdf_file(model: Path) -> None:
    robots(model, {LWR1: {"urdf": "robots/nowhere.urdf"}})
    found = only(failure(model), "IMP042")
    assert "'robots/nowhere.urdf'" in found.message and "device 'lwr1'" in found.message
    assert "is not there" in found.message


def test_a_urdf_file_that_is_not_well_formed(model: Path) -> None:
    path = arm(model.parent / "broken.urdf", 3)
    path.write_text(path.read_text(encoding="utf-8").replace("</robot>", ""), encoding="utf-8")
    robots(model, {LWR1: {"urdf": "broken.urdf"}})
    found = only(failure(model), "IMP043")
    assert "'broken.urdf'" in found.message and "not well-formed XML" in found.message


def test_a_urdf_file_without_a_robot(model: Path) -> None:
    (model.parent / "scene.urdf").write_text('<?xml version="1.0"?>\n<world name="w"><link name="ground"/></world>\n',
                                             encoding="utf-8")
    robots(model, {LWR1: {"urdf": "scene.urdf"}})
    found = only(failure(model), "IMP044")
    assert "root element is world, not robot" in found.message


def test_an_unexpanded_xacro_file(model: Path) -> None:
    path = arm(model.parent / "arm.urdf.xacro", 2)
    text = path.read_text(encoding="utf-8").replace(
        '<robot name="arm2">', '<robot name="arm2" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:property name="reach" value="0.8"/>')
    path.write_text(text, encoding="utf-8")
    robots(model, {LWR1: {"urdf": "arm.urdf.xacro"}})
    found = only(failure(model), "IMP044")
    assert "xacro" in found.message and "expand it" in found.message


@pytest.mark.parametrize("path", ["../outside.urdf", "package://lwr_description/urdf/lwr.urdf",
                                  "http://example.org/lwr.urdf"])
def test_a_file_outside_the_models_folder(model: Path, path: str) -> None:
    arm(model.parent.parent / "outside.urdf", 2)
    robots(model, {LWR1: {"urdf": path}})
    found = only(failure(model), "IMP040")
    assert f"'{path}'" in found.message and "--model-path" in found.message


@pytest.mark.parametrize("tags, named", [
    ({"rootLink": "pelvis", "tipLink": "llink7"}, ["rootLink", "pelvis"]),
    ({"rootLink": "torso", "tipLink": "gripper"}, ["tipLink", "gripper"]),
])
def test_a_root_or_tip_link_the_urdf_does_not_have(model: Path, tags: dict[str, str], named: list[str]) -> None:
    torso(model.parent / "twoarms.urdf")
    robots(model, {LWR1: {"urdf": "twoarms.urdf", **tags}})
    found = only(failure(model), "IMP045")
    assert all(word in found.message for word in named) and "its links: world, torso" in found.message


def test_both_links_missing_are_both_reported(model: Path) -> None:
    torso(model.parent / "twoarms.urdf")
    robots(model, {LWR1: {"urdf": "twoarms.urdf", "rootLink": "pelvis", "tipLink": "gripper"}})
    error = failure(model)
    assert [d.code for d in error.diagnostics] == ["IMP045", "IMP045"]
    assert "'pelvis'" in error.diagnostics[0].message and "'gripper'" in error.diagnostics[1].message


@pytest.mark.parametrize("root, tip", [("llink3", "rlink2"), ("llink7", "torso")],
                         ids=["another-branch", "above-the-root"])
def test_a_tip_not_below_the_root(model: Path, root: str, tip: str) -> None:
    torso(model.parent / "twoarms.urdf")
    robots(model, {LWR1: {"urdf": "twoarms.urdf", "rootLink": root, "tipLink": tip}})
    found = only(failure(model), "IMP046")
    assert f"from link '{root}' (rootLink) to link '{tip}' (tipLink)" in found.message
    assert f"'{tip}' is not below '{root}'" in found.message


@pytest.mark.parametrize("kind", ["floating", "planar", "spherical"])
def test_a_joint_robomda_does_not_count(model: Path, kind: str) -> None:
    urdf(model.parent / "mobile.urdf", [("base", kind, "odom", "base_link")] + serial("a", 3, "base_link"))
    robots(model, {LWR1: {"urdf": "mobile.urdf"}})
    found = only(failure(model), "IMP047")
    assert f"joint 'base' of type '{kind}'" in found.message and "rootLink / tipLink" in found.message
    # a chain that leaves it out is counted
    robots_tags = model.read_text(encoding="utf-8").replace('urdf="mobile.urdf"', 'urdf="mobile.urdf" rootLink="base_link"')
    model.write_text(robots_tags, encoding="utf-8")
    found_chain = chain(model)
    assert found_chain is not None and found_chain.get("dof") == "3"


def test_every_urdf_error_of_the_model_at_once(model: Path) -> None:
    robots(model, {LWR1: {"urdf": "one.urdf"}, LWR2: {"urdf": "two.urdf"}})
    error = failure(model)
    assert [(d.code, d.xmi_id) for d in error.diagnostics] == [("IMP042", f"_robot{LWR1}"), ("IMP042", f"_robot{LWR2}")]


def test_root_and_tip_without_a_urdf_file_are_named(model: Path) -> None:
    robots(model, {LWR1: {"dof": "7", "rootLink": "base"}})
    said: list[Diagnostic] = []
    found = pim(model, said)
    assert found.find(f".//{PIM}kinematic-chain") is None
    assert [(d.code, d.severity, d.xmi_id) for d in said if d.code == "IMP048"] == [("IMP048", "warning", f"_robot{LWR1}")]


def test_the_check_command_exits_1_without_a_traceback(model: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from robomda.cli import main

    path = arm(model.parent / "broken.urdf", 3)
    path.write_text(path.read_text(encoding="utf-8")[:-20], encoding="utf-8")
    robots(model, {LWR1: {"urdf": "broken.urdf"}})
    assert main(["check", str(model), "--target", "orocos"]) == 1
    err = capsys.readouterr().err
    assert re.search(r"model\.xmi:\d+:\d+: error: \[IMP043\] the URDF file 'broken\.urdf' of device 'lwr1' "
                     r"is not well-formed XML", err), err
    assert "Traceback" not in err and "INTERNAL" not in err


def test_an_external_entity_in_the_urdf_reads_no_file(model: Path, tmp_path: Path) -> None:
    """The URDF is parsed like the model (tests/test_xxe.py): no external entity, no DTD."""
    secret = model.parent / "secret.txt"
    secret.write_text("robomda-secret-5e1d\n", encoding="utf-8")
    path = arm(model.parent / "leaky.urdf", 2)
    text = path.read_text(encoding="utf-8").replace(
        '<robot name="arm2">', f'<!DOCTYPE robot [\n  <!ENTITY leak SYSTEM "{secret.as_uri()}">\n]>\n<robot name="arm2">'
        '\n  <material name="m">&leak;</material>')
    path.write_text(text, encoding="utf-8")
    robots(model, {LWR1: {"urdf": "leaky.urdf"}})
    found = chain(model)
    assert found is not None and found.get("dof") == "2"
    assert "robomda-secret" not in import_model(model)


# ========================================= bind: which number, and the check
def warnings(model: Path) -> list[Diagnostic]:
    return check(model, "orocos").diagnostics


def test_the_dof_mismatch_warning_with_the_urdf_count(model: Path) -> None:
    """Seed 001's DoF mismatch with the number read from the URDF file, located on both elements."""
    arm(model.parent / "arm6.urdf", 6)
    robots(model, {LWR1: {"urdf": "arm6.urdf"}})
    without_dof_attribute(model)
    said = warnings(model)
    assert not [d for d in said if d.severity == "error"], said
    mismatch = [d for d in said if d.code == "BND021"]
    on_port = [d for d in mismatch if d.xmi_id == "_qa090q"]  # arm1's jointState port
    on_device = [d for d in mismatch if d.xmi_id == LWR1 and "port 'jointState' of arm1" in d.message]
    assert len(on_port) == 1 and len(on_device) == 1
    for found in on_port + on_device:
        assert "has 6 degrees of freedom (the movable joints of URDF file 'arm6.urdf')" in found.message
        assert "JointState.position[7]" in found.message and found.line
    assert on_port[0].element_kind == "uml:Port" and on_device[0].element_kind == "uml:Device"
    # the controller connected to arm1 is checked too; the other arms are not concerned
    assert {d.xmi_id for d in mismatch} == {"_qa090q", "_qa091q", "_qa095q", "_qa096q", "_qa064a", LWR1}
    assert not [d for d in said if d.code in ("BND022", "BND023")]


def test_a_urdf_that_fits_the_arrays_gives_no_warning(model: Path) -> None:
    torso(model.parent / "twoarms.urdf")
    robots(model, {LWR1: {"urdf": "twoarms.urdf", "rootLink": "torso", "tipLink": "llink7"}})
    assert not [d for d in warnings(model) if d.code.startswith("BND02")]


def test_the_tag_wins_and_disagreeing_sources_are_named(model: Path) -> None:
    arm(model.parent / "arm6.urdf", 6)
    robots(model, {LWR1: {"urdf": "arm6.urdf", "dof": "5"}})
    said = warnings(model)
    [disagree] = [d for d in said if d.code == "BND023"]
    assert disagree.severity == "warning" and disagree.xmi_id == f"_robot{LWR1}" and disagree.line
    assert disagree.message == ("device 'lwr1' declares its degrees of freedom three times, differently: "
                                "5 (the Robot tag dof), 6 (the movable joints of URDF file 'arm6.urdf'), "
                                "7 (the attribute dof); robomda checks against 5, the Robot tag dof")
    assert all("has 5 degrees of freedom (the Robot tag dof)" in d.message for d in said if d.code == "BND021")


@pytest.mark.parametrize("tags, attribute, expected", [
    ({"urdf": "arm6.urdf"}, True, "twice, differently: 6 (the movable joints of URDF file 'arm6.urdf'), "
                                  "7 (the attribute dof); robomda checks against 6"),
    ({"dof": "7", "urdf": "arm6.urdf"}, False, "twice, differently: 7 (the Robot tag dof), "
                                               "6 (the movable joints of URDF file 'arm6.urdf'); robomda checks against 7"),
    ({"dof": "6"}, True, "twice, differently: 6 (the Robot tag dof), 7 (the attribute dof)"),
    ({"dof": "7"}, True, None),
    ({"dof": "7", "urdf": "arm7.urdf"}, True, None),
], ids=["urdf-attribute", "tag-urdf", "tag-attribute", "tag-agrees", "all-agree"])
def test_two_sources_that_disagree(model: Path, tags: dict[str, str], attribute: bool, expected: str | None) -> None:
    arm(model.parent / "arm6.urdf", 6)
    arm(model.parent / "arm7.urdf", 7)
    robots(model, {LWR1: tags})
    if not attribute:
        without_dof_attribute(model)
    disagree = [d.message for d in warnings(model) if d.code == "BND023"]
    if expected is None:
        assert disagree == []
    else:
        assert len(disagree) == 1 and expected in disagree[0], disagree


def test_a_device_nobody_drives_is_checked_for_disagreement_too(model: Path) -> None:
    text = model.read_text(encoding="utf-8")
    drives = '<packagedElement xmi:type="uml:Dependency" xmi:id="_qa223d" name="drives" client="_qa102m" supplier="_qa220v"/>'
    assert text.count(drives) == 1
    model.write_text(text.replace(drives, ""), encoding="utf-8")
    robots(model, {LWR2: {"dof": "6"}})
    said = warnings(model)
    assert [d.xmi_id for d in said if d.code == "BND023"] == [f"_robot{LWR2}"]
    assert not [d for d in said if d.code == "BND021" and "lwr2" in d.message]


def test_dof_zero_is_the_unset_default(model: Path) -> None:
    """EMF writes no Integer tag equal to its default 0 and other tools may write 0: it means not given."""
    robots(model, {LWR1: {"dof": "0"}})
    said = warnings(model)
    assert not [d for d in said if d.code.startswith("BND02")], said


def test_a_robot_with_nothing_declared(model: Path) -> None:
    robots(model, {LWR1: {}})
    without_dof_attribute(model)
    [missing] = [d for d in warnings(model) if d.code == "BND022"]
    assert missing.xmi_id == LWR1 and "a Robot tag dof or urdf, or an attribute dof" in missing.message


def test_a_tag_dof_that_is_no_number_of_joints(model: Path) -> None:
    robots(model, {LWR1: {"dof": "seven"}, LWR2: {"dof": "-2"}})
    result = check(model, "orocos")
    assert result.exit_code == 1
    errors = [d for d in result.diagnostics if d.severity == "error"]
    assert [(d.code, d.xmi_id) for d in errors] == [("BND010", f"_robot{LWR1}"), ("BND010", f"_robot{LWR2}")]
    assert "'seven' is not a number of degrees of freedom" in errors[0].message
    assert all(d.element_kind == "robomda:Robot" for d in errors)


# ================================================================= engines
from test_engines import ENGINES, Cli  # noqa: E402  (the engines' command lines, shared)

IMPORT_XSL = ROOT / "xslt" / "import" / "import.xsl"
BIND_XSL = ROOT / "xslt" / "m2m" / "bind.xsl"


@pytest.fixture(scope="module")
def workdir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("urdf-engines")


def _run(engine: Cli, xsl: Path, source: Path, out: Path, params: dict[str, str], workdir: Path):
    import subprocess

    cmd = engine.argv + [f"-s:{source}", f"-xsl:{engine.stylesheet(xsl, workdir)}", f"-o:{out}"]
    return subprocess.run(cmd + [f"{k}={v}" for k, v in params.items()], capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize("engine", ENGINES)
def test_saxon_java_and_saxonjs_read_the_urdf_as_saxonc_does(engine: Cli, model: Path, tmp_path: Path,
                                                              workdir: Path) -> None:
    """Import and bind of URDF chains give the same bytes and the same warnings under every engine."""
    torso(model.parent / "robot files" / "twoarms.urdf")
    arm(model.parent / "arm6.urdf", 6)
    robots(model, {LWR1: {"urdf": "robot files/twoarms.urdf", "rootLink": "torso", "tipLink": "llink7", "dof": "6"},
                   LWR2: {"urdf": "arm6.urdf"}, "_qa230v": {"urdf": "robot files/twoarms.urdf", "rootLink": "rlink2"}})
    imported = tmp_path / "import.xml"
    done = _run(engine, IMPORT_XSL, model, imported, {"source-name": "model.xmi", "model-path": ""}, workdir)
    assert done.returncode == 0, done.stderr[-3000:]
    assert imported.read_text(encoding="utf-8") == import_model(model, bind=False)
    bound = tmp_path / "bind.xml"
    done = _run(engine, BIND_XSL, imported, bound, {}, workdir)
    assert done.returncode == 0, done.stderr[-3000:]
    assert bound.read_text(encoding="utf-8") == import_model(model)
    said: list[Diagnostic] = []
    import_model(model, warnings=said)
    # the same warnings, in the same order
    expected = [f"{d.code}: {d.message}" for d in said if d.code.startswith("BND02")]
    assert "BND023" in expected[0] and "BND021" in expected[-1]
    assert re.findall(r"(BND02\d: .*?) \[xmi:id=", done.stderr) == expected


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("case, code", [("missing", "IMP042"), ("malformed", "IMP043"), ("tip", "IMP046"),
                                        ("outside", "IMP040")])
def test_saxon_java_and_saxonjs_refuse_a_bad_urdf_as_saxonc_does(engine: Cli, model: Path, tmp_path: Path,
                                                                  workdir: Path, case: str, code: str) -> None:
    """Never an engine's own error (a parse error of doc(), a type error): robomda's code and message."""
    torso(model.parent / "twoarms.urdf")
    (model.parent / "broken.urdf").write_text("<robot><link name='a'></robot>\n", encoding="utf-8")
    tags = {"missing": {"urdf": "nowhere.urdf"}, "malformed": {"urdf": "broken.urdf"},
            "tip": {"urdf": "twoarms.urdf", "rootLink": "llink2", "tipLink": "rlink5"},
            "outside": {"urdf": "../twoarms.urdf"}}[case]
    robots(model, {LWR1: tags})
    [expected] = failure(model).diagnostics
    assert expected.code == code
    done = _run(engine, IMPORT_XSL, model, tmp_path / "import.xml", {"source-name": "model.xmi", "model-path": ""}, workdir)
    assert done.returncode != 0
    assert f"{code}: {expected.message} [xmi:id=_robot{LWR1}]" in " ".join(done.stderr.split()), done.stderr[-3000:]
