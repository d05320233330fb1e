"""XSD validation of the intermediate models (xmlschema), schemas loaded once."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import xmlschema
from lxml import etree

__all__ = ["Violation", "validate"]

_SCHEMAS: dict[Path, xmlschema.XMLSchema] = {}
_PARSER = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True, remove_blank_text=False)


@dataclass(frozen=True)
class Violation:
    """One schema violation: the reason and the nearest model element's id."""

    reason: str
    path: str
    element_id: str | None


def _schema(path: Path) -> xmlschema.XMLSchema:
    path = path.resolve()
    schema = _SCHEMAS.get(path)
    if schema is None:
        schema = _SCHEMAS[path] = xmlschema.XMLSchema(str(path))
    return schema


def validate(text: str, schema_path: Path, *, limit: int = 20) -> tuple[etree._Element, list[Violation]]:
    """Parse ``text`` and validate it against ``schema_path``.

    Returns the parsed tree and at most ``limit`` violations, each with the id
    of the closest element (itself or an ancestor) that carries one, so the
    driver can point at the XMI.
    """
    root = etree.fromstring(text.encode("utf-8"), _PARSER)
    found: list[Violation] = []
    for error in _schema(schema_path).iter_errors(root):
        elem = error.elem if isinstance(error.elem, etree._Element) else None
        found.append(Violation(error.reason or str(error.message), error.path or "", _nearest_id(elem)))
        if len(found) >= limit:
            break
    return root, found


def _nearest_id(elem: etree._Element | None) -> str | None:
    while elem is not None:
        for attr in ("xmi-id", "id"):
            value = elem.get(attr)
            if value:
                return value
        elem = elem.getparent()
    return None
