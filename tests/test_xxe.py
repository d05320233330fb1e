"""Models that declare external entities or name a DTD (issue 11, defect class 5).

An external entity must never pull a file into robomda's output, a DTD is
never fetched, and EA's XMI 1.1 with its DOCTYPE gets the XMI 1.x refusal
(IMP001), not INTERNAL. Checked for the driver (SaxonC) and for the
standalone chain's documented command lines (Saxon-HE Java, SaxonJS).
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from robomda.api import check, generate, import_model
from robomda.diagnostics import RobomdaError

ROOT = Path(__file__).resolve().parents[1]
SECRET = "robomda-secret-0f3c"  # what a leaked file would show
SAXON_JAR = Path(os.environ.get("ROBOMDA_SAXON_JAR", "/usr/share/java/Saxon-HE.jar"))
XSLT3 = Path(os.environ.get("ROBOMDA_XSLT3", ROOT / "tests" / "engines" / "node_modules" / "xslt3" / "xslt3.js"))
SAFE_JAVA = [f"--parserFeature?uri=http%3A//{f}:false" for f in (
    "xml.org/sax/features/external-general-entities", "xml.org/sax/features/external-parameter-entities",
    "apache.org/xml/features/nonvalidating/load-external-dtd")]


def _xxe_model(tmp_path: Path) -> Path:
    """Headlamp with an external entity used in a comment: the secret must appear nowhere."""
    secret = tmp_path / "secret.txt"
    secret.write_text(SECRET + "\n")
    text = (ROOT / "fixtures" / "cases" / "headlamp" / "model.xmi").read_text(encoding="utf-8")
    head, rest = text.split("<xmi:XMI", 1)
    doctype = f'<!DOCTYPE xmi:XMI [\n  <!ENTITY leak SYSTEM "{secret.as_uri()}">\n]>\n'
    body = ('<xmi:XMI' + rest).replace(
        'name="Guppy80">', 'name="Guppy80"><ownedComment xmi:type="uml:Comment" xmi:id="_leak"><body>&leak;</body>'
        '</ownedComment>', 1)
    model = tmp_path / "model.xmi"
    model.write_text(head + doctype + body, encoding="utf-8")
    shutil.copytree(ROOT / "fixtures" / "cases" / "headlamp" / "atomic", tmp_path / "atomic")
    return model


def test_an_external_entity_reads_no_file_and_is_named(tmp_path: Path) -> None:
    model = _xxe_model(tmp_path)
    pim = import_model(model)
    assert SECRET not in pim
    done = generate(model, tmp_path / "out", "orocos")
    assert all(SECRET not in text for text in done.stages.values())
    assert not [p for p in (tmp_path / "out").rglob("*") if p.is_file() and SECRET in p.read_text(errors="replace")]
    [warning] = [w for w in done.warnings if w.code == "IMP005"]
    line = next(n for n, text in enumerate(model.read_text().splitlines(), 1) if "<!ENTITY leak" in text)
    assert "'leak'" in warning.message and warning.line == line


def _headlamp_with(tmp_path: Path, doctype: str, body: str) -> Path:
    """Headlamp with DOCTYPE before its root and a comment of BODY on its model."""
    text = (ROOT / "fixtures" / "cases" / "headlamp" / "model.xmi").read_text(encoding="utf-8")
    head, rest = text.split("<xmi:XMI", 1)
    model = tmp_path / "model.xmi"
    model.write_text(head + doctype + ("<xmi:XMI" + rest).replace(
        'name="Guppy80">', 'name="Guppy80"><ownedComment xmi:type="uml:Comment" xmi:id="_note"><body>'
        + body + "</body></ownedComment>", 1), encoding="utf-8")
    shutil.copytree(ROOT / "fixtures" / "cases" / "headlamp" / "atomic", tmp_path / "atomic")
    return model


def test_a_model_with_long_escaped_notes_is_read(tmp_path: Path) -> None:
    """EA and MagicDraw keep notes as escaped HTML: 30,000 paragraphs are 120,000 references to `<` and
    `>`, past the 100,000 characters SaxonC-HE 13's parser allows from references by default (it
    failed the import as INTERNAL, and the bench's identity over a PSM of 10,000 data types)."""
    model = _headlamp_with(tmp_path, "", "&lt;p&gt;note&lt;/p&gt;" * 30000)
    done = generate(model, tmp_path / "out", "orocos")
    assert "<p>note</p>" * 3 in done.stages["import"] or "&lt;p&gt;note" in done.stages["import"]
    assert (tmp_path / "out" / "package.xml").is_file()


