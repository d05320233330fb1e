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


# ============================================== class 3: ids are per file
def _shared_ids(folder: Path) -> Path:
    """The split fixture in ``folder`` with the three component files using one set of xmi:ids (as files
    copied from one template do) and the services file the system model's id for its model."""
    shutil.copytree(SPLIT, folder, ignore=shutil.ignore_patterns("expected"))
    for path in [folder / "model.xmi", *(folder / "components").glob("*.uml")]:
        text = path.read_text(encoding="utf-8")
        for prefix in ("_spT", "_spP", "_spR"):
            text = text.replace(prefix, "_spX")
        path.write_text(text, encoding="utf-8")
    services = folder / "services" / "joint.servicedef.uml"
    services.write_text(services.read_text(encoding="utf-8").replace('xmi:id="_spS0model"', 'xmi:id="_spY0model"'),
                        encoding="utf-8")
    return folder / "model.xmi"


def test_two_files_may_use_one_xmi_id(tmp_path: Path) -> None:
    model = _shared_ids(tmp_path / "split")
    text = import_model(model)
    pim = etree.fromstring(text.encode())
    parts = {p.get("name"): (p.get("type"), p.get("type-name")) for p in pim.iter(f"{PIM}part")}
    assert parts == {"trajectory": ("components/TrajectoryGenerator.compdef.uml#_spXk", "TrajectoryGenerator"),
                     "controller": ("components/PIDController.compdef.uml#_spXk", "PIDController"),
                     "robot": ("components/RobotInterface.compdef.uml#_spXk", "RobotInterface")}
    # each reference inside a file resolved in that file: every port of every component keeps its interface
    ports = {(c.get("name"), p.get("name")): p.get("type-name")
             for c in pim.iter(f"{PIM}component") for p in c.iter(f"{PIM}port")}
    original = etree.fromstring(import_model(SPLIT / "model.xmi").encode())
    assert ports == {(c.get("name"), p.get("name")): p.get("type-name")
                     for c in original.iter(f"{PIM}component") for p in c.iter(f"{PIM}port")}
    assert _connected(pim) == CONNECTIONS
    # the model file's own element with an id another file uses is qualified too
    assert pim.get("id") == "model.xmi#_spY0model"
    ids = [e.get("id") for e in pim.iter() if e.get("id")]
    assert len(ids) == len(set(ids))
    assert import_model(model) == text  # deterministic


def test_a_model_with_shared_ids_generates_what_the_model_without_does(tmp_path: Path) -> None:
    from robomda.api import generate
    for side in ("a", "b"):
        (tmp_path / side).mkdir()
        (tmp_path / side / "pid").symlink_to(ROOT / "fixtures" / "cases" / "pid")
    shutil.copytree(SPLIT, tmp_path / "a" / "split", ignore=shutil.ignore_patterns("expected"))
    shared = _shared_ids(tmp_path / "b" / "split")
    for target in ("orocos", "ros1"):
        done = [generate(m, m.parent.parent / f"out-{target}", target)
                for m in (tmp_path / "a" / "split" / "model.xmi", shared)]
        assert [w.code for w in done[0].warnings] == [w.code for w in done[1].warnings]
        files = [{p.relative_to(d): p.read_bytes() for p in d.rglob("*") if p.is_file() and ".robomda" not in p.parts}
                 for d in (tmp_path / "a" / f"out-{target}", tmp_path / "b" / f"out-{target}")]
        assert files[0] and files[0] == files[1]


def test_a_duplicate_id_within_one_file_is_still_an_error_located_there(tmp_path: Path) -> None:
    model = _shared_ids(tmp_path / "split")
    lib = model.parent / "components" / "PIDController.compdef.uml"
    text = lib.read_text(encoding="utf-8")
    lib.write_text(text.replace('xmi:id="_spXa2v"', 'xmi:id="_spXa1v"'), encoding="utf-8")
    found = _refused(model)
    assert [d.code for d in found] == ["IMP004"]
    assert "_spXa1v" in found[0].xmi_id and "on 2 elements" in found[0].message
    assert found[0].file.endswith("PIDController.compdef.uml") and found[0].line


def test_an_error_on_an_element_with_a_shared_id_is_located_in_its_file(tmp_path: Path, capsys) -> None:
    model = _shared_ids(tmp_path / "split")
    (model.parent.parent / "pid").symlink_to(ROOT / "fixtures" / "cases" / "pid")
    lib = model.parent / "components" / "RobotInterface.compdef.uml"
    text = lib.read_text(encoding="utf-8")
    # a negative period, on an attribute whose id the other component files use too
    assert text.count('value="0.01"') == 1
    lib.write_text(text.replace('value="0.01"', 'value="-0.01"'), encoding="utf-8")
    assert main(["check", str(model)]) == 1
    err = capsys.readouterr().err
    line = next(line for line in err.splitlines() if "[BND010]" in line)
    assert line.startswith(str(lib)), line
    assert "RobotInterface.compdef.uml#_spX" in line


# ================================== class 8: MagicDraw used projects
MD_HEAD = ('<?xml version="1.0" encoding="UTF-8"?>\n'
           '<xmi:XMI xmi:version="2.5" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" '
           'xmlns:uml="http://www.omg.org/spec/UML/20131001">\n'
           '  <xmi:Documentation><xmi:exporter>MagicDraw Clean XMI Exporter</xmi:exporter></xmi:Documentation>\n')


