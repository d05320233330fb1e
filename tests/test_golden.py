"""Golden files: every stage model and every generated file of every fixture case.

Goldens live in fixtures/cases/<case>/expected/: the stage models as
<step>.xml and the generated package under <target>/. The fixtures of one
target, fixtures/<target>/<case>/ (a model the other targets refuse yet),
have goldens for that target only (fixtures/ros/usercode, components
without a realizing class, also for OpenRTM). Regenerate on purpose only
(``tests/run.sh --force-regen``) and review the diff.

The chain runs as if the output folder were fixtures/cases/<case>/out, so
relative library paths in the goldens are the same on every machine.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate, targets

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted(p.parent for p in (ROOT / "fixtures" / "cases").glob("*/model.xmi"))
TARGETS = targets()  # from the pipeline manifests
# (case, target): every case on every target, and the one-target fixtures
RUNS = [(case, target) for case in CASES for target in TARGETS] + [
    (p.parent, "orocos") for p in sorted((ROOT / "fixtures" / "orocos").glob("*/model.xmi"))] + [
    # OpenRTM components without a realizing class: the user's classes in the shared frames
    (ROOT / "fixtures" / "ros" / "usercode", "openrtm")]
RUN_IDS = [f"{target}-{case.name}" for case, target in RUNS]
FS = "{urn:robomda:fileset:1}"


def _check_all(file_regression, items: list[tuple[str, Path]]) -> None:
    """Check every (text, golden path); report all differences, not only the first."""
    failures = []
    for text, golden in items:
        try:
            file_regression.check(text, fullpath=golden, binary=False)
        except (AssertionError, pytest.fail.Exception) as exc:
            failures.append(f"{golden.relative_to(ROOT)}: {str(exc).strip().splitlines()[0]}")
    if failures:
        pytest.fail("\n".join(failures))


def _run(case: Path, target: str):
    return generate(case / "model.xmi", case / "out", target, write=False)


@pytest.fixture(scope="module")
def runs() -> dict[tuple[str, str], object]:
    return {}


def _cached(runs: dict, case: Path, target: str):
    key = (case.name, target)
    if key not in runs:
        runs[key] = _run(case, target)
    return runs[key]


@pytest.mark.parametrize(("case", "target"), RUNS, ids=RUN_IDS)
def test_stage_models_match_goldens(case: Path, target: str, runs: dict, file_regression) -> None:
    done = _cached(runs, case, target)
    _check_all(file_regression, [
        (text, case / "expected" / f"{'' if step in ('import', 'bind') else target + '/'}{step}.xml")
        for step, text in done.stages.items() if step != "text"])


@pytest.mark.parametrize(("case", "target"), RUNS, ids=RUN_IDS)
def test_generated_files_match_goldens(case: Path, target: str, runs: dict, file_regression) -> None:
    done = _cached(runs, case, target)
    files = etree.fromstring(done.stages["text"].encode("utf-8"))
    nodes = list(files.iter(f"{FS}file"))
    listing = "".join(f"{node.get('mode', 'generated')}\t{node.get('path')}\n" for node in nodes)
    _check_all(file_regression, [(listing, case / "expected" / target / "files.tsv")] + [
        (node.text or "", case / "expected" / target / "files" / node.get("path")) for node in nodes])


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_two_runs_write_identical_bytes(case: Path, tmp_path: Path) -> None:
    trees = []
    for name in ("a", "b"):
        out = tmp_path / name
        generate(case / "model.xmi", out, "orocos")
        trees.append({p.relative_to(out).as_posix(): p.read_bytes()
                      for p in sorted(out.rglob("*")) if p.is_file() and ".robomda" not in p.parts})
    assert trees[0] == trees[1]
    assert any(path.endswith(".cpp") for path in trees[0])
