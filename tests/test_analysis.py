"""The feature model analysis (robomda features, the optional extra robomda[analysis]: flamapy).

Runs the real library on the product line fixtures and on feature models
written here: a void one, one with a dead and a false-optional feature, and
a resolution model whose presence conditions never, always or cannot hold.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robomda.cli import main

ROOT = Path(__file__).resolve().parent.parent
LINES = ROOT / "fixtures" / "variability"


def _feature_model(folder: Path, rules: str) -> Path:
    """Root R: mandatory A, optional B and C, an alternative group G of X and Y; ``rules`` its constraints."""
    path = folder / "model.xml"
    path.write_text(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<featureModel>\n  <struct>\n"
        "    <and abstract=\"true\" mandatory=\"true\" name=\"R\">\n"
        "      <feature mandatory=\"true\" name=\"A\"/>\n"
        "      <feature name=\"B\"/>\n"
        "      <feature name=\"C\"/>\n"
        "      <alt abstract=\"true\" mandatory=\"true\" name=\"G\">\n"
        "        <feature name=\"X\"/>\n        <feature name=\"Y\"/>\n      </alt>\n"
        "    </and>\n  </struct>\n"
        f"  <constraints>\n{rules}  </constraints>\n</featureModel>\n", encoding="utf-8")
    return path


def _run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str], str]:
    code = main(["features", *argv])
    out = capsys.readouterr()
    return code, out.err.strip().splitlines(), out.out


@pytest.mark.parametrize("line, products", [("researchcamp", 36), ("calligraphy", 16)])
def test_fixture_product_lines(line: str, products: int, capsys: pytest.CaptureFixture[str]) -> None:
    # Research Camp: 3 navigation choices (map-based in a hall or lab, marker-based) x 2 avoiders x
    # 3 perception / manipulation pairs x offboard or not; every presence condition holds in some variant
    # and fails in another
    folder = LINES / line / "variability"
    code, err, out = _run(capsys, str(folder / "model.xml"), "--resolution", str(folder / "resolution.xml"))
    assert code == 0
    assert [e.split("[")[1][:6] for e in err] == ["VAR044"]
    assert f"has {products} valid configurations" in err[0]
    assert out.strip().endswith(f"{products} products, 0 dead, 0 false-optional, 0 never-present")


def test_void_model_is_an_error_at_the_root(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model = _feature_model(tmp_path, "    <rule><not><var>A</var></not></rule>\n")
    code, err, _ = _run(capsys, str(model))
    assert code == 1
    assert err == [f"{model}:4: error: [VAR041] the feature model is void: no configuration satisfies it "
                   "(its constraints contradict its tree) (feature 'R')"]


def test_dead_and_false_optional_features(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # B excludes the mandatory A: dead; A requires C: C is optional yet always there
    model = _feature_model(tmp_path, "    <rule><not><conj><var>A</var><var>B</var></conj></not></rule>\n"
                                     "    <rule><imp><var>A</var><var>C</var></imp></rule>\n")
    code, err, out = _run(capsys, str(model))
    assert code == 0
    assert err[0].startswith(f"{model}:6: warning: [VAR042] a dead feature") and err[0].endswith("(feature 'B')")
    assert err[1].startswith(f"{model}:7: warning: [VAR043] a false-optional") and err[1].endswith("(feature 'C')")
    # C fixed, B gone: the alternative group alone varies
    assert "has 2 valid configurations" in err[2]
    assert "2 products, 1 dead, 1 false-optional" in out


def test_presence_conditions(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model = _feature_model(tmp_path, "    <rule><imp><var>X</var><var>B</var></imp></rule>\n")
    resolution = tmp_path / "resolution.xml"
    resolution.write_text(
        "<resolution xmlns=\"urn:robomda:resolution:1\">\n"
        "  <present element=\"m::s::never\"><conj><var>X</var><not><var>B</var></not></conj></present>\n"
        "  <present element=\"m::s::always\" when=\"A\"/>\n"
        "  <present element=\"m::s::sometimes\" when=\"X\"/>\n"
        "  <present element=\"m::s::unknown\"><disj><var>X</var><var>Nope</var></disj></present>\n"
        "  <present element=\"m::s::empty\"/>\n"
        "  <present element=\"m::s::unknown2\" when=\"Gone\"/>\n"
        "</resolution>\n", encoding="utf-8")
    code, err, out = _run(capsys, str(model), "--resolution", str(resolution))
    assert code == 1
    assert err[1:] == [
        f"{resolution}:2: warning: [VAR045] no valid configuration satisfies the presence condition: the element "
        "is in no variant (present 'm::s::never')",
        f"{resolution}:3: info: [VAR046] every valid configuration satisfies the presence condition: the element "
        "is in every variant (present 'm::s::always')",
        f"{resolution}:5: error: [VAR047] the presence condition names features the feature model does not have: "
        "Nope (present 'm::s::unknown')",
        f"{resolution}:6: error: [VAR048] the presence condition is empty: give @when (a feature) or a formula "
        "(present 'm::s::empty')",
        f"{resolution}:7: error: [VAR047] the presence condition names features the feature model does not have: "
        "Gone (present 'm::s::unknown2')"]
    assert "1 never-present" in out


def test_without_flamapy_the_command_names_the_extra(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    # a None entry makes Python's import fail, as an uninstalled package does
    for name in ["flamapy", *(m for m in sys.modules if m.startswith("flamapy."))]:
        monkeypatch.setitem(sys.modules, name, None)
    code, err, _ = _run(capsys, str(_feature_model(tmp_path, "")))
    assert code == 2 and len(err) == 1
    assert err[0].startswith("error: [VAR040] ") and "pip install 'robomda[analysis]'" in err[0]


def test_generate_and_check_never_import_flamapy() -> None:
    probe = ("import sys, robomda.api, robomda.cli, robomda.variability, robomda.batch\n"
             "print(sorted(m for m in sys.modules if m.split('.')[0] in ('flamapy', 'pysat')))")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"


def test_json_report_and_a_schema_error_located(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    import json

    model = _feature_model(tmp_path, "    <rule><not><var>A</var></not></rule>\n")
    code, _, out = _run(capsys, str(model), "--format", "json")
    report = json.loads(out)
    assert code == 1 and report["exit_code"] == 1
    assert [(d["code"], d["line"], d["element"]["name"]) for d in report["diagnostics"]] == [("VAR041", 4, "R")]
    model.write_text(model.read_text(encoding="utf-8").replace('<feature name="C"/>', "<bogus/>"), encoding="utf-8")
    code, err, _ = _run(capsys, str(model))
    assert code == 1 and err[0].startswith(f"{model}:7: error: [VAR002] ") and "'bogus'" in err[0]


def test_readme_and_docs_name_the_command_and_the_extra() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "robomda features FEATURE-MODEL [--resolution FILE]" in readme
    assert "pip install 'robomda[analysis]'" in readme
    assert "Research Camp line has 36 products, the calligraphy line\n16" in \
        (ROOT / "docs" / "variability.md").read_text(encoding="utf-8")


def test_help_names_the_extra(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as done:
        main(["features", "--help"])
    out = capsys.readouterr().out
    assert done.value.code == 0 and "--resolution FILE" in out and "robomda[analysis]" in out
