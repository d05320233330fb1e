"""The broken-model corpus (fixtures/broken): exact diagnostics, never a traceback.

Each case is a fixture model with one defect (fixtures/broken/make.py says
which). ``robomda check`` must print exactly the golden diagnostics, located
on the right XMI line, and exit with the golden code; every target's
``generate`` must fail or warn the same way, never with an internal error.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from robomda.api import targets
from robomda.cli import main

ROOT = Path(__file__).resolve().parents[1]
BROKEN = ROOT / "fixtures" / "broken"
CORPUS = sorted(p.name for p in BROKEN.iterdir() if (p / "model.xmi").is_file())
GOOD = sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "fixtures" / "cases").glob("*/model*.xmi"))


def _run(capsys: pytest.CaptureFixture[str], argv: list[str]) -> tuple[int, str, str]:
    capsys.readouterr()
    code = main(argv)
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.fixture(autouse=True)
def _in_repo(monkeypatch: pytest.MonkeyPatch) -> None:
    # diagnostics name the model as given: run from the repository root so the
    # goldens hold repository-relative paths
    monkeypatch.chdir(ROOT)


def test_the_corpus_covers_every_kind_of_breakage() -> None:
    assert len(CORPUS) >= 25
    for wanted in ("malformed-xml", "xmi-1x", "wrong-namespace", "dangling-idref", "duplicate-ids",
                   "cyclic-generalization", "empty-component-name", "keyword-names", "non-identifier-names",
                   "same-identifier", "huge-values"):
        assert wanted in CORPUS


@pytest.mark.parametrize("case", CORPUS)
def test_check_prints_the_golden_diagnostics(case: str, capsys: pytest.CaptureFixture[str],
                                              file_regression) -> None:
    model = f"fixtures/broken/{case}/model.xmi"
    args = (BROKEN / case / "args").read_text(encoding="utf-8").split()
    code, out, err = _run(capsys, ["check", model, *args])
    assert code in (0, 1, 2), err
    assert "Traceback" not in err + out
    file_regression.check(f"exit {code}\n{err}", fullpath=BROKEN / case / "expected.txt", binary=False)


@pytest.mark.parametrize("case", CORPUS)
def test_json_and_sarif_carry_the_same_findings(case: str, capsys: pytest.CaptureFixture[str]) -> None:
    model = f"fixtures/broken/{case}/model.xmi"
    args = (BROKEN / case / "args").read_text(encoding="utf-8").split()
    code, _, err = _run(capsys, ["check", model, *args])
    # the text groups what is said of several elements (a finding, then a note per other element: in
    # the order found, under the first); JSON and SARIF keep one result per element, in the order found
    text_codes = [line.split("[", 1)[1].split("]", 1)[0] for line in err.splitlines() if ": [" in line
                  and any(f": {severity}: [" in line for severity in ("error", "warning", "info", "note"))]
    code_json, out, _ = _run(capsys, ["check", model, *args, "--format", "json"])
    report = json.loads(out)
    assert code_json == code == report["exit_code"]
    assert sorted(d["code"] for d in report["diagnostics"]) == sorted(text_codes)
    code_sarif, out, _ = _run(capsys, ["check", model, *args, "--format", "sarif"])
    sarif = json.loads(out)
    assert code_sarif == code
    assert [r["ruleId"] for r in sarif["runs"][0]["results"]] == [d["code"] for d in report["diagnostics"]]


@pytest.mark.parametrize("case", CORPUS)
@pytest.mark.parametrize("target", targets())
def test_generate_never_crashes(case: str, target: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = _run(capsys, ["generate", f"fixtures/broken/{case}/model.xmi", "-o", str(tmp_path / "out"),
                                   "-t", target])
    assert code in (0, 1, 2), err
    assert "Traceback" not in err + out and "INTERNAL" not in err
    if code != 0:
        # nothing is written when a run fails
        assert not (tmp_path / "out").exists() or not any((tmp_path / "out").rglob("*.cpp"))
        assert ": error: [" in err


@pytest.mark.parametrize("model", GOOD)
def test_good_fixtures_have_no_errors(model: str, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = _run(capsys, ["check", model])
    assert code == 0
    assert ": error: [" not in err
    assert out.startswith(f"robomda: {model}: 0 errors")


def _multitool() -> Path | None:
    tool = ROOT / "tests" / "engines" / "node_modules" / "@microsoft" / "sarif-multitool-linux" / "Sarif.Multitool"
    return tool if tool.is_file() else None


@pytest.mark.skipif(_multitool() is None, reason="SARIF Multitool not installed: run "
                    "'npm ci --prefix tests/engines' (tests/run.sh does)")
@pytest.mark.parametrize("case", ["unconnected-hosts", "orocos-no-activity", "malformed-xml"])
def test_sarif_passes_the_sarif_multitool(case: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    import subprocess

    _, out, _ = _run(capsys, ["check", f"fixtures/broken/{case}/model.xmi", "--format", "sarif"])
    log = tmp_path / "robomda.sarif"
    log.write_text(out, encoding="utf-8")
    tool = _multitool()
    assert tool is not None
    os.chmod(tool, 0o755)
    verdict = tmp_path / "verdict.sarif"
    done = subprocess.run([str(tool), "validate", str(log), "--output", str(verdict)], capture_output=True,
                          text=True, timeout=300, env={**os.environ, "DOTNET_CLI_TELEMETRY_OPTOUT": "1"})
    assert done.returncode == 0, done.stdout + done.stderr
    found = json.loads(verdict.read_text(encoding="utf-8-sig"))
    errors = [r for run in found["runs"] for r in run.get("results", []) if r.get("level") == "error"]
    assert errors == [], errors


def test_sarif_names_the_qualified_name_and_keeps_the_xmi_id_apart(capsys) -> None:
    """SARIF's fullyQualifiedName held the xmi:id (issue 10 item 9)."""
    import json

    from robomda.cli import main
    model = next(p for p in sorted(BROKEN.glob("*/model.xmi"))
                 if (p.parent / "expected.txt").read_text().count("(uml:Port ") > 0)
    main(["check", str(model), "--format", "sarif"])
    log = json.loads(capsys.readouterr().out)
    logical = [loc["logicalLocations"][0] for r in log["runs"][0]["results"] for loc in r.get("locations", [])
               if "logicalLocations" in loc]
    assert logical
    for loc in logical:
        # the model itself (a finding about the whole system) is its own qualified name
        nested = "::" in loc["fullyQualifiedName"] or loc["kind"] == "uml:Model"
        assert nested and loc["fullyQualifiedName"].endswith(loc["name"])
        assert loc["properties"]["xmiId"] and loc["properties"]["xmiId"] not in loc["fullyQualifiedName"]


@pytest.mark.parametrize("case, kind", [("buffer-size-zero", "robomda:ConnectionPolicy"),
                                        ("negative-period", "uml:Property 'sample'"),
                                        ("priority-out-of-range", "uml:Property 'priority'")])
def test_a_bad_value_is_located_where_it_is_written(case: str, kind: str, capsys) -> None:
    """Errors pointed at the component or connector instead of the element holding the bad
    value (a stereotype application's tag, a convention attribute): issue 10 item 9."""
    code, out, err = _run(capsys, ["check", f"fixtures/broken/{case}/model.xmi"])
    assert code != 0
    line = next(line for line in (out + err).splitlines() if ": error: [" in line)
    assert f"({kind}" in line, line
    where = int(line.split(":")[1])
    # the element's start tag, or its defaultValue just below
    text = "\n".join((BROKEN / case / "model.xmi").read_text(encoding="utf-8").splitlines()[where - 1:where + 2])
    bad = {"buffer-size-zero": 'size="0"', "negative-period": 'value="-0.01"', "priority-out-of-range": 'value="150"'}[case]
    assert bad in text, text
