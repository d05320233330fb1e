"""Model constraints: ISO Schematron rules run on an intermediate model.

The rules live in ``schemas/*/1/*.sch`` next to the XSD of the model they
check. They use the standard XSLT 1.0 query binding (with ``xsl:key`` for
look-ups), so any ISO Schematron engine runs them unchanged. robomda
compiles each rule set once per process to XSLT with lxml's ISO Schematron
implementation (the ISO reference skeleton), and keeps that XSLT in the
user's cache folder (``$XDG_CACHE_HOME/robomda``, else ``~/.cache/robomda``;
named by a digest of the rules, the phase, the compile options and lxml's
version), so that a fresh command reads it instead of running the skeleton
again. On a large model that
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
import hashlib
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

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


# the skeleton's parameters: no svrl:fired-rule per matched element: only
# failures and reports are read, and the full trace was larger than the model
# itself. Every rule context of ours is an element (tests/test_rules.py
# checks), so the walk visits elements only: the skeleton guesses attribute
# contexts from any "@" or "attribute" in a context (pim:attribute,
# r:host[@...]) and then applies templates to every attribute of the model
# too (at 10,000 components, 1.9 million attributes: the PIM rules took
# 1.8 s, 0.7 s without them, the same report).
_COMPILE_PARAMS = {"generate-fired-rule": "'false'", "attributes": "'false'", "only-child-elements": "'true'"}


@dataclass
class CompiledRules:
    """A rule set compiled by the ISO skeleton: its XSLT 1.0 text (writing the SVRL report), run on Saxon, and
    that stylesheet on libxslt (made on first use)."""

    validator_xslt: str
    _libxslt: etree.XSLT | None = field(default=None, repr=False)

    def report(self, tree: etree._Element) -> etree._Element:
        """The SVRL report of the rules on ``tree``, run on libxslt."""
        if self._libxslt is None:
            self._libxslt = etree.XSLT(etree.fromstring(self.validator_xslt.encode("utf-8")))
        return self._libxslt(tree).getroot()


def _cache_file(rules: Path, phase: str | None) -> Path:
    """Where the compiled form of ``rules`` (in ``phase``) is kept: named by a digest of what it is made from."""
    digest = hashlib.sha256(b"\0".join([rules.read_bytes(), (phase or "").encode(), repr(sorted(_COMPILE_PARAMS.items())).encode(),
                                         etree.__version__.encode()])).hexdigest()[:32]
    base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return base / "robomda" / "schematron" / f"{rules.stem}-{digest}.xsl"


@functools.lru_cache(maxsize=None)
def _compiled(rules: Path, phase: str | None) -> CompiledRules:
    """The rule set compiled by the ISO skeleton (once per process, and read from the user's cache folder when
    an earlier process compiled the same rules there)."""
    cached = _cache_file(rules, phase)
    try:
        return CompiledRules(cached.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError):
        pass
    from lxml import isoschematron  # only to compile: a fresh command with the cache filled never imports it

    text = str(isoschematron.Schematron(etree.parse(str(rules)), phase=phase, store_xslt=True,
                                        compile_params=_COMPILE_PARAMS).validator_xslt)
    try:  # a folder that cannot be written leaves the rules compiled for this process only
        cached.parent.mkdir(parents=True, exist_ok=True)
        partial = cached.with_name(f"{cached.name}.{os.getpid()}.tmp")
        partial.write_text(text, encoding="utf-8")
        os.replace(partial, cached)  # whole or not at all, whatever another process does meanwhile
    except OSError:
        pass
    return CompiledRules(text)


def _report(rules: Path, phase: str | None, tree: etree._Element | Callable[[], etree._Element],
            source: Tree | None, engine: Engine | None) -> etree._Element:
    """The SVRL report of ``rules``: run in SaxonC on ``source``, else on libxslt on ``tree``."""
    compiled = _compiled(rules, phase)
    if source is None:
        return compiled.report(_tree(tree))
    engine = engine or shared()
    name = rules.with_name(f"{rules.name}.{phase or 'all'}.xsl")  # what the compiled rules are known by
    engine.compile(name, compiled.validator_xslt)
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
