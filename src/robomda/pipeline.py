"""Pipelines as data: load a manifest, run its steps, validate every output.

A manifest (``pipelines/*.xml``, schema ``schemas/pipeline/1``) lists the
stylesheets of a chain, the parameters each one takes, the schema its output
must satisfy and the Schematron rules checked on it. :func:`run` executes it
on one XMI file and returns every stage's output and every finding, all in
memory: nothing is written here.
"""

from __future__ import annotations

import dataclasses
import functools
import time
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import unquote, urlparse

from lxml import etree

from robomda import checker as checking
from robomda.diagnostics import (
    EXIT_FINDINGS,
    EXIT_INPUT,
    EXIT_INTERNAL,
    INPUT_CODES,
    Diagnostic,
    RobomdaError,
    XmiLocator,
    parse_stylesheet_error,
    parse_stylesheet_message,
)
from robomda.engine import Engine, TransformError, Tree
from robomda.resources import resource_root
from robomda.rules import SAXON_FROM, run_rules
from robomda.validate import parse, schema_of, validate

__all__ = ["Param", "Check", "Step", "Pipeline", "RunResult", "load", "run", "settle", "for_context"]

_NS = {"p": "urn:robomda:pipeline:1"}


@dataclass(frozen=True)
class Param:
    name: str
    value: str | None
    source: str | None  # one of the manifest's @from values


@dataclass(frozen=True)
class Check:
    rules: Path  # a Schematron schema
    phase: str | None


@dataclass(frozen=True)
class Step:
    name: str
    stylesheet: Path
    schema: Path
    params: tuple[Param, ...]
    checks: tuple[Check, ...] = ()
    when: str | None = None  # the manifest's @if: run only when one of these values is supplied (_MODEL_VALUES)


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
    # the file set's lxml tree (the last step of a chain that yields files), for
    # the writer; no other stage is held as an lxml tree (0.3 to 0.6 GiB each
    # at 10,000 components)
    tree: etree._Element | None = None
    # per step: (name, seconds in XSLT, in XSD validation, in Schematron rules);
    # for a stage validated in the checker process, the seconds the run waited
    # for it (robomda.checker)
    timings: list[tuple[str, float, float, float]] = field(default_factory=list)
    # warnings and infos: from the stylesheets (f:warn) and from the rules,
    # located in the XMI, in the order the steps found them
    warnings: list[Diagnostic] = field(default_factory=list)
    # per step: what determines its output (see _step_key), the number of
    # warnings once it was done and the rules checked on it: what a later
    # run may resume from
    done: list[tuple[tuple, int, tuple[Check, ...]]] = field(default_factory=list)
    # the last step's result as Saxon holds it, when the chain yields a model:
    # the first run that resumes from this one takes it and reads it as it is
    # (parsing its text again cost 1.8 s of 41 at 10,000 components); a later
    # one parses the text
    handed: Tree | None = None
    # large stages still being validated in the checker process (see
    # robomda.checker), oldest first, each with its rules' findings: a run
    # settles them before anything of a later step counts, and before it ends
    # (or a run resuming from it does)
    pending: list[_Pending] = field(default_factory=list)
    # the steps left out because their input model did not ask for them (step/@if, _MODEL_VALUES):
    # a run resuming from this one leaves them out too, without looking again
    skipped: list[str] = field(default_factory=list)

    @property
    def output(self) -> str:
        return list(self.stages.values())[-1]


@dataclass
class _Pending:
    """A stage being validated in the checker process, and the findings of its rules, which count
    once it is known valid."""

    step: Step
    text: str
    job: checking.Job
    index: int  # the step's place in timings and done
    locator: XmiLocator
    found: list[list[Diagnostic]] = field(default_factory=list)  # per rule set


@functools.lru_cache(maxsize=None)
def load(manifest: Path) -> Pipeline:
    """Read and validate a pipeline manifest (following its includes).

    Cached per path: a batch worker generates many models with the same
    manifests, which do not change while it runs.
    """
    manifest = manifest.resolve()
    xsd = resource_root() / "schemas/pipeline/1/pipeline.xsd"
    root = etree.parse(str(manifest)).getroot()
    # libxml2 says yes in a millisecond; xmlschema (0.3 s to import and
    # compile) only explains a manifest that breaks the schema
    if not schema_of(xsd).validate(root):
        import xmlschema

        xmlschema.XMLSchema(str(xsd)).validate(str(manifest))
        raise ValueError(f"{manifest}: breaks {xsd}: {schema_of(xsd).error_log.last_error}")
    base = manifest.parent
    steps: list[Step] = []
    for node in root.iterchildren(f"{{{_NS['p']}}}include", f"{{{_NS['p']}}}step", f"{{{_NS['p']}}}check"):
        kind = etree.QName(node).localname
        if kind == "include":
            steps.extend(load(base / node.get("href")).steps)
            continue
        if kind == "check":
            if not steps:
                raise ValueError(f"{manifest}: a check needs a step before it")
            check = Check((base / node.get("rules")).resolve(), node.get("phase"))
            steps[-1] = dataclasses.replace(steps[-1], checks=steps[-1].checks + (check,))
            continue
        params = tuple(Param(p.get("name"), p.get("value"), p.get("from")) for p in node.findall("p:param", _NS))
        steps.append(Step(node.get("name"), (base / node.get("stylesheet")).resolve(),
                          (base / node.get("schema")).resolve(), params, when=node.get("if")))
    description = " ".join((root.findtext("p:description", namespaces=_NS) or "").split())
    return Pipeline(root.get("name"), root.get("yields"), description, tuple(steps), manifest)


