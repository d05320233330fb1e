"""The public functions: import a model, check it, generate a target, list targets."""

from __future__ import annotations

import dataclasses
import os
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from lxml import etree

from robomda import pipeline as pipelines
from robomda.diagnostics import EXIT_FINDINGS, EXIT_INPUT, EXIT_INTERNAL, EXIT_OK, Diagnostic, RobomdaError
from robomda.engine import shared
from robomda.output import Drift, WriteReport, compare_fileset, recorded_paths, user_findings, write_fileset
from robomda.resources import available_targets, default_target, pipeline_path, target_of_middleware
from robomda.validate import stream
from robomda.variability import feature_context

__all__ = ["generate", "diagram", "import_model", "check", "targets", "default_targets", "Generated", "Checked",
           "PackageInfo"]

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
    target: str = ""
    drift: Drift | None = None  # check mode: how the output folder differs from what would be written


@dataclass
class Checked:
    """What :func:`check` found: every diagnostic, the targets checked, the rule sets run, the exit code."""

    diagnostics: list[Diagnostic]
    targets: list[str]
    exit_code: int
    rule_sets: list[str] = field(default_factory=list)

    def count(self, severity: str) -> int:
        return sum(1 for d in self.diagnostics if d.severity == severity)


# the middleware an instance is deployed on -> the target that generates for it
def _check_readable(model: Path) -> None:
    """Fail with a diagnostic when ``model`` is not a file (well-formedness: :func:`_run`)."""
    if not model.is_file():
        raise RobomdaError([Diagnostic("error", "IO001", f"no such model file: {model}", file=str(model))],
                           EXIT_INPUT)


class _NoTree:
    """A parser target that builds nothing: the parse only checks that the XML is well-formed."""

    def close(self) -> None:
        return None


def _check_well_formed(model: Path) -> None:
    """Fail with a located diagnostic when ``model`` is not well-formed XML."""
    # parsed to a target that keeps nothing: a tree of the whole model, freed at once, still left the
    # process 550 MiB larger on a 53 MiB model (glibc keeps the freed nodes; the later stages reused most
    # of it, so the run's peak fell by about 50 MiB, issue 35); the events alone are 3.6 times faster
    parser = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True, target=_NoTree())
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


def _run(chain: pipelines.Pipeline, model: Path, context: dict[str, str], *, steps: int | None = None,
         resume: pipelines.RunResult | None = None, settle: bool = True) -> pipelines.RunResult:
    """Run ``chain`` on ``model``; a model Saxon cannot parse fails as XML001, located by lxml.

    Well-formedness is checked only after a failure: a good model is parsed
    once, by Saxon, not once more up front.
    """
    unread = _external_entities(model)
    if resume is not None and unread:  # the earlier run's warnings start with them: _run put them there
        original, resume = resume, dataclasses.replace(resume, warnings=resume.warnings[len(unread):])
        original.handed = None  # the copy takes the tree (see RunResult.handed)
    try:
        result = pipelines.run(chain, shared(), model, context, steps=steps, resume=resume, settle=settle)
    except RobomdaError as exc:
        if exc.exit_code == EXIT_INTERNAL:
            _check_well_formed(model)
        exc.diagnostics[:0] = unread
        raise
    result.warnings[:0] = unread
    return result


# an external entity declared in the document type: <!ENTITY [%] name SYSTEM|PUBLIC ...>
_EXTERNAL_ENTITY = re.compile(rb"<!ENTITY\s+(?:%\s+)?([^\s>]+)\s+(?:SYSTEM|PUBLIC)\s+[\"']([^\"']*)", re.S)


def _external_entities(model: Path) -> list[Diagnostic]:
    """IMP005 for each external entity the model declares: no parser of robomda's reads them."""
    try:
        with model.open("rb") as handle:
            head = handle.read(1 << 16)
    except OSError:
        return []
    prolog = head.split(b"]>", 1)[0] if b"<!DOCTYPE" in head else b""
    found = []
    for match in _EXTERNAL_ENTITY.finditer(prolog):
        line = head.count(b"\n", 0, match.start()) + 1
        name, target = (g.decode("utf-8", "replace") for g in match.groups())
        found.append(Diagnostic("warning", "IMP005", f"the model declares the external entity '{name}' "
                                f"({target}): robomda reads no external entity or DTD, so its references are empty",
                                file=str(model), line=line, column=1))
    return found


