"""Jobs given as configurations of a product line (issue 33; docs/jobs.md, "Jobs given as configurations").

The fixture is fixtures/variability/teleop (written by its make.py): the teleop case's model as a
product line's template, whose «Job»s name FeatureIDE configurations instead of listing slots. Its
jobs must come out as the teleop case's, so its coordinators are the case's byte for byte. The broken
inputs are edits of a copy of it. Goldens: fixtures/variability/teleop/expected/ (the template's PIM,
the configured PIM, the bound PIM); regenerate on purpose only (``--force-regen``) and read the diff.
The last test runs the Orocos coordinator on the real toolchain (marker ``orocos_toolchain``).
"""

from __future__ import annotations

import importlib.util
import shutil
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import check, generate, import_model
from robomda.cli import main
from test_golden import _check_all

ROOT = Path(__file__).resolve().parents[1]
LINE = ROOT / "fixtures" / "variability" / "teleop"
MODEL = LINE / "model.xmi"
CASE = ROOT / "fixtures" / "cases" / "teleop"
PIM = {"pim": "urn:robomda:pim:1"}
FS = "{urn:robomda:fileset:1}file"


def _make():
    spec = importlib.util.spec_from_file_location("teleop_line_make", LINE / "make.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _copy(tmp_path: Path, edits: dict[str, list[tuple[str, str]]] | None = None) -> Path:
    """The product line copied under tmp_path (with the case's atomic code where the model looks for
    it), each file of ``edits`` (relative to the line's folder) edited; the copied model's path."""
    line = tmp_path / "variability" / "teleop"
    shutil.copytree(LINE, line, ignore=shutil.ignore_patterns("expected", "__pycache__", "make.py"))
    (tmp_path / "cases").mkdir()
    (tmp_path / "cases" / "teleop").symlink_to(CASE)
    for name, changes in (edits or {}).items():
        path = line / name
        text = path.read_text(encoding="utf-8")
        for old, new in changes:
            assert text.count(old) == 1, (name, old)
            text = text.replace(old, new)
        path.write_text(text, encoding="utf-8")
    return line / "model.xmi"


def _line_of(path: Path, needle: str) -> int:
    return next(n for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1) if needle in line)


def _errors(model: Path, **options) -> list:
    done = check(model, **options)
    assert done.exit_code == 1
    return [d for d in done.diagnostics if d.severity == "error"]


def _files(done) -> dict[str, str]:
    tree = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {f.get("path"): f.text or "" for f in tree.iter(FS)}


def test_the_fixture_is_what_make_py_writes() -> None:
    for path, text in _make().texts().items():
        assert path.read_text(encoding="utf-8") == text, path


def test_the_template_and_its_configured_and_bound_pims_match_their_goldens(file_regression) -> None:
    """The template's PIM (the import alone: what the configure step reads), the configured PIM and the
    bound PIM."""
    done = generate(MODEL, None, "orocos", write=False)
    assert list(done.stages)[:3] == ["import", "configure", "bind"]
    _check_all(file_regression, [(done.stages["import"], LINE / "expected" / "import.xml"),
                                 (done.stages["configure"], LINE / "expected" / "configure.xml"),
                                 (done.stages["bind"], LINE / "expected" / "bind.xml")])


def test_the_import_keeps_the_tag_and_the_configure_step_makes_the_members() -> None:
    configured = etree.fromstring(import_model(MODEL, bind=False).encode("utf-8"))
    jobs = configured.findall("pim:coordination/pim:job", PIM)
    assert [j.get("name") for j in jobs] == ["teleoperation", "playback"]
    tags = [j.find("pim:stereotype[@name='Job']/pim:tag[@name='configuration']", PIM).get("value") for j in jobs]
    assert tags == ["variability/configs/teleoperation.xml", "variability/configs/playback.xml"]
    members = {j.get("name"): [(m.get("part"), m.get("at"), [(v.get("attribute"), v.get("value"))
                                                              for v in m.findall("pim:value", PIM)])
                               for m in j.findall("pim:member", PIM)] for j in jobs}
    assert members == {
        "teleoperation": [("_telP_trackball", "_telJ_teleoperation", [("_telTrackballInput_scale", "0.5")]),
                          ("_telP_invkin", "_telJ_teleoperation", []), ("_telP_robot", "_telJ_teleoperation", [])],
        "playback": [("_telP_player", "_telJ_playback", [("_telRecordedTrajectory_duration", "4.0")]),
                     ("_telP_invkin", "_telJ_playback", [("_telGeneralizedInverseKinematics_gain", "2.0")]),
                     ("_telP_robot", "_telJ_playback", [])]}
    # the system is the union of the variants: both trajectory sources stay, each in its own job
    parts = configured.findall(".//pim:component[@name='TeleopSystem']/pim:part", PIM)
    assert [p.get("name") for p in parts] == ["trackball", "player", "invkin", "robot"]


