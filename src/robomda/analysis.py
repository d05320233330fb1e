"""Product lines: analyse a feature model with flamapy, the optional extra ``robomda[analysis]`` (issue 32).

A void feature model, dead and false-optional features, the number of
products, and each presence condition of a resolution model that no valid
configuration satisfies (its element is in no variant) or that every one
satisfies (the condition is idle): a SAT solver answers each (flamapy's
PySAT operations). robomda reads the FeatureIDE file itself (lxml, so each
finding carries its line) and hands flamapy the feature tree and formulas;
flamapy is imported here only, never by generate or check
(docs/variability.md).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

from lxml import etree

from robomda.diagnostics import EXIT_FINDINGS, EXIT_INPUT, Diagnostic, RobomdaError
from robomda.variability import schema_findings

__all__ = ["Analysis", "analyse"]

_R = "{urn:robomda:resolution:1}"
_GROUPS = {"and", "or", "alt"}
_EXTRA = "pip install 'robomda[analysis]'"


@dataclass
class Analysis:
    """What the analysis found: located diagnostics and the number of products (0 when void)."""

    diagnostics: list[Diagnostic] = field(default_factory=list)
    products: int = 0


class _Flamapy(NamedTuple):
    """The flamapy modules robomda uses (imported on demand: flamapy is an optional extra)."""

    ast: Any  # flamapy.core.models.ast: formulas
    fm: Any  # flamapy.metamodels.fm_metamodel.models.feature_model: the feature tree
    ops: Any  # flamapy.metamodels.pysat_metamodel.operations: the SAT analyses
    sat: Any  # flamapy.metamodels.pysat_metamodel.transformations: feature model -> CNF


def _flamapy() -> _Flamapy:
    """The flamapy modules robomda uses, or VAR040 (exit 2) naming the extra."""
    try:
        from flamapy.core.models import ast
        from flamapy.metamodels.fm_metamodel.models import feature_model
        from flamapy.metamodels.pysat_metamodel import operations, transformations
    except ImportError as exc:
        raise RobomdaError([Diagnostic("error", "VAR040", "the feature model analysis needs flamapy, the optional "
                                       f"extra of robomda: {_EXTRA} ({exc})")], EXIT_INPUT) from exc
    return _Flamapy(ast, feature_model, operations, transformations)


def _parsed(kind: str, path: Path) -> etree._ElementTree:
    """``path`` parsed and valid against robomda's schema of ``kind``, or its located findings."""
    found = schema_findings(kind, path)
    if found:
        raise RobomdaError(found, EXIT_INPUT if any(d.code == "XML001" for d in found) else EXIT_FINDINGS)
    return etree.parse(str(path), etree.XMLParser(resolve_entities=False, no_network=True))


def _feature(fl: _Flamapy, el: etree._Element, lines: dict[str, int]) -> Any:
    """The flamapy feature of FeatureIDE element ``el`` (and, or, alt, feature) with its subtree."""
    name = el.get("name", "")
    lines[name] = el.sourceline or 0
    node = fl.fm.Feature(name, [], is_abstract=el.get("abstract") == "true")
    kids = [k for k in el if isinstance(k.tag, str) and (k.tag in _GROUPS or k.tag == "feature")]
    children = [_feature(fl, k, lines) for k in kids]
    if el.tag in ("or", "alt") and children:
        node.add_relation(fl.fm.Relation(node, children, 1, 1 if el.tag == "alt" else len(children)))
    else:
        for kid, child in zip(kids, children):
            low = 1 if kid.get("mandatory") == "true" else 0
            node.add_relation(fl.fm.Relation(node, [child], low, 1))
    return node


def _formula(fl: _Flamapy, el: etree._Element, names: set[str], unknown: set[str]) -> Any:
    """The flamapy AST node of a formula (var, not, conj, disj, imp, eq) in either namespace."""
    ast = fl.ast
    tag = etree.QName(el).localname
    if tag == "var":
        name = (el.text or "").strip()
        if name not in names:
            unknown.add(name)
        return ast.Node(name)
    args = [_formula(fl, k, names, unknown) for k in el if isinstance(k.tag, str)
            and etree.QName(k).localname != "description"]
    if tag == "not":
        return ast.Node(ast.ASTOperation.NOT, args[0])
    op = {"conj": ast.ASTOperation.AND, "disj": ast.ASTOperation.OR, "imp": ast.ASTOperation.IMPLIES,
          "eq": ast.ASTOperation.EQUIVALENCE}[tag]
    node = args[0]
    for arg in args[1:]:
        node = ast.Node(op, node, arg)
    return node


