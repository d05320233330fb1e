"""Models split over several files (issue 11): references across files, the sandbox, locations, batch.

The fixture fixtures/cases/split is the pid loop in the layout of Papyrus for
Robotics: a system model whose parts and connector ends are hrefs into
component definitions (components/*.compdef.uml), whose ports are typed by
services in a third file (services/joint.servicedef.uml). Its goldens for
every target are checked by test_golden.py / test_ros.py like every case;
here: what used to be dropped, and what must fail, warn or be located.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate, import_model, targets
from robomda.batch import run_batch
from robomda.cli import main
from robomda.diagnostics import RobomdaError

from edits import edit

ROOT = Path(__file__).resolve().parents[1]
SPLIT = ROOT / "fixtures" / "cases" / "split"
PIM = "{urn:robomda:pim:1}"


def _copy(tmp_path: Path) -> Path:
    """The split fixture copied into tmp_path/cases/split (with the pid atomic code beside it)."""
    dest = tmp_path / "cases" / "split"
    shutil.copytree(SPLIT, dest, ignore=shutil.ignore_patterns("expected"))
    (tmp_path / "cases" / "pid").symlink_to(ROOT / "fixtures" / "cases" / "pid")
    return dest


def test_the_system_keeps_its_connectors_and_parts_from_other_files() -> None:
    """Every connector of the system joined ports in other files and was dropped (exit code 0)."""
    pim = etree.fromstring(import_model(SPLIT / "model.xmi").encode())
    files = {p.get("name"): p.get("file") for p in pim.iter(f"{PIM}package") if p.get("file")}
    assert files == {"TrajectoryGenerator_def": "components/TrajectoryGenerator.compdef.uml",
                     "PIDController_def": "components/PIDController.compdef.uml",
                     "RobotInterface_def": "components/RobotInterface.compdef.uml",
                     "joint_services": "services/joint.servicedef.uml"}
    binding = pim.find(f"{PIM}binding")
    assert sorted(i.get("name") for i in binding.iter(f"{PIM}instance")) == ["controller", "robot", "trajectory"]
    connections = {c.get("name"): ({w.get("instance") for w in c.iter(f"{PIM}writer")},
                                   {r.get("instance") for r in c.iter(f"{PIM}reader")})
                   for c in binding.iter(f"{PIM}connection")}
    assert connections == {"desiredPositionConn": ({"trajectory"}, {"controller"}),
                           "measuredPositionConn": ({"robot"}, {"controller"}),
                           "referenceTorqueConn": ({"controller"}, {"robot"})}


@pytest.mark.parametrize("target", targets())
def test_every_target_generates_the_split_model(target: str) -> None:
    done = generate(SPLIT / "model.xmi", SPLIT / "out", target, write=False)
    assert not [w for w in done.warnings if w.code.startswith("IMP")]
    # the connections reach the bound model every target starts from
    assert 'name="referenceTorqueConn"' in done.stages["bind"]


def test_an_error_in_a_library_file_is_located_there(tmp_path: Path, capsys) -> None:
    model = _copy(tmp_path) / "model.xmi"
    lib = model.parent / "components" / "TrajectoryGenerator.compdef.uml"
    edit(lib, 'xmi:id="_spTa4v" value="0.01"', 'xmi:id="_spTa4v" value="-0.01"')
    assert main(["check", str(model)]) == 1
    err = capsys.readouterr().err
    line = next(line for line in err.splitlines() if "[BND010]" in line)
    where = lib.read_text().splitlines().index(next(t for t in lib.read_text().splitlines() if 'name="sample"' in t)) + 1
    assert line.startswith(f"{model.parent / 'components' / 'TrajectoryGenerator.compdef.uml'}:{where}:"), line
    assert "uml:Property 'sample'" in line


def test_a_file_outside_the_sandbox_is_refused_until_the_model_path_names_its_folder(tmp_path: Path, capsys) -> None:
    model = _copy(tmp_path) / "model.xmi"
    elsewhere = tmp_path / "shared-libs"
    shutil.move(model.parent / "services", elsewhere)
    for comp in (model.parent / "components").glob("*.compdef.uml"):
        text = comp.read_text(encoding="utf-8").replace("../services/", "../../../shared-libs/")
        comp.write_text(text, encoding="utf-8")
    with pytest.raises(RobomdaError) as refused:
        import_model(model)
    found = refused.value.diagnostics
    assert {d.code for d in found} == {"IMP040"}
    assert "joint.servicedef.uml" in found[0].message and "--model-path" in found[0].message
    assert found[0].file.endswith(".compdef.uml") and found[0].line  # located on the referencing element
    assert main(["check", str(model)]) == 1
    assert "Traceback" not in capsys.readouterr().err
    pim = etree.fromstring(import_model(model, model_path=[elsewhere]).encode())
    assert any(p.get("file") == "../../shared-libs/joint.servicedef.uml" for p in pim.iter(f"{PIM}package"))


def test_a_missing_file_is_named_and_the_rest_still_imports(tmp_path: Path) -> None:
    model = _copy(tmp_path) / "model.xmi"
    (model.parent / "components" / "RobotInterface.compdef.uml").unlink()
    warnings = []
    try:
        import_model(model, warnings=warnings)
    except RobomdaError as exc:  # parts typed by a missing component may be refused later: never in silence
        warnings = exc.diagnostics
    missing = [w for w in warnings if w.code == "IMP041"]
    assert missing and "RobotInterface.compdef.uml" in missing[0].message


def test_files_that_reference_each_other_load_once(tmp_path: Path) -> None:
    model = _copy(tmp_path) / "model.xmi"
    services = model.parent / "services" / "joint.servicedef.uml"
    # the services file references the system back (a cycle of files)
    edit(services, '<packagedElement xmi:type="uml:Interface" xmi:id="_spS1i" name="IDesiredPosition">',
          '<packagedElement xmi:type="uml:Interface" xmi:id="_spS1i" name="IDesiredPosition">\n'
          '    <ownedComment xmi:type="uml:Comment" xmi:id="_spS1n" body="used by the system">\n'
          '      <annotatedElement href="../model.xmi#_spY1k"/>\n    </ownedComment>')
    pim = etree.fromstring(import_model(model).encode())
    assert [p.get("file") for p in pim.iter(f"{PIM}package")].count("services/joint.servicedef.uml") == 1


def test_a_linked_file_is_read_without_external_entities(tmp_path: Path) -> None:
    model = _copy(tmp_path) / "model.xmi"
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP-SECRET-CONTENT")
    services = model.parent / "services" / "joint.servicedef.uml"
    text = services.read_text(encoding="utf-8").replace(
        '<?xml version="1.0" encoding="UTF-8"?>\n',
        f'<?xml version="1.0" encoding="UTF-8"?>\n<!DOCTYPE uml:Model [<!ENTITY leak SYSTEM "{secret.as_uri()}">]>\n')
    services.write_text(text.replace('name="IDesiredPosition"', 'name="IDesired&leak;"'), encoding="utf-8")
    try:
        out = import_model(model)
    except RobomdaError as exc:
        out = "\n".join(d.message for d in exc.diagnostics)
    assert "TOP-SECRET" not in out


def test_batch_generates_the_system_once_and_reports_its_files_as_libraries(tmp_path: Path) -> None:
    model = _copy(tmp_path) / "model.xmi"
    out = tmp_path / "out"
    first = run_batch(tmp_path / "cases" / "split", out, "ros1", jobs=1)
    status = {r.model: r.status for r in first.results}
    assert status == {"model.xmi": "ok", "components/PIDController.compdef.uml": "library",
                      "components/RobotInterface.compdef.uml": "library",
                      "components/TrajectoryGenerator.compdef.uml": "library",
                      "services/joint.servicedef.uml": "library"}
    assert first.exit_code == 0
    again = run_batch(tmp_path / "cases" / "split", out, "ros1", jobs=1)
    assert {r.model: r.status for r in again.results}["model.xmi"] == "skipped"
    # a changed library regenerates the model that uses it
    edit(model.parent / "components" / "PIDController.compdef.uml",
          'xmi:id="_spPa1v" value="20.0"', 'xmi:id="_spPa1v" value="25.0"')
    third = run_batch(tmp_path / "cases" / "split", out, "ros1", jobs=1)
    assert {r.model: r.status for r in third.results}["model.xmi"] == "ok"
    assert "kp: 25.0" in (out / "model.xmi" / "config" / "controller.yaml").read_text()


def test_a_reference_over_the_network_is_never_followed(tmp_path: Path) -> None:
    model = _copy(tmp_path) / "model.xmi"
    edit(model.parent / "components" / "PIDController.compdef.uml",
          '<type xmi:type="uml:Interface" href="../services/joint.servicedef.uml#_spS1i"/>',
          '<type xmi:type="uml:Interface" href="http://127.0.0.1:9/joint.servicedef.uml#_spS1i"/>')
    warnings = []
    try:
        import_model(model, bind=False, warnings=warnings)
    except RobomdaError as exc:
        warnings = exc.diagnostics
    assert not [w for w in warnings if w.code in ("IMP040", "IMP041", "INTERNAL")]
