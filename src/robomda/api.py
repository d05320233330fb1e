"""The public functions: import a model, check it, generate a target, list targets."""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from robomda import pipeline as pipelines
from robomda.diagnostics import EXIT_FINDINGS, EXIT_INPUT, EXIT_INTERNAL, EXIT_OK, Diagnostic, RobomdaError
from robomda.engine import Engine
from robomda.output import WriteReport, write_fileset
from robomda.resources import available_targets, pipeline_path

__all__ = ["generate", "import_model", "check", "targets", "Generated", "Checked"]

_ENGINE: Engine | None = None


def _engine() -> Engine:
    """The process's one Saxon engine (stylesheets stay compiled across calls)."""
    global _ENGINE
    if _ENGINE is None:
        _ENGINE = Engine()
    return _ENGINE


def targets() -> list[str]:
    """The middleware targets ``generate`` knows."""
    return available_targets()


@dataclass
class Generated:
    """What :func:`generate` did: the stage models and the write report."""

    stages: dict[str, str]
    report: WriteReport | None
    timings: list[tuple[str, float, float, float]]
    warnings: list[Diagnostic]


@dataclass
class Checked:
    """What :func:`check` found: every diagnostic, the targets checked, the exit code."""

    diagnostics: list[Diagnostic]
    targets: list[str]
    exit_code: int

    def count(self, severity: str) -> int:
        return sum(1 for d in self.diagnostics if d.severity == severity)


# the middleware an instance is deployed on -> the target that generates for it
_TARGET_OF_MIDDLEWARE = {"OROCOS": "orocos", "ROS": "ros1", "ROS2": "ros2"}


def _check_readable(model: Path) -> None:
    """Fail with a diagnostic when ``model`` is not a file (well-formedness: :func:`_run`)."""
    if not model.is_file():
        raise RobomdaError([Diagnostic("error", "IO001", f"no such model file: {model}", file=str(model))],
                           EXIT_INPUT)


def _check_well_formed(model: Path) -> None:
    """Fail with a located diagnostic when ``model`` is not well-formed XML."""
    parser = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True)
    try:
        etree.parse(str(model), parser)
    except etree.XMLSyntaxError as exc:
        line, column = exc.position if exc.position else (None, None)
        reason = re.sub(r"(, line \d+)+, column \d+$", "", exc.msg)  # the position is in FILE:LINE:COL
        raise RobomdaError([Diagnostic("error", "XML001", f"not well-formed XML: {reason}", file=str(model),
                                       line=line, column=column)], EXIT_INPUT) from None
    except OSError as exc:
        raise RobomdaError([Diagnostic("error", "IO001", f"cannot read: {exc}", file=str(model))],
                           EXIT_INPUT) from None


def _run(chain: pipelines.Pipeline, model: Path, context: dict[str, str], *,
         steps: int | None = None) -> pipelines.RunResult:
    """Run ``chain`` on ``model``; a model Saxon cannot parse fails as XML001, located by lxml.

    Well-formedness is checked only after a failure: a good model is parsed
    once, by Saxon, not once more up front.
    """
    try:
        return pipelines.run(chain, _engine(), model, context, steps=steps)
    except RobomdaError as exc:
        if exc.exit_code == EXIT_INTERNAL:
            _check_well_formed(model)
        raise


def _context(model: Path, out: Path | None, package_name: str, type_map: Path | None = None) -> dict[str, str]:
    model_dir = model.resolve().parent
    rel = os.path.relpath(model_dir, out.resolve()) if out is not None else "."
    return {
        "model-file-name": model.name,
        "model-dir-from-output": Path(rel).as_posix(),
        "package-name": package_name,
        "type-map": type_map.resolve().as_uri() if type_map is not None else "",
    }


def import_model(model: Path | str, *, bind: bool = True, warnings: list[Diagnostic] | None = None) -> str:
    """The PIM of ``model`` as XML text (bound to its platform unless ``bind`` is false).

    The warnings and notes of the run are appended to ``warnings`` when given.
    """
    model = Path(model)
    _check_readable(model)
    chain = pipelines.load(pipeline_path("import"))
    if not bind:
        chain = pipelines.Pipeline(chain.name, chain.yields, chain.description, chain.steps[:1], chain.manifest)
    result = _run(chain, model, _context(model, None, ""))
    if warnings is not None:
        warnings.extend(result.warnings)
    return result.output