# the values of step/@if that the step's input model supplies, not the runner: each an XPath that finds
# something in a model that asks for the step (jobs given as configurations: docs/jobs.md)
_MODEL_VALUES = {"job-configurations": "/pim:model/pim:coordination/pim:job/pim:stereotype[@name = 'Job']"
                                       "/pim:tag[@name = 'configuration'][normalize-space(@value)]/@value"}
_PIM = {"pim": "urn:robomda:pim:1"}


def for_context(pipeline: Pipeline, context: dict[str, str], *, model_may_ask: bool = True) -> Pipeline:
    """``pipeline`` without the steps that no value of their ``if`` can ask for: none that ``context``
    supplies, none that the model may (the configure step without a configuration or jobs given as
    configurations; a step only the model may ask for is decided when it comes: :func:`run`).
    ``model_may_ask=False``: the model is known to ask for none (the bench's synthetic models), so
    such a step is left out here, as a run would leave it out."""
    kept = tuple(s for s in pipeline.steps if s.when is None or any(
        context.get(v) or (model_may_ask and v in _MODEL_VALUES) for v in s.when.split()))
    return pipeline if len(kept) == len(pipeline.steps) else dataclasses.replace(pipeline, steps=kept)


def _left_out(step: Step, context: dict[str, str], previous: Path | str | Tree, engine: Engine,
              resume: RunResult | None) -> bool:
    """Whether ``step`` is left out: only its input model may ask for it, and it does not (an earlier run
    on the same model, ``resume``, decided it already)."""
    if step.when is None or any(context.get(v) for v in step.when.split()):
        return False
    if resume is not None and step.name in resume.skipped:
        return True
    if isinstance(previous, Path):  # the first step: nothing to ask yet
        return False
    tree = previous if isinstance(previous, Tree) else engine.parse(previous)
    return not any(engine.strings(tree, _MODEL_VALUES[v], _PIM) for v in step.when.split() if v in _MODEL_VALUES)


def _step_key(step: Step, params: dict[str, str]) -> tuple:
    """What a step's output depends on, besides its input: stylesheet, parameters, schema."""
    return (step.stylesheet, tuple(sorted(params.items())), step.schema)