def _bound(model: Path) -> tuple[list, bytes]:
    binding = etree.fromstring(import_model(model).encode("utf-8")).find("pim:binding", PIM)
    jobs = [(j.get("name"), [(m.get("instance"), [(s.get("name"), s.get("value")) for s in m]) for m in j])
            for j in binding.findall("pim:bound-job", PIM)]
    subsystem = binding.find("pim:bound-subsystem", PIM)
    for step in subsystem.iter():  # where a value is set in the model: the slot in the case, the job here
        step.attrib.pop("holder", None)
    return jobs, etree.tostring(subsystem)


def test_the_jobs_and_switches_are_the_teleop_cases() -> None:
    assert _bound(MODEL) == _bound(CASE / "model.xmi")


def test_check_reports_each_job_and_the_switches_as_for_the_case() -> None:
    done = check(MODEL)
    assert done.exit_code == 0, [str(d) for d in done.diagnostics]
    reports = {d.code: [] for d in done.diagnostics}
    for d in done.diagnostics:
        reports[d.code].append(d)
    assert [d.message for d in reports["JOB020"]] == [d.message for d in check(CASE / "model.xmi").diagnostics
                                                      if d.code == "JOB020"]
    assert [(d.severity, d.message) for d in reports["JOB111"]] == [
        ("info", "job 'teleoperation' is configuration 'teleoperation.xml' (features Teleop, Source, Trackball): members "
                 "trackball, invkin, robot; sets trackball.scale = 0.5"),
        ("info", "job 'playback' is configuration 'playback.xml' (features Teleop, Source, Playback, HighGain): members "
                 "player, invkin, robot; sets player.duration = 4.0, invkin.gain = 2.0")]
    line = _line_of(MODEL, 'xmi:id="_telJ_teleoperation"')
    assert reports["JOB111"][0].line == line and reports["JOB111"][0].file == str(MODEL)


@pytest.mark.parametrize("target,coordinators", [
    ("orocos", ["deploy/teleop_arm.lua", "deploy/teleop.xml", "deploy/teleop.ops", "deploy/teleop.lua"]),
    ("ros1", ["src/arm_coordinator.cpp"]), ("ros2", ["src/arm_coordinator.cpp"])])
def test_every_target_switches_the_variants_as_it_switches_the_case(target: str, coordinators: list[str]) -> None:
    """The coordinators (and the deployments that start them) are the teleop case's goldens, byte for byte."""
    files = _files(generate(MODEL, None, target, write=False))
    golden = CASE / "expected" / target / "files"
    for path in coordinators:
        assert files[path] == (golden / path).read_text(encoding="utf-8"), path
    # the whole package differs from the case's only where the atomic code is found
    differ = sorted(p for p, text in files.items() if not (golden / p).is_file()
                    or (golden / p).read_text(encoding="utf-8") != text)
    assert differ == ["CMakeLists.txt"]
    case = (golden / "CMakeLists.txt").read_text(encoding="utf-8")
    assert files["CMakeLists.txt"].replace("'../../cases/teleop/atomic'", "'atomic'").replace(
        "/../../cases/teleop/atomic", "/../atomic") == case


def test_a_model_without_jobs_of_configurations_runs_no_configure_step() -> None:
    done = generate(CASE / "model.xmi", None, "orocos", write=False)
    assert "configure" not in done.stages and list(done.stages)[:2] == ["import", "bind"]


# ------------------------------------------------------------------------- broken inputs
def test_a_missing_configuration_is_located_on_the_job(tmp_path: Path) -> None:
    model = _copy(tmp_path, {"model.xmi": [('configuration="variability/configs/playback.xml"',
                                            'configuration="variability/configs/nowhere.xml"')]})
    errors = _errors(model)
    assert [d.code for d in errors] == ["JOB100"]
    assert "job 'playback' names configuration 'variability/configs/nowhere.xml': no such file" in errors[0].message
    assert (errors[0].file, errors[0].line) == (str(model), _line_of(model, 'xmi:id="_telJ_playback"'))


