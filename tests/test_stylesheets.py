"""The stylesheets stay standalone: portable XSLT 3.0, documented, compilable."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from lxml import etree

from robomda import pipeline
from robomda.engine import Engine
from robomda.resources import resource_root

ROOT = resource_root()
STYLESHEETS = sorted((ROOT / "xslt").rglob("*.xsl"))
MANIFESTS = sorted((ROOT / "pipelines").glob("*.xml"))
XSL = "http://www.w3.org/1999/XSL/Transform"


@pytest.mark.parametrize("path", STYLESHEETS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_stylesheet_is_portable_and_documented(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    root = etree.fromstring(text.encode("utf-8"))
    assert root.get("version") == "3.0"
    # no engine-specific extensions: nothing from Saxon's namespace, no packages, no schema import
    assert "http://saxon.sf.net/" not in text
    for forbidden in ("use-package", "import-schema", "evaluate"):
        assert not root.findall(f".//{{{XSL}}}{forbidden}"), forbidden
    # the header says what the stylesheet reads and writes
    header = next((c.text for c in root.itersiblings(preceding=True) if isinstance(c, etree._Comment)), None)
    header = header or next((c.text for c in root if isinstance(c, etree._Comment)), "")
    for word in ("Reads", "Writes"):
        assert re.search(rf"\b{word}\b", header or "", re.I), f"header lacks '{word}:'"


@pytest.mark.parametrize("manifest", MANIFESTS, ids=lambda p: p.name)
def test_every_manifest_step_compiles_and_names_an_existing_schema(manifest: Path) -> None:
    chain = pipeline.load(manifest)
    engine = Engine()
    assert chain.steps
    for step in chain.steps:
        assert step.schema.is_file(), step.schema
        engine.compile(step.stylesheet)