def _usage_target(target: str) -> None:
    if target not in targets():
        raise RobomdaError([Diagnostic("error", "USAGE", f"unknown target '{target}' (known: "
                                       f"{', '.join(targets())})")], EXIT_INPUT)


def _type_map(type_map: Path | str | None) -> Path | None:
    """The user's type-map file, which must exist when given."""
    if type_map is None:
        return None
    if not Path(type_map).is_file():
        raise RobomdaError([Diagnostic("error", "IO001", f"no such type-map file: {type_map}", file=str(type_map))],
                           EXIT_INPUT)
    return Path(type_map)


def check(model: Path | str, target: str | None = None, *, package_name: str = "",
          type_map: Path | str | None = None) -> Checked:
    """Run the checks of ``model`` without generating anything.

    With a ``target``, everything ``generate`` would check for it: the import
    and bind errors, the PIM rules, the PSM step and its rules. Without one,
    the same for every target the model's instances are deployed on (the
    shared PIM rules when they are deployed on none robomda generates for).
    Diagnostics found by several targets are reported once. Input that
    cannot be read at all still raises :class:`RobomdaError` (exit code 2).
    """
    model = Path(model)
    if target is not None:
        _usage_target(target)
    _check_readable(model)
    context = _context(model, None, package_name, _type_map(type_map))
    chosen = [target] if target is not None else []
    diagnostics: list[Diagnostic] = []
    exit_code = EXIT_OK

    def run_until_text(name: str) -> pipelines.RunResult | None:
        nonlocal exit_code
        chain = pipelines.load(pipeline_path(name))
        steps = len(chain.steps) - 1 if chain.yields == "files" else None
        try:
            result = _run(chain, model, context, steps=steps)
        except RobomdaError as exc:
            if exc.exit_code != EXIT_FINDINGS:
                raise
            exit_code = EXIT_FINDINGS
            _add(diagnostics, exc.diagnostics)
            return None
        _add(diagnostics, result.warnings)
        return result

    if not chosen:
        shared = run_until_text("check")
        if shared is None:
            return Checked(diagnostics, ["model"], exit_code)
        deployed = {i.get("middleware") for i in shared.tree.iter("{urn:robomda:pim:1}instance")}
        chosen = [t for m, t in _TARGET_OF_MIDDLEWARE.items() if m in deployed]
        if not chosen:
            return Checked(diagnostics, ["model"], exit_code)
        diagnostics.clear()  # the targets' runs repeat the shared findings
    for name in chosen:
        run_until_text(name)
    return Checked(diagnostics, chosen, exit_code)


def _add(into: list[Diagnostic], found: list[Diagnostic]) -> None:
    """Append the diagnostics of ``found`` that ``into`` does not hold yet."""
    seen = {(d.severity, d.code, d.message, d.line, d.column) for d in into}
    for d in found:
        key = (d.severity, d.code, d.message, d.line, d.column)
        if key not in seen:
            seen.add(key)
            into.append(d)


def generate(model: Path | str, out: Path | str | None, target: str = "orocos", *, package_name: str = "",
             type_map: Path | str | None = None, write: bool = True) -> Generated:
    """Run ``target``'s chain on ``model`` and write its files into ``out``.

    Nothing is written unless every step succeeded and every intermediate
    model is valid. With ``write=False`` only the stage outputs are returned.
    """
    model = Path(model)
    _usage_target(target)
    _check_readable(model)
    out_path = Path(out) if out is not None else None
    chain = pipelines.load(pipeline_path(target))
    context = _context(model, out_path, package_name, _type_map(type_map))
    result = _run(chain, model, context)
    report = None
    if write and out_path is not None and chain.yields == "files" and result.tree is not None:
        report = write_fileset(result.tree, out_path)
    return Generated(result.stages, report, result.timings, result.warnings)