@dataclass(frozen=True)
class PackageInfo:
    """What package.xml says of a generated package: empty fields are placeholders (PKG002)."""

    version: str = ""
    maintainer: str = ""  # "Name <e-mail>"
    license: str = ""
    year: str = ""  # of the copyright notices in generated sources; empty: none with a year

    def context(self) -> dict[str, str]:
        found = re.fullmatch(r"\s*(.*?)\s*<([^<>]*)>\s*", self.maintainer)
        name, email = (found.group(1), found.group(2)) if found else (self.maintainer.strip(), "")
        return {"package-version": self.version, "maintainer-name": name, "maintainer-email": email,
                "license": self.license, "copyright-year": self.year}


def _context(model: Path, out: Path | None, package_name: str, type_map: Path | None = None,
             package: PackageInfo | None = None, model_path: Sequence[Path] = (),
             features: Path | str | None = None) -> dict[str, str]:
    model_dir = model.resolve().parent
    rel = os.path.relpath(model_dir, out.resolve()) if out is not None else "."
    return {
        "model-file-name": model.name,
        "model-dir-from-output": Path(rel).as_posix(),
        "package-name": package_name,
        "type-map": type_map.resolve().as_uri() if type_map is not None else "",
        "model-path": " ".join(d.resolve().as_uri().rstrip("/") + "/" for d in _model_path(model_path)),
        "model-uri": model.resolve().as_uri(),
        **(package or PackageInfo()).context(),
        **feature_context(features),
    }


def _model_path(model_path: Sequence[Path | str]) -> list[Path]:
    """The model path (folders that referenced model files may be read from), each an existing folder."""
    for folder in model_path:
        if not Path(folder).is_dir():
            raise RobomdaError([Diagnostic("error", "IO001", f"--model-path {folder} is not a folder",
                                           file=str(folder))], EXIT_INPUT)
    return [Path(f) for f in model_path]


