"""Pipelines as data: load a manifest, run its steps, validate every output.

A manifest (``pipelines/*.xml``, schema ``schemas/pipeline/1``) lists the
stylesheets of a chain, the parameters each one takes and the schema its
output must satisfy. :func:`run` executes it on one XMI file and returns every
stage's output, all in memory: nothing is written here.
"""

from __future__ import annotations

import functools
import time
from dataclasses import dataclass, field
from pathlib import Path

import xmlschema
from lxml import etree

from robomda.diagnostics import (
    EXIT_FINDINGS,
    EXIT_INPUT,
    EXIT_INTERNAL,
    INPUT_CODES,
    Diagnostic,
    RobomdaError,
    XmiLocator,
    parse_stylesheet_error,
    parse_stylesheet_warning,
)
from robomda.engine import Engine, TransformError
from robomda.resources import resource_root
from robomda.validate import validate

__all__ = ["Param", "Step", "Pipeline", "RunResult", "load", "run"]

_NS = {"p": "urn:robomda:pipeline:1"}


@dataclass(frozen=True)
class Param:
    name: str
    value: str | None
    source: str | None  # one of the manifest's @from values


@dataclass(frozen=True)
class Step:
    name: str
    stylesheet: Path
    schema: Path
    params: tuple[Param, ...]


@dataclass(frozen=True)
class Pipeline:
    name: str
    yields: str
    description: str
    steps: tuple[Step, ...]
    manifest: Path


@dataclass
class RunResult:
    """Each step's output text, in order; ``output`` is the last one."""

    stages: dict[str, str] = field(default_factory=dict)
    tree: etree._Element | None = None
    # per step: (name, seconds in XSLT, seconds in XSD validation)
    timings: list[tuple[str, float, float]] = field(default_factory=list)
    # warnings the stylesheets reported (f:warn), located in the XMI
    warnings: list[Diagnostic] = field(default_factory=list)

    @property
    def output(self) -> str:
        return list(self.stages.values())[-1]


_MANIFEST_SCHEMA: xmlschema.XMLSchema | None = None


@functools.lru_cache(maxsize=None)
def load(manifest: Path) -> Pipeline:
    """Read and validate a pipeline manifest (following its includes).

    Cached per path: a batch worker generates many models with the same
    manifests, which do not change while it runs.
    """
    global _MANIFEST_SCHEMA
    if _MANIFEST_SCHEMA is None:
        _MANIFEST_SCHEMA = xmlschema.XMLSchema(str(resource_root() / "schemas/pipeline/1/pipeline.xsd"))
    manifest = manifest.resolve()
    _MANIFEST_SCHEMA.validate(str(manifest))
    root = etree.parse(str(manifest)).getroot()
    base = manifest.parent
    steps: list[Step] = []
    for node in root.iterchildren(f"{{{_NS['p']}}}include", f"{{{_NS['p']}}}step"):
        if etree.QName(node).localname == "include":
            steps.extend(load(base / node.get("href")).steps)
            continue
        params = tuple(Param(p.get("name"), p.get("value"), p.get("from")) for p in node.findall("p:param", _NS))
        steps.append(Step(node.get("name"), (base / node.get("stylesheet")).resolve(),
                          (base / node.get("schema")).resolve(), params))
    description = " ".join((root.findtext("p:description", namespaces=_NS) or "").split())
    return Pipeline(root.get("name"), root.get("yields"), description, tuple(steps), manifest)


def run(pipeline: Pipeline, engine: Engine, model: Path, context: dict[str, str]) -> RunResult:
    """Run every step on ``model``; raise :class:`RobomdaError` on the first failure.

    ``context`` supplies the values of parameters declared with ``from``.
    Each output is validated against its step's schema before the next step
    sees it.
    """
    locator = XmiLocator(model)
    result = RunResult()
    previous: str | None = None
    for step in pipeline.steps:
        params = {p.name: (p.value if p.value is not None else context.get(p.source or "", "")) for p in step.params}
        started = time.perf_counter()
        try:
            if previous is None:
                text = engine.transform(step.stylesheet, params, source_file=model)
            else:
                text = engine.transform(step.stylesheet, params, source_text=previous)
        except TransformError as exc:
            raise _transform_failure(exc, step, locator) from None
        for message in engine.messages:
            parsed = parse_stylesheet_warning(message)
            if parsed is not None:
                code, text_, xmi_id = parsed
                result.warnings.append(locator.diagnostic(code, text_, xmi_id, severity="warning", step=step.name))
        transformed = time.perf_counter()
        tree, violations = validate(text, step.schema)
        result.timings.append((step.name, transformed - started, time.perf_counter() - transformed))
        if violations:
            raise RobomdaError([
                locator.diagnostic("SCHEMA", f"the {step.name} step wrote a model that breaks "
                                   f"{step.schema.name}: {v.reason} at {v.path}", v.element_id, step=step.name)
                for v in violations], EXIT_INTERNAL)
        result.stages[step.name] = text
        result.tree = tree
        previous = text
    return result


def _transform_failure(exc: TransformError, step: Step, locator: XmiLocator) -> RobomdaError:
    parsed = parse_stylesheet_error(exc.message)
    if parsed is None:
        # Not one of ours: a bug in a stylesheet (or Saxon). Say where, no traceback.
        detail = " ".join((exc.message or exc.detail).split())[:2000]
        diag = Diagnostic("error", "INTERNAL", f"stylesheet {exc.stylesheet.name} failed in step "
                          f"'{step.name}': {detail}", file=str(locator.path), step=step.name)
        return RobomdaError([diag], EXIT_INTERNAL)
    code, message, xmi_id = parsed
    exit_code = EXIT_INPUT if code in INPUT_CODES else EXIT_FINDINGS
    return RobomdaError([locator.diagnostic(code, message, xmi_id, step=step.name)], exit_code)
