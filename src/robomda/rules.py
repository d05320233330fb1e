"""Model constraints: ISO Schematron rules run on an intermediate model.

The rules live in ``schemas/*/1/*.sch`` next to the XSD of the model they
check. They use the standard XSLT 1.0 query binding (with ``xsl:key`` for
look-ups), so any ISO Schematron engine runs them unchanged. robomda
compiles each rule set once per process to XSLT with lxml's ISO Schematron
implementation (the ISO reference skeleton). On a large model that
stylesheet runs in SaxonC, on the tree of the stage Saxon already holds, so
no lxml tree of the stage is needed unless a finding must be located (at
10,000 components such a tree is 0.3 to 0.6 GiB); on a small one (below
:data:`SAXON_FROM` characters) it runs on libxslt, as compiling it for
Saxon would cost more than the whole check.

Each finding of the SVRL report becomes a :class:`Diagnostic`: the code is
the assert's or report's ``id``, the severity its ``role`` (``error`` when
absent), the message its text, and the location the XMI element whose
xmi:id the failing model element (or its nearest ancestor) carries.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from lxml import etree, isoschematron

from robomda.diagnostics import Diagnostic, XmiLocator, model_element_id
from robomda.engine import Engine, Tree, shared

__all__ = ["Finding", "findings", "run_rules", "SEVERITIES", "SAXON_FROM"]

SEVERITIES = ("error", "warning", "info")
_SVRL = "http://purl.oclc.org/dsdl/svrl"


@dataclass(frozen=True)
class Finding:
    """One Schematron finding before it is located in the XMI."""

    code: str
    severity: str
    message: str
    xmi_id: str | None


# a model of fewer characters has its rules run on libxslt: parsing it for
# lxml costs less than compiling the rules for Saxon (0.03 s a fresh command);
# a larger one in Saxon, on the tree Saxon holds (no lxml tree of it)
SAXON_FROM = 1 << 20


@functools.lru_cache(maxsize=None)
def _compiled(rules: Path, phase: str | None) -> isoschematron.Schematron:
    """The rule set compiled by the ISO skeleton (once per process): runs on libxslt, and its XSLT
    (XSLT 1.0, writing the SVRL report) on Saxon."""
    # no svrl:fired-rule per matched element: only failures and reports are
    # read, and the full trace was larger than the model itself. Every rule
    # context of ours is an element (tests/test_rules.py checks), so the walk
    # visits elements only: the skeleton guesses attribute contexts from any
    # "@" or "attribute" in a context (pim:attribute, r:host[@...]) and then
    # applies templates to every attribute of the model too (at 10,000
    # components, 1.9 million attributes: the PIM rules took 1.8 s, 0.7 s
    # without them, the same report).
    return isoschematron.Schematron(etree.parse(str(rules)), phase=phase, store_report=True, store_xslt=True,
                                    compile_params={"generate-fired-rule": "'false'", "attributes": "'false'",
                                                    "only-child-elements": "'true'"})


def _report(rules: Path, phase: str | None, tree: etree._Element | Callable[[], etree._Element],
            source: Tree | None, engine: Engine | None) -> etree._Element:
    """The SVRL report of ``rules``: run in SaxonC on ``source``, else on libxslt on ``tree``."""
    compiled = _compiled(rules, phase)
    if source is None:
        compiled.validate(_tree(tree))
        return compiled.validation_report.getroot()
    engine = engine or shared()
    name = rules.with_name(f"{rules.name}.{phase or 'all'}.xsl")  # what the compiled rules are known by
    engine.compile(name, str(compiled.validator_xslt))
    return etree.fromstring(engine.run(name, {}, source, keep_tree=False)[0].encode("utf-8"))


def findings(rules: Path, phase: str | None, tree: etree._Element | Callable[[], etree._Element], *,
             source: Tree | None = None, engine: Engine | None = None) -> list[Finding]:
    """Every failed assert and successful report of ``rules`` on a model, in report order.

    The rules run in SaxonC on ``source``, the model's tree there, when
    given, else on libxslt on ``tree``, its lxml tree; ``tree`` (or a
    function that makes it) also locates the findings, and is asked for
    only when there are some.
    """
    found = list(_report(rules, phase, tree, source, engine).iter(f"{{{_SVRL}}}failed-assert",
                                                                  f"{{{_SVRL}}}successful-report"))
    if not found:
        return []
    doc = _tree(tree).getroottree()
    result: list[Finding] = []
    for item in found:
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


def _tree(tree: etree._Element | Callable[[], etree._Element]) -> etree._Element:
    return tree() if callable(tree) else tree


def run_rules(rules: Path, phase: str | None, tree: etree._Element | Callable[[], etree._Element],
              locator: XmiLocator, step: str, *, source: Tree | None = None,
              engine: Engine | None = None) -> list[Diagnostic]:
    """The findings of ``rules`` on a model (see :func:`findings`) as located diagnostics, sorted by XMI
    position."""
    diags = [locator.diagnostic(f.code, f.message, f.xmi_id, severity=f.severity, step=step)
             for f in findings(rules, phase, tree, source=source, engine=engine)]
    return sorted(diags, key=lambda d: (d.line or 0, d.column or 0, d.code))
