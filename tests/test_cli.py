"""The command line: usage, bad input, exit codes, and nothing written on failure."""

from __future__ import annotations

from pathlib import Path

import pytest

from robomda.cli import main


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.mark.parametrize("command", ["generate", "import", "watch"])
def test_help_names_the_options_and_exit_codes(capsys: pytest.CaptureFixture[str], command: str) -> None:
    with pytest.raises(SystemExit) as done:
        main([command, "--help"])
    assert done.value.code == 0
    out = capsys.readouterr().out
    assert "-o OUT" in out and "exit codes" in out and "MODEL" in out


def test_missing_model_is_an_input_error(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _, err = run(capsys, "generate", str(tmp_path / "nope.xmi"), "-o", str(tmp_path / "out"))
    assert code == 2
    assert "[IO001]" in err and "nope.xmi" in err
    assert not (tmp_path / "out").exists()


def test_malformed_xml_names_file_line_and_column(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    model = tmp_path / "broken.xmi"
    model.write_text('<?xml version="1.0"?>\n<xmi:XMI xmlns:xmi="http://www.omg.org/spec/XMI/20131001">\n'
                     "  <uml:Model>\n</xmi:XMI>\n")
    code, _, err = run(capsys, "generate", str(model), "-o", str(tmp_path / "out"))
    assert code == 2
    first = err.splitlines()[0]
    assert first.startswith(f"{model}:3:") and "[XML001]" in first
    assert not (tmp_path / "out").exists()


def test_unknown_target_is_refused_by_the_parser(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    with pytest.raises(SystemExit) as done:
        main(["generate", "m.xmi", "-o", str(tmp_path), "--target", "player"])
    assert done.value.code == 2
    assert "invalid choice" in capsys.readouterr().err


def test_import_writes_the_pim_and_never_replaces_a_user_file(capsys: pytest.CaptureFixture[str],
                                                               tmp_path: Path) -> None:
    model = Path(__file__).resolve().parent.parent / "fixtures" / "cases" / "meka" / "model.xmi"
    assert main(["import", str(model), "-o", str(tmp_path)]) == 0
    pim = tmp_path / "model.pim.xml"
    assert "urn:robomda:pim:1" in pim.read_text() and "<pim:binding" in pim.read_text()
    assert main(["import", str(model), "-o", str(pim), "--no-bind"]) == 0  # a robomda model: replaced
    assert "<pim:binding" not in pim.read_text()
    mine = tmp_path / "notes.xml"
    mine.write_text("<notes>mine</notes>")
    capsys.readouterr()
    assert main(["import", str(model), "-o", str(mine)]) == 2
    assert "[OUT001]" in capsys.readouterr().err and mine.read_text() == "<notes>mine</notes>"


def test_a_user_type_map_overrides_the_message_types(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    model = Path(__file__).resolve().parent.parent / "fixtures" / "cases" / "pid" / "model.xmi"
    type_map = tmp_path / "my-types.xml"
    type_map.write_text('<types xmlns="urn:robomda:ros-types:1"><type primitive="float64" cpp="double" '
                        'msg="my_msgs/Angle" field="radians" msg-field="float64" param1="double" '
                        'param2="double" sample="0.0"/></types>')
    assert main(["generate", str(model), "-o", str(tmp_path / "out"), "--target", "ros1",
                 "--type-map", str(type_map)]) == 0
    header = (tmp_path / "out" / "include" / "pid" / "PIDController.hpp").read_text()
    assert "my_msgs/Angle.h" in header and "std_msgs/Float64" not in header
    capsys.readouterr()
    assert main(["generate", str(model), "-o", str(tmp_path / "o2"), "--target", "ros1",
                 "--type-map", str(tmp_path / "missing.xml")]) == 2
    assert "[IO001]" in capsys.readouterr().err


ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT / "fixtures" / "cases"


def test_generate_defaults_to_the_middleware_the_model_deploys_on(capsys: pytest.CaptureFixture[str],
                                                                  tmp_path: Path) -> None:
    """pid deploys on ROS only: without --target it was generated for Orocos (issue 10 item 9)."""
    code, out, _ = run(capsys, "generate", str(CASES / "pid" / "model.xmi"), "-o", str(tmp_path / "pid"))
    assert code == 0 and "ros1 package in" in out
    assert (tmp_path / "pid" / "launch").is_dir() and not (tmp_path / "pid" / "deploy").exists()


def _two_middlewares(tmp_path: Path) -> Path:
    """pid with the robot interface's class in a second artifact, deployed on an Orocos environment."""
    text = (CASES / "pid" / "model.xmi").read_text(encoding="utf-8")
    edits = [('      <manifestation xmi:type="uml:Manifestation" xmi:id="_pid093m" client="_pid089f" '
              'supplier="_pid046c" utilizedElement="_pid046c"/>\n', ''),
             ('      </nestedNode>\n',
              '      </nestedNode>\n      <nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="_ee2" name="OROCOS">\n'
              '        <deployment xmi:type="uml:Deployment" xmi:id="_d2" client="_ee2" supplier="_a2" '
              'deployedArtifact="_a2"/>\n      </nestedNode>\n'),
             ('  </packagedElement>\n</uml:Model>',
              '    <packagedElement xmi:type="uml:Artifact" xmi:id="_a2" name="robot_atomic" fileName="atomic">\n'
              '      <manifestation xmi:type="uml:Manifestation" xmi:id="_m2" client="_a2" supplier="_pid046c" '
              'utilizedElement="_pid046c"/>\n    </packagedElement>\n  </packagedElement>\n</uml:Model>')]
    for old, new in edits:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    model = tmp_path / "two.xmi"
    model.write_text(text, encoding="utf-8")
    return model


def test_a_model_on_several_middlewares_must_name_its_target(capsys: pytest.CaptureFixture[str],
                                                             tmp_path: Path) -> None:
    from robomda.api import default_targets
    model = _two_middlewares(tmp_path)
    assert default_targets(model) == ["orocos", "ros1"]
    code, _, err = run(capsys, "generate", str(model), "-o", str(tmp_path / "out"))
    assert code == 2 and "name the one to generate with --target" in err and not (tmp_path / "out").exists()
    code, out, _ = run(capsys, "generate", str(model), "-o", str(tmp_path / "out"), "--target", "ros1")
    assert code == 0 and "ros1 package in" in out


def test_check_runs_what_generate_runs_and_names_the_rule_sets(capsys: pytest.CaptureFixture[str],
                                                               tmp_path: Path) -> None:
    """check without --target passed models that generate refuses ('nothing to generate') (item 4)."""
    model = tmp_path / "empty.uml"
    model.write_text('<?xml version="1.0" encoding="UTF-8"?>\n<uml:Model xmi:version="20131001" '
                     'xmlns:xmi="http://www.omg.org/spec/XMI/20131001" '
                     'xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML" xmi:id="m" name="empty">\n'
                     '  <packagedElement xmi:type="uml:Class" xmi:id="c" name="Lonely"/>\n</uml:Model>\n',
                     encoding="utf-8")
    gen_code, _, gen_err = run(capsys, "generate", str(model), "-o", str(tmp_path / "out"))
    code, out, err = run(capsys, "check", str(model))
    assert gen_code == 1 and code == 1
    assert "nothing to generate" in gen_err and "nothing to generate" in err
    # ORO005 comes from the PSM stylesheet: the PSM rules never ran, and the summary says so
    assert "checked for orocos; rules: pim.sch)" in out
    code, out, _ = run(capsys, "check", str(CASES / "pid" / "model.xmi"))
    assert code == 0 and "checked for ros1; rules: pim.sch, ros-limits.sch (ros1), psm-ros.sch" in out


def test_a_package_name_that_is_rewritten_says_so(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, out, err = run(capsys, "generate", str(CASES / "headlamp" / "model.xmi"), "-o", str(tmp_path / "o"),
                         "--package-name", "My Lamp")
    assert code == 0 and "[PKG001] --package-name 'My Lamp' is written 'my_lamp'" in err
    code, _, err = run(capsys, "generate", str(CASES / "headlamp" / "model.xmi"), "-o", str(tmp_path / "p"),
                       "--package-name", "my_lamp")
    assert code == 0 and "PKG001" not in err


def test_package_xml_says_who_and_which_license(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    """package.xml said license TODO and a placeholder maintainer, hard-coded (issue 10 item 7)."""
    code, _, err = run(capsys, "generate", str(CASES / "pid" / "model.xmi"), "-o", str(tmp_path / "a"),
                       "--maintainer", "Jane Roe & Co <jane@example.org>", "--license", "Apache-2.0",
                       "--package-version", "1.2.3")
    assert code == 0 and "PKG002" not in err
    text = (tmp_path / "a" / "package.xml").read_text()
    assert "<version>1.2.3</version>" in text and "<license>Apache-2.0</license>" in text
    assert '<maintainer email="jane@example.org">Jane Roe &amp; Co</maintainer>' in text
    code, _, err = run(capsys, "generate", str(CASES / "pid" / "model.xmi"), "-o", str(tmp_path / "b"))
    assert code == 0 and "[PKG002] package.xml names a placeholder maintainer and license" in err


def _files(folder: Path) -> dict[str, tuple[bytes, int]]:
    return {p.relative_to(folder).as_posix(): (p.read_bytes(), p.stat().st_mtime_ns)
            for p in folder.rglob("*") if p.is_file()}


def test_check_and_diff_compare_the_output_and_write_nothing(capsys: pytest.CaptureFixture[str],
                                                             tmp_path: Path) -> None:
    """generate --check / --diff, as black --check --diff: exit 1 and the files (and diffs) that would change."""
    import subprocess
    model, out = str(CASES / "headlamp" / "model.xmi"), tmp_path / "headlamp"
    check = ["generate", model, "-o", str(out), "--target", "orocos", "--check"]
    code, stdout, err = run(capsys, *check)
    assert code == 1 and not out.exists() and list(tmp_path.iterdir()) == []  # not even a staging folder
    assert "orocos package in" in err and "would change (22 files):" in err and "  added   CMakeLists.txt" in err
    assert stdout == ""
    assert run(capsys, "generate", model, "-o", str(out), "--target", "orocos")[0] == 0
    code, stdout, err = run(capsys, *check)
    assert code == 0 and "is up to date" in err and stdout == ""
    # an edited generated file, a removed one, an edited user file (never drift), a missing user file
    cmake = out / "CMakeLists.txt"
    cmake.write_text(cmake.read_text().replace("orocos_generate_package()", "orocos_generate_package(my)"))
    (out / "deploy" / "headlamp.ops").unlink()
    (out / "deploy" / "camera.user.cpf").write_text("<properties/>\n")
    (out / "deploy" / "arm.user.cpf").unlink()
    before = _files(tmp_path)
    code, stdout, err = run(capsys, *check[:-1], "--diff")
    assert code == 1 and _files(tmp_path) == before
    assert [line.strip() for line in err.splitlines() if line.startswith("  ")] == [
        "changed CMakeLists.txt", "added   deploy/arm.user.cpf", "added   deploy/headlamp.ops"]
    assert "--- a/CMakeLists.txt\n+++ b/CMakeLists.txt\n" in stdout
    assert "-orocos_generate_package(my)\n+orocos_generate_package()\n" in stdout
    assert "--- /dev/null\n+++ b/deploy/headlamp.ops\n" in stdout and "b/deploy/camera.user.cpf" not in stdout
    # the diff is a patch that brings the folder up to date
    subprocess.run(["patch", "-s", "-p1", "-d", str(out)], input=stdout, text=True, check=True)
    assert run(capsys, *check)[0] == 0
    assert (out / "deploy" / "camera.user.cpf").read_text() == "<properties/>\n"


def test_check_refuses_what_would_write_or_mix_stdout(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    model = str(CASES / "headlamp" / "model.xmi")
    code, _, err = run(capsys, "generate", model, "-o", str(tmp_path / "o"), "--check", "--save-stages",
                       str(tmp_path / "s"))
    assert code == 2 and "--check and --diff write nothing" in err
    code, _, _ = run(capsys, "generate", model, "-o", str(tmp_path / "o"), "--diff", "--format", "json")
    assert code == 2 and list(tmp_path.iterdir()) == []


def test_warnings_saying_the_same_read_as_one_finding_with_notes(capsys: pytest.CaptureFixture[str],
                                                                 tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    """The README's first command printed five CMP009 of 370 characters saying the same (issue 31 item 5)."""
    monkeypatch.chdir(ROOT)
    code, _, err = run(capsys, "generate", "fixtures/cases/headlamp/model.xmi", "-o", str(tmp_path / "h"),
                       "--target", "orocos")
    lines = err.splitlines()
    assert code == 0 and len(lines) == 6
    assert lines[0].endswith("[5 alike: 'camera', 'forceSensor', 'vision', 'controller', 'arm']")
    assert ": warning: [CMP009] instance 'camera' asks for real-time priority 50 (scheduler RT) on host " \
           "'controlPC', which the model does not declare real-time" in lines[0]
    assert [line.split(": note: ")[1].split(" (")[0] for line in lines[1:5]] == [
        "[CMP009] the same for 'forceSensor'", "[CMP009] the same for 'vision'",
        "[CMP009] the same for 'controller'", "[CMP009] the same for 'arm'"]
    assert [line.split(": note: ")[0].rsplit(":", 2)[1:] for line in lines[1:5]] == [
        ["502", "3"], ["503", "3"], ["504", "3"], ["505", "3"]]
    assert "[PKG002]" in lines[5]
    assert len(err) < 1100  # 2,200 characters before, each CMP009 saying it all again
    assert len(lines[0].split("[CMP009] ")[1].split(" (robomda:Activity")[0]) < 220
    # json keeps one finding per element
    code, stdout, _ = run(capsys, "generate", str(CASES / "headlamp" / "model.xmi"), "-o", str(tmp_path / "j"),
                          "--target", "orocos", "--format", "json")
    import json
    assert [d["code"] for d in json.loads(stdout)["diagnostics"]] == ["CMP009"] * 5 + ["PKG002"]


def test_the_readme_quick_start_prints_what_the_readme_shows(capsys: pytest.CaptureFixture[str], tmp_path: Path,
                                                             monkeypatch: pytest.MonkeyPatch) -> None:
    """The README shows the quick start's output and says what its two warnings mean (issue 31 item 5)."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    command = "robomda generate fixtures/cases/headlamp/model.xmi -o out/headlamp --target orocos"
    assert command in readme
    shown = readme.split("prints two warnings about the model")[1].split("```\n", 2)[1]
    (tmp_path / "fixtures").symlink_to(ROOT / "fixtures")
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *command.split()[1:])
    assert code == 0 and err + out == shown
    explained = readme.split(shown)[1].split("The second installs")[0]
    assert "- `CMP009`:" in explained and "- `PKG002`:" in explained
    # what the README says makes them go, does
    code, _, err = run(capsys, *command.split()[1:], "--maintainer", "Jane Doe <jane@example.org>",
                       "--license", "Apache-2.0")
    assert code == 0 and "PKG002" not in err


def test_check_says_what_generate_would_say_of_your_user_files(capsys: pytest.CaptureFixture[str],
                                                               tmp_path: Path) -> None:
    """A user file whose instance is gone stops generate (OUT003): --check must not call that up to date."""
    model, out = tmp_path / "lamp.xmi", tmp_path / "out"
    text = (CASES / "headlamp" / "model.xmi").read_text(encoding="utf-8")
    model.write_text(text, encoding="utf-8")
    assert run(capsys, "generate", str(model), "-o", str(out), "--target", "orocos")[0] == 0
    model.write_text(text.replace('name="camera"', 'name="camera2"'), encoding="utf-8")
    before = _files(tmp_path)
    code, _, err = run(capsys, "generate", str(model), "-o", str(out), "--target", "orocos", "--check")
    assert code == 2 and "[OUT003] user file deploy/camera.user.cpf holds your work" in err
    assert _files(tmp_path) == before
