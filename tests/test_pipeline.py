"""The pipeline runner with small stand-in stylesheets: warnings, bugs and schema breaks are located."""

from __future__ import annotations

from pathlib import Path

import pytest

from robomda import pipeline
from robomda.diagnostics import RobomdaError
from robomda.engine import Engine

ROOT = Path(__file__).resolve().parent.parent
XMI = ROOT / "tests" / "data" / "import" / "features.uml"

_STEP = """<xsl:stylesheet version="3.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:f="urn:robomda:xslt:function" xmlns:fs="urn:robomda:fileset:1" exclude-result-prefixes="#all">
  <xsl:include href="{errors}"/>
  <xsl:template match="/">
    {body}
  </xsl:template>
</xsl:stylesheet>"""


def _manifest(tmp_path: Path, body: str) -> pipeline.Pipeline:
    xsl = tmp_path / "step.xsl"
    xsl.write_text(_STEP.format(errors=(ROOT / "xslt/common/errors.xsl").as_uri(), body=body))
    manifest = tmp_path / "test.xml"
    manifest.write_text(f"""<pipeline xmlns="urn:robomda:pipeline:1" name="test" yields="files">
  <description>test</description>
  <step name="only" stylesheet="step.xsl" schema="{(ROOT / 'schemas/fileset/1/fileset.xsd').as_posix()}"/>
</pipeline>""")
    return pipeline.load(manifest)


def _first_id_and_line() -> tuple[str, int]:
    for number, line in enumerate(XMI.read_text(encoding="utf-8").splitlines(), 1):
        if 'xmi:id="' in line and "packagedElement" in line:
            return line.split('xmi:id="')[1].split('"')[0], number
    raise AssertionError("no packagedElement with an id")


def test_warnings_are_collected_with_their_xmi_location(tmp_path: Path) -> None:
    xid, line = _first_id_and_line()
    chain = _manifest(tmp_path, f"""<xsl:sequence select="f:warn('TST001', '{xid}', 'look here')"/>
    <fs:files target="t"/>""")
    result = pipeline.run(chain, Engine(), XMI, {})
    assert [w.code for w in result.warnings] == ["TST001"]
    warning = result.warnings[0]
    assert warning.severity == "warning" and warning.line == line and warning.xmi_id == xid
    assert warning.format().startswith(f"{XMI}:{line}:") and ": warning: [TST001] look here" in warning.format()


def test_an_unexpected_stylesheet_error_is_an_internal_error_without_traceback(tmp_path: Path) -> None:
    chain = _manifest(tmp_path, "<xsl:sequence select=\"error(QName('urn:x', 'BOOM'), 'kaput')\"/>")
    with pytest.raises(RobomdaError) as caught:
        pipeline.run(chain, Engine(), XMI, {})
    assert caught.value.exit_code == 3
    assert caught.value.diagnostics[0].code == "INTERNAL" and "kaput" in caught.value.diagnostics[0].message


def test_output_breaking_its_schema_is_reported_as_a_bug(tmp_path: Path) -> None:
    chain = _manifest(tmp_path, '<fs:files target="t"><fs:file path="../escape" stylesheet="s">x</fs:file></fs:files>')
    with pytest.raises(RobomdaError) as caught:
        pipeline.run(chain, Engine(), XMI, {})
    assert caught.value.exit_code == 3
    assert caught.value.diagnostics[0].code == "SCHEMA" and "fileset.xsd" in caught.value.diagnostics[0].message


def test_a_target_chain_resumes_from_the_import_run_that_found_its_target(monkeypatch) -> None:
    """generate without --target runs import + bind once, not once to find the target and once more."""
    from robomda import api
    from robomda.resources import pipeline_path

    model = ROOT / "fixtures" / "cases" / "headlamp" / "model.xmi"
    context = api._context(model, None, "")
    engine = Engine()
    bound = pipeline.run(pipeline.load(pipeline_path("import")), engine, model, context)
    chain = pipeline.load(pipeline_path("orocos"))
    ran: list[str] = []
    real_run = engine.run
    # the stages' stylesheets (the rules, compiled to XSLT, run on the engine too)
    monkeypatch.setattr(engine, "run", lambda stylesheet, *a, **k: (
        ran.extend([stylesheet.name] if ".sch." not in stylesheet.name else []), real_run(stylesheet, *a, **k))[1])
    tree = bound.handed
    assert tree is not None
    monkeypatch.setattr(engine, "parse", lambda text: pytest.fail("the bound PIM was parsed again"))
    resumed = pipeline.run(chain, engine, model, context, resume=bound)
    assert ran == ["psm.xsl", "main.xsl"]  # import.xsl and bind.xsl were not run again
    # the bound PIM's tree was handed over, and taken: the earlier result no longer holds it
    assert bound.handed is None and resumed.handed is None
    monkeypatch.undo()
    monkeypatch.setattr(engine, "run", lambda stylesheet, *a, **k: (
        ran.extend([stylesheet.name] if ".sch." not in stylesheet.name else []), real_run(stylesheet, *a, **k))[1])
    ran.clear()
    # a second run resuming from it reads the text
    assert pipeline.run(chain, engine, model, context, resume=bound).stages == resumed.stages
    assert ran == ["psm.xsl", "main.xsl"]
    fresh = pipeline.run(chain, Engine(), model, context)
    assert resumed.stages == fresh.stages
    assert [(d.code, d.line, d.message) for d in resumed.warnings] == [(d.code, d.line, d.message) for d in fresh.warnings]
    # other parameters for the import step: nothing is taken from the earlier run
    ran.clear()
    other = dict(context, **{"model-path": (ROOT / "fixtures").as_uri() + "/"})
    pipeline.run(chain, engine, model, other, resume=bound)
    assert ran[:2] == ["import.xsl", "bind.xsl"]
