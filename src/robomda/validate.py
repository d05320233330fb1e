"""XSD validation of the intermediate models, schemas compiled once.

Two validators, each for what it does best:

- libxml2 (through lxml) decides *whether* a model is valid. It is written in
  C and about 60 times faster than a pure-Python validator on robomda's
  models (0.14 s against 8 s for the PIM of a 1,000-component model), which
  is what keeps validation between every pair of steps affordable. It is
  also the stricter of the two: it enforces the Unique Particle Attribution
  rule of XSD 1.0.
- xmlschema explains *why* not: when libxml2 rejects a model, xmlschema
  re-validates it to report each violation with its reason and path (the
  driver then maps the nearest element's id back to the XMI line).
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Iterator

from lxml import etree

from robomda.diagnostics import model_element_id

if TYPE_CHECKING:  # imported where a failure is explained: 0.13 s a run saved on success
    import xmlschema

__all__ = ["Violation", "validate", "parse", "schema_of", "stream", "streams_valid"]

_FAST: dict[Path, etree.XMLSchema] = {}
_EXPLAIN: dict[Path, xmlschema.XMLSchema] = {}
_PARSER = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True)


@dataclass(frozen=True)
class Violation:
    """One schema violation: the reason and the nearest model element's id."""

    reason: str
    path: str
    element_id: str | None


def parse(text: str) -> etree._Element:
    """Parse a stage's output (robomda's own XML: safe parser settings)."""
    return etree.fromstring(text.encode("utf-8"), _PARSER)


def schema_of(path: Path) -> etree.XMLSchema:
    """The libxml2 validator of the XSD at ``path``, compiled once per process."""
    return _fast(path.resolve())


def _fast(path: Path) -> etree.XMLSchema:
    schema = _FAST.get(path)
    if schema is None:
        schema = _FAST[path] = etree.XMLSchema(etree.parse(str(path), _PARSER))
    return schema


def stream(text: str | Path, schema: etree.XMLSchema | None = None) -> Iterator[etree._Element]:
    """Each element of ``text`` (or of the file it names) once read (its end tag), then forgotten: a
    model read, and validated against ``schema`` when given (XMLSyntaxError when not valid), without a
    tree of it all (at 10,000 components a stage's tree is 0.3 to 0.6 GiB), as fast as parsing one."""
    source = str(text) if isinstance(text, Path) else io.BytesIO(text.encode("utf-8"))
    for _, element in etree.iterparse(source, events=("end",), schema=schema,
                                      huge_tree=True, resolve_entities=False, no_network=True):
        yield element
        element.clear(keep_tail=True)
        while element.getprevious() is not None:
            del element.getparent()[0]


def streams_valid(text: str | Path, schema: etree.XMLSchema) -> bool:
    """Whether ``text`` (or the file it names) is valid against ``schema``, read as a stream."""
    try:
        for _ in stream(text, schema):
            pass
    except etree.XMLSyntaxError:
        return False
    return True


def _explain(path: Path) -> xmlschema.XMLSchema:
    schema = _EXPLAIN.get(path)
    if schema is None:
        import xmlschema

        schema = _EXPLAIN[path] = xmlschema.XMLSchema(str(path))
    return schema


def validate(text: str, schema_path: Path, *, limit: int = 20,
             keep_tree: bool = True) -> tuple[etree._Element | None, list[Violation]]:
    """Parse ``text`` and validate it against ``schema_path``.

    Returns the parsed tree (None for a valid model without ``keep_tree``)
    and at most ``limit`` violations, each with the id of the closest element
    (itself or an ancestor) that carries one.
    """
    schema_path = schema_path.resolve()
    fast = _fast(schema_path)
    if not keep_tree and streams_valid(text, fast):
        return None, []
    root = parse(text)
    if fast.validate(root):
        return root, []
    found: list[Violation] = []
    for error in _explain(schema_path).iter_errors(root):
        elem = error.elem if isinstance(error.elem, etree._Element) else None
        found.append(Violation(error.reason or str(error.message), error.path or "", model_element_id(elem)))
        if len(found) >= limit:
            break
    if not found:  # the validators disagree: report libxml2's own findings
        for entry in list(fast.error_log)[:limit]:
            found.append(Violation(entry.message, f"line {entry.line}", None))
    return root, found