def test_a_configuration_outside_the_models_folder_or_not_xml_is_refused(tmp_path: Path) -> None:
    model = _copy(tmp_path, {"model.xmi": [('configuration="variability/configs/playback.xml"',
                                            'configuration="../../cases/teleop/model.xmi"'),
                                           ('configuration="variability/configs/teleoperation.xml"',
                                            'configuration="variability/configs/broken.xml"')]})
    (model.parent / "variability" / "configs" / "broken.xml").write_text("<configuration>", encoding="utf-8")
    errors = _errors(model)
    assert [d.code for d in errors] == ["JOB100", "JOB100"]
    assert "'variability/configs/broken.xml': not well-formed XML" in errors[0].message
    assert "which is no file in the model's folder or below it" in errors[1].message


def test_an_invalid_selection_is_located_in_the_configuration(tmp_path: Path) -> None:
    config = "variability/configs/playback.xml"
    model = _copy(tmp_path, {config: [('manual="unselected" name="Trackball"', 'manual="selected" name="Trackball"')]})
    errors = _errors(model)
    assert [d.code for d in errors] == ["VAR016"]
    path = model.parent / config
    assert (errors[0].file, errors[0].line) == (str(path), _line_of(path, 'name="Source"'))


def test_a_swap_only_some_jobs_select_is_refused_at_the_action(tmp_path: Path) -> None:
    action = ('<realize component="teleop::components::InverseKinematics" '
              'class="teleop::atomic::GeneralizedInverseKinematics"/>')
    model = _copy(tmp_path, {"variability/resolution.xml": [
        ('<feature name="HighGain">\n', f'<feature name="HighGain">\n    {action}\n')]})
    errors = _errors(model)
    assert [d.code for d in errors] == ["JOB104"]
    assert ("feature 'HighGain' swaps the realizing class of 'teleop::components::InverseKinematics' in the "
            "configurations of jobs 'playback' and not in those of 'teleoperation'") in errors[0].message
    resolution = model.parent / "variability" / "resolution.xml"
    assert (errors[0].file, errors[0].line) == (str(resolution), _line_of(resolution, "<realize "))


def test_a_slot_naming_a_part_the_configuration_removes_is_refused(tmp_path: Path) -> None:
    model = _copy(tmp_path, {"model.xmi": [
        ('name="teleoperation" classifier="_telSystem"/>',
         'name="teleoperation" classifier="_telSystem">\n'
         '      <slot xmi:type="uml:Slot" xmi:id="_telJ_teleoperation_player" definingFeature="_telP_player"/>\n'
         '    </packagedElement>')]})
    errors = _errors(model)
    assert [d.code for d in errors] == ["JOB105"]
    assert "job 'teleoperation' lists part 'player', which its configuration 'teleoperation.xml' removes" in errors[0].message
    assert errors[0].line == _line_of(model, 'xmi:id="_telJ_teleoperation_player"')


def test_a_slot_on_top_of_the_configuration_wins(tmp_path: Path) -> None:
    model = _copy(tmp_path, {"model.xmi": [
        ('name="playback" classifier="_telSystem"/>',
         'name="playback" classifier="_telSystem">\n'
         '      <slot xmi:type="uml:Slot" xmi:id="_telS_ik" definingFeature="_telP_invkin">\n'
         '        <value xmi:type="uml:InstanceValue" xmi:id="_telS_ikv" instance="_telS_iki"/>\n'
         '      </slot>\n    </packagedElement>\n'
         '    <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="_telS_iki" name="fast" '
         'classifier="_telInverseKinematics">\n'
         '      <slot xmi:type="uml:Slot" xmi:id="_telS_ikg" definingFeature="_telGeneralizedInverseKinematics_gain">\n'
         '        <value xmi:type="uml:LiteralReal" xmi:id="_telS_ikgv" value="3.0"/>\n'
         '      </slot>\n    </packagedElement>')]})
    jobs, _ = _bound(model)
    assert dict(jobs)["playback"] == [("player", [("duration", "4.0")]), ("robot", []), ("invkin", [("gain", "3.0")])]


def test_features_given_with_jobs_of_configurations_are_refused(tmp_path: Path) -> None:
    errors = _errors(MODEL, features=LINE / "variability" / "configs" / "playback.xml")
    assert [d.code for d in errors] == ["JOB106"] and errors[0].line == _line_of(MODEL, 'xmi:id="_telJ_teleoperation"')


def test_jobs_of_two_product_lines_are_refused(tmp_path: Path) -> None:
    model = _copy(tmp_path, {"model.xmi": [('configuration="variability/configs/playback.xml"',
                                            'configuration="other/configs/playback.xml"')]})
    shutil.copytree(model.parent / "variability", model.parent / "other")
    errors = _errors(model)
    assert [d.code for d in errors] == ["JOB102"] and "job 'playback' is a configuration of feature model" in errors[0].message


