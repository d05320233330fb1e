"""Models split over several files in their tools' own layouts (issue 30, classes 2, 3 and 8).

The models are built here from the split fixture (fixtures/cases/split: the
pid loop in the export dialect of Papyrus, a system model whose parts are
hrefs into component definitions typed by a services file) laid out as
Papyrus for Robotics, Papyrus Designer, Eclipse UML2 and RSA keep them, and
from small files written by the builders below (ids shared by several files,
MagicDraw used projects):

- the sandbox is the model's project (the nearest folder above it with a
  .project, .git, .hg or .svn) and the other projects of its workspace,
  plus --model-path; every reference outside it is named in one run;
- platform:/resource/<Project>/ is followed, platform:/plugin/ never;
- RSA fragments (#id?Path/Name?) and URL-encoded names are read;
- an xmi:id is per file: two files may share one;
- a MagicDraw used project is an external reference with one warning.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import import_model
from robomda.cli import main
from robomda.diagnostics import Diagnostic, RobomdaError, linked_files

ROOT = Path(__file__).resolve().parents[1]
SPLIT = ROOT / "fixtures" / "cases" / "split"
PIM = "{urn:robomda:pim:1}"
COMPONENTS = ("TrajectoryGenerator", "PIDController", "RobotInterface")


# ================================================================= builders
def _mark(folder: Path, marker: str) -> None:
    """Make ``folder`` a project: an Eclipse .project, a git / Mercurial / Subversion root."""
    path = folder / marker
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text({".project": '<?xml version="1.0"?>\n<projectDescription><name>'
                                 f'{folder.name}</name></projectDescription>\n',
                     ".git": "gitdir: /elsewhere/.git/worktrees/x\n"}.get(marker, "ref: refs/heads/main\n"),
                    encoding="utf-8")


def _system(dest: Path, prefix: str) -> Path:
    """The split fixture's system model at ``dest``, its hrefs into the component files as ``prefix``."""
    text = (SPLIT / "model.xmi").read_text(encoding="utf-8").replace('href="components/', f'href="{prefix}')
    dest.parent.mkdir(parents=True, exist_ok=True)
    dest.write_text(text, encoding="utf-8")
    return dest


def _libraries(folder: Path) -> None:
    """The split fixture's components/ and services/ folders in ``folder``."""
    for name in ("components", "services"):
        shutil.copytree(SPLIT / name, folder / name)


def robotics_layout(tmp_path: Path, marker: str | None = ".project") -> Path:
    """Papyrus for Robotics: RobotProj/models/{system,components,services}, the system referring to
    ../components/X.compdef.uml and those to ../services/joint.servicedef.uml."""
    project = tmp_path / "ws" / "RobotProj"
    _libraries(project / "models")
    if marker:
        _mark(project, marker)
    return _system(project / "models" / "system" / "model.xmi", "../components/")


def workspace_layout(tmp_path: Path, prefix: str) -> Path:
    """Papyrus Designer / Eclipse UML2 / RSA: the system in project App, the components and services in
    the sibling project Lib, referred to as ``prefix`` (../../Lib/components/, platform:/resource/...)."""
    workspace = tmp_path / "ws"
    _libraries(workspace / "Lib")
    _mark(workspace / "Lib", ".project")
    _mark(workspace / "App", ".project")
    return _system(workspace / "App" / "models" / "model.xmi", prefix)


def _pim(model: Path, **kwargs) -> etree._Element:
    return etree.fromstring(import_model(model, **kwargs).encode())


def _files(pim: etree._Element) -> set[str]:
    return {p.get("file") for p in pim.iter(f"{PIM}package") if p.get("file")}


def _refused(model: Path, **kwargs) -> list[Diagnostic]:
    with pytest.raises(RobomdaError) as refused:
        import_model(model, **kwargs)
    return refused.value.diagnostics


def _connected(pim: etree._Element) -> set[str]:
    return {c.get("name") for c in pim.find(f"{PIM}binding").iter(f"{PIM}connection")}