def run(pipeline: Pipeline, engine: Engine, model: Path, context: dict[str, str], *,
        steps: int | None = None, resume: RunResult | None = None, settle: bool = True) -> RunResult:
    """Run every step (or the first ``steps``) on ``model``; raise :class:`RobomdaError` on failure.

    ``context`` supplies the values of parameters declared with ``from``.
    Each output is validated against its step's schema, then checked by the
    step's rules, before the next step sees it. A stylesheet error stops at
    once, with the errors the stage reported before it (f:fail-all: every
    error of the stage); rule findings at error level stop after the whole
    check, and the error carries every finding so far (warnings included).
    Every message a stylesheet writes becomes a diagnostic: ``warning:``,
    ``error:``, or a note (code NOTE).

    ``resume``: an earlier run on the same model (e.g. the import chain that
    found the model's targets). The leading steps that it ran with the same
    stylesheet, parameters, schema and rules are taken from it, with their
    warnings, instead of being run again.

    A stage of :data:`~robomda.rules.SAXON_FROM` characters or more (but the
    file set) is validated in the checker process while its rules and the
    next step run here (robomda.checker); its rules' findings count once it
    is known valid, before anything of the next step. ``settle=False`` leaves
    the last one unsettled in ``pending``, for a run that resumes from this
    one (or :func:`settle`).
    """
    locator = XmiLocator(model, tuple(Path(unquote(urlparse(u).path)) for u in context.get("model-path", "").split()))
    result = RunResult()
    if steps is not None:  # the first `steps` steps of the manifest, as many of them as run
        steps = len(for_context(dataclasses.replace(pipeline, steps=pipeline.steps[:steps]), context).steps)
    pipeline = for_context(pipeline, context)
    chain = pipeline.steps[:steps]
    previous: Path | str | Tree = model.resolve()
    resuming = resume is not None
    index = -1
    while index + 1 < len(chain):
        index += 1
        step = chain[index]
        params = {p.name: (p.value if p.value is not None else context.get(p.source or "", "")) for p in step.params}
        key = _step_key(step, params)
        ran = resuming and index < len(resume.done) and resume.done[index][0] == key
        if not ran and _left_out(step, context, previous, engine, resume if resuming else None):
            # as if the manifest had no such step: the later ones take its place
            result.skipped.append(step.name)
            pipeline = dataclasses.replace(pipeline, steps=tuple(s for s in pipeline.steps if s is not step))
            chain = chain[:index] + chain[index + 1:]
            index -= 1
            continue
        # only a leading run of steps: a step after one that ran has new input
        resuming = ran
        if resuming:
            previous = _resumed(pipeline, index, key, resume, result, locator, engine)
            continue
        started = time.perf_counter()
        try:
            # every stage but the last keeps its tree for the next one, every
            # stage with rules for them, and the last one of a chain that
            # yields a model for the runs that resume from it
            text, handed = engine.run(step.stylesheet, params, previous,
                                      keep_tree=index < len(chain) - 1 or bool(step.checks)
                                      or pipeline.yields == "model")
        except TransformError as exc:
            _settle(result)  # an earlier stage's error comes first
            failure = _transform_failure(exc, step, locator)
            found, errors = _messages(engine.messages, step, locator)
            # the error that stopped the stage first, then the others it
            # reported before stopping (f:fail-all: in the stage's order)
            if failure.exit_code != EXIT_INTERNAL:
                failure.diagnostics.extend(errors)
            failure.diagnostics[:0] = result.warnings + found
            raise failure from None
        messages = engine.messages
        _settle(result)  # the earlier stages' findings before this one's
        found, errors = _messages(messages, step, locator)
        result.warnings.extend(found)
        if errors:  # reported without stopping: an error all the same
            raise RobomdaError(result.warnings + errors, EXIT_FINDINGS)
        transformed = time.perf_counter()
        writes = _writes_files(pipeline, index)
        result.stages[step.name] = text
        result.timings.append((step.name, transformed - started, 0.0, 0.0))
        result.done.append((key, len(result.warnings), step.checks))
        waiting = None if writes else _hand_over(step, text, index, result, locator)
        tree = _validate(step, text, writes, locator) if waiting is None else None
        result.tree = tree if writes else None
        validated = time.perf_counter()
        try:
            found = _findings(step.checks, step, locator, tree, handed, text, engine)
        except Exception:
            if waiting is not None:  # rules failing on a model that breaks its schema: that first
                _settle(result)
            raise
        if waiting is not None:  # counted once the stage is known valid
            waiting.found = found
        else:
            _add(found, result)
        result.timings[index] = (step.name, transformed - started, validated - transformed,
                                 time.perf_counter() - validated)
        result.done[index] = (key, len(result.warnings), step.checks)
        previous = handed if handed is not None else text
        result.handed = handed if pipeline.yields == "model" else None
    if settle:
        _settle(result)
    return result


def _resumed(pipeline: Pipeline, index: int, key: tuple, resume: RunResult, result: RunResult,
             locator: XmiLocator, engine: Engine) -> str | Tree:
    """Take step ``index`` from ``resume`` into ``result`` (output, warnings, checks still pending),
    check it by the rules this chain adds, and return what the next step reads."""
    step = pipeline.steps[index]
    _, warned, checked = resume.done[index]
    # the rules this chain checks on the step and the earlier run did not
    pending = tuple(c for c in step.checks if c not in checked)
    text = result.stages[step.name] = previous = resume.stages[step.name]
    result.tree = parse(text) if _writes_files(pipeline, index) else None
    result.warnings = list(resume.warnings[:warned])
    if index == len(resume.done) - 1 and resume.handed is not None:
        # taken, not shared: left in the earlier result, the tree stayed alive through
        # the later stages and cost them 1.5 s of garbage collection at 10,000 components
        previous = result.handed = resume.handed
        resume.handed = None
    elif pending:  # its tree in Saxon: a large model's rules run on it, and the next step reads it
        previous = engine.parse(text)
    # the step's validation still out in the checker is taken too: a job's answer is read once, so a
    # second run resuming from the same result must not wait for it again
    result.pending.extend(p for p in resume.pending if p.index == index)
    resume.pending[:] = [p for p in resume.pending if p.index != index]
    started = time.perf_counter()
    result.timings.append(resume.timings[index])
    result.done.append((key, len(result.warnings), step.checks))
    if pending:
        found = _findings(pending, step, locator, result.tree,
                          previous if isinstance(previous, Tree) else None, text, engine)
        if result.pending and result.pending[-1].index == index:  # counted once it is known valid
            result.pending[-1].found += found
        else:
            _settle(result)  # an earlier stage's findings first
            _add(found, result)
    name, xslt, xsd, rules = result.timings[index]
    result.timings[index] = (name, xslt, xsd, rules + time.perf_counter() - started)
    result.done[index] = (key, len(result.warnings), step.checks)
    return previous