def import_model(model: Path | str, *, bind: bool = True, warnings: list[Diagnostic] | None = None,
                 model_path: Sequence[Path | str] = (), features: Path | str | None = None) -> str:
    """The PIM of ``model`` as XML text (bound to its platform unless ``bind`` is false).

    The warnings and notes of the run are appended to ``warnings`` when given. With ``features`` (a
    FeatureIDE configuration) the PIM is the template model configured for it (docs/variability.md).
    """
    model = Path(model)
    _check_readable(model)
    chain = pipelines.load(pipeline_path("import"))
    if not bind:
        chain = pipelines.Pipeline(chain.name, chain.yields, chain.description,
                                   tuple(s for s in chain.steps if s.name != "bind"), chain.manifest)
    result = _run(chain, model, _context(model, None, "", model_path=_model_path(model_path), features=features))
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
          type_map: Path | str | None = None, model_path: Sequence[Path | str] = (),
          features: Path | str | None = None, replace: Sequence[str] = ()) -> Checked:
    """Run the checks of ``model`` without generating anything.

    With a ``target``, everything ``generate`` would check for it: the import
    and bind errors, the PIM rules, the PSM step and its rules. Without one,
    the same for every target ``generate`` would pick (:func:`default_targets`):
    the middlewares the model's instances are deployed on, or Orocos when
    they are deployed on none robomda generates for (ROS 2 when they are
    deployed on none and run as managed nodes: Papyrus for Robotics). ``rule_sets`` names the
    rule files (and phases) that ran. Diagnostics found by several targets
    are reported once. Input that cannot be read at all still raises
    :class:`RobomdaError` (exit code 2).

    Once those pass, the component swaps (seed 004's substitutability,
    docs/substitution.md): every «Alternative» of the model, and each
    ``replace`` pair ``"OLD=NEW"``, whose violations are errors SUB001-SUB011;
    then every job as a configuration of its own and the report of each
    switch between jobs (docs/jobs.md: JOB010-JOB029).
    """
    model = Path(model)
    if target is not None:
        _usage_target(target)
    _check_readable(model)
    context = _context(model, None, package_name, _type_map(type_map), model_path=_model_path(model_path),
                       features=features)
    context["replace"] = " ".join(replace)
    diagnostics: list[Diagnostic] = []
    rule_sets: list[str] = []
    exit_code = EXIT_OK

    def run_until_text(name: str, resume: pipelines.RunResult | None = None) -> pipelines.RunResult | None:
        nonlocal exit_code
        chain = pipelines.load(pipeline_path(name))
        steps = len(chain.steps) - 1 if chain.yields == "files" else None
        ran = chain.steps[:steps]
        try:
            result = _run(chain, model, context, steps=steps, resume=resume)
        except RobomdaError as exc:
            if exc.exit_code != EXIT_FINDINGS:
                raise
            exit_code = EXIT_FINDINGS
            _add(diagnostics, exc.diagnostics)
            ran = _steps_checked(ran, exc.diagnostics)
            return None
        finally:
            for step in ran:
                for rules in step.checks:
                    label = rules.rules.name + (f" ({rules.phase})" if rules.phase else "")
                    if label not in rule_sets:
                        rule_sets.append(label)
        _add(diagnostics, result.warnings)
        return result

    shared = None
    if target is not None:
        chosen = [target]
    else:
        shared = run_until_text("check")
        if shared is None:
            return Checked(diagnostics, ["model"], exit_code, rule_sets)
        chosen = _targets_of(shared) or [default_target()]
        diagnostics.clear()  # the targets' runs repeat the shared findings
    last = shared
    for name in chosen:
        last = run_until_text(name, shared) if exit_code == EXIT_OK else None
    if exit_code == EXIT_OK and last is not None:
        run_until_text("substitute", last)  # the swaps and the jobs, on the bound PIM the last run made
    return Checked(diagnostics, chosen, exit_code, rule_sets)


def _steps_checked(steps: list[pipelines.Step], found: list[Diagnostic]) -> list[pipelines.Step]:
    """The steps of a failed run whose rules ran: those before the failing step, and the failing step
    itself when its rules made the error (an error of its stylesheet stops it before its rules)."""
    failing = next((d.step for d in found if d.severity == "error" and d.step), None)
    names = [step.name for step in steps]
    if failing not in names:
        return []
    at = names.index(failing)
    codes = {d.code for d in found if d.severity == "error" and d.step == failing}
    by_rules = any(codes & _rule_ids(check.rules) for check in steps[at].checks)
    return steps[:at + 1] if by_rules else steps[:at]


@lru_cache(maxsize=None)
def _rule_ids(rules: Path) -> frozenset[str]:
    tree = etree.parse(str(rules))
    return frozenset(tree.xpath("//sch:assert/@id | //sch:report/@id",
                                namespaces={"sch": "http://purl.oclc.org/dsdl/schematron"}))


def _targets_of(bound: pipelines.RunResult) -> list[str]:
    """The targets of the middlewares the instances of a bound PIM (the import chain's result) are
    deployed on (ROS 2's when they are deployed on none and their default processes are managed), in
    target order (looked up in the tree Saxon holds, else read from the text as a stream: no lxml tree
    of the whole model for a few attributes)."""
    pim = {"m": "urn:robomda:pim:1"}
    if bound.handed is not None:
        deployed = set(shared().strings(bound.handed, "distinct-values(//m:instance/@middleware)", pim))
        managed = set(shared().strings(bound.handed, "distinct-values(//m:process[@default = 'true']/@managed)", pim))
    else:
        deployed, managed = set(), set()
        for e in stream(bound.output):  # each element is cleared once read: take what is needed now
            if e.tag == "{urn:robomda:pim:1}instance":
                deployed.add(e.get("middleware"))
            elif e.tag == "{urn:robomda:pim:1}process" and e.get("default") == "true":
                managed.add(e.get("managed"))
    deployed.discard(None)
    if not deployed and managed == {"true"}:
        # deployed on nothing, but run as managed (lifecycle) nodes, as its tool means them (Papyrus
        # for Robotics): ROS 2, the middleware with a node lifecycle
        deployed = {"ROS2"}
    served = target_of_middleware()
    return [t for t in available_targets() if any(served.get(m) == t for m in deployed)]


