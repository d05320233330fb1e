"""Diagnostics for machines: robomda's JSON report and SARIF 2.1.0.

Text (``FILE:LINE:COL: severity: [CODE] message (kind 'name', xmi:id)``) is
for people and compilers' habits; ``--format json`` gives the same fields as
one JSON document, and ``--format sarif`` the OASIS Static Analysis Results
Interchange Format that editors (VS Code's SARIF viewer) and CI systems
(GitHub code scanning, GitLab) read. Both go to standard output, in the
order found, with nothing else on standard output. Neither groups
what is said of several elements alike, as the text does
(:func:`robomda.diagnostics.format_all`): one result per element, each with
its location and its full message, as code-scanning tools annotate each
line on its own.
"""

from __future__ import annotations

import json
from pathlib import Path

from robomda import __version__
from robomda.diagnostics import Diagnostic

__all__ = ["FORMATS", "render"]

FORMATS = ("text", "json", "sarif")
_SARIF_LEVEL = {"error": "error", "warning": "warning", "info": "note"}


def _element(d: Diagnostic) -> dict[str, str] | None:
    if not (d.xmi_id or d.element_kind):
        return None
    return {"kind": d.element_kind or "", "name": d.element_name or "", "qualified_name": d.qualified_name or "",
            "xmi_id": d.xmi_id or ""}


def to_json(diagnostics: list[Diagnostic], exit_code: int) -> str:
    """robomda's own report: ``{"tool", "version", "exit_code", "diagnostics": [...]}``."""
    items = []
    for d in diagnostics:
        item: dict[str, object] = {"severity": d.severity, "code": d.code, "message": d.message}
        for key, value in (("file", d.file), ("line", d.line), ("column", d.column), ("step", d.step)):
            if value is not None:
                item[key] = value
        element = _element(d)
        if element:
            item["element"] = element
        items.append(item)
    return json.dumps({"tool": "robomda", "version": __version__, "exit_code": exit_code,
                       "diagnostics": items}, indent=2, ensure_ascii=False) + "\n"


def _uri(file: str) -> str:
    path = Path(file)
    return path.as_uri() if path.is_absolute() else path.as_posix()


def to_sarif(diagnostics: list[Diagnostic], exit_code: int) -> str:
    """One SARIF 2.1.0 log with one run of robomda."""
    results = []
    for d in diagnostics:
        result: dict[str, object] = {
            "ruleId": d.code,
            "level": _SARIF_LEVEL.get(d.severity, "error"),
            "message": {"text": d.message},
        }
        location: dict[str, object] = {}
        if d.file:
            physical: dict[str, object] = {"artifactLocation": {"uri": _uri(d.file)}}
            if d.line:
                region: dict[str, int] = {"startLine": d.line}
                if d.column:
                    region["startColumn"] = d.column
                physical["region"] = region
            location["physicalLocation"] = physical
        if d.xmi_id or d.element_name:
            logical: dict[str, object] = {"name": d.element_name or d.xmi_id or "", "kind": d.element_kind or "element"}
            if d.qualified_name:
                logical["fullyQualifiedName"] = d.qualified_name
            if d.xmi_id:
                logical["properties"] = {"xmiId": d.xmi_id}
            location["logicalLocations"] = [logical]
        if location:
            result["locations"] = [location]
        results.append(result)
    log = {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {"name": "robomda", "version": __version__}},
            "invocations": [{"executionSuccessful": exit_code in (0, 1), "exitCode": exit_code}],
            "results": results,
        }],
    }
    return json.dumps(log, indent=2, ensure_ascii=False) + "\n"


def render(fmt: str, diagnostics: list[Diagnostic], exit_code: int) -> str:
    """``diagnostics`` in ``fmt`` (``json`` or ``sarif``)."""
    return to_sarif(diagnostics, exit_code) if fmt == "sarif" else to_json(diagnostics, exit_code)