def test_an_entity_that_amplifies_is_refused_before_anything_is_written(tmp_path: Path) -> None:
    """Lifting that cap leaves "billion laughs" refused: ten entities of ten references each."""
    entities = '<!ENTITY a "aaaaaaaaaa">' + "".join(
        f'<!ENTITY {name} "{("&" + inner + ";") * 10}">' for inner, name in zip("abcdefg", "bcdefgh"))
    model = _headlamp_with(tmp_path, f"<!DOCTYPE xmi:XMI [{entities}]>\n", "&h;")
    with pytest.raises(RobomdaError) as refused:
        generate(model, tmp_path / "out", "orocos")
    [said] = refused.value.diagnostics
    assert said.code == "XML001" and "amplification" in said.message
    assert not (tmp_path / "out").exists()


def test_a_doctype_naming_a_missing_dtd_is_no_problem(tmp_path: Path) -> None:
    text = (ROOT / "fixtures" / "cases" / "headlamp" / "model.xmi").read_text(encoding="utf-8")
    head, rest = text.split("<xmi:XMI", 1)
    model = tmp_path / "model.xmi"
    model.write_text(head + '<!DOCTYPE xmi:XMI SYSTEM "http://example.invalid/UML.dtd">\n<xmi:XMI' + rest,
                     encoding="utf-8")
    assert check(model, "orocos").exit_code == 0


def test_ea_xmi_1_1_with_its_doctype_is_refused_as_xmi_1(tmp_path: Path) -> None:
    model = tmp_path / "ea.xmi"
    model.write_text('<?xml version="1.0" encoding="windows-1252"?>\n<!DOCTYPE XMI SYSTEM "UML_EA.dtd">\n'
                     '<XMI xmi.version="1.1" xmlns:UML="omg.org/UML1.3">\n<XMI.content><UML:Model name="m" '
                     'xmi.id="MX_1"/></XMI.content>\n</XMI>\n', encoding="windows-1252")
    with pytest.raises(RobomdaError) as refused:
        check(model)
    assert [d.code for d in refused.value.diagnostics] == ["IMP001"] and refused.value.exit_code == 2


@pytest.mark.skipif(not (shutil.which("java") and SAXON_JAR.is_file()), reason=f"no java or {SAXON_JAR}")
def test_saxon_he_java_with_the_documented_options_reads_no_entity(tmp_path: Path) -> None:
    model = _xxe_model(tmp_path)
    cmd = ["java", "-cp", str(SAXON_JAR), "net.sf.saxon.Transform", *SAFE_JAVA, f"-s:{model}",
           f"-xsl:{ROOT / 'xslt' / 'import' / 'import.xsl'}", "source-name=model.xmi"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert SECRET not in done.stdout and "<pim:model" in done.stdout
    # without them, the JDK parser reads the file: the options are what makes it safe
    unsafe = subprocess.run([c for c in cmd if c not in SAFE_JAVA], capture_output=True, text=True, timeout=300)
    assert SECRET in unsafe.stdout


@pytest.mark.skipif(not (shutil.which("node") and XSLT3.is_file()), reason=f"no node or {XSLT3}")
def test_saxonjs_reads_no_entity(tmp_path: Path) -> None:
    model = _xxe_model(tmp_path)
    done = subprocess.run(["node", str(XSLT3), f"-s:{model}", f"-xsl:{ROOT / 'xslt' / 'import' / 'import.xsl'}",
                           "source-name=model.xmi"], capture_output=True, text=True, timeout=600)
    assert SECRET not in done.stdout + done.stderr