def default_targets(model: Path | str, model_path: Sequence[Path | str] = ()) -> list[str]:
    """The targets ``generate`` and ``check`` use without ``--target``: the model's middlewares, else Orocos
    (ROS 2 for a model deployed on none whose default processes run managed nodes)."""
    model = Path(model)
    _check_readable(model)
    return _default_targets(model, _context(model, None, "", model_path=_model_path(model_path)))[0]


def _default_targets(model: Path, context: dict[str, str], *,
                     settle: bool = True) -> tuple[list[str], pipelines.RunResult]:
    """:func:`default_targets` of a readable ``model``, and the import run that found them (a
    target's chain resumes from it; with ``settle=False``, the checks of its last stage may still be
    running: see pipelines.run)."""
    bound = _run(pipelines.load(pipeline_path("import")), model, context, settle=settle)
    return _targets_of(bound) or [default_target()], bound


def _add(into: list[Diagnostic], found: list[Diagnostic]) -> None:
    """Append the diagnostics of ``found`` that ``into`` does not hold yet."""
    seen = {(d.severity, d.code, d.message, d.line, d.column) for d in into}
    for d in found:
        key = (d.severity, d.code, d.message, d.line, d.column)
        if key not in seen:
            seen.add(key)
            into.append(d)


def _package_name_note(asked: str, psm: str | None, model: Path) -> list[Diagnostic]:
    """PKG001 when the package name written is not the one ``--package-name`` gave."""
    if not asked or not psm:
        return []
    root = etree.fromstring(psm.encode("utf-8"))
    written = root.get("package") or root.get("name") or ""
    if written == asked:
        return []
    return [Diagnostic("warning", "PKG001", f"--package-name '{asked}' is written '{written}': package names "
                       "are lower-case letters, digits and underscores (CMake, catkin and ament)", file=str(model))]


def generate(model: Path | str, out: Path | str | None, target: str | None = None, *, package_name: str = "",
             type_map: Path | str | None = None, write: bool = True, package: PackageInfo | None = None,
             model_path: Sequence[Path | str] = (), diagrams: bool = False, check: bool = False,
             features: Path | str | None = None) -> Generated:
    """Run ``target``'s chain on ``model`` and write its files into ``out``.

    Without a ``target``: the one middleware the model deploys on (Orocos
    when it deploys on none robomda generates for, ROS 2 when it deploys on
    none but runs managed nodes); a model deployed on
    several must name one (usage error, exit code 2). Nothing is written
    unless every step succeeded and every intermediate model is valid. With
    ``write=False`` only the stage outputs are returned. With ``diagrams``,
    the package also gets the model's diagrams (:func:`diagram`), written
    and tracked as its other generated files. With ``check=True``
    nothing is written either: ``drift`` says how ``out`` differs from what
    would be written (:func:`robomda.output.compare_fileset`; empty when ``out``
    is up to date).
    """
    model = Path(model)
    if target is not None:
        _usage_target(target)
    _check_readable(model)
    out_path = Path(out) if out is not None else None
    context = _context(model, out_path, package_name, _type_map(type_map), package, _model_path(model_path), features)
    bound = None
    if target is None:
        found, bound = _default_targets(model, context, settle=False)
        if len(found) > 1:
            pipelines.settle(bound)  # an error of the model comes first
            raise RobomdaError([Diagnostic(
                "error", "USAGE", f"the model deploys on several middlewares ({', '.join(found)}): "
                "name the one to generate with --target", file=str(model))], EXIT_INPUT)
        target = found[0]  # a target of the manifests: no usage check needed
    chain = pipelines.load(pipeline_path(target))
    result = _run(chain, model, context, resume=bound)
    warnings = result.warnings + _package_name_note(package_name, result.stages.get("psm"), model)
    if diagrams and result.tree is not None:
        warnings += _add_diagrams(result, model, context, render=write)
    missing = [opt for opt, key in (("--maintainer", "maintainer-email"), ("--license", "license")) if not context[key]]
    writes_manifest = result.tree is not None and any(
        f.get("path") == "package.xml" for f in result.tree.iter("{urn:robomda:fileset:1}file"))
    if missing and write and out_path is not None and chain.yields == "files" and writes_manifest:
        warnings.append(Diagnostic("warning", "PKG002", f"package.xml names a placeholder {' and '.join(m[2:] for m in missing)}: "
                                   f"give {' and '.join(missing)} (a package cannot be released as it is)",
                                   file=str(model)))
    report, drift = None, None
    if check and out_path is not None and chain.yields == "files" and result.tree is not None:
        errors, found = user_findings(result.tree, out_path)  # what writing would say of the user files
        if errors:
            raise RobomdaError(warnings + errors, EXIT_INPUT)
        warnings += found
        drift = compare_fileset(result.tree, out_path)
    elif write and out_path is not None and chain.yields == "files" and result.tree is not None:
        report = write_fileset(result.tree, out_path)
        warnings += report.warnings
    return Generated(result.stages, report, result.timings, warnings, target, drift)