def _model(fl: _Flamapy, tree: etree._ElementTree, lines: dict[str, int]) -> Any:
    """The flamapy feature model of a FeatureIDE ``featureModel`` document."""
    root = next(k for k in tree.getroot().find("struct") if isinstance(k.tag, str))
    top = _feature(fl, root, lines)
    rules = [next(k for k in rule if isinstance(k.tag, str) and k.tag != "description")
             for rule in tree.getroot().iterfind("constraints/rule")]
    ctcs = [fl.fm.Constraint(f"rule{i}", fl.ast.AST(_formula(fl, r, set(lines), set())))
            for i, r in enumerate(rules, 1)]
    return fl.fm.FeatureModel(top, ctcs)


def _satisfiable(fl: _Flamapy, model: Any, extra: Any) -> bool:
    """Whether some valid configuration of ``model`` also satisfies formula node ``extra``."""
    model.ctcs.append(fl.fm.Constraint("robomda-condition", fl.ast.AST(extra)))
    try:
        return bool(fl.ops.PySATSatisfiable().execute(fl.sat.FmToPysat(model).transform()).get_result())
    finally:
        model.ctcs.pop()


def _feature_findings(fl: _Flamapy, model: Any, path: Path, lines: dict[str, int]) -> Analysis:
    """VAR041 (void), VAR042 (dead), VAR043 (false-optional), VAR044 (the number of products)."""
    sat = fl.sat.FmToPysat(model).transform()
    done = Analysis()
    if not fl.ops.PySATSatisfiable().execute(sat).get_result():
        done.diagnostics.append(Diagnostic("error", "VAR041", "the feature model is void: no configuration "
                                           "satisfies it (its constraints contradict its tree)", file=str(path),
                                           line=lines[model.root.name], element_kind="feature",
                                           element_name=model.root.name))
        return done
    for code, text, operation in (
            ("VAR042", "a dead feature: no valid configuration selects it", fl.ops.PySATDeadFeatures()),
            ("VAR043", "a false-optional feature: optional in the tree, yet every valid configuration that "
                       "selects its parent selects it", fl.ops.PySATFalseOptionalFeatures())):
        for name in sorted(operation.execute(sat).get_result(), key=lambda n: lines.get(n, 0)):
            done.diagnostics.append(Diagnostic("warning", code, text, file=str(path), line=lines.get(name),
                                               element_kind="feature", element_name=name))
    done.products = int(fl.ops.PySATConfigurationsNumber().execute(sat).get_result())
    done.diagnostics.append(Diagnostic("info", "VAR044", f"the feature model has {done.products} valid "
                                       "configurations (products)", file=str(path), line=lines[model.root.name],
                                       element_kind="feature", element_name=model.root.name))
    return done


def _condition_findings(fl: _Flamapy, model: Any, path: Path, names: set[str]) -> list[Diagnostic]:
    """VAR045 (a presence condition never holds), VAR046 (always holds), VAR047 (an unknown feature), VAR048
    (no condition)."""
    found = []
    for present in _parsed("resolution", path).getroot().iterfind(f"{_R}present"):
        where = {"file": str(path), "line": present.sourceline, "element_kind": "present",
                 "element_name": present.get("element", "")}
        when = present.get("when")
        formulas = [k for k in present if isinstance(k.tag, str)]
        if when is None and not formulas:
            found.append(Diagnostic("error", "VAR048", "the presence condition is empty: give @when (a feature) "
                                    "or a formula", **where))
            continue
        unknown = {when} - names if when is not None else set()
        cond = fl.ast.Node(when) if when is not None else _formula(fl, formulas[0], names, unknown)
        if unknown:
            found.append(Diagnostic("error", "VAR047", "the presence condition names features the feature model "
                                    f"does not have: {', '.join(sorted(unknown))}", **where))
        elif not _satisfiable(fl, model, cond):
            found.append(Diagnostic("warning", "VAR045", "no valid configuration satisfies the presence "
                                    "condition: the element is in no variant", **where))
        elif not _satisfiable(fl, model, fl.ast.Node(fl.ast.ASTOperation.NOT, cond)):
            found.append(Diagnostic("info", "VAR046", "every valid configuration satisfies the presence "
                                    "condition: the element is in every variant", **where))
    return found


def analyse(feature_model: Path | str, resolution: Path | str | None = None) -> Analysis:
    """Analyse a FeatureIDE feature model (and the presence conditions of a resolution model) with flamapy.

    Raises :class:`RobomdaError` (exit 2) when flamapy is not installed, or when a file breaks its schema."""
    fl = _flamapy()
    path = Path(feature_model)
    lines: dict[str, int] = {}
    model = _model(fl, _parsed("feature model", path), lines)
    done = _feature_findings(fl, model, path, lines)
    if resolution is not None and done.products:
        done.diagnostics += _condition_findings(fl, model, Path(resolution), set(lines))
    return done
