"""The schemas: both validators accept them and agree on every golden stage model."""

from __future__ import annotations

from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from robomda.validate import validate

ROOT = Path(__file__).resolve().parent.parent
SCHEMAS = sorted(p for p in (ROOT / "schemas").rglob("*.xsd") if p.name != "binding.xsd")


def _schema_of(model: Path) -> Path:
    """robomda's convention: namespace urn:robomda:NAME:MAJOR has schemas/NAME/MAJOR/NAME.xsd."""
    namespace = etree.QName(etree.parse(str(model)).getroot()).namespace or ""
    _, _, name, major = namespace.split(":")
    return ROOT / "schemas" / name / major / f"{name}.xsd"


GOLDEN_MODELS = [
    (path, _schema_of(path))
    for path in sorted((ROOT / "fixtures" / "cases").glob("*/expected/**/*.xml"))
    if path.name in ("import.xml", "bind.xml", "psm.xml")
]


@pytest.mark.parametrize("xsd", SCHEMAS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_schema_compiles_in_both_validators(xsd: Path) -> None:
    xmlschema.XMLSchema(str(xsd))
    etree.XMLSchema(etree.parse(str(xsd)))  # libxml2 also checks Unique Particle Attribution


@pytest.mark.parametrize(("model", "xsd"), GOLDEN_MODELS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_golden_models_are_valid_for_both_validators(model: Path, xsd: Path) -> None:
    text = model.read_text(encoding="utf-8")
    _, violations = validate(text, xsd)
    assert violations == []
    assert xmlschema.XMLSchema(str(xsd)).is_valid(text)


def test_an_invalid_model_is_explained_with_the_element_id() -> None:
    model = ROOT / "fixtures" / "cases" / "headlamp" / "expected" / "bind.xml"
    text = model.read_text(encoding="utf-8").replace('visibility="protected"', 'visibility="secret"', 1)
    _, violations = validate(text, ROOT / "schemas" / "pim" / "1" / "pim.xsd")
    assert violations and "secret" in violations[0].reason
    assert violations[0].element_id