def _add_diagrams(result: pipelines.RunResult, model: Path, context: dict[str, str], *, render: bool) -> list[Diagnostic]:
    """Add the model's diagrams (and their SVGs, with ``render``) to the file set of a target's run; the
    diagram chain resumes from that run (import, bind and the PIM rules are not run again)."""
    from robomda.diagrams import add_svgs

    drawn = _run(pipelines.load(pipeline_path("diagrams")), model, context, resume=result)
    found = [d for d in drawn.warnings if d not in result.warnings]
    if drawn.tree is not None and result.tree is not None:
        for node in list(drawn.tree.iterchildren("{urn:robomda:fileset:1}file")):
            result.tree.append(node)
        if render:
            found += add_svgs(result.tree, str(model))
    return found


def diagram(model: Path | str, out: Path | str | None, *, write: bool = True, render: bool = True,
            model_path: Sequence[Path | str] = ()) -> Generated:
    """Write the diagrams of ``model`` into ``out``: its component view and deployment view as PlantUML
    (``diagrams/<model>-components.puml``, ``-deployment.puml``; pipelines/diagrams.xml), and each as SVG
    when PlantUML is installed and ``render`` (robomda.diagrams). Nothing is written if the model has
    errors; ``write=False`` returns the stage outputs only.
    """
    from robomda.diagrams import add_svgs

    model = Path(model)
    _check_readable(model)
    out_path = Path(out) if out is not None else None
    context = _context(model, out_path, "", model_path=_model_path(model_path))
    if write and out_path is not None:
        _refuse_package_folder(out_path)
    result = _run(pipelines.load(pipeline_path("diagrams")), model, context)
    warnings = list(result.warnings)
    report = None
    if result.tree is not None and render and write:
        warnings += add_svgs(result.tree, str(model))
    if write and out_path is not None and result.tree is not None:
        report = write_fileset(result.tree, out_path)
        warnings += report.warnings
    return Generated(result.stages, report, result.timings, warnings, "diagrams")


def _refuse_package_folder(out: Path) -> None:
    """USAGE when ``out`` holds a package robomda generated: written there, the diagrams alone would
    make every file of the package stale (removed) for the writer."""
    package = [p for p in recorded_paths(out.resolve()) if not p.startswith("diagrams/")]
    if package:
        raise RobomdaError([Diagnostic(
            "error", "USAGE", f"{out} holds a package robomda generated ({package[0]} ...): draw its diagrams "
            "with generate --diagrams, or give diagram another folder", file=str(out))], EXIT_INPUT)