CONNECTIONS = {"desiredPositionConn", "measuredPositionConn", "referenceTorqueConn"}


# ================================================== class 2: the sandbox
@pytest.mark.parametrize("marker", [".project", ".git/HEAD", ".git", ".hg/requires", ".svn/entries"])
def test_papyrus_for_robotics_layout_reads_its_sibling_folders(tmp_path: Path, marker: str) -> None:
    model = robotics_layout(tmp_path, marker)
    pim = _pim(model)
    assert _files(pim) == {f"../components/{c}.compdef.uml" for c in COMPONENTS} | {"../services/joint.servicedef.uml"}
    assert _connected(pim) == CONNECTIONS
    # batch and watch hash the same files the import read
    assert {p.name for p in linked_files(model)} == {f"{c}.compdef.uml" for c in COMPONENTS} | {"joint.servicedef.uml"}


def test_without_a_project_every_refused_reference_is_named_in_one_run(tmp_path: Path, capsys) -> None:
    """No folder above the model marks a project: the sandbox is the model's folder, and each of the three
    component files is refused, each located on its own referencing element."""
    model = robotics_layout(tmp_path, marker=None)
    found = _refused(model)
    assert [d.code for d in found] == ["IMP040"] * 3
    assert {c for c in COMPONENTS for d in found if f"{c}.compdef.uml" in d.message} == set(COMPONENTS)
    assert all("no folder above it is a project" in d.message and "--model-path" in d.message for d in found)
    assert all(d.file == str(model) and d.line for d in found)
    assert len({d.line for d in found}) == 3
    assert linked_files(model) == []
    # --model-path still opens a folder
    assert _connected(_pim(model, model_path=[model.parent.parent])) == CONNECTIONS


@pytest.mark.parametrize("prefix", ["../../Lib/components/", "platform:/resource/Lib/components/"])
def test_a_sibling_project_of_the_workspace(tmp_path: Path, prefix: str) -> None:
    model = workspace_layout(tmp_path, prefix)
    pim = _pim(model)
    assert _connected(pim) == CONNECTIONS
    assert _files(pim) == {f"../../Lib/components/{c}.compdef.uml" for c in COMPONENTS} | {
        "../../Lib/services/joint.servicedef.uml"}
    assert {p.parent.name for p in linked_files(model)} == {"components", "services"}


@pytest.mark.parametrize("prefix", ["../../Lib/components/", "platform:/resource/Lib/components/"])
def test_a_folder_of_the_workspace_that_is_no_project_is_refused(tmp_path: Path, prefix: str) -> None:
    model = workspace_layout(tmp_path, prefix)
    (model.parents[2] / "Lib" / ".project").unlink()
    found = _refused(model)
    assert [d.code for d in found] == ["IMP040"] * 3
    assert all("the model's project" in d.message and "App" in d.message for d in found)
    assert linked_files(model) == []


def test_platform_resource_without_a_project_names_the_fix(tmp_path: Path) -> None:
    model = workspace_layout(tmp_path, "platform:/resource/Lib/components/")
    for project in ("App", "Lib"):
        (tmp_path / "ws" / project / ".project").unlink()
    found = _refused(model)
    assert [d.code for d in found] == ["IMP040"] * 3
    assert all("Eclipse project 'Lib'" in d.message and "knows no workspace" in d.message for d in found)
    # the model path names the project's folder, or the folder holding it
    for folder in (tmp_path / "ws" / "Lib", tmp_path / "ws"):
        assert _connected(_pim(model, model_path=[folder])) == CONNECTIONS
        assert len(linked_files(model, (folder,))) == 4