def _validate(step: Step, text: str, writes: bool, locator: XmiLocator) -> etree._Element | None:
    """Validate a stage against its step's schema (SCHEMA errors when it breaks it); its lxml tree when
    kept: for the writer, and for a small stage's rules (libxslt). A large stage's rules run on Saxon's
    tree, and a valid large stage is validated as it is parsed."""
    tree, violations = validate(text, step.schema, keep_tree=writes or bool(step.checks) and len(text) < SAXON_FROM)
    if violations:
        raise RobomdaError([
            locator.diagnostic("SCHEMA", f"the {step.name} step wrote a model that breaks "
                               f"{step.schema.name}: {v.reason} at {v.path}", v.element_id, step=step.name)
            for v in violations], EXIT_INTERNAL)
    return tree


def _hand_over(step: Step, text: str, index: int, result: RunResult, locator: XmiLocator) -> _Pending | None:
    """Hand a large stage to the checker process to validate (see robomda.checker); None when it is
    small, or no checker can take it: the caller validates it."""
    if len(text) < SAXON_FROM or not checking.ENABLED:
        return None
    job = checking.checker().submit(text, step.schema)
    if job is None:
        return None
    result.pending.append(_Pending(step, text, job, index, locator))
    return result.pending[-1]


def settle(result: RunResult) -> None:
    """Wait for the stages of ``result`` still being validated in the checker process: a SCHEMA error,
    else their rules' findings (warnings join ``result``, an error is raised), as the run would have
    had them."""
    _settle(result)


def _settle(result: RunResult) -> None:
    while result.pending:
        waiting = result.pending.pop(0)
        started = time.perf_counter()
        if not checking.checker().valid(waiting.job):
            # validated here: the checker could not tell, or the model breaks its schema (explained here)
            _validate(waiting.step, waiting.text, False, waiting.locator)
        _add(waiting.found, result)
        name, xslt, xsd, rules = result.timings[waiting.index]
        result.timings[waiting.index] = (name, xslt, xsd + time.perf_counter() - started, rules)
        key, _, checks = result.done[waiting.index]
        result.done[waiting.index] = (key, len(result.warnings), checks)


def _writes_files(pipeline: Pipeline, index: int) -> bool:
    """Whether step ``index`` of ``pipeline`` makes the file set, whose lxml tree the writer reads."""
    return pipeline.yields == "files" and index == len(pipeline.steps) - 1


def _findings(checks: tuple[Check, ...], step: Step, locator: XmiLocator, tree: etree._Element | None,
              source: Tree | None, text: str, engine: Engine) -> list[list[Diagnostic]]:
    """The findings of ``checks`` on the step's model, per rule set (``tree``: its lxml tree, if
    parsed; ``source``: its tree in Saxon; ``text``: the same, parsed by lxml when a small model's rules
    or a finding's location need it)."""
    lxml_tree = tree if tree is not None else functools.cache(lambda: parse(text))
    on_saxon = source if len(text) >= SAXON_FROM else None  # see robomda.rules
    return [run_rules(check.rules, check.phase, lxml_tree, locator, step.name, source=on_saxon, engine=engine)
            for check in checks]


def _add(found: list[list[Diagnostic]], result: RunResult) -> None:
    """The findings of each rule set in turn join the run's warnings; one with an error stops the run
    (with every finding so far)."""
    for diags in found:
        if any(d.severity == "error" for d in diags):
            raise RobomdaError(result.warnings + diags, EXIT_FINDINGS)
        result.warnings.extend(diags)


def _messages(messages: list[str], step: Step, locator: XmiLocator) -> tuple[list[Diagnostic], list[Diagnostic]]:
    """The stylesheet's messages as (warnings and notes, errors), located."""
    found: list[Diagnostic] = []
    errors: list[Diagnostic] = []
    for message in messages:
        parsed = parse_stylesheet_message(message)
        if parsed is None:
            continue
        severity, code, text, xmi_id = parsed
        diag = locator.diagnostic(code, text, xmi_id, severity=severity, step=step.name)
        (errors if severity == "error" else found).append(diag)
    return found, errors


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
