"""Large stages are validated in the checker process (robomda.checker) with the same outcome.

A stage of rules.SAXON_FROM characters or more is handed to the checker,
validated there while its rules and the next step run in the driver; its
rules' findings count once it is known valid. The outcome must not change:
the same diagnostics, in the same order, with the same exit code, a schema
break reported before anything the next step did, and a checker that died
leaves the validation to the driver.
"""

from __future__ import annotations

import os
import signal
from pathlib import Path

import pytest

from robomda import checker as checking
from robomda import pipeline
from robomda.api import generate
from robomda.checker import Checker
from robomda.diagnostics import RobomdaError
from robomda.engine import Engine
from test_broken import CORPUS, ROOT
from test_rules_saxon import _diagnostics

XMI = ROOT / "tests" / "data" / "import" / "features.uml"
FILESET = ROOT / "schemas" / "fileset" / "1" / "fileset.xsd"
VALID = '<fs:files xmlns:fs="urn:robomda:fileset:1" target="t"><fs:file path="a" stylesheet="s">x</fs:file></fs:files>'
INVALID = VALID.replace('path="a"', 'path="../escape"')


@pytest.fixture
def submitted(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """The length of each stage handed to a checker."""
    lengths: list[int] = []
    submit = Checker.submit
    monkeypatch.setattr(Checker, "submit", lambda self, text, schema: lengths.append(len(text))
                        or submit(self, text, schema))
    return lengths


@pytest.fixture
def fresh() -> Checker:
    made = Checker()
    yield made
    made.close()


def test_the_checker_says_whether_a_stage_is_valid_and_leaves_no_file(fresh: Checker) -> None:
    jobs = [fresh.submit(text, FILESET) for text in (VALID, INVALID, VALID)]
    assert [fresh.valid(job) for job in jobs] == [True, False, True]
    folder = fresh._folder
    assert folder is not None and not list(folder.iterdir())
    fresh.close()
    assert not folder.exists()


def test_a_checker_that_died_leaves_the_validation_to_the_driver(fresh: Checker) -> None:
    job = fresh.submit(VALID, FILESET)
    assert fresh.valid(job) is True
    # stopped first, so that it cannot answer before it dies (it once did, and the run failed)
    os.kill(fresh._proc.pid, signal.SIGSTOP)
    job = fresh.submit(VALID, FILESET)
    os.kill(fresh._proc.pid, signal.SIGKILL)
    assert fresh.valid(job) is None
    # and the next stage gets a new checker
    assert fresh.valid(fresh.submit(VALID, FILESET)) is True


_STEP = """<xsl:stylesheet version="3.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:f="urn:robomda:xslt:function" xmlns:fs="urn:robomda:fileset:1" exclude-result-prefixes="#all">
  <xsl:include href="{errors}"/>
  <xsl:template match="/">{body}</xsl:template>
</xsl:stylesheet>"""


def _chain(tmp_path: Path, first: str, second: str) -> pipeline.Pipeline:
    """Two steps writing file sets: the first one's stage is handed to the checker (SAXON_FROM 0)."""
    for name, body in (("first", first), ("second", second)):
        (tmp_path / f"{name}.xsl").write_text(_STEP.format(errors=(ROOT / "xslt/common/errors.xsl").as_uri(),
                                                           body=body))
    manifest = tmp_path / "test.xml"
    manifest.write_text(f"""<pipeline xmlns="urn:robomda:pipeline:1" name="test" yields="model">
  <description>test</description>
  <step name="first" stylesheet="first.xsl" schema="{FILESET.as_posix()}"/>
  <step name="second" stylesheet="second.xsl" schema="{FILESET.as_posix()}"/>
</pipeline>""")
    return pipeline.load(manifest)


def _outcome(chain: pipeline.Pipeline) -> tuple[int, list[str]]:
    try:
        result = pipeline.run(chain, Engine(), XMI, {})
    except RobomdaError as exc:
        return exc.exit_code, [f"{d.code} {d.message}" for d in exc.diagnostics]
    return 0, [f"{d.code} {d.message}" for d in result.warnings]


@pytest.mark.parametrize("second", [
    "<xsl:sequence select=\"f:warn('TST001', 'x', 'the second step ran')\"/><xsl:copy-of select=\".\"/>",
    "<xsl:sequence select=\"error(QName('urn:x', 'BOOM'), 'kaput')\"/>",
])
def test_a_stage_that_breaks_its_schema_is_reported_before_anything_of_the_next(
        tmp_path: Path, second: str, monkeypatch: pytest.MonkeyPatch, submitted: list[int]) -> None:
    chain = _chain(tmp_path, INVALID, second)
    monkeypatch.setattr(checking, "ENABLED", False)
    in_driver = _outcome(chain)
    assert in_driver[0] == 3 and in_driver[1][0].startswith("SCHEMA the first step wrote a model that breaks")
    monkeypatch.setattr(pipeline, "SAXON_FROM", 0)
    monkeypatch.setattr(checking, "ENABLED", True)
    assert _outcome(chain) == in_driver
    assert submitted


def test_a_valid_stage_checked_aside_keeps_the_order_of_warnings(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                               submitted: list[int]) -> None:
    chain = _chain(tmp_path, f"<xsl:sequence select=\"f:warn('TST001', 'x', 'first')\"/>{VALID}",
                   "<xsl:sequence select=\"f:warn('TST002', 'x', 'second')\"/><xsl:copy-of select=\".\"/>")
    monkeypatch.setattr(checking, "ENABLED", False)
    in_driver = _outcome(chain)
    assert in_driver == (0, ["TST001 first", "TST002 second"])
    monkeypatch.setattr(pipeline, "SAXON_FROM", 0)
    monkeypatch.setattr(checking, "ENABLED", True)
    assert _outcome(chain) == in_driver
    assert submitted


@pytest.mark.parametrize("case", CORPUS)
def test_the_broken_corpus_checks_the_same_with_every_stage_validated_aside(
        case: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every stage of every broken model through the checker (and its rules on Saxon, as for a large
    model): the same diagnostics, order and exit code as validated in the driver."""
    monkeypatch.chdir(ROOT)
    monkeypatch.setattr(pipeline, "SAXON_FROM", 0)
    monkeypatch.setattr(checking, "ENABLED", False)
    in_driver = _diagnostics(case)
    monkeypatch.setattr(checking, "ENABLED", True)
    assert _diagnostics(case) == in_driver


def test_a_large_model_generates_the_same_with_its_stages_validated_aside(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, submitted: list[int]) -> None:
    """A synthetic model whose stages are large (no setting changed): the checker takes them."""
    import sys

    sys.path.insert(0, str(ROOT / "bench"))
    from synth import write_model

    model = write_model(600, tmp_path / "model.xmi")
    aside = generate(model, tmp_path / "aside")
    assert len(submitted) == 3 and min(submitted) >= pipeline.SAXON_FROM  # import, bind, psm
    monkeypatch.setattr(checking, "ENABLED", False)
    here = generate(model, tmp_path / "here")
    assert aside.stages == here.stages
    assert [d.format() for d in aside.warnings] == [d.format() for d in here.warnings]
    assert aside.report.written == here.report.written


def test_a_process_forked_from_the_driver_gets_a_checker_of_its_own() -> None:
    ours = checking.checker()
    assert ours.valid(ours.submit(VALID, FILESET)) is True
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: a checker of its own, which answers it
        mine = checking.checker()
        ok = mine is not ours and mine.valid(mine.submit(VALID, FILESET)) is True
        os.write(write, b"1" if ok else b"0")
        os._exit(0)
    os.close(write)
    assert os.read(read, 1) == b"1"
    os.waitpid(pid, 0)
    os.close(read)
    assert ours.valid(ours.submit(INVALID, FILESET)) is False


def test_a_checker_that_answers_nonsense_leaves_the_validation_to_the_driver(fresh: Checker) -> None:
    job = fresh.submit(VALID, FILESET)
    fresh._proc.stdout.close()
    fresh._proc.stdout = __import__("io").StringIO("Traceback (most recent call last):\n")
    assert fresh.valid(job) is None
    assert fresh.valid(fresh.submit(VALID, FILESET)) is True


@pytest.mark.parametrize("case", CORPUS)
def test_the_broken_corpus_checks_the_same_when_the_checker_never_answers(
        case: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every stage handed over and never answered for (the checker died each time): the driver
    validates each one itself, with the same outcome."""
    monkeypatch.chdir(ROOT)
    monkeypatch.setattr(pipeline, "SAXON_FROM", 0)
    monkeypatch.setattr(checking, "ENABLED", False)
    in_driver = _diagnostics(case)
    monkeypatch.setattr(checking, "ENABLED", True)
    monkeypatch.setattr(Checker, "valid", lambda self, job: None)
    assert _diagnostics(case) == in_driver


def test_two_runs_resuming_from_one_unsettled_run_each_settle_once(monkeypatch: pytest.MonkeyPatch,
                                                                  submitted: list[int]) -> None:
    """generate leaves the import run's last stage unsettled for the target's chain, which takes it; a
    second run resuming from the same result must not wait for that answer again (it is read once)."""
    from robomda.api import _context
    from robomda.resources import pipeline_path

    monkeypatch.setattr(pipeline, "SAXON_FROM", 0)
    engine, model = Engine(), ROOT / "fixtures" / "cases" / "headlamp" / "model.xmi"
    context = _context(model, None, "")
    bound = pipeline.run(pipeline.load(pipeline_path("import")), engine, model, context, settle=False)
    assert bound.pending and submitted
    orocos = pipeline.load(pipeline_path("orocos"))
    first = pipeline.run(orocos, engine, model, context, resume=bound)
    assert not bound.pending and not first.pending
    second = pipeline.run(orocos, engine, model, context, resume=bound)
    assert [d.format() for d in second.warnings] == [d.format() for d in first.warnings]
    assert second.stages == first.stages
