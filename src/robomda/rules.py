"""Model constraints: ISO Schematron rules run on an intermediate model.

The rules live in ``schemas/*/1/*.sch`` next to the XSD of the model they
check. They use the standard XSLT 1.0 query binding (with ``xsl:key`` for
look-ups), so any ISO Schematron engine runs them unchanged; robomda runs
them with lxml's ISO Schematron implementation (the ISO reference skeleton
compiled to XSLT and run by libxslt), compiled once per process.

Each finding of the SVRL report becomes a :class:`Diagnostic`: the code is
the assert's or report's ``id``, the severity its ``role`` (``error`` when
absent), the message its text, and the location the XMI element whose
xmi:id the failing model element (or its nearest ancestor) carries.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from lxml import etree, isoschematron

from robomda.diagnostics import Diagnostic, XmiLocator, model_element_id

__all__ = ["Finding", "run_rules", "SEVERITIES"]

SEVERITIES = ("error", "warning", "info")
_SVRL = "http://purl.oclc.org/dsdl/svrl"
_COMPILED: dict[tuple[Path, str | None], isoschematron.Schematron] = {}


@dataclass(frozen=True)
class Finding:
    """One Schematron finding before it is located in the XMI."""

    code: str
    severity: str
    message: str
    xmi_id: str | None


def _validator(rules: Path, phase: str | None) -> isoschematron.Schematron:
    key = (rules, phase)
    if key not in _COMPILED:
        # no svrl:fired-rule per matched element: only failures and reports
        # are read, and the full trace was larger than the model itself
        _COMPILED[key] = isoschematron.Schematron(etree.parse(str(rules)), phase=phase, store_report=True,
                                                  compile_params={"generate-fired-rule": "'false'"})
    return _COMPILED[key]


def findings(rules: Path, phase: str | None, tree: etree._Element) -> list[Finding]:
    """Every failed assert and successful report of ``rules`` on ``tree``, in report order."""
    validator = _validator(rules, phase)
    validator.validate(tree)
    report = validator.validation_report
    result: list[Finding] = []
    doc = tree.getroottree()
    for item in report.iter(f"{{{_SVRL}}}failed-assert", f"{{{_SVRL}}}successful-report"):
        severity = (item.get("role") or "error").lower()
        if severity not in SEVERITIES:
            severity = "error"
        message = " ".join("".join(item.findtext(f"{{{_SVRL}}}text") or "").split())
        located = doc.xpath(item.get("location", "/")) if item.get("location") else []
        node = located[0] if located and isinstance(located[0], etree._Element) else None
        # a "-holder" diagnostic names the element that holds the bad value
        holders = [" ".join("".join(d.itertext()).split()) for d in item.iter(f"{{{_SVRL}}}diagnostic-reference")
                   if (d.get("diagnostic") or "").endswith("-holder")]
        holder = next((h for h in holders if h), None)
        result.append(Finding(item.get("id") or "RULE", severity, message, holder or model_element_id(node)))
    return result


def run_rules(rules: Path, phase: str | None, tree: etree._Element, locator: XmiLocator,
              step: str) -> list[Diagnostic]:
    """The findings of ``rules`` on ``tree`` as located diagnostics, sorted by XMI position."""
    diags = [locator.diagnostic(f.code, f.message, f.xmi_id, severity=f.severity, step=step)
             for f in findings(rules, phase, tree)]
    return sorted(diags, key=lambda d: (d.line or 0, d.column or 0, d.code))