def _md_ref(tag: str, href: str, path: str, meta: str = "Class") -> str:
    """A MagicDraw reference into another project: the href and, in an extension, the referent's path."""
    return (f'<{tag} href="{href}"><xmi:Extension extender="MagicDraw UML 2021x"><referenceExtension '
            f'referentPath="{path}" referentType="{meta}"/></xmi:Extension></{tag}>')


def magicdraw_model(folder: Path, project: str) -> Path:
    """A MagicDraw model whose types and general live in used projects: ``project`` (a PROJECT-<id> href,
    with or without local:/) holds Pose, Lib.mdzip the general Base, the UML Standard Profile int."""
    body = (f'  <uml:Model xmi:type="uml:Model" xmi:id="_m" name="robot">\n'
            f'    <packagedElement xmi:type="uml:Class" xmi:id="_c" name="Controller">\n'
            f'      <generalization xmi:type="uml:Generalization" xmi:id="_g">'
            f'{_md_ref("general", "Lib.mdzip#_base", "Lib::Base")}</generalization>\n'
            f'      <ownedAttribute xmi:type="uml:Property" xmi:id="_a1" name="pose">'
            f'{_md_ref("type", project + "?resource=com.nomagic.magicdraw.uml_umodel.shared_umodel#_pose", "Types::Pose")}'
            f'</ownedAttribute>\n'
            f'      <ownedAttribute xmi:type="uml:Property" xmi:id="_a2" name="count">'
            f'{_md_ref("type", "local:/PROJECT-877ab?resource=com.nomagic.magicdraw.uml_umodel.shared_umodel#_int", "UML Standard Profile::MagicDraw Profile::datatypes::int", "DataType")}'
            f'</ownedAttribute>\n'
            f'    </packagedElement>\n'
            f'    <packagedElement xmi:type="uml:Component" xmi:id="_k" name="Ctrl"/>\n'
            f'  </uml:Model>\n</xmi:XMI>\n')
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "model.xmi"
    path.write_text(MD_HEAD + body, encoding="utf-8")
    return path


@pytest.mark.parametrize("project", ["PROJECT-4f1e2d", "local:/PROJECT-4f1e2d"])
def test_magicdraw_used_projects_are_external_with_one_warning_each(tmp_path: Path, project: str) -> None:
    model = magicdraw_model(tmp_path / "md", project)
    warnings: list[Diagnostic] = []
    pim = _pim(model, warnings=warnings)
    assert not [w for w in warnings if w.code in ("IMP040", "IMP041")]
    used = [w for w in warnings if w.code == "IMP049"]
    assert sorted(w.message.split("used project '")[1].split("'")[0] for w in used) == ["Lib.mdzip", "PROJECT-4f1e2d"]
    pose = next(w for w in used if "PROJECT-4f1e2d" in w.message)
    assert "type 'Pose'" in pose.message and pose.xmi_id == "_a1" and pose.line and pose.file == str(model)
    assert "general 'Base'" in next(w for w in used if "Lib.mdzip" in w.message).message
    # the primitive of the standard profile's used project is no loss: no warning names it
    assert not [w for w in used if "PROJECT-877ab" in w.message]
    attrs = {a.get("name"): a for a in pim.iter(f"{PIM}attribute")}
    assert attrs["pose"].get("type-name") == "Pose" and attrs["pose"].get("type-library") == "external"
    assert attrs["count"].get("primitive") == "int32"
    assert linked_files(model) == []


def _codes(argv: list[str], capsys) -> tuple[int, list[str]]:
    code = main(argv)
    err = capsys.readouterr().err
    assert "Traceback" not in err and "INTERNAL" not in err
    return code, sorted(line.split("[")[1].split("]")[0] for line in err.splitlines() if "[IMP" in line)


@pytest.mark.parametrize("case", ["refused", "magicdraw"])
def test_import_check_and_generate_agree(tmp_path: Path, capsys, case: str) -> None:
    model = robotics_layout(tmp_path, None) if case == "refused" else magicdraw_model(tmp_path / "md", "PROJECT-4f1e2d")
    found = [_codes([command, str(model), "-o", str(tmp_path / f"out-{command}")] if command != "check"
                    else [command, str(model)], capsys) for command in ("import", "check", "generate")]
    imp = found[0][1]
    assert imp == (["IMP040"] * 3 if case == "refused" else ["IMP049", "IMP049"])
    assert all(codes == imp for _, codes in found), found
    if case == "refused":
        assert {code for code, _ in found} == {1}


def test_batch_over_a_workspace_generates_the_system_and_reads_the_sibling_project_as_its_library(
        tmp_path: Path) -> None:
    from robomda.batch import run_batch
    from robomda.inputs import model_files

    model = workspace_layout(tmp_path, "platform:/resource/Lib/components/")
    (tmp_path / "ws" / "pid").symlink_to(ROOT / "fixtures" / "cases" / "pid")
    done = run_batch(tmp_path / "ws" / "App", tmp_path / "out", "ros1", jobs=1)
    assert {r.model: r.status for r in done.results} == {"models/model.xmi": "ok"}
    # watch stats (and batch hashes) the sibling project's files the model reads
    assert {p.name for p in model_files(model)} >= {f"{c}.compdef.uml" for c in COMPONENTS}
    library = tmp_path / "ws" / "Lib" / "components" / "PIDController.compdef.uml"
    library.write_text(library.read_text(encoding="utf-8").replace('value="20.0"', 'value="25.0"'), encoding="utf-8")
    again = run_batch(tmp_path / "ws" / "App", tmp_path / "out", "ros1", jobs=1)
    assert {r.model: r.status for r in again.results} == {"models/model.xmi": "ok"}