def test_missing_resolution_and_wrong_files_are_refused(tmp_path: Path) -> None:
    model = _copy(tmp_path)
    (model.parent / "variability" / "resolution.xml").unlink()
    assert [d.code for d in _errors(model)] == ["JOB101", "JOB101"]
    (model.parent / "variability" / "resolution.xml").write_text("<resolution/>", encoding="utf-8")
    errors = _errors(model)
    assert [d.code for d in errors] == ["JOB103", "JOB103"] and "is no robomda resolution model" in errors[0].message


def test_a_job_of_a_configuration_needs_its_composite(tmp_path: Path) -> None:
    model = _copy(tmp_path, {"model.xmi": [('name="playback" classifier="_telSystem"/>', 'name="playback"/>')]})
    errors = _errors(model)
    assert [d.code for d in errors] == ["JOB107"] and "it has no classifier" in errors[0].message


def test_a_connector_one_job_drops_between_parts_it_runs_is_kept_with_a_warning(tmp_path: Path) -> None:
    model = _copy(tmp_path, {"variability/resolution.xml": [
        ('  <feature name="Trackball">', '  <present element="teleop::components::TeleopSystem::link" when="HighGain"/>\n'
                                         '  <feature name="Trackball">')]})
    done = check(model)
    assert done.exit_code == 0
    warnings = [d for d in done.diagnostics if d.code == "JOB110"]
    assert len(warnings) == 1 and warnings[0].severity == "warning"
    assert "connector 'link' is not in configuration 'teleoperation.xml' of job 'teleoperation'" in warnings[0].message
    assert warnings[0].line == _line_of(model, 'xmi:id="_telC_link"')


def test_a_default_set_by_some_jobs_becomes_their_members_values_or_a_warning(tmp_path: Path) -> None:
    """A `set` without part of a feature not every job selects sets the job's members whose realizing class
    owns the attribute: the player's scale in playback; the trackball's, which playback does not run, nowhere."""
    model = _copy(tmp_path, {"variability/resolution.xml": [
        ('  <feature name="HighGain">\n', '  <feature name="HighGain">\n'
                                          '    <set attribute="teleop::atomic::RecordedTrajectory::scale" value="0.8"/>\n'
                                          '    <set attribute="teleop::atomic::TrackballInput::scale" value="0.9"/>\n')]})
    done = check(model)
    assert done.exit_code == 0
    warnings = [d for d in done.diagnostics if d.code == "JOB112"]
    assert len(warnings) == 1 and "sets 'teleop::atomic::TrackballInput::scale' in the configuration of job 'playback'" \
        in warnings[0].message
    resolution = model.parent / "variability" / "resolution.xml"
    assert (warnings[0].file, warnings[0].line) == (str(resolution), _line_of(resolution, 'value="0.9"'))
    jobs, _ = _bound(model)
    assert dict(jobs)["playback"][0] == ("player", [("scale", "0.8"), ("duration", "4.0")])


def test_the_cli_refuses_a_broken_configuration_and_writes_nothing(tmp_path: Path,
                                                                  capsys: pytest.CaptureFixture[str]) -> None:
    model = _copy(tmp_path, {"model.xmi": [('configuration="variability/configs/playback.xml"',
                                            'configuration="variability/configs/nowhere.xml"')]})
    code = main(["generate", str(model), "-o", str(tmp_path / "out"), "-t", "orocos"])
    err = capsys.readouterr().err
    assert code == 1 and "[JOB100]" in err and "Traceback" not in err
    assert not (tmp_path / "out").exists()


# ---------------------------------------------------------------- the real Orocos toolchain
@pytest.fixture(scope="module")
def line_package(tmp_path_factory) -> Path:
    from test_jobs import switch_package  # the teleop case's run: the same switches

    return switch_package(MODEL, tmp_path_factory.mktemp("jobs-line") / "teleop")


@pytest.mark.orocos_toolchain
@pytest.mark.parametrize("fmt", ["xml", "ops", "lua"])
def test_orocos_switches_the_variants_without_stopping_the_robot_interface(line_package: Path, fmt: str) -> None:
    from test_jobs import _bash

    run = _bash(f"oro_add_prefix {line_package / 'install'} && JOBS_FILE=teleop.{fmt} timeout 120 nice -n 19 rttlua "
                "../switch.lua", line_package / "deploy", timeout=300)
    out = run.stdout + run.stderr
    assert run.returncode == 0 and "JOBS-RESULT: OK" in out and "JOBS-CHECK FAILED" not in out, out[-4000:]
    assert "the robot interface was never stopped" in out and "[ ERROR" not in out, out[-4000:]
