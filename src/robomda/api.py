"""The public functions: import a model, generate a target, list targets."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from robomda import pipeline as pipelines
from robomda.diagnostics import EXIT_INPUT, Diagnostic, RobomdaError
from robomda.engine import Engine
from robomda.output import WriteReport, write_fileset
from robomda.resources import available_targets, pipeline_path

__all__ = ["generate", "import_model", "targets", "Generated"]

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
    timings: list[tuple[str, float, float]]
    warnings: list[Diagnostic]


def _check_readable(model: Path) -> None:
    """Fail with a located diagnostic when ``model`` is missing or not well-formed XML."""
    if not model.is_file():
        raise RobomdaError([Diagnostic("error", "IO001", f"no such model file: {model}", file=str(model))],
                           EXIT_INPUT)
    parser = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True)
    try:
        etree.parse(str(model), parser)
    except etree.XMLSyntaxError as exc:
        line, column = exc.position if exc.position else (None, None)
        raise RobomdaError([Diagnostic("error", "XML001", f"not well-formed XML: {exc.msg}", file=str(model),
                                       line=line, column=column)], EXIT_INPUT) from None
    except OSError as exc:
        raise RobomdaError([Diagnostic("error", "IO001", f"cannot read: {exc}", file=str(model))],
                           EXIT_INPUT) from None


def _context(model: Path, out: Path | None, package_name: str, type_map: Path | None = None) -> dict[str, str]:
    model_dir = model.resolve().parent
    rel = os.path.relpath(model_dir, out.resolve()) if out is not None else "."
    return {
        "model-file-name": model.name,
        "model-dir-from-output": Path(rel).as_posix(),
        "package-name": package_name,
        "type-map": type_map.resolve().as_uri() if type_map is not None else "",
    }


def import_model(model: Path | str, *, bind: bool = True) -> str:
    """The PIM of ``model`` as XML text (bound to its platform unless ``bind`` is false)."""
    model = Path(model)
    _check_readable(model)
    chain = pipelines.load(pipeline_path("import"))
    if not bind:
        chain = pipelines.Pipeline(chain.name, chain.yields, chain.description, chain.steps[:1], chain.manifest)
    return pipelines.run(chain, _engine(), model, _context(model, None, "")).output


def generate(model: Path | str, out: Path | str | None, target: str = "orocos", *, package_name: str = "",
             type_map: Path | str | None = None, write: bool = True) -> Generated:
    """Run ``target``'s chain on ``model`` and write its files into ``out``.

    Nothing is written unless every step succeeded and every intermediate
    model is valid. With ``write=False`` only the stage outputs are returned.
    """
    model = Path(model)
    if target not in targets():
        raise RobomdaError([Diagnostic("error", "USAGE", f"unknown target '{target}' (known: "
                                       f"{', '.join(targets())})")], EXIT_INPUT)
    _check_readable(model)
    out_path = Path(out) if out is not None else None
    chain = pipelines.load(pipeline_path(target))
    if type_map is not None and not Path(type_map).is_file():
        raise RobomdaError([Diagnostic("error", "IO001", f"no such type-map file: {type_map}", file=str(type_map))],
                           EXIT_INPUT)
    context = _context(model, out_path, package_name, Path(type_map) if type_map is not None else None)
    result = pipelines.run(chain, _engine(), model, context)
    report = None
    if write and out_path is not None and chain.yields == "files" and result.tree is not None:
        report = write_fileset(result.tree, out_path)
    return Generated(result.stages, report, result.timings, result.warnings)
