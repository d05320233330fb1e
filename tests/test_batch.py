"""Batch mode: a folder of models, found by content, in parallel, incremental."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from robomda.batch import find_models, run_batch
from robomda.cli import main

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "fixtures" / "cases"


@pytest.fixture()
def tree(tmp_path: Path) -> Path:
    src = tmp_path / "models"
    shutil.copytree(CASES / "meka", src / "meka", ignore=shutil.ignore_patterns("expected"))
    shutil.copytree(CASES / "headlamp", src / "headlamp", ignore=shutil.ignore_patterns("expected"))
    # found by content: an XMI model whose name says nothing
    shutil.copy(CASES / "meka" / "model.ea.xmi", src / "meka" / "exported-by-ea.txt")
    # not models: a robomda PIM, a text file, broken XML
    (src / "notes.xml").write_text('<pim:model xmlns:pim="urn:robomda:pim:1"/>')
    (src / "readme.txt").write_text("hello")
    (src / "half.xmi").write_text("<xmi:XMI xmlns:xmi='http://www.omg.org/spec/XMI/20131001'")
    # a model with an error
    text = (CASES / "meka" / "model.xmi").read_text(encoding="utf-8")
    (src / "broken").mkdir()
    (src / "broken" / "gazebo.xmi").write_text(text.replace('name="OROCOS"', 'name="Gazebo"', 1), encoding="utf-8")
    return src


def test_models_are_found_by_content(tree: Path) -> None:
    found = [p.relative_to(tree).as_posix() for p in find_models(tree)]
    assert found == ["broken/gazebo.xmi", "headlamp/model.ea.xmi", "headlamp/model.xmi",
                     "meka/exported-by-ea.txt", "meka/model.ea.xmi", "meka/model.xmi"]


def test_batch_reports_each_model_and_goes_on_after_a_failure(tree: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    report = run_batch(tree, out, jobs=2)
    status = {r.model: r.status for r in report.results}
    assert status.pop("broken/gazebo.xmi") == "failed"
    assert set(status.values()) == {"ok"} and len(status) == 5
    failed = next(r for r in report.results if r.status == "failed")
    assert "[BND003]" in failed.diagnostics[0] and "gazebo.xmi:" in failed.diagnostics[0]
    assert report.exit_code == 1
    assert (out / "headlamp" / "model" / "deploy" / "headlamp.xml").is_file()
    assert (out / "meka" / "exported-by-ea" / "CMakeLists.txt").is_file()
    assert not (out / "broken" / "gazebo").exists()
    # each model's package equals the single-model run
    assert ((out / "meka" / "model" / "src" / "components.cpp").read_bytes()
            == (CASES / "meka" / "expected" / "orocos" / "files" / "src" / "components.cpp").read_bytes())


def test_second_run_skips_unchanged_models_and_redoes_changed_ones(tree: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    run_batch(tree, out, jobs=1)
    again = run_batch(tree, out, jobs=1)
    assert {r.model: r.status for r in again.results if r.status != "failed"} == {
        m: "skipped" for m in ["headlamp/model.ea.xmi", "headlamp/model.xmi", "meka/exported-by-ea.txt",
                               "meka/model.ea.xmi", "meka/model.xmi"]}
    model = tree / "meka" / "model.xmi"
    model.write_text(model.read_text(encoding="utf-8").replace("0.05", "0.1"), encoding="utf-8")
    third = run_batch(tree, out, jobs=1)
    assert {r.model for r in third.results if r.status == "ok"} == {"meka/model.xmi"}
    assert "0.1" in (out / "meka" / "model" / "deploy" / "meka.ops").read_text()
    forced = run_batch(tree, out, jobs=1, force=True)
    assert forced.count("skipped") == 0 and forced.count("ok") == 5


def test_cli_prints_a_summary_and_exits_non_zero(tree: Path, tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["generate", str(tree), "-o", str(tmp_path / "out"), "-j", "2"])
    out, err = capsys.readouterr()
    assert code == 1
    assert "6 models: 5 ok, 0 unchanged, 1 failed" in out
    assert "broken/gazebo.xmi" in out and "[BND003]" in err
    assert "[####" not in err  # no progress bar when stderr is not a terminal
