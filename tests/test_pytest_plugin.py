"""The pytest plugin (robomda.pytest_plugin): a user's repository of models under golden-file test.

Each test copies the sample repository (tests/data/user-repo: the headlamp
model and its expected Orocos package, laid out as docs/testing.md says) into
a pytester folder and runs pytest there in a process of its own, as a user
would (in-process, pytester's module snapshot would make a second run import
robomda anew beside the first one's engine).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from robomda.cli import main

pytest_plugins = ["pytester"]

SAMPLE = Path(__file__).resolve().parent / "data" / "user-repo"
PACKAGE = Path("expected") / "orocos" / "headlamp.xmi"


@pytest.fixture()
def repo(pytester: pytest.Pytester, monkeypatch: pytest.MonkeyPatch) -> Path:
    # the user's pytest as on a developer's machine: under CI (variables CI, BUILD_NUMBER) pytest also
    # prints each failure's whole message in its short summary, so every line checked below would be there twice
    monkeypatch.delenv("CI", raising=False)
    monkeypatch.delenv("BUILD_NUMBER", raising=False)
    shutil.copytree(SAMPLE, pytester.path, dirs_exist_ok=True)
    return pytester.path


def test_the_sample_repository_gets_one_passing_test_per_model_and_target(repo: Path,
                                                                          pytester: pytest.Pytester) -> None:
    """Also the sample's golden: after a change of the Orocos output, `cd tests/data/user-repo && pytest
    --force-regen`, and review the diff."""
    listed = pytester.runpytest_subprocess("--collect-only", "-q")
    assert "models/headlamp.xmi::orocos" in listed.outlines
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(passed=1)


def test_the_cli_check_reads_the_same_layout(repo: Path, capsys: pytest.CaptureFixture[str],
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(repo)
    assert main(["generate", "models", "-o", "expected/orocos", "--target", "orocos", "--check"]) == 0
    assert "1 models: 1 up to date, 0 drifted" in capsys.readouterr().err


def test_a_changed_package_fails_with_the_files_and_their_diff(repo: Path, pytester: pytest.Pytester) -> None:
    cmake = repo / PACKAGE / "CMakeLists.txt"
    cmake.write_text(cmake.read_text().replace("orocos_generate_package()", "orocos_generate_package(old)"))
    (repo / PACKAGE / "deploy" / "headlamp.lua").unlink()
    (repo / PACKAGE / "deploy" / "stale.ops").write_text("old\n")
    camera = repo / PACKAGE / "deploy" / "camera.user.cpf"  # a user file of the golden: compared too
    camera.write_text(camera.read_text() + "<!-- edited -->\n")
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(failed=1)
    text = result.stdout.str()
    assert ("the orocos package generated from headlamp.xmi is not the expected one, expected/orocos/headlamp.xmi/ "
            "(4 differing files; - expected, + generated now):") in text
    listing = [line.strip() for line in result.outlines if line.startswith("  ") and line.strip().split()[0]
               in ("added", "changed", "removed")]
    assert listing == ["changed CMakeLists.txt", "changed deploy/camera.user.cpf", "added   deploy/headlamp.lua",
                       "removed deploy/stale.ops"]
    assert "-orocos_generate_package(old)" in result.outlines and "+orocos_generate_package()" in result.outlines
    assert "--- a/CMakeLists.txt" in result.outlines and "-<!-- edited -->" in result.outlines
    assert "accept the new package with: pytest --force-regen (then review the change, e.g. git diff)" in text
    assert "Traceback" not in text and "runtest" not in text  # the diff, not the plugin's insides


def test_force_regen_accepts_the_change_as_pytest_regressions_does(repo: Path, pytester: pytest.Pytester) -> None:
    cmake = repo / PACKAGE / "CMakeLists.txt"
    good = cmake.read_bytes()
    cmake.write_text("edited\n")
    (repo / PACKAGE / "extra.txt").write_text("x\n")
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider", "--force-regen")
    result.assert_outcomes(failed=1)
    assert "Files differ and --force-regen set, regenerating the expected package at:" in result.stdout.str()
    assert cmake.read_bytes() == good and not (repo / PACKAGE / "extra.txt").exists()
    pytester.runpytest_subprocess("-p", "no:cacheprovider").assert_outcomes(passed=1)
    cmake.write_text("edited\n")
    pytester.runpytest_subprocess("-p", "no:cacheprovider", "--regen-all").assert_outcomes(passed=1)
    assert cmake.read_bytes() == good


def test_a_new_model_gets_its_expected_package_written_once(repo: Path, pytester: pytest.Pytester) -> None:
    shutil.copy(repo / "models" / "headlamp.xmi", repo / "models" / "lamp2.xmi")
    (repo / "models" / "notes.xml").write_text("<notes/>")  # not a UML model: no test
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(passed=1, failed=1)  # headlamp passes; lamp2 deploys on Orocos: its package is written
    assert "Expected package not found, created:" in result.stdout.str()
    assert (repo / "expected" / "orocos" / "lamp2.xmi" / "CMakeLists.txt").is_file()
    pytester.runpytest_subprocess("-p", "no:cacheprovider").assert_outcomes(passed=2)


def test_a_long_diff_is_cut_and_says_how_to_see_it_all(repo: Path, pytester: pytest.Pytester) -> None:
    for path in (repo / PACKAGE / "src").glob("*.cpp"):
        path.write_text("\n".join(f"line {n}" for n in range(100)) + "\n")
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(failed=1)
    diff = [line for line in result.outlines if line.startswith(("-line ", "+"))]
    assert 50 < len(diff) <= 120
    assert any(line.startswith("... (diff cut: 6 files differ; all of it: robomda generate MODEL -o "
                               "expected/orocos/headlamp.xmi --target orocos --diff)") for line in result.outlines)


def test_a_model_with_errors_fails_with_its_diagnostics(repo: Path, pytester: pytest.Pytester) -> None:
    model = repo / "models" / "headlamp.xmi"
    text = model.read_text(encoding="utf-8")
    assert ' type="_OvrYHkhPodbwEviCI8ZQU9"' in text
    model.write_text(text.replace(' type="_OvrYHkhPodbwEviCI8ZQU9"', ' type="_nowhere"', 1), encoding="utf-8")
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(failed=1)
    assert "robomda could not generate the package:" in result.stdout.str()
    assert any(line.startswith("models/headlamp.xmi:355:9: error: [IMP011] Port 'visionValue'") or
               "headlamp.xmi:355:9: error: [IMP011] Port 'visionValue'" in line for line in result.outlines)


def test_without_the_ini_option_the_plugin_does_nothing(pytester: pytest.Pytester) -> None:
    """Installed for everyone: a repository that does not opt in (robomda's own) collects what it did."""
    shutil.copytree(SAMPLE / "models", pytester.path / "models")
    pytester.makepyfile(test_mine="def test_one():\n    pass\n")
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(passed=1)
    assert not (pytester.path / "expected").exists()


def test_the_plugin_is_a_pytest11_entry_point_of_the_package() -> None:
    from importlib.metadata import entry_points
    found = [ep for ep in entry_points(group="pytest11") if ep.name == "robomda"]
    assert [ep.value for ep in found] == ["robomda.pytest_plugin"]
    assert "[project.entry-points.pytest11]\nrobomda = \"robomda.pytest_plugin\"" in (
        SAMPLE.parents[2] / "pyproject.toml").read_text(encoding="utf-8")


def test_a_library_model_is_tested_with_the_model_that_uses_it(pytester: pytest.Pytester) -> None:
    """A model split over files (fixtures/cases/split): one test per model, none per library file."""
    split = Path(__file__).resolve().parents[1] / "fixtures" / "cases" / "split"
    shutil.copytree(split, pytester.path / "models" / "split", ignore=shutil.ignore_patterns("expected"))
    pytester.makeini("[pytest]\nrobomda_models = models\nrobomda_targets = orocos ros2\n")
    listed = pytester.runpytest_subprocess("--collect-only", "-q", "-p", "no:cacheprovider")
    assert [line for line in listed.outlines if "::" in line] == [
        "models/split/model.xmi::orocos", "models/split/model.xmi::ros2"]


def test_without_pytest_regressions_the_plugin_says_what_to_install(repo: Path, pytester: pytest.Pytester) -> None:
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider", "-p", "no:regressions")
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    assert "robomda's pytest plugin needs pytest-regressions" in result.stderr.str()
    assert "pip install 'robomda[pytest]'" in result.stderr.str()