def test_platform_plugin_and_the_network_stay_external(tmp_path: Path) -> None:
    """platform:/plugin/ (a library shipped in a tool's plug-in) and http: are never loaded nor refused."""
    model = robotics_layout(tmp_path)
    text = model.read_text(encoding="utf-8")
    model.write_text(text.replace(
        '<ownedAttribute xmi:type="uml:Property" xmi:id="_spY1p"',
        '<ownedAttribute xmi:type="uml:Property" xmi:id="_spYx1" name="flag">\n'
        '        <type xmi:type="uml:PrimitiveType" href="platform:/plugin/org.example.libs/Types.uml#_b?Types/Boolean?"/>\n'
        '      </ownedAttribute>\n'
        '      <ownedAttribute xmi:type="uml:Property" xmi:id="_spYx2" name="remote">\n'
        '        <type xmi:type="uml:DataType" href="http://example.org/models/Remote.uml#_r"/>\n'
        '      </ownedAttribute>\n'
        '      <ownedAttribute xmi:type="uml:Property" xmi:id="_spY1p"'), encoding="utf-8")
    warnings: list[Diagnostic] = []
    pim = _pim(model, warnings=warnings)
    assert not [w for w in warnings if w.code in ("IMP040", "IMP041")]
    attrs = {a.get("name"): a for a in pim.iter(f"{PIM}attribute")}
    assert attrs["flag"].get("type-name") == "Boolean" and attrs["flag"].get("primitive") == "boolean"
    assert attrs["remote"].get("type-library") == "external"


def test_a_reference_that_climbs_out_of_the_project_is_refused(tmp_path: Path) -> None:
    """Inside a project a reference still cannot leave it (nor the workspace's projects)."""
    model = robotics_layout(tmp_path)
    secret = tmp_path / "private" / "types.uml"
    secret.parent.mkdir()
    shutil.copy(SPLIT / "services" / "joint.servicedef.uml", secret)
    services = model.parents[1] / "components" / "PIDController.compdef.uml"
    services.write_text(services.read_text(encoding="utf-8").replace(
        "../services/joint.servicedef.uml", "../../../../private/types.uml"), encoding="utf-8")
    found = _refused(model)
    assert {d.code for d in found} == {"IMP040"}
    assert "private/types.uml" in found[0].message and found[0].file.endswith("PIDController.compdef.uml")


# ======================================== RSA fragments, URL-encoded names
def test_rsa_fragments_name_the_id_before_the_readable_path(tmp_path: Path) -> None:
    model = workspace_layout(tmp_path, "platform:/resource/Lib/components/")
    text = model.read_text(encoding="utf-8")
    for comp, comp_id in (("TrajectoryGenerator", "_spTk"), ("PIDController", "_spPk"), ("RobotInterface", "_spRk")):
        text = text.replace(f'{comp}.compdef.uml#{comp_id}"', f'{comp}.compdef.uml#{comp_id}?{comp}_def/{comp}?"')
    assert text.count('?"') == 3
    model.write_text(text, encoding="utf-8")
    pim = _pim(model)
    assert _connected(pim) == CONNECTIONS
    parts = {p.get("name"): p.get("type-name") for p in pim.iter(f"{PIM}part")} or {
        a.get("name"): a.get("type-name") for a in pim.iter(f"{PIM}attribute")}
    assert parts["controller"] == "PIDController"


@pytest.mark.parametrize("written", ["joint%20services.servicedef.uml", "joint services.servicedef.uml"])
def test_a_file_name_with_a_space_url_encoded_or_not(tmp_path: Path, written: str) -> None:
    model = robotics_layout(tmp_path)
    services = model.parents[1] / "services"
    (services / "joint.servicedef.uml").rename(services / "joint services.servicedef.uml")
    for comp in (model.parents[1] / "components").glob("*.uml"):
        comp.write_text(comp.read_text(encoding="utf-8").replace("joint.servicedef.uml", written), encoding="utf-8")
    pim = _pim(model)
    assert "../services/joint services.servicedef.uml" in _files(pim)
    assert _connected(pim) == CONNECTIONS
    assert "joint services.servicedef.uml" in {p.name for p in linked_files(model)}
